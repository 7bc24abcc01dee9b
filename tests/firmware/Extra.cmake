# The brick's mode machine is plain C++ over the drivers' logic: tested on the host from its source.
target_sources(test_firmware PRIVATE ${PROJECT_SOURCE_DIR}/firmware/app/ModeMachine.cpp
                                     ${PROJECT_SOURCE_DIR}/firmware/app/ModeMachineHouse.cpp
                                     ${PROJECT_SOURCE_DIR}/firmware/app/ModeMachineOutputs.cpp)

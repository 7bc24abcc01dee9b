# Included by tests/CMakeLists.txt for the emu folder: cross-builds the probe programs (tests/emu/fw) with
# the arm-none-eabi toolchain as an external project and tells test_emu where they are.
include(ExternalProject)
set(NXTMAP_EMU_PROBE_DIR ${CMAKE_BINARY_DIR}/emu-probes)
ExternalProject_Add(emu_probes
  SOURCE_DIR ${CMAKE_CURRENT_SOURCE_DIR}/emu/fw
  BINARY_DIR ${NXTMAP_EMU_PROBE_DIR}
  CMAKE_GENERATOR Ninja
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/toolchain/arm-none-eabi.cmake -DCMAKE_BUILD_TYPE=MinSizeRel
  BUILD_ALWAYS ON
  INSTALL_COMMAND "")
add_dependencies(test_emu emu_probes)
target_compile_definitions(test_emu PRIVATE NXTMAP_EMU_PROBE_DIR="${NXTMAP_EMU_PROBE_DIR}")

# The real firmware image (firmware/, when present), cross-built the same way for the end-to-end tests.
if(EXISTS ${PROJECT_SOURCE_DIR}/firmware/CMakeLists.txt)
  set(NXTMAP_EMU_FIRMWARE_DIR ${CMAKE_BINARY_DIR}/emu-firmware)
  ExternalProject_Add(emu_firmware
    SOURCE_DIR ${PROJECT_SOURCE_DIR}/firmware
    BINARY_DIR ${NXTMAP_EMU_FIRMWARE_DIR}
    CMAKE_GENERATOR Ninja
    CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/toolchain/arm-none-eabi.cmake
    BUILD_ALWAYS ON
    INSTALL_COMMAND "")
  add_dependencies(test_emu emu_firmware)
  target_compile_definitions(test_emu PRIVATE NXTMAP_EMU_FIRMWARE_DIR="${NXTMAP_EMU_FIRMWARE_DIR}")
endif()

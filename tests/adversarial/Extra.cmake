# Included by tests/CMakeLists.txt for the adversarial folder: the suite runs `nxtmap emulate` on the real
# firmware image, cross-built by tests/emu/Extra.cmake's emu_firmware project.
add_dependencies(test_adversarial emu_firmware)
target_compile_definitions(test_adversarial PRIVATE
                           NXTMAP_FIRMWARE_ELF="${CMAKE_BINARY_DIR}/emu-firmware/nxtmap-sim.elf")

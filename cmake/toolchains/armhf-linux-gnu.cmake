# Cross toolchain for 32-bit ARM with hardware floating point (Cortex-A9: Zynq-7000), Debian's g++-arm-linux-gnueabihf:
#   scripts/cross armhf        (sysroot, configure, build, ctest -L flight under qemu-user)
#   cmake -S . -B build-cross-armhf -G Ninja -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/armhf-linux-gnu.cmake \
#         -DEVADE_FLIGHT_WING_ONLY=ON      (after scripts/cross_sysroot armhf)
# docs/INTEGRATION.md "Cross-building for your flight computer".
set(EVADE_CROSS_TARGET armhf)
set(EVADE_CROSS_TRIPLE arm-linux-gnueabihf)
set(EVADE_CROSS_QEMU qemu-arm-static)
set(CMAKE_SYSTEM_PROCESSOR arm)
include(${CMAKE_CURRENT_LIST_DIR}/evade-linux-gnu-cross.cmake)

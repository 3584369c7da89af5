# Cross toolchain for 32-bit ARM with hardware floating point (Cortex-A9: Zynq-7000), Debian's g++-arm-linux-gnueabihf:
#   scripts/cross armhf        (sysroot, configure, build, ctest -L flight under qemu-user)
#   cmake -S . -B build-cross-armhf -G Ninja -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/armhf-linux-gnu.cmake \
#         -DEVADE_FLIGHT_WING_ONLY=ON      (after scripts/cross_sysroot armhf)
# docs/INTEGRATION.md "Cross-building for your flight computer".
set(EVADE_CROSS_TARGET armhf)
set(EVADE_CROSS_TRIPLE arm-linux-gnueabihf)
set(EVADE_CROSS_QEMU qemu-arm-static)
set(CMAKE_SYSTEM_PROCESSOR arm)
# GCC's -Wpsabi notes on armhf say only that GCC 7.1 changed how some std::vector iterators are
# passed: they matter when linking objects built by GCC < 7.1, which this toolchain never does.
# 64-bit time_t and file offsets (glibc >= 2.34): a 32-bit time_t ends in January 2038, within
# a spacecraft's life; evade's own times are int64 microseconds, but the node reads the clocks
# through timespec.
set(CMAKE_CXX_FLAGS_INIT "-Wno-psabi -D_FILE_OFFSET_BITS=64 -D_TIME_BITS=64")
set(CMAKE_C_FLAGS_INIT "-D_FILE_OFFSET_BITS=64 -D_TIME_BITS=64")
include(${CMAKE_CURRENT_LIST_DIR}/evade-linux-gnu-cross.cmake)

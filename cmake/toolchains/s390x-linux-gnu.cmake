# Cross toolchain for big-endian 64-bit IBM Z (the big-endian target Debian carries), Debian's g++-s390x-linux-gnu:
#   scripts/cross s390x        (sysroot, configure, build, ctest -L flight under qemu-user)
#   cmake -S . -B build-cross-s390x -G Ninja -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/s390x-linux-gnu.cmake \
#         -DEVADE_FLIGHT_WING_ONLY=ON      (after scripts/cross_sysroot s390x)
# docs/INTEGRATION.md "Cross-building for your flight computer".
set(EVADE_CROSS_TARGET s390x)
set(EVADE_CROSS_TRIPLE s390x-linux-gnu)
set(EVADE_CROSS_QEMU qemu-s390x-static)
set(CMAKE_SYSTEM_PROCESSOR s390x)
include(${CMAKE_CURRENT_LIST_DIR}/evade-linux-gnu-cross.cmake)

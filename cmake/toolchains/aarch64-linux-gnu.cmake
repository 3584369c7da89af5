# Cross toolchain for 64-bit ARM (Cortex-A53/A72: Zynq UltraScale+, i.MX 8), Debian's g++-aarch64-linux-gnu:
#   scripts/cross aarch64        (sysroot, configure, build, ctest -L flight under qemu-user)
#   cmake -S . -B build-cross-aarch64 -G Ninja -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/aarch64-linux-gnu.cmake \
#         -DEVADE_FLIGHT_WING_ONLY=ON      (after scripts/cross_sysroot aarch64)
# docs/INTEGRATION.md "Cross-building for your flight computer".
set(EVADE_CROSS_TARGET aarch64)
set(EVADE_CROSS_TRIPLE aarch64-linux-gnu)
set(EVADE_CROSS_QEMU qemu-aarch64-static)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
include(${CMAKE_CURRENT_LIST_DIR}/evade-linux-gnu-cross.cmake)

# The part of evade's Debian cross toolchain files they share (aarch64-linux-gnu.cmake,
# armhf-linux-gnu.cmake, s390x-linux-gnu.cmake set EVADE_CROSS_TARGET, EVADE_CROSS_TRIPLE,
# EVADE_CROSS_QEMU and CMAKE_SYSTEM_PROCESSOR, then include this file).
#
# The compiler is <triple>-g++ from Debian's g++-<triple> package, never the host's: when it
# is missing, the configure stops at once with one line naming the package. The libraries
# come from the sysroot EVADE_SYSROOT (-DEVADE_SYSROOT=DIR, else the environment's
# EVADE_SYSROOT, else build-cross-sysroot-<target> in the source tree, which
# scripts/cross_sysroot <target> builds from Debian's packages); a missing sysroot stops the
# configure the same way. The C library and libstdc++ the programs link are the cross
# toolchain's (libc6-<arch>-cross, the same glibc 2.36 and GCC 12 as the target's Debian
# packages); the sysroot holds the target's own copies for the emulator. Programs (lcm-gen,
# pkg-config, python3) are the host's. ctest runs the target programs under
# qemu-<arch>-static -L <sysroot> (CMAKE_CROSSCOMPILING_EMULATOR).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_LIBRARY_ARCHITECTURE ${EVADE_CROSS_TRIPLE})

# try_compile projects read this file again: they get the sysroot from the main project.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES EVADE_SYSROOT)

# On PATH only (where Debian puts them), never a guessed host compiler.
find_program(EVADE_CROSS_CXX NAMES ${EVADE_CROSS_TRIPLE}-g++ NO_CACHE NO_CMAKE_PATH
             NO_CMAKE_ENVIRONMENT_PATH NO_CMAKE_SYSTEM_PATH)
find_program(EVADE_CROSS_CC NAMES ${EVADE_CROSS_TRIPLE}-gcc NO_CACHE NO_CMAKE_PATH
             NO_CMAKE_ENVIRONMENT_PATH NO_CMAKE_SYSTEM_PATH)
if(NOT EVADE_CROSS_CXX OR NOT EVADE_CROSS_CC)
  message(FATAL_ERROR " evade: the cross compiler ${EVADE_CROSS_TRIPLE}-g++ is not installed: apt-get install g++-${EVADE_CROSS_TRIPLE}")
endif()
set(CMAKE_CXX_COMPILER ${EVADE_CROSS_CXX})
set(CMAKE_C_COMPILER ${EVADE_CROSS_CC})

if(NOT EVADE_SYSROOT)
  if(DEFINED ENV{EVADE_SYSROOT} AND NOT "$ENV{EVADE_SYSROOT}" STREQUAL "")
    set(EVADE_SYSROOT "$ENV{EVADE_SYSROOT}")
  else()
    get_filename_component(_evade_src "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
    set(EVADE_SYSROOT "${_evade_src}/build-cross-sysroot-${EVADE_CROSS_TARGET}")
  endif()
endif()
set(EVADE_SYSROOT "${EVADE_SYSROOT}" CACHE PATH "the target's sysroot (scripts/cross_sysroot)")
if(NOT EXISTS "${EVADE_SYSROOT}/usr/include/lcm/lcm.h"
   OR NOT EXISTS "${EVADE_SYSROOT}/usr/lib/${EVADE_CROSS_TRIPLE}/liblcm.so")
  message(FATAL_ERROR " evade: no ${EVADE_CROSS_TARGET} sysroot with LCM at ${EVADE_SYSROOT}: run scripts/cross_sysroot ${EVADE_CROSS_TARGET} (or give -DEVADE_SYSROOT=DIR)")
endif()

# Headers, libraries and CMake packages from the sysroot only; programs from the host.
set(CMAKE_FIND_ROOT_PATH "${EVADE_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(ENV{PKG_CONFIG_LIBDIR}
    "${EVADE_SYSROOT}/usr/lib/${EVADE_CROSS_TRIPLE}/pkgconfig:${EVADE_SYSROOT}/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "${EVADE_SYSROOT}")
set(ENV{PKG_CONFIG_PATH} "")
# The sysroot's shared libraries find theirs (liblcm needs GLib) at link time.
set(_evade_rpath_link
    "-Wl,-rpath-link,${EVADE_SYSROOT}/usr/lib/${EVADE_CROSS_TRIPLE}:${EVADE_SYSROOT}/lib/${EVADE_CROSS_TRIPLE}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${_evade_rpath_link}")
set(CMAKE_SHARED_LINKER_FLAGS_INIT "${_evade_rpath_link}")

find_program(EVADE_CROSS_QEMU_PATH NAMES ${EVADE_CROSS_QEMU} NO_CACHE)
if(EVADE_CROSS_QEMU_PATH)
  set(CMAKE_CROSSCOMPILING_EMULATOR "${EVADE_CROSS_QEMU_PATH};-L;${EVADE_SYSROOT}")
else()
  message(WARNING " evade: ${EVADE_CROSS_QEMU} is not installed (apt-get install qemu-user-static): the target's programs build, but ctest cannot run them here")
endif()

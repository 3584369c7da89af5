# cmake -DTARGET=aarch64|armhf|s390x -DSOURCE_DIR=... -DWORK_DIR=... -P check_missing_toolchain.cmake
# 1. The cross compiler missing: PATH holds only a directory with the host's compilers (g++,
#    gcc, c++, cc), so that a toolchain file falling back to them would find them there. The
#    configure must fail, print the toolchain file's line naming the Debian package, and never
#    identify a compiler (no fallback to the host's, fprime#2563).
# 2. The sysroot missing (only where the cross compiler is installed): -DEVADE_SYSROOT naming
#    an empty directory must fail with the line naming scripts/cross_sysroot.
set(_triple_aarch64 aarch64-linux-gnu)
set(_triple_armhf arm-linux-gnueabihf)
set(_triple_s390x s390x-linux-gnu)
set(triple ${_triple_${TARGET}})
if(NOT triple)
  message(FATAL_ERROR "unknown TARGET '${TARGET}'")
endif()
set(toolchain ${SOURCE_DIR}/cmake/toolchains/${TARGET}-linux-gnu.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/host_only_path ${WORK_DIR}/empty_sysroot)
foreach(cc g++ gcc c++ cc)
  find_program(host_${cc} ${cc})
  if(host_${cc})
    file(CREATE_LINK ${host_${cc}} ${WORK_DIR}/host_only_path/${cc} SYMBOLIC)
  endif()
endforeach()

# Runs the configure given after `case` and `want`; fails unless it exits non-zero, stops with an
# error of the toolchain file itself (at once, not a warning and a later failure), prints the
# line want, and identifies no compiler (never a fallback to the host's).
function(expect_configure_fails case want)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 100)
  set(out "${out}${err}")
  if(rc EQUAL 0)
    message(FATAL_ERROR "${TARGET}: the configure with ${case} succeeded:\n${out}")
  endif()
  if(NOT out MATCHES "CMake Error at [^\n]*cmake/toolchains/evade-linux-gnu-cross[.]cmake")
    message(FATAL_ERROR "${TARGET}: the toolchain file did not stop the configure itself:\n${out}")
  endif()
  string(FIND "${out}" "${want}" at)
  if(at LESS 0)
    message(FATAL_ERROR "${TARGET}: no line '${want}' in:\n${out}")
  endif()
  if(out MATCHES "compiler identification is")
    message(FATAL_ERROR "${TARGET}: a compiler was identified (a fallback):\n${out}")
  endif()
  message(STATUS "${TARGET}: ${case} -> exit ${rc}: ${want}")
endfunction()

expect_configure_fails("no cross compiler"
  "evade: the cross compiler ${triple}-g++ is not installed: apt-get install g++-${triple}"
  ${CMAKE_COMMAND} -E env PATH=${WORK_DIR}/host_only_path
  ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/no_compiler
  -DCMAKE_TOOLCHAIN_FILE=${toolchain} -DEVADE_FLIGHT_WING_ONLY=ON)

find_program(cross_cxx ${triple}-g++)
if(NOT cross_cxx)
  message(STATUS "${TARGET}: ${triple}-g++ not installed here: the missing-sysroot case is not run")
  return()
endif()
expect_configure_fails("no sysroot"
  "evade: no ${TARGET} sysroot with LCM at ${WORK_DIR}/empty_sysroot: run scripts/cross_sysroot ${TARGET}"
  ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/no_sysroot
  -DCMAKE_TOOLCHAIN_FILE=${toolchain} -DEVADE_FLIGHT_WING_ONLY=ON
  -DEVADE_SYSROOT=${WORK_DIR}/empty_sysroot)

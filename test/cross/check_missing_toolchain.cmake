# cmake -DTARGET=aarch64|armhf|s390x -DSOURCE_DIR=... -DWORK_DIR=... -P check_missing_toolchain.cmake
# 1. The cross compiler missing: PATH holds only an empty directory, so that neither
#    <triple>-g++ nor a host compiler can be found there. The configure must fail, print the
#    toolchain file's line naming the Debian package, and never identify a compiler (no
#    fallback to /usr/bin/c++, fprime#2563).
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
file(MAKE_DIRECTORY ${WORK_DIR}/empty_path ${WORK_DIR}/empty_sysroot)

function(configure out_var rc_var)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 100)
  set(${out_var} "${out}${err}" PARENT_SCOPE)
  set(${rc_var} "${rc}" PARENT_SCOPE)
endfunction()

configure(out rc ${CMAKE_COMMAND} -E env PATH=${WORK_DIR}/empty_path
          ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/no_compiler
          -DCMAKE_TOOLCHAIN_FILE=${toolchain} -DEVADE_FLIGHT_WING_ONLY=ON)
set(want "evade: the cross compiler ${triple}-g++ is not installed: apt-get install g++-${triple}")
if(rc EQUAL 0)
  message(FATAL_ERROR "${TARGET}: the configure without the cross compiler succeeded:\n${out}")
endif()
string(FIND "${out}" "${want}" at)
if(at LESS 0)
  message(FATAL_ERROR "${TARGET}: no line '${want}' in:\n${out}")
endif()
if(out MATCHES "compiler identification is")
  message(FATAL_ERROR "${TARGET}: a compiler was identified (a fallback):\n${out}")
endif()
message(STATUS "${TARGET}: no cross compiler -> exit ${rc}: ${want}")

find_program(cross_cxx ${triple}-g++)
if(NOT cross_cxx)
  message(STATUS "${TARGET}: ${triple}-g++ not installed here: the missing-sysroot case is not run")
  return()
endif()
configure(out rc ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/no_sysroot
          -DCMAKE_TOOLCHAIN_FILE=${toolchain} -DEVADE_FLIGHT_WING_ONLY=ON
          -DEVADE_SYSROOT=${WORK_DIR}/empty_sysroot)
set(want "evade: no ${TARGET} sysroot with LCM at ${WORK_DIR}/empty_sysroot: run scripts/cross_sysroot ${TARGET}")
if(rc EQUAL 0)
  message(FATAL_ERROR "${TARGET}: the configure without a sysroot succeeded:\n${out}")
endif()
string(FIND "${out}" "${want}" at)
if(at LESS 0)
  message(FATAL_ERROR "${TARGET}: no line '${want}' in:\n${out}")
endif()
message(STATUS "${TARGET}: no sysroot -> exit ${rc}: ${want}")

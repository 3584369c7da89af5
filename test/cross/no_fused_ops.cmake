# cross.NoFusedMultiplyAddInTheFlightLibraries (docs/GUIDANCE_NODE.md NODE-RT-5): disassembles
# each file of FILES (a |-separated list) with OBJDUMP and fails when an instruction matching
# FUSED (the target's fused multiply-add mnemonics) is there, outside the functions whose
# demangled name matches ALLOW (when given: Eigen's general matrix-product kernel, which fuses
# in its aarch64 NEON code whatever the compiler's flags; those are counted and printed).
# PLAIN, a multiply of this target, must be found in one of them at least, so an empty or
# foreign disassembly cannot pass. Run on a file that has fused instructions (the C library's
# libm), it must report them: the negative control,
# cross.NoFusedMultiplyAddInTheFlightLibraries.Control.
string(REPLACE "|" ";" files "${FILES}")
set(plain_found FALSE)
foreach(f IN LISTS files)
  execute_process(COMMAND ${OBJDUMP} -d -C --no-show-raw-insn ${f} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE asm ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${OBJDUMP} -d ${f}: exit ${rc}: ${err}")
  endif()
  if(asm MATCHES "[ \t](${PLAIN})[ \t]")
    set(plain_found TRUE)
  endif()
  # Function headers ("<name>:" at a line's end) and fused instructions, in order.
  string(REGEX MATCHALL "<[^\n]*>:\n|[ \t](${FUSED})[ \t][^\n]*" tokens "${asm}")
  set(fn "")
  set(bad 0)
  set(allowed 0)
  set(first "")
  foreach(t IN LISTS tokens)
    if(t MATCHES ">:\n$")
      set(fn "${t}")
    elseif(ALLOW AND fn MATCHES "${ALLOW}")
      math(EXPR allowed "${allowed} + 1")
    else()
      math(EXPR bad "${bad} + 1")
      if(first STREQUAL "")
        string(STRIP "${fn}${t}" first)
      endif()
    endif()
  endforeach()
  if(bad GREATER 0)
    message(STATUS "found ${bad} fused multiply-add instructions in ${f}")  # one line, unwrapped
    message(FATAL_ERROR "${f}: ${bad} fused multiply-add instructions, the first in ${first}")
  endif()
  message(STATUS "${f}: no fused multiply-add (${allowed} inside '${ALLOW}')")
endforeach()
if(NOT plain_found)
  message(FATAL_ERROR "no '${PLAIN}' in any disassembly: not this target's code?")
endif()

# cross.InstructionHarnessRunsStepsAndSignedCycles: the harness (under the target's emulator,
# EMU, |-separated, in a cross build) runs 10 steps and 10 signed cycles with a status signature, exit 0,
# and its checksum is a finite number (the law thrusted: the cycles' sum is not zero).
string(REPLACE "|" ";" emu "${EMU}")
foreach(args "step;10" "cycle;2;10")
  execute_process(COMMAND ${emu} ${H} ${args} RESULT_VARIABLE rc ERROR_VARIABLE err
                  OUTPUT_VARIABLE out TIMEOUT 240)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "")
    message(FATAL_ERROR "harness ${args}: exit ${rc}, stdout '${out}', stderr '${err}'")
  endif()
  if(NOT err MATCHES "^checksum [0-9.e+-]+\n$" OR err MATCHES "^checksum 0\n$")
    message(FATAL_ERROR "harness ${args}: checksum line '${err}'")
  endif()
  message(STATUS "harness ${args}: ${err}")
endforeach()

# Runs EXE with ARGS (a ;-list) and checks the exit code is EXPECT_RC and that stdout+stderr
# contains EXPECT_TEXT.
execute_process(COMMAND ${EXE} ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT rc EQUAL EXPECT_RC)
  message(FATAL_ERROR "exit code ${rc}, expected ${EXPECT_RC}\n${all}")
endif()
string(FIND "${all}" "${EXPECT_TEXT}" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "output does not contain '${EXPECT_TEXT}':\n${all}")
endif()
message(STATUS "ok: exit ${rc}; found '${EXPECT_TEXT}'")

# Fails when docs/PARAMETERS.md is not what `evade params` prints from the parameter tables
# today (a table changed and the document was not regenerated).
#   cmake -DEXE=<evade> -DDOC=<docs/PARAMETERS.md> -P check_parameters_md.cmake
execute_process(COMMAND ${EXE} params OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "evade params exited ${rc}")
endif()
file(READ ${DOC} committed)
if(NOT generated STREQUAL committed)
  message(FATAL_ERROR "docs/PARAMETERS.md is stale: regenerate it with "
                      "`build/apps/evade params > docs/PARAMETERS.md`")
endif()

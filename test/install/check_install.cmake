# Installs the built tree into a scratch prefix, builds the outside project consumer/ against it
# (one executable per exported target, its own -Werror, evade's headers not system headers),
# runs each, and runs the installed `evade` from the prefix with the source tree's scenarios
# out of reach: it must find its shipped scenario under <prefix>/share/evade/scenarios.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_out "${out}" PARENT_SCOPE)
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
foreach(t core auth dynamics sgp4 config lcm_types guidance sim guidance_lcm lcm_link
          observability threat conjunction assessment formation distributed)
  run(${WORK_DIR}/build/consumer_${t})
  string(FIND "${last_out}" "${t} ok" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "consumer_${t} did not print '${t} ok':\n${last_out}")
  endif()
  message(STATUS "${last_out}")
endforeach()
foreach(f include/evade/lcm_types/evade_burn_plan_t.lcm include/evade/lcm_types/evade_auth_t.lcm
          share/evade/scripts/plot_sim.py share/evade/scenarios/seed0.yaml)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
if(EXISTS ${prefix}/bin/evade)
  # The installed CLI resolves a scenario by name from its own prefix: a copy of seed0 that
  # exists only there is found, and the search order lists the prefix before the source tree.
  file(COPY_FILE ${prefix}/share/evade/scenarios/seed0.yaml
       ${prefix}/share/evade/scenarios/only-in-prefix.yaml)
  run(${CMAKE_COMMAND} -E env --unset=EVADE_SCENARIO_DIR ${prefix}/bin/evade sim
      --scenario only-in-prefix --json)
  string(FIND "${last_out}" "\"miss_m\"" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "the installed evade did not run the scenario of its prefix:\n${last_out}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=EVADE_SCENARIO_DIR ${prefix}/bin/evade
                          sim --scenario no-such-scenario
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  string(FIND "${err}" "searched: ${prefix}/bin/../share/evade/scenarios" pos)
  if(NOT rc EQUAL 2 OR pos EQUAL -1)
    message(FATAL_ERROR "the installed evade does not search its prefix first (exit ${rc}):\n${err}")
  endif()
  message(STATUS "installed evade: scenarios from ${prefix}/share/evade/scenarios")
endif()

# evade_add_module(NAME <m> SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...] [NO_INSTALL])
# Creates library target evade_<m> with alias evade::<m>, warnings (as errors with
# EVADE_WERROR), sanitizer flags,
# public include dir include/, and (unless NO_INSTALL) adds it to the evadeTargets export.
# -Wall -Wextra always; -Werror only with EVADE_WERROR (a developer option, on in scripts/test
# and the developer scripts, off by default): a user's compiler version or build type must not
# turn a new warning into a failed build.
function(evade_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra $<$<BOOL:${EVADE_WERROR}>:-Werror>)
endfunction()

# The flight code (src/guidance, src/guidance_lcm, apps/evade_guidance_node) also gets
# -Wpedantic -Wconversion -Wshadow: no implicit narrowing, no shadowed names, standard C++
# only. A conversion the code needs is an explicit cast with a comment proving it safe.
# In the coverage build (scripts/coverage, CMAKE_BUILD_TYPE=Coverage, -O1 elsewhere) the
# flight code is compiled at -O0, so that its line and branch counts map one to one onto
# the source: at -O1 GCC merges identical tails (two `cancel(...); return {};` blocks)
# and the gate would count one of them as never executed.
# The floating-point contract of flight code (docs/INTEGRATION.md, docs/GUIDANCE_NODE.md): no
# contraction of a*b+c into a fused multiply-add, on every target. GCC contracts by default in
# C++ wherever the CPU has FMA (aarch64, s390x; not x86-64's baseline, where the flag changes
# no instruction), and a fused result rounds once where x86-64 rounds twice: with it off, the
# guidance law computes the same bits on every target. The flight modules, the scenario
# reader and the simulator they are checked in on every target (test/cross/
# same_guidance_test.cpp), the guidance node and the test programs (which inline the same
# header code) get it.
set(EVADE_FLIGHT_FP_MODULES core auth config dynamics guidance autonomy sim assessment guidance_lcm)
# Eigen fuses on its own where the compiler would not: its NEON packet multiply-add for
# doubles is vfmaq_f64 whenever __ARM_FEATURE_FMA is defined (Eigen/src/Core/arch/NEON/
# PacketMath.h), which every aarch64 compiler defines, so a 3x3 product's packet half was fused
# and its scalar third not (seed3's first burn came out 1 ulp from x86-64's in
# same_guidance_test). Flight code on aarch64 undefines the macro: Eigen keeps its two-double
# packets (SSE2's width, the same order of operations) and multiplies and adds separately.
function(evade_set_flight_fp target)
  target_compile_options(${target} PRIVATE -ffp-contract=off)
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64)$")
    target_compile_options(${target} PRIVATE -U__ARM_FEATURE_FMA)
  endif()
endfunction()

# The stack report (scripts/stack_check, docs/GUIDANCE_NODE.md NODE-RT-6): with
# EVADE_STACK_USAGE, GCC writes each flight function's frame (-fstack-usage, .su) and each
# translation unit's call graph with the frames (-fcallgraph-info=su, .ci) beside its object.
# Neither changes the code generated.
function(evade_set_stack_usage target)
  if(EVADE_STACK_USAGE AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -fstack-usage -fcallgraph-info=su)
  endif()
endfunction()

function(evade_set_flight_warnings target)
  evade_set_warnings(${target})
  evade_set_flight_fp(${target})
  # Clang's -Wconversion also turns on -Wsign-conversion, which GCC's does not in C++; it
  # fires in lcm-gen's generated headers (hash = _computeHash(NULL)). The same set on both
  # compilers: sign conversion off under Clang (the fuzz configuration).
  # -O0 in the coverage build only where the coverage is measured (EVADE_COVERAGE_MODULES).
  set(o0 $<$<CONFIG:Coverage>:-O0>)
  string(REGEX REPLACE "^evade_" "" m "${target}")
  if(EVADE_COVERAGE_MODULES AND NOT m IN_LIST EVADE_COVERAGE_MODULES)
    set(o0 "")
  endif()
  target_compile_options(${target} PRIVATE -Wpedantic -Wconversion -Wshadow
                                           $<$<CXX_COMPILER_ID:Clang>:-Wno-sign-conversion>
                                           ${o0})
endfunction()

if(EVADE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# The fuzz configuration: every module and harness instrumented for libFuzzer's coverage
# feedback and checked by ASan+UBSan (any UB aborts, so libFuzzer keeps the input); the
# harness executables add -fsanitize=fuzzer (libFuzzer's main) at link time.
if(EVADE_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                      -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# The coverage gate (scripts/coverage --gate) measures only the modules of
# EVADE_COVERAGE_MODULES (empty: every module is measured). In a coverage build the others are
# compiled as in a release, without the counters (-fno-profile-arcs -fno-test-coverage, -O2):
# they run under the gate's tests (the onboard conjunction response's planning: the 2D Pc and
# the avoidance burn search) 50 to 100 times slower with atomic counters, which the gate does not read.
set(EVADE_COVERAGE_MODULES "" CACHE STRING "Modules the coverage build instruments (empty: all)")
function(evade_set_coverage_scope target name)
  if(CMAKE_BUILD_TYPE STREQUAL "Coverage" AND EVADE_COVERAGE_MODULES AND
     NOT name IN_LIST EVADE_COVERAGE_MODULES)
    target_compile_options(${target} PRIVATE -fno-profile-arcs -fno-test-coverage -O2)
  endif()
endfunction()

function(evade_add_module)
  cmake_parse_arguments(M "NO_INSTALL" "NAME" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  set(t evade_${M_NAME})
  add_library(${t} ${M_SOURCES})
  add_library(evade::${M_NAME} ALIAS ${t})
  set_target_properties(${t} PROPERTIES EXPORT_NAME ${M_NAME} OUTPUT_NAME evade_${M_NAME}
                                        POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${t} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${t} PUBLIC cxx_std_17)
  if(EVADE_UNITY_MODULES)
    set_target_properties(${t} PROPERTIES UNITY_BUILD ON)
  endif()
  target_link_libraries(${t} PUBLIC ${M_PUBLIC_DEPS} PRIVATE ${M_PRIVATE_DEPS})
  evade_set_warnings(${t})
  evade_set_coverage_scope(${t} ${M_NAME})
  if(M_NAME IN_LIST EVADE_FLIGHT_FP_MODULES)
    evade_set_flight_fp(${t})
    evade_set_stack_usage(${t})
  endif()
  if(NOT M_NO_INSTALL)
    install(TARGETS ${t} EXPORT evadeTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  endif()
endfunction()

# evade_add_test(<name> SOURCES ... LIBS ... [LABELS ...] [TIMEOUT s] [RUN_SERIAL])
# One gtest executable per test file group, registered with gtest_discover_tests.
function(evade_add_test name)
  cmake_parse_arguments(T "RUN_SERIAL" "TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/test)  # test/support/
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  evade_set_warnings(${name})
  evade_set_flight_fp(${name})
  if(TARGET evade_test_pch)  # test/CMakeLists.txt, EVADE_TEST_PCH
    target_link_libraries(${name} PRIVATE Eigen3::Eigen)  # the header's own include path
    target_precompile_headers(${name} REUSE_FROM evade_test_pch)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  set(serial FALSE)
  if(T_RUN_SERIAL)
    set(serial TRUE)  # timing- or network-sensitive: never beside another test
  endif()
  # Cross builds (cmake/toolchains/) list a test program's tests when ctest runs, under the
  # emulator (CMAKE_CROSSCOMPILING_EMULATOR), not at build time: the build needs no qemu, and
  # the emulator's start-up is paid once per program.
  set(discovery POST_BUILD)
  if(CMAKE_CROSSCOMPILING)
    set(discovery PRE_TEST)
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 DISCOVERY_MODE ${discovery}
    PROPERTIES TIMEOUT ${T_TIMEOUT} RUN_SERIAL ${serial})
  # Labels are set after discovery, from a file ctest includes after the discovered tests:
  # passed through gtest_discover_tests' PROPERTIES, a list of two labels ("conjunction;sgp4")
  # is split into separate arguments, and every test ends up with no label at all.
  if(T_LABELS)
    set(labels_file ${CMAKE_CURRENT_BINARY_DIR}/${name}_labels.cmake)
    file(WRITE ${labels_file}
      "if(${name}_TESTS)\n  set_tests_properties(\${${name}_TESTS} PROPERTIES LABELS \"${T_LABELS}\")\nendif()\n")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${labels_file})
  endif()
endfunction()

# evade_add_cli_test(<name> <label> <expected_rc> <expected_text> <args>...)
# Runs the real `evade` binary with <args> and checks its exit code and that its output
# contains <expected_text> (test/cli/expect_cli.cmake).
function(evade_add_cli_test name label expected_rc expected_text)
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:evade> -DEXPECT_RC=${expected_rc}
            "-DEXPECT_TEXT=${expected_text}" "-DARGS=${ARGN}"
            -P ${PROJECT_SOURCE_DIR}/test/cli/expect_cli.cmake)
  set_tests_properties(${name} PROPERTIES TIMEOUT 120 LABELS "${label}")
endfunction()

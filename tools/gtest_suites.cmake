# Run after a GoogleTest program is linked (tests/CMakeLists.txt,
# rayspec_suite_tests): lists its tests and writes OUT, a ctest script with one
# test per suite, PREFIX/<Suite>, running `PROGRAM --gtest_filter=<Suite>.*`.
# One process runs a suite's tests, instead of one process per test (each
# start loads OpenImageIO's few hundred libraries: about 0.2 s).
# EXCLUDE: suites left out (;-separated); LABELS: the tests' labels;
# ENVIRONMENT: their environment (NAME=VALUE). A suite
# in which a test skips (GTEST_SKIP) is reported skipped, never passed: a test
# that skips where the build lacks something sits in a suite of its own.
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND "${PROGRAM}" --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE rc TIMEOUT 60)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --gtest_list_tests failed (${rc}):\n${listing}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(script "# Written by tools/gtest_suites.cmake from ${PROGRAM} --gtest_list_tests\n")
foreach(line IN LISTS lines)
  # A suite line starts in column 0 and ends its name with '.'; test lines are indented.
  if(NOT line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
    continue()
  endif()
  set(suite "${CMAKE_MATCH_1}")
  if(suite IN_LIST EXCLUDE)
    continue()
  endif()
  string(APPEND script "add_test([==[${PREFIX}${suite}]==] [==[${PROGRAM}]==] [==[--gtest_filter=${suite}.*]==])\n"
                       "set_tests_properties([==[${PREFIX}${suite}]==] PROPERTIES LABELS [==[${LABELS}]==] "
                       "ENVIRONMENT [==[${ENVIRONMENT}]==] SKIP_REGULAR_EXPRESSION [==[\\[  SKIPPED \\]]==])\n")
endforeach()
file(WRITE "${OUT}" "${script}")

# Registers one ctest test per TEST suite of a test program (tests/CMakeLists.txt), named
# "test_x:Suite.*" and run as test_x --gtest_filter=Suite.*: each process costs about 0.2 s of
# start-up (the OpenCV and HDF5 libraries it loads), which one process per TEST paid 900 times.
# Run after the program is built, as gtest_discover_tests is; reads TEST_EXECUTABLE, CTEST_FILE, TIMEOUT.
execute_process(COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests failed (${status}):\n${listing}")
endif()
get_filename_component(program "${TEST_EXECUTABLE}" NAME)
string(REPLACE "\n" ";" lines "${listing}")
set(content "")
foreach(line IN LISTS lines)
  # A suite's line ends with '.', before a "# TypeParam" comment if it has one; its tests are indented.
  if(line MATCHES "^([^ ]+)\\.( .*)?$")
    set(name "${program}:${CMAKE_MATCH_1}.*")
    string(APPEND content "add_test([==[${name}]==] [==[${TEST_EXECUTABLE}]==] [==[--gtest_filter=${CMAKE_MATCH_1}.*]==])\n"
                          "set_tests_properties([==[${name}]==] PROPERTIES TIMEOUT ${TIMEOUT})\n")
  endif()
endforeach()
file(WRITE "${CTEST_FILE}" "${content}")

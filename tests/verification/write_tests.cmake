# Writes OUTPUT: one ctest test per name that `METHODS --names` prints,
# verification.<name>, running that method's case of TEST_EXE.
execute_process(COMMAND ${METHODS} --names OUTPUT_VARIABLE names RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${METHODS} --names failed (${rc})")
endif()
string(STRIP "${names}" names)
string(REPLACE "\n" ";" names "${names}")
set(content "")
foreach(name IN LISTS names)
  string(APPEND content
    "add_test(verification.${name} \"${TEST_EXE}\" --gtest_filter=Registry/Verification.*/${name})\n"
    "set_tests_properties(verification.${name} PROPERTIES LABELS \"verification;hardcase\" TIMEOUT 300)\n")
endforeach()
file(WRITE ${OUTPUT} "${content}")

# Reruns scripts/derive_nonholonomic.py (which also checks the Euler-Lagrange
# consistency of the modified Lagrangian and fails if it does not hold) and
# requires its output to equal the committed header byte for byte.
execute_process(COMMAND ${PYTHON} ${SOURCE_DIR}/scripts/derive_nonholonomic.py --output ${OUTPUT}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "scripts/derive_nonholonomic.py failed (exit ${rc})")
endif()
set(committed ${SOURCE_DIR}/src/geomint/systems/nonholonomic_modified.hpp)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUTPUT} ${committed} RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "the committed ${committed} differs from a fresh derivation (${OUTPUT}); "
                      "regenerate it with: python3 scripts/derive_nonholonomic.py")
endif()
message(STATUS "committed header equals a fresh derivation")

# The run summary (JOB.summary.json, docs/summary.md) and the Python tools package (tools/ldfcz_tools): label tools.
# The JSON writer and the summary counters (no solver); the summaries of real runs against the documented keys (a
# completed run, one without convergence, one stopped after 5 increments and its restart, an input error, a deck
# error; under mpirun -np 2 in the LDFCZ_MPI build); the package's own unit tests (tests/tools, no network, seconds).
if(TARGET ldfcz_host)
  ldfcz_add_pf_suite(NAME test_json_writer PF test_json_writer.pf LINK ldfcz_host)
endif()
if(TARGET ldfcz)
  set(_ldfcz_summary_check "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_summary_json.py"
      --exe $<TARGET_FILE:ldfcz> --decks "${PROJECT_SOURCE_DIR}/decks/single" --doc "${PROJECT_SOURCE_DIR}/docs/summary.md")
  add_test(NAME summary_json_keys COMMAND Python3::Interpreter ${_ldfcz_summary_check}
           --out "${CMAKE_CURRENT_BINARY_DIR}/summary_json_keys")
  set_tests_properties(summary_json_keys PROPERTIES LABELS "tools" TIMEOUT 300
    PASS_REGULAR_EXPRESSION "PASS" FAIL_REGULAR_EXPRESSION "FAIL")
  if(LDFCZ_MPI)
    add_test(NAME summary_json_mpi COMMAND Python3::Interpreter ${_ldfcz_summary_check}
             --out "${CMAKE_CURRENT_BINARY_DIR}/summary_json_mpi" --np 2)
    set_tests_properties(summary_json_mpi PROPERTIES LABELS "mpi" TIMEOUT 300 ENVIRONMENT "${LDFCZ_MPI_ENV}"
      PASS_REGULAR_EXPRESSION "PASS" FAIL_REGULAR_EXPRESSION "FAIL")
  endif()
endif()
# The package's unit tests (tests/tools: readers against a real run, deck generator invariants, the package's shape)
add_test(NAME tools_package
  COMMAND Python3::Interpreter -m unittest discover -s "${CMAKE_CURRENT_SOURCE_DIR}/tools" -v)
set_tests_properties(tools_package PROPERTIES LABELS "tools" TIMEOUT 120
  ENVIRONMENT "LDFCZ_DECKS=${PROJECT_SOURCE_DIR}/decks")
if(TARGET ldfcz)
  set_property(TEST tools_package APPEND PROPERTY ENVIRONMENT "LDFCZ_EXE=$<TARGET_FILE:ldfcz>")
endif()

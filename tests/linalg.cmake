# Suites of the host's linear algebra (host/linalg) and of the Abaqus utility routines (host/abaqus).
if(TARGET ldfcz_linalg)
  ldfcz_add_pf_suite(NAME test_sparse_system PF test_sparse_system.pf LINK ldfcz_linalg)
endif()
if(TARGET ldfcz_abaqus_utils)
  ldfcz_add_pf_suite(NAME test_abaqus_utils PF test_abaqus_utils.pf LINK ldfcz_abaqus_utils)
endif()
# The heap setting of the host (host/linalg/heap_reuse.c): freed large blocks reused without new page faults.
if(TARGET ldfcz_linalg)
  add_executable(test_heap_reuse test_heap_reuse.c "${PROJECT_SOURCE_DIR}/host/linalg/heap_reuse.c")
  set_target_properties(test_heap_reuse PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/tests")
  add_test(NAME test_heap_reuse COMMAND test_heap_reuse)
  set_tests_properties(test_heap_reuse PROPERTIES SKIP_RETURN_CODE 77 LABELS unit)
endif()

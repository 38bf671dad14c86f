# Suites of the host's linear algebra (host/linalg) and of the Abaqus utility routines (host/abaqus).
if(TARGET ldfcz_linalg)
  ldfcz_add_pf_suite(NAME test_sparse_system PF test_sparse_system.pf LINK ldfcz_linalg)
endif()
if(TARGET ldfcz_abaqus_utils)
  ldfcz_add_pf_suite(NAME test_abaqus_utils PF test_abaqus_utils.pf LINK ldfcz_abaqus_utils)
endif()

# Suites of the LDF cohesive element (uel/): the law, then the Abaqus adapter called exactly as Abaqus would call it.
ldfcz_add_pf_suite(NAME test_cohesive_law PF test_cohesive_law.pf LINK ldfcz_uel abaqus_test_stubs)
foreach(suite test_uel test_uel_tangent test_uel_energy test_uel_patch)
  if(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${suite}.pf")
    ldfcz_add_pf_suite(NAME ${suite} PF ${suite}.pf LINK ldfcz_test_support ldfcz_uel abaqus_test_stubs)
  endif()
endforeach()
ldfcz_add_pf_suite(NAME test_uel_viscous PF test_uel_viscous.pf LINK ldfcz_test_support ldfcz_uel abaqus_test_stubs)

# Suites of the LDF cohesive element (uel/): the law, then the Abaqus adapter called exactly as Abaqus would call it.
ldfcz_add_pf_suite(NAME test_cohesive_law PF test_cohesive_law.pf LINK ldfcz_uel abaqus_test_stubs)
foreach(suite test_uel test_uel_tangent test_uel_energy test_uel_patch)
  if(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${suite}.pf")
    ldfcz_add_pf_suite(NAME ${suite} PF ${suite}.pf LINK ldfcz_test_support ldfcz_uel abaqus_test_stubs)
  endif()
endforeach()
ldfcz_add_pf_suite(NAME test_uel_viscous PF test_uel_viscous.pf LINK ldfcz_test_support ldfcz_uel abaqus_test_stubs)

# USELEM (uel/uselem.f) built against the test doubles of Marc's include files 'concom' and 'creeps' and of QUIT
# (tests/support/marc): the Marc entry point itself is called with Marc's argument list and compared with the UEL
add_library(marc_uselem_test STATIC "${PROJECT_SOURCE_DIR}/uel/uselem.f" support/marc/marc_test_stubs.f)
target_include_directories(marc_uselem_test PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}/support/marc")
target_link_libraries(marc_uselem_test PUBLIC ldfcz_uel)
if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  target_compile_options(marc_uselem_test PRIVATE ${LDFCZ_FIXED_FORM_FLAGS} -Wno-unused-dummy-argument)
endif()
ldfcz_add_pf_suite(NAME test_uselem PF test_uselem.pf LINK ldfcz_uel abaqus_test_stubs marc_uselem_test)

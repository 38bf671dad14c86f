# Unit tests of the compressible Leonov model: the pure core and the Abaqus/Marc adapters.
ldfcz_add_pf_suite(NAME test_leonov PF test_leonov.pf LINK ldfcz_test_support ldfcz_umat)
# The finiteness test the UMAT and UEL cores use instead of ieee_is_finite (common/ldfcz_finite.f90)
ldfcz_add_pf_suite(NAME test_finite PF test_finite.pf LINK ldfcz_kinds)
# HYPELA2 (umat/hypela2.f) built against test doubles of Marc's include files 'concom' and 'creeps' and of QUIT
# (tests/support/marc): the Marc entry point itself is called with Marc's argument list, not only its layer
add_library(marc_hypela2_test STATIC "${PROJECT_SOURCE_DIR}/umat/hypela2.f" support/marc/marc_test_stubs.f)
target_include_directories(marc_hypela2_test PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}/support/marc")
target_link_libraries(marc_hypela2_test PUBLIC ldfcz_umat)
ldfcz_warnings(marc_hypela2_test)
if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  target_compile_options(marc_hypela2_test PRIVATE ${LDFCZ_FIXED_FORM_FLAGS} -Wno-unused-dummy-argument)
endif()
ldfcz_add_pf_suite(NAME test_umat PF test_umat.pf LINK ldfcz_umat abaqus_test_stubs marc_hypela2_test)

# Energy balance of the Leonov UMAT on one C3D8 under loading, holding and unloading (issue 17): closes to 1e-4 in
# simple shear with second-order convergence in the increment; uniaxial: the model-intrinsic 3e-4, increment-free
# (tolerances and reasons in the script)
if(TARGET ldfcz)
  add_test(NAME umat_energy_balance
    COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_energy_pet.py"
            $<TARGET_FILE:ldfcz> "${CMAKE_CURRENT_BINARY_DIR}/umat_energy_balance")
  set_tests_properties(umat_energy_balance PROPERTIES LABELS "umat" TIMEOUT 300)
endif()

# The Leonov UMAT's plane-stress branch (NTENS = 3, the UMAT solves sigma_33 = 0) in uniaxial stress against the
# 3D UMAT in bin/material_point's uniaxial mode, tension / relaxation / unloading with a rotation: 1e-8 of the peak
if(TARGET material_point)
  add_test(NAME umat_plane_stress_uniaxial
    COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_plane_stress_uniaxial.py"
            --mp $<TARGET_FILE:material_point> --out "${CMAKE_CURRENT_BINARY_DIR}/umat_plane_stress_uniaxial")
  set_tests_properties(umat_plane_stress_uniaxial PROPERTIES LABELS "umat" TIMEOUT 120)
endif()

# Unit tests of the compressible Leonov model: the pure core and the Abaqus/Marc adapters.
ldfcz_add_pf_suite(NAME test_leonov PF test_leonov.pf LINK ldfcz_umat)
ldfcz_add_pf_suite(NAME test_umat PF test_umat.pf LINK ldfcz_umat abaqus_test_stubs)

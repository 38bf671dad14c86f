# Reproducibility (docs/testing.md): the same deck run again gives the same bits (tests/regression/check_reproducible.py:
# JOB.csv, JOB.dat and JOB.sta compared byte for byte, and the closing summary's counts). The small 3D peel (Leonov
# C3D8 coating, cohesive layer; 20 increments with PNEWDT cutbacks) under the application scene's solver options
# (tools/peel_study.py application: --newton auto, whose GMRES budget decides the path, and single-precision LDL^T
# factors as its preconditioner).
if(NOT TARGET ldfcz)
  return()
endif()
set(LDFCZ_REPRO_OPTIONS --newton auto --factors symmetric-single --max-opening-increment 0.33
  --max-plastic-increment 1.0 --stop-after-increments 20)
if(NOT LDFCZ_MPI)
  # twice on 1 thread, once on 2
  add_test(NAME reproducible_peel3d COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_reproducible.py --exe $<TARGET_FILE:ldfcz>
    --deck ${PROJECT_SOURCE_DIR}/decks/peel/peel_3d_quarter.inp --out ${CMAKE_CURRENT_BINARY_DIR}/reproducible_peel3d
    --expect-exit 3 -- ${LDFCZ_REPRO_OPTIONS})
  set_tests_properties(reproducible_peel3d PROPERTIES LABELS "deck" TIMEOUT 300 PASS_REGULAR_EXPRESSION "PASS")
else()
  # two identical 2-process runs, the linear systems on one process (--reproducible: MUMPS' parallel
  # factorization sums in the order its messages arrive; docs/host.md)
  add_test(NAME mpi_reproducible_peel3d COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_reproducible.py --exe $<TARGET_FILE:ldfcz> --np 2
    --deck ${PROJECT_SOURCE_DIR}/decks/peel/peel_3d_quarter.inp --out ${CMAKE_CURRENT_BINARY_DIR}/mpi_reproducible_peel3d
    --expect-exit 3 -- ${LDFCZ_REPRO_OPTIONS} --reproducible)
  set_tests_properties(mpi_reproducible_peel3d PROPERTIES LABELS "mpi" TIMEOUT 300 PASS_REGULAR_EXPRESSION "PASS"
    ENVIRONMENT "${LDFCZ_MPI_ENV}")
endif()

# Tests of the distributed run (LDFCZ_MPI=ON only; tools/test.sh builds that configuration in build-mpi): each deck
# class under mpirun -np 2 and -np 3 against the same deck on one process (tests/regression/check_mpi.py: same
# increments, attempts and Newton iterations, results within 1e-6 of each column's largest value; XIT: the same
# message naming the element), and the partition test (tests/mpi/partition_check.f90: every element owned once,
# the distributed force and tangent equal to the serial ones to 1e-12).
if(NOT LDFCZ_MPI OR NOT TARGET ldfcz)
  return()
endif()
find_program(LDFCZ_MPIEXEC NAMES mpirun mpiexec REQUIRED)
# yield_when_idle: a process waiting for a message gives its core away (the test machine is shared; 3 processes on
# 2 cores)
set(LDFCZ_MPI_ENV OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
  OMPI_MCA_mpi_yield_when_idle=1)

add_executable(partition_check mpi/partition_check.f90)
ldfcz_warnings(partition_check)
target_link_libraries(partition_check PRIVATE ldfcz_host "$<LINK_LIBRARY:WHOLE_ARCHIVE,ldfcz_abaqus_utils>")
set_target_properties(partition_check PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/tests/bin")
foreach(np 2 3)
  foreach(deck patch/patch_c3d8 peel/peel_ps)
    get_filename_component(name ${deck} NAME)
    add_test(NAME mpi_partition_${name}_np${np}
      COMMAND ${LDFCZ_MPIEXEC} -np ${np} --oversubscribe --bind-to none $<TARGET_FILE:partition_check>
        ${PROJECT_SOURCE_DIR}/decks/${deck}.inp)
    set_tests_properties(mpi_partition_${name}_np${np} PROPERTIES LABELS "mpi" TIMEOUT 120
      ENVIRONMENT "${LDFCZ_MPI_ENV}" PASS_REGULAR_EXPRESSION "PASS" FAIL_REGULAR_EXPRESSION "FAIL")
  endforeach()
  # the interleaved partition (4 METIS pieces per process dealt out in turn on the plane-strain peel's 90 elements;
  # 3 per process with 3 processes: at least 10 elements a piece)
  add_test(NAME mpi_partition_interleaved_np${np}
    COMMAND ${LDFCZ_MPIEXEC} -np ${np} --oversubscribe --bind-to none $<TARGET_FILE:partition_check>
      ${PROJECT_SOURCE_DIR}/decks/peel/peel_ps.inp 4)
  set_tests_properties(mpi_partition_interleaved_np${np} PROPERTIES LABELS "mpi" TIMEOUT 120
    ENVIRONMENT "${LDFCZ_MPI_ENV}" PASS_REGULAR_EXPRESSION "PASS" FAIL_REGULAR_EXPRESSION "FAIL")
endforeach()

set(LDFCZ_CHECK_MPI "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_mpi.py")
function(ldfcz_add_mpi_test name deck)
  add_test(NAME ${name} COMMAND Python3::Interpreter ${LDFCZ_CHECK_MPI} --exe $<TARGET_FILE:ldfcz>
    --deck ${deck} --out ${CMAKE_CURRENT_BINARY_DIR}/mpi/${name} ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS "mpi" TIMEOUT 600 ENVIRONMENT "${LDFCZ_MPI_ENV}")
endfunction()
ldfcz_add_mpi_test(mpi_cohesive_block ${PROJECT_SOURCE_DIR}/decks/single/cohesive_block.inp)
ldfcz_add_mpi_test(mpi_leonov_uniaxial ${PROJECT_SOURCE_DIR}/decks/single/c3d8_umat_uniaxial.inp)
ldfcz_add_mpi_test(mpi_rotation ${PROJECT_SOURCE_DIR}/decks/single/c3d8_rotation_uniaxial.inp)
# with the element-loop trace (LDFCZ_LOOP_TRACE): the same loops as on one process, every element computed once per
# loop over the processes, the slowest time the largest process's, benchmarks/loop_trace.py's sum of the slowest loops the
# summary's; an unwritable trace path only warns
ldfcz_add_mpi_test(mpi_peel_ps ${CMAKE_CURRENT_SOURCE_DIR}/mpi/peel_ps_short.inp --trace)
# the interleaved partition (4 pieces per process, 3 with 3 processes; the default gives these small decks one)
ldfcz_add_mpi_test(mpi_peel_ps_interleaved ${CMAKE_CURRENT_SOURCE_DIR}/mpi/peel_ps_short.inp
  -- --partition-pieces 4)
# the small 3D peel (Leonov C3D8 coating, cohesive layer): its first 12 increments (PNEWDT cutbacks included); with
# the trace, whose files must hold every loop on every process although the run ends with exit 3 (mpirun ends the
# other processes as soon as one has exited with a non-zero status: the trace is closed before the processes part)
ldfcz_add_mpi_test(mpi_peel_3d ${PROJECT_SOURCE_DIR}/decks/peel/peel_3d_quarter.inp --expect-exit 3 --trace
  -- --stop-after-increments 12)
# *EL PRINT / *NODE PRINT tables, which rank 0 writes: the printed states of elements on other processes are
# gathered first (JOB.dat equal to the one-process run's to its printed digits)
ldfcz_add_mpi_test(mpi_el_print ${CMAKE_CURRENT_SOURCE_DIR}/mpi/el_print_beam.inp --dat)
ldfcz_add_mpi_test(mpi_user_uel ${PROJECT_SOURCE_DIR}/decks/single/user_uel.inp
  --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_uel_elastic.f)
ldfcz_add_mpi_test(mpi_xit ${PROJECT_SOURCE_DIR}/decks/bad/runtime/uel_phi_zero.inp --xit)
# the first cohesive element of a row calls XIT; with 2 processes and the weights 20,2,1 it is rank 1's (the log says
# whose; the test fails if the partition puts it on rank 0): the stop and the message come from another process than
# the one that writes the output
ldfcz_add_mpi_test(mpi_xit_remote ${CMAKE_CURRENT_SOURCE_DIR}/mpi/xit_first_element.inp --xit --remote-at 2
  -- --element-weights 20,2,1)

# start-up errors (a malformed deck, an unknown option or a bad value, a missing --user file, found by every process; a
# restart file missing on the last rank only, JOB.sta not writable on rank 0 only; a restart with other
# --element-weights or --partition-pieces, found when the restart files are read) under -np 2 and -np 3: exit status
# 2, the message once, no MPI_Abort, no hang (tests/mpi/check_mpi_errors.py)
add_test(NAME mpi_startup_errors COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/mpi/check_mpi_errors.py
  --exe $<TARGET_FILE:ldfcz> --decks ${PROJECT_SOURCE_DIR}/decks --peel ${CMAKE_CURRENT_SOURCE_DIR}/mpi/peel_ps_short.inp
  --out ${CMAKE_CURRENT_BINARY_DIR}/mpi/startup_errors)
set_tests_properties(mpi_startup_errors PROPERTIES LABELS "mpi" TIMEOUT 600 ENVIRONMENT "${LDFCZ_MPI_ENV}")

# restart from per-process restart files (JOB.rst.RofN) and SIGTERM to the launcher (tests/regression/check_restart.py
# --np): the continuation reproduces the uninterrupted distributed run to 1e-9 (observed 1e-12: two distributed runs
# differ in the last bits, MUMPS' parallel assembly order), every process stops after the increment under way.
set(LDFCZ_CHECK_RESTART_MPI "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_restart.py")
function(ldfcz_add_mpi_restart_test name deck)
  add_test(NAME ${name} COMMAND Python3::Interpreter ${LDFCZ_CHECK_RESTART_MPI} --exe $<TARGET_FILE:ldfcz>
    --deck ${deck} --out ${CMAKE_CURRENT_BINARY_DIR}/mpi/${name} --rel 1e-9 ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS "mpi" TIMEOUT 600 ENVIRONMENT "${LDFCZ_MPI_ENV}")
endfunction()
ldfcz_add_mpi_restart_test(mpi_restart_cohesive_np2 ${PROJECT_SOURCE_DIR}/decks/single/cohesive_block.inp
  --np 2 --stop 9 --freq 1 --other-deck ${PROJECT_SOURCE_DIR}/decks/single/cohesive_mode_I.inp)
ldfcz_add_mpi_restart_test(mpi_restart_umat_np3 ${PROJECT_SOURCE_DIR}/decks/single/c3d8_umat_uniaxial.inp
  --np 3 --stop 45 --freq 7)
# every kind of deck (tests/restart, tests/host.cmake) distributed: loads, amplitudes, follower pressure and OP=NEW
# releases on 2 processes stopped in step 3, predefined fields and velocities on 2 processes, constraints, local
# systems and DISP on 3 (one element each) stopped by SIGUSR1. With --reproducible (LDFCZ_REPRODUCIBLE=1: the linear
# systems on rank 0, so that two distributed runs give the same bits) the continuation must reproduce the
# uninterrupted distributed run bit for bit: CSV, frames and JOB.dat.
ldfcz_add_mpi_restart_test(mpi_restart_loads_np2 ${CMAKE_CURRENT_SOURCE_DIR}/restart/loads_steps.inp
  --np 2 --stop 10 --freq 1 --rel 0 --atol 0 --dat --point mid)
ldfcz_add_mpi_restart_test(mpi_restart_fields_np2 ${CMAKE_CURRENT_SOURCE_DIR}/restart/fields_velocity.inp
  --np 2 --stop 7 --freq 1 --rel 0 --atol 0 --dat --point mid
  --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_fields.f)
ldfcz_add_mpi_restart_test(mpi_restart_constraints_np3 ${CMAKE_CURRENT_SOURCE_DIR}/restart/constraints_transform.inp
  --np 3 --modes term --stop 5 --freq 100000 --rel 0 --atol 0 --dat
  --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_disp.f)
set_tests_properties(mpi_restart_loads_np2 mpi_restart_fields_np2 mpi_restart_constraints_np3 PROPERTIES
  ENVIRONMENT "${LDFCZ_MPI_ENV};LDFCZ_REPRODUCIBLE=1")
# the graceful stop of a distributed run: SIGUSR1 to mpirun, which OpenMPI forwards to every process at once (SIGTERM
# it does not forward: mpi_launcher_sigterm below)
ldfcz_add_mpi_restart_test(mpi_sigusr1_peel_np2 ${CMAKE_CURRENT_SOURCE_DIR}/mpi/peel_ps_short.inp
  --np 2 --stop 20 --freq 100000 --term)
# SIGTERM to mpirun, which OpenMPI 4 does not forward: it sends the processes SIGTERM odls_base_sigkill_timeout
# seconds later and SIGKILL as many seconds after that; with OpenMPI's default grace of 1 s (set explicitly, so that
# a site's own default does not change the test) the processes stop gracefully (closing summary, restart files) on
# the small 3D peel (tests/mpi/check_launcher_sigterm.py; passed as well with two other MPI runs sharing
# the 2 cores)
add_test(NAME mpi_launcher_sigterm COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/mpi/check_launcher_sigterm.py
  --exe $<TARGET_FILE:ldfcz> --deck ${PROJECT_SOURCE_DIR}/decks/peel/peel_3d_quarter.inp
  --out ${CMAKE_CURRENT_BINARY_DIR}/mpi/launcher_sigterm --grace 1)
set_tests_properties(mpi_launcher_sigterm PROPERTIES LABELS "mpi" TIMEOUT 300 ENVIRONMENT "${LDFCZ_MPI_ENV}"
  PASS_REGULAR_EXPRESSION "PASS" FAIL_REGULAR_EXPRESSION "FAIL")

# other Newton variants and preconditioning factors distributed (GMRES products summed over the processes, LDL^T
# factors of the symmetric part from the processes' entries): the full-Newton iterates, so the same counts
ldfcz_add_mpi_test(mpi_cohesive_krylov_symmetric_single ${PROJECT_SOURCE_DIR}/decks/single/cohesive_block.inp
  -- --newton krylov --factors symmetric-single)
ldfcz_add_mpi_test(mpi_cohesive_modified ${PROJECT_SOURCE_DIR}/decks/single/cohesive_block.inp -- --newton modified)
# the application scene's preconditioner (tools/peel_study.py application): single-precision LDL^T factors, whose
# right-hand side and solution MUMPS takes and leaves distributed, on the interleaved plane-strain peel; with
# --newton krylov (GMRES to 1e-8: full Newton's iterates) rather than the scene's auto, whose inexact GMRES
# tolerance the last-bit differences between distributed and one-process runs can cross (docs/host.md)
ldfcz_add_mpi_test(mpi_peel_ps_krylov_single ${CMAKE_CURRENT_SOURCE_DIR}/mpi/peel_ps_short.inp
  -- --newton krylov --factors symmetric-single --partition-pieces 4)

# the closed-form load tests of tests/host.cmake run distributed (ldfcz_np2: mpirun -np 2 ldfcz): *DLOAD/*DSLOAD
# pressure on a thick cylinder (Lame), *EQUATION and *TIE constraints, load history over steps, initial stress
file(GENERATE OUTPUT "${CMAKE_BINARY_DIR}/tests/bin/ldfcz_np2"
  CONTENT "#!/bin/sh\nexec \"${CMAKE_CURRENT_SOURCE_DIR}/mpi/mpirun_ldfcz.sh\" 2 \"$<TARGET_FILE:ldfcz>\" \"$@\"\n"
  FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
foreach(case lame2d lame3d equation tie steps release)
  add_test(NAME mpi_loads_${case} COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_loads.py
    --exe ${CMAKE_BINARY_DIR}/tests/bin/ldfcz_np2 --out ${CMAKE_CURRENT_BINARY_DIR}/mpi/loads_${case} --case ${case})
  set_tests_properties(mpi_loads_${case} PROPERTIES LABELS "mpi" TIMEOUT 300 ENVIRONMENT "${LDFCZ_MPI_ENV}")
endforeach()
add_test(NAME mpi_loads_initial_stress COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_loads.py
  --exe ${CMAKE_BINARY_DIR}/tests/bin/ldfcz_np2 --out ${CMAKE_CURRENT_BINARY_DIR}/mpi/loads_initial_stress
  --case initial_stress --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_prestress.f90)
set_tests_properties(mpi_loads_initial_stress PROPERTIES LABELS "mpi" TIMEOUT 300 ENVIRONMENT "${LDFCZ_MPI_ENV}")

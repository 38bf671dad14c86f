# Suites and deck regression tests of the host (host/deck, host/analysis, the program ldfcz).
if(TARGET ldfcz_deck)
  ldfcz_add_pf_suite(NAME test_deck_reader PF test_deck_reader.pf LINK ldfcz_deck)
  ldfcz_add_pf_suite(NAME test_deck_generate PF test_deck_generate.pf LINK ldfcz_deck)
endif()
if(TARGET ldfcz_control)
  ldfcz_add_pf_suite(NAME test_step_control PF test_step_control.pf LINK ldfcz_control)
  ldfcz_add_pf_suite(NAME test_convergence PF test_convergence.pf LINK ldfcz_control)
endif()

# finite-difference check of the assembled tangent (host assembly + continuum element + sparse system)
if(TARGET ldfcz_host)
  ldfcz_add_pf_suite(NAME test_assembled_tangent PF test_assembled_tangent.pf LINK ldfcz_host ldfcz_abaqus_utils)
  ldfcz_add_pf_suite(NAME test_element_colors PF test_element_colors.pf LINK ldfcz_host)
endif()

if(NOT TARGET ldfcz)
  return()
endif()

set(LDFCZ_CHECK "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_run.py")
set(LDFCZ_DECKS "${PROJECT_SOURCE_DIR}/decks")
set(LDFCZ_RUNS "${CMAKE_CURRENT_BINARY_DIR}/regression")

#[[ ldfcz_add_deck_test(NAME <test> DECK <path> [CASE <check>] [BAD] [USER <file>] [EXIT <status>])
    Runs bin/ldfcz on the deck and checks the result with tests/regression/check_run.py. ]]
function(ldfcz_add_deck_test)
  cmake_parse_arguments(D "BAD" "NAME;DECK;CASE;USER;EXIT;OPTIONS" "" ${ARGN})
  set(args --exe $<TARGET_FILE:ldfcz> --deck ${D_DECK} --out ${LDFCZ_RUNS}/${D_NAME})
  if(D_BAD)
    list(APPEND args --bad)
  endif()
  if(D_CASE)
    list(APPEND args --case ${D_CASE})
  endif()
  if(D_USER)
    list(APPEND args --user ${D_USER})
  endif()
  if(D_EXIT)
    list(APPEND args --expect-exit ${D_EXIT})
  endif()
  if(D_OPTIONS)
    list(APPEND args "--extra-args=${D_OPTIONS}")
  endif()
  add_test(NAME ${D_NAME} COMMAND Python3::Interpreter ${LDFCZ_CHECK} ${args})
  set_tests_properties(${D_NAME} PROPERTIES LABELS "deck" TIMEOUT 300)
endfunction()

# malformed decks: exit 2 and a message naming file, line and keyword
file(GLOB bad_decks "${LDFCZ_DECKS}/bad/*.inp")
foreach(deck IN LISTS bad_decks)
  get_filename_component(name "${deck}" NAME_WE)
  ldfcz_add_deck_test(NAME deck_${name} DECK ${deck} BAD)
endforeach()

# patch tests on distorted meshes (constant state reproduced)
foreach(patch patch_c3d8 patch_cpe4 patch_c3d6)
  ldfcz_add_deck_test(NAME deck_${patch} DECK ${LDFCZ_DECKS}/patch/${patch}.inp CASE patch)
endforeach()
ldfcz_add_deck_test(NAME deck_patch_c3d8_linear DECK ${LDFCZ_DECKS}/patch/patch_c3d8_linear.inp CASE patch_linear)

# single elements against closed-form answers
ldfcz_add_deck_test(NAME deck_c3d8_uniaxial DECK ${LDFCZ_DECKS}/single/c3d8_uniaxial.inp CASE c3d8_uniaxial)
# C3D6 (the type added through the element catalogue, docs/extending.md): the same closed form on a cube of two
# wedges, and its faces S1..S5 under a self-balanced uniform pressure
ldfcz_add_deck_test(NAME deck_c3d6_uniaxial DECK ${LDFCZ_DECKS}/single/c3d6_uniaxial.inp CASE c3d6_uniaxial)
ldfcz_add_deck_test(NAME deck_c3d6_faces DECK ${LDFCZ_DECKS}/single/c3d6_faces.inp CASE c3d6_faces)
ldfcz_add_deck_test(NAME deck_c3d15_faces DECK ${LDFCZ_DECKS}/single/c3d15_faces.inp CASE c3d6_faces)
# *INITIAL CONDITIONS, USER: SIGINI and SDVINI of the user library (a relieved initial stress in closed form; the
# state variables at the points' coordinates)
ldfcz_add_deck_test(NAME deck_user_initial_values DECK ${LDFCZ_DECKS}/single/user_initial_values.inp
  CASE user_initial_values USER ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_initial_values.f90)
# a *SURFACE of several element-set lines (as Abaqus/CAE writes it) under two *DSLOAD lines: the applied resultant
ldfcz_add_deck_test(NAME deck_surface_two_lines DECK ${LDFCZ_DECKS}/single/surface_two_lines.inp CASE surface_two_lines)
# temperatures in second-order hexahedra and quadrilaterals: their first-order part (as Abaqus), a free expansion
foreach(mt c3d20 cps8)
  ldfcz_add_deck_test(NAME deck_${mt}_midside_temperature DECK ${LDFCZ_DECKS}/single/${mt}_midside_temperature.inp
    CASE midside_temperature)
endforeach()
# the triangles (CPE3, CPS6, CAX3, CAX6; all six types in test_solid_element): their edges S1..S3 under a
# self-balanced uniform pressure against the closed form
foreach(tri cpe3 cps6 cax3 cax6)
  ldfcz_add_deck_test(NAME deck_${tri}_faces DECK ${LDFCZ_DECKS}/single/${tri}_faces.inp CASE tri_faces)
endforeach()
foreach(mode I II mixed)
  ldfcz_add_deck_test(NAME deck_cohesive_mode_${mode} DECK ${LDFCZ_DECKS}/single/cohesive_mode_${mode}.inp
    CASE cohesive_${mode})
endforeach()
foreach(extra cohesive_block quadratic_rotation user_uel nonconvergence)
  if(EXISTS "${LDFCZ_DECKS}/single/${extra}.inp")
    set(case ${extra})
    set(exit_status 0)
    set(user "")
    if(extra STREQUAL "nothing")
    elseif(extra STREQUAL "quadratic_rotation")
      set(case quadratic)
      set(user USER ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_neohooke.f90)
    elseif(extra STREQUAL "user_uel")
      set(user USER ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_uel_elastic.f)
    elseif(extra STREQUAL "nonconvergence")
      set(exit_status 3)
    endif()
    ldfcz_add_deck_test(NAME deck_${extra} DECK ${LDFCZ_DECKS}/single/${extra}.inp CASE ${case} EXIT ${exit_status}
      ${user})
  endif()
endforeach()


# performance options of the host and two single-element decks (tests/regression/check_perf_decks.py;
# decks written by tests/regression/make_perf_decks.py)
set(LDFCZ_CHECK_PERF "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_perf_decks.py")
function(ldfcz_add_perf_test name deck case)
  add_test(NAME ${name} COMMAND Python3::Interpreter ${LDFCZ_CHECK_PERF} --exe $<TARGET_FILE:ldfcz> --deck ${deck}
    --out ${LDFCZ_RUNS}/${name} --case ${case} ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS "deck" TIMEOUT 300)
endfunction()
if(TARGET material_point AND EXISTS "${LDFCZ_DECKS}/single/c3d8_umat_uniaxial.inp")
  ldfcz_add_perf_test(deck_c3d8_umat_uniaxial ${LDFCZ_DECKS}/single/c3d8_umat_uniaxial.inp umat_uniaxial
    --mp $<TARGET_FILE:material_point>)
endif()
# the Leonov UMAT in one element of each continuum type under a homogeneous F against the driver (docs/elements.md)
if(TARGET material_point)
  add_test(NAME deck_element_leonov COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_element_leonov.py --exe $<TARGET_FILE:ldfcz>
    --mp $<TARGET_FILE:material_point> --out ${LDFCZ_RUNS}/element_leonov)
  set_tests_properties(deck_element_leonov PROPERTIES LABELS "deck" TIMEOUT 300)
  # The 2D cohesive user element with an axisymmetric (JPROPS(3) = 1, totals over 2 pi as CAX4) and a plane-stress
  # section (PROPS(7) thickness as the CPS4 *SOLID SECTION) between two elastic layers: RF against T(Delta) x area
  add_test(NAME deck_cohesive_section COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_cohesive_section.py --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/cohesive_section)
  set_tests_properties(deck_cohesive_section PROPERTIES LABELS "deck" TIMEOUT 120)
  # Plane stress under NLGEOM (*ELASTIC: thickness stretch from the plane-stress condition): CPS4, CPS4I, CPS4R
  # uniaxial stretch to 1.5 against the hypoelastic closed form with the current width and thickness (1e-9)
  add_test(NAME deck_plane_stress_nlgeom COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_plane_stress_nlgeom.py --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/plane_stress_nlgeom)
  set_tests_properties(deck_plane_stress_nlgeom PROPERTIES LABELS "deck" TIMEOUT 120)
  # Plane stress with a UMAT under NLGEOM (thickness t0 / det F_2D, inferred Abaqus behaviour): the neo-Hookean user
  # UMAT (own thickness stretch) in CPS4, CPS4I, CPS4R, uniaxial stretch to 1.5 against the exact answer (1e-9) and
  # the incompressible closed form (mu / lambda), then a rigid 90 degree rotation (reactions rotated, 1e-9)
  add_test(NAME deck_plane_stress_umat COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_plane_stress_umat.py --exe $<TARGET_FILE:ldfcz>
    --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_neohooke.f90 --out ${LDFCZ_RUNS}/plane_stress_umat)
  set_tests_properties(deck_plane_stress_umat PROPERTIES LABELS "deck" TIMEOUT 180)
endif()
if(EXISTS "${LDFCZ_DECKS}/single/c3d8_rotation_uniaxial.inp")
  ldfcz_add_perf_test(deck_c3d8_rotation_uniaxial ${LDFCZ_DECKS}/single/c3d8_rotation_uniaxial.inp rotation_uniaxial)
endif()
ldfcz_add_perf_test(deck_newton_modes ${LDFCZ_DECKS}/single/cohesive_block.inp newton_modes)
ldfcz_add_perf_test(deck_opening_control ${LDFCZ_DECKS}/single/cohesive_block.inp opening_control)
# *STEP, EXTRAPOLATION=LINEAR (the default) against NO: exact start on a linear ramp, same answers when nonlinear
ldfcz_add_perf_test(deck_extrapolation_linear ${LDFCZ_DECKS}/single/c3d8_uniaxial.inp extrapolation_linear)
ldfcz_add_perf_test(deck_extrapolation ${LDFCZ_DECKS}/single/cohesive_block.inp extrapolation)
ldfcz_add_perf_test(deck_extrapolation_parabolic ${LDFCZ_DECKS}/single/c3d8_uniaxial.inp extrapolation_parabolic)
# the first Newton iteration carries the prescribed increment through the tangent: a linear block converges in one
# iteration (residual at round-off), a nonlinear one's residual falls from the first iteration on
# (tests/regression/check_first_iteration.py)
add_test(NAME deck_first_iteration COMMAND Python3::Interpreter
  ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_first_iteration.py --exe $<TARGET_FILE:ldfcz>
  --out ${LDFCZ_RUNS}/first_iteration)
set_tests_properties(deck_first_iteration PROPERTIES LABELS "deck" TIMEOUT 300)

# restart from the last converged increment (docs/host.md, "Restart"; tests/regression/check_restart.py): the run
# interrupted (--stop-after-increments or SIGKILL) and restarted with --restart-from must give the uninterrupted run's
# CSV to 1e-12 relative (it is bit-identical with full Newton), the same VTU frames and energy balance; a restart file
# of another model, a truncated one and a non-restart file are refused with exit 2.
set(LDFCZ_CHECK_RESTART "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_restart.py")
function(ldfcz_add_restart_test name deck)
  add_test(NAME ${name} COMMAND Python3::Interpreter ${LDFCZ_CHECK_RESTART} --exe $<TARGET_FILE:ldfcz> --deck ${deck}
    --out ${LDFCZ_RUNS}/${name} ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS "restart" TIMEOUT 300)
endfunction()
# UEL (cohesive element, SVARS/ENERGY) under a C3D8 block, automatic increments; restart refused for another deck
ldfcz_add_restart_test(restart_cohesive_block ${LDFCZ_DECKS}/single/cohesive_block.inp --stop 9 --freq 1
  --other-deck ${LDFCZ_DECKS}/single/c3d8_uniaxial.inp)
# graceful stop (host/analysis/stop_signal.f90): SIGTERM after 5 CSV rows ends the run after the current increment
# with exit 143, the closing summary and restart data written at the stop (the only ones: frequency 100000); the
# restart from them gives the uninterrupted run
ldfcz_add_restart_test(restart_cohesive_sigterm ${LDFCZ_DECKS}/single/cohesive_block.inp --stop 5 --freq 100000 --term)
if(EXISTS "${LDFCZ_DECKS}/single/c3d8_umat_uniaxial.inp")
  # Leonov UMAT (STATEV): restart data every 7 increments, stopped after 45: rows 43-45 are dropped and recomputed
  ldfcz_add_restart_test(restart_umat_uniaxial ${LDFCZ_DECKS}/single/c3d8_umat_uniaxial.inp --stop 45 --freq 7)
  # the same killed with SIGKILL after 30 CSV rows (restart data every increment)
  ldfcz_add_restart_test(restart_umat_kill ${LDFCZ_DECKS}/single/c3d8_umat_uniaxial.inp --stop 30 --kill)
endif()
if(EXISTS "${LDFCZ_DECKS}/stability/stab_rotation_90.inp")
  # *RESTART, WRITE, FREQUENCY=2 in the deck; stopped at the end of step 1 of 2: the restart begins step 2
  ldfcz_add_restart_test(restart_two_steps ${LDFCZ_DECKS}/stability/stab_rotation_90.inp --stop 4 --freq 2
    --deck-restart)
endif()
if(EXISTS "${LDFCZ_DECKS}/stability/stab_one_increment_50pct_pet.inp")
  # PET cube with 12 cutbacks (UMAT PNEWDT): increment size and growth state carried over
  ldfcz_add_restart_test(restart_pet_cutbacks ${LDFCZ_DECKS}/stability/stab_one_increment_50pct_pet.inp --stop 8)
endif()
# Restart of every kind of deck (tests/restart/*.inp; their headers say what each step does): every deck is stopped
# within a step with --stop-after-increments and, in a second run, with SIGTERM, continued, and compared with the
# uninterrupted run bit for bit (--rel 0): JOB.csv, JOB.dat, the VTU frames, and the files the user routines write
# on every call (the temperatures and fields a UMAT receives, the arguments of DISP), so that any part of the analysis
# state a restart lost (a load, an amplitude's start, a released reaction, a velocity, a field variable's ramp, a
# local system's prescribed value) shows as a difference.
set(LDFCZ_RESTART_DECKS "${CMAKE_CURRENT_SOURCE_DIR}/restart")
# loads and amplitudes over four steps: *CLOAD (RAMP, OP=MOD on a tabular amplitude, OP=NEW decaying, SMOOTH STEP
# under AMPLITUDE=STEP), follower *DSLOAD pressure and *DLOAD GRAV under NLGEOM, a prescribed deflection released by
# *BOUNDARY, OP=NEW (its reaction decays); stopped in step 3, while the released loads decay; with the refusals
ldfcz_add_restart_test(restart_loads_steps ${LDFCZ_RESTART_DECKS}/loads_steps.inp --modes stop,term --stop 10
  --freq 1 --rel 0 --dat --point mid --other-deck ${LDFCZ_RESTART_DECKS}/fields_velocity.inp
  --other-user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_fields.f)
# the same deck stopped at the end of step 1 (restart data every 3rd increment and at the end of the step): the
# continuation begins step 2 from the loads, boundaries and increment size the file holds
ldfcz_add_restart_test(restart_loads_step_end ${LDFCZ_RESTART_DECKS}/loads_steps.inp --stop 4 --freq 3 --rel 0 --dat
  --point end --no-refusals)
# *MODEL CHANGE, ADD=WITH STRAIN at the start of step 2: stopped at the end of step 1 (the restart begins step 2
# with the reactivation) and within step 2 (after it)
ldfcz_add_restart_test(restart_model_change_with_strain ${LDFCZ_RESTART_DECKS}/model_change_with_strain.inp
  --stop 4 --freq 1 --rel 0 --dat --point end --no-refusals)
ldfcz_add_restart_test(restart_model_change_with_strain_mid ${LDFCZ_RESTART_DECKS}/model_change_with_strain.inp
  --modes stop,term --stop 6 --freq 1 --rel 0 --dat --point mid --no-refusals)
# element deletion by a UMAT's state variable (*DEPVAR, DELETE=): stopped after the deletion (increment 7 of 10);
# the restart needs the deleted element from the restart file
ldfcz_add_restart_test(restart_element_deletion ${LDFCZ_RESTART_DECKS}/element_deletion.inp --modes stop,term
  --stop 7 --freq 1 --rel 0 --dat --point mid --no-refusals
  --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_delete.f90)
# *TEMPERATURE (with thermal expansion), *FIELD on an amplitude, OP=NEW of both, TYPE=VELOCITY boundaries on an
# amplitude, then a displacement; stopped in step 2 (automatic increments); the recording UMAT's file compared
ldfcz_add_restart_test(restart_fields_velocity ${LDFCZ_RESTART_DECKS}/fields_velocity.inp --modes stop,term --stop 7
  --freq 1 --rel 0 --dat --point mid --no-refusals --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_fields.f
  --compare-files umat_fields.txt)
# *EQUATION, *TIE, *TRANSFORM and *BOUNDARY, USER (DISP) under NLGEOM, OP=NEW and a *CLOAD in the local system in
# step 2; stopped in step 2; the file of DISP's calls compared
ldfcz_add_restart_test(restart_constraints_transform ${LDFCZ_RESTART_DECKS}/constraints_transform.inp
  --modes stop,term --stop 6 --freq 1 --rel 0 --dat --point mid --no-refusals
  --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_disp.f --compare-files disp_calls.txt)
# *MODEL CHANGE (removal, strain-free reactivation, the removed elements' forces ramped down), a kinematic *COUPLING
# with the reference node's rotational dofs, CENTRIF and ROTA, *TIME POINTS over three steps; stopped within step 2
# (after the reactivation) and, in a second test, at the end of step 2 (the forces to ramp down in step 3 come from
# the restart file)
ldfcz_add_restart_test(restart_model_change ${LDFCZ_RESTART_DECKS}/model_change.inp --modes stop,term --stop 7
  --freq 1 --rel 0 --dat --point mid --no-refusals)
ldfcz_add_restart_test(restart_model_change_step_end ${LDFCZ_RESTART_DECKS}/model_change.inp --stop 10 --freq 1
  --rel 0 --dat --point end --no-refusals)

# *PRE-TENSION SECTION (the sections' extra dofs are part of the checkpointed displacement): tightened by a force
# in step 1, held by *BOUNDARY, FIXED in step 2 while a load is added; stopped within step 2 (by increment count:
# the run is too short for a SIGTERM to land in time)
ldfcz_add_restart_test(restart_pretension ${LDFCZ_RESTART_DECKS}/pretension_fixed.inp --modes stop --stop 5
  --freq 1 --rel 0 --dat --point mid --no-refusals)
# issue 36 item 4 (docs/host.md): *COUPLING against statics, rigid motion, beam theory and twin *EQUATION decks;
# *EQUATION over node sets against the same equations node by node, a chain of equations against the direct ones
# (tests/regression/check_couplings.py)
foreach(case kinematic kinematic_twin distributing distributing_twin kinematic_2d equation_sets equation_chain)
  add_test(NAME deck_coupling_${case} COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_couplings.py --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/coupling_${case} --case ${case})
  set_tests_properties(deck_coupling_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# *COUPLING, ORIENTATION= (local constrained dofs: cylindrical, rectangular) against *EQUATION twins with
# hand-computed directions; partial rotational *DISTRIBUTING against statics, the all-rotations twin and Saint-Venant
# torsion (tests/regression/check_coupling_local.py)
foreach(case kinematic_cylindrical kinematic_rectangular kinematic_assembly distributing_partial
    distributing_torsion)
  add_test(NAME deck_coupling_${case} COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_coupling_local.py --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/coupling_${case} --case ${case})
  set_tests_properties(deck_coupling_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# CENTRIF and ROTA against the closed forms of a spinning disc (tests/regression/check_rotational_loads.py)
foreach(case centrif_plane_stress centrif_axisymmetric centrif_3d rota centrif_nlgeom)
  add_test(NAME deck_rotational_${case} COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_rotational_loads.py --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/rotational_${case} --case ${case}
    --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_neohooke.f90)
  set_tests_properties(deck_rotational_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# *MODEL CHANGE against closed forms and the deck without the elements, *TIME POINTS hit exactly, *NODE PRINT,
# GLOBAL=YES against the transformed components, *BOUNDARY, FIXED against the held value and the reaction,
# *NODE PRINT and *EL PRINT requests carried into later steps until respecified
# (tests/regression/check_step_options.py)
foreach(case model_change model_change_nlgeom model_change_with_strain time_points node_print_global boundary_fixed
    print_carry)
  add_test(NAME deck_step_${case} COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_step_options.py --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/step_${case} --case ${case})
  set_tests_properties(deck_step_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()

# *PRE-TENSION SECTION: a bar cut by the section against its closed forms (force, the length held while a load is
# added: two springs, FIXED and OP=MOD, a normal given into the moving side, tetrahedra touching the section at an
# edge or vertex, NLGEOM, the length prescribed) and the node tables unchanged (tests/regression/check_pretension.py)
foreach(case force_2d fixed_2d mod_2d reversed_3d tet_3d nlgeom_2d length_2d)
  add_test(NAME deck_pretension_${case} COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_pretension.py --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/pretension_${case} --case ${case})
  set_tests_properties(deck_pretension_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# *DEPVAR, DELETE=: two bars in parallel, one deleted by its UMAT's state variable: the force drops to the other's
# share (closed form), the log names the element (tests/regression/check_element_deletion.py)
add_test(NAME deck_element_deletion COMMAND Python3::Interpreter
  ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_element_deletion.py --exe $<TARGET_FILE:ldfcz>
  --deck ${LDFCZ_RESTART_DECKS}/element_deletion.inp
  --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_delete.f90 --out ${LDFCZ_RUNS}/deck_element_deletion)
set_tests_properties(deck_element_deletion PROPERTIES LABELS "deck" TIMEOUT 300)

# field output as ParaView reads it: tensors in VTK's order with names, principal values, requests carried over
# to the next step, a warning for a variable that cannot be written (python3-vtk9 reads the frames)
add_test(NAME deck_field_output COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_field_output.py
  --exe $<TARGET_FILE:ldfcz> --deck ${LDFCZ_DECKS}/single/field_output_shear.inp --out ${LDFCZ_RUNS}/deck_field_output)
set_tests_properties(deck_field_output PROPERTIES LABELS "deck" TIMEOUT 300)
# the VTU cell of every type of the element catalogue as VTK reads it: cell type, positive size, outward faces
if(TARGET ldfcz_doc_tables)
  add_test(NAME deck_vtu_cells COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_vtu_cells.py
    --exe $<TARGET_FILE:ldfcz> --tables $<TARGET_FILE:ldfcz_doc_tables> --out ${LDFCZ_RUNS}/deck_vtu_cells)
  set_tests_properties(deck_vtu_cells PROPERTIES LABELS "deck" TIMEOUT 300)
  # docs/elements.md's type table and docs/host.md's output-variable table are the ones the element catalogue and
  # the output registry write (ldfcz_doc_tables)
  add_test(NAME docs_tables COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_doc_tables.py
    --tables $<TARGET_FILE:ldfcz_doc_tables> --docs ${PROJECT_SOURCE_DIR}/docs)
  set_tests_properties(docs_tables PROPERTIES LABELS "deck" TIMEOUT 60)
endif()
# outputs resolved against the output registry: unprovidable requests warned with their line and not written (no
# arrays of zeros for a user UEL), declared SVARS written, JOB.dat plane-stress table under the right names
add_test(NAME deck_output_registry COMMAND Python3::Interpreter
  ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_output_registry.py --exe $<TARGET_FILE:ldfcz> --decks ${LDFCZ_DECKS}
  --user-uel ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_uel_elastic.f --out ${LDFCZ_RUNS}/deck_output_registry)
set_tests_properties(deck_output_registry PROPERTIES LABELS "deck" TIMEOUT 300)

# double-cantilever beam bonded by the LDF element (tools/dcb_deck.py): beam theory within 1 % on the propagation
# branch; the two classic mis-orientations refused before the analysis, and reordered by --reorient-interfaces
add_test(NAME deck_dcb_orientation COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_dcb.py
  --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/deck_dcb_orientation)
set_tests_properties(deck_dcb_orientation PROPERTIES LABELS "deck" TIMEOUT 600)
# the same DCB with C3D8I arms, one element through each arm's thickness: beam theory within 0.5 % (docs/elements.md)
add_test(NAME deck_dcb_c3d8i COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_dcb.py
  --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/deck_dcb_c3d8i --c3d8i)
set_tests_properties(deck_dcb_c3d8i PROPERTIES LABELS "deck" TIMEOUT 600)
# concentrated loads, amplitudes and load propagation across steps (tests/regression/check_loads.py: decks written
# by the script, checked against beam theory, the elastica and the linear response to the load history)
set(LDFCZ_CHECK_LOADS "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_loads.py")
foreach(case small large steps release visco equation tie)
  add_test(NAME deck_cload_${case} COMMAND Python3::Interpreter ${LDFCZ_CHECK_LOADS} --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/cload_${case} --case ${case})
  set_tests_properties(deck_cload_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# distributed loads: gravity column (exact), thick cylinder under *DSLOAD/*DLOAD pressure (Lame, CPE4 and C3D8),
# follower pressure inflating a neo-Hookean ring (quadratic Newton convergence), a UEL reading its Un loads
foreach(case gravity lame2d lame3d lame_quadratic lame_axisymmetric bending kirsch)
  add_test(NAME deck_dload_${case} COMMAND Python3::Interpreter ${LDFCZ_CHECK_LOADS} --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/dload_${case} --case ${case})
  set_tests_properties(deck_dload_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
add_test(NAME deck_dload_balloon COMMAND Python3::Interpreter ${LDFCZ_CHECK_LOADS} --exe $<TARGET_FILE:ldfcz>
  --out ${LDFCZ_RUNS}/dload_balloon --case balloon --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_neohooke.f90)
add_test(NAME deck_dload_balloon3d COMMAND Python3::Interpreter ${LDFCZ_CHECK_LOADS} --exe $<TARGET_FILE:ldfcz>
  --out ${LDFCZ_RUNS}/dload_balloon3d --case balloon3d
  --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_neohooke.f90)
add_test(NAME deck_dload_uel COMMAND Python3::Interpreter ${LDFCZ_CHECK_LOADS} --exe $<TARGET_FILE:ldfcz>
  --out ${LDFCZ_RUNS}/dload_uel --case uel_loads --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_uel_dload.f90)
add_test(NAME deck_initial_stress COMMAND Python3::Interpreter ${LDFCZ_CHECK_LOADS} --exe $<TARGET_FILE:ldfcz>
  --out ${LDFCZ_RUNS}/initial_stress --case initial_stress
  --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_prestress.f90)
add_test(NAME deck_thermal_expansion COMMAND Python3::Interpreter ${LDFCZ_CHECK_LOADS} --exe $<TARGET_FILE:ldfcz>
  --out ${LDFCZ_RUNS}/thermal --case thermal --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_prestress.f90)
set_tests_properties(deck_dload_balloon deck_dload_balloon3d deck_dload_uel deck_initial_stress deck_thermal_expansion PROPERTIES
  LABELS "deck" TIMEOUT 300)
# field variables (*INITIAL CONDITIONS, TYPE=FIELD; *FIELD with an amplitude and OP=NEW) as PREDEF/DPRED of a UMAT
# and PREDEF of a UEL, and *BOUNDARY, TYPE=VELOCITY, against closed forms (tests/regression/check_fields.py)
set(LDFCZ_CHECK_FIELDS "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_fields.py")
add_test(NAME deck_fields COMMAND Python3::Interpreter ${LDFCZ_CHECK_FIELDS} --exe $<TARGET_FILE:ldfcz>
  --out ${LDFCZ_RUNS}/fields --case fields
  --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_fields.f,${CMAKE_CURRENT_SOURCE_DIR}/regression/user_uel_fields.f)
add_test(NAME deck_boundary_velocity COMMAND Python3::Interpreter ${LDFCZ_CHECK_FIELDS} --exe $<TARGET_FILE:ldfcz>
  --out ${LDFCZ_RUNS}/boundary_velocity --case velocity)
set_tests_properties(deck_fields deck_boundary_velocity PROPERTIES LABELS "deck" TIMEOUT 300)

# a user UMAT that returns NaN at one point: the cutback's cause (element, routine, point, reason) in JOB.log once,
# at default verbosity
ldfcz_add_deck_test(NAME deck_broken_umat DECK ${LDFCZ_DECKS}/single/broken_umat.inp CASE broken_umat
  USER ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_broken.f90 EXIT 3)

# the README's first deck: two blocks glued by one cohesive element (force = A T(opening), peak A T_max)
ldfcz_add_deck_test(NAME deck_first_two_blocks DECK ${LDFCZ_DECKS}/first/two_blocks.inp CASE first_deck)

# material-point driver: stress relaxation in the Leonov model's linear viscoelastic limit (closed form)
if(TARGET material_point)
  add_test(NAME material_linear_relaxation COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_relaxation.py --mp $<TARGET_FILE:material_point>
    --case ${LDFCZ_DECKS}/material/history/linear_relaxation_shear.txt --out ${LDFCZ_RUNS}/material_linear_relaxation)
  set_tests_properties(material_linear_relaxation PROPERTIES LABELS "umat" TIMEOUT 300)
endif()

# the arguments of every UEL call against Abaqus' documented values (LFLAGS, TIME, PERIOD, PARAMS, ...)
ldfcz_add_deck_test(NAME deck_uel_arguments DECK ${LDFCZ_DECKS}/single/uel_arguments.inp CASE uel_arguments
  USER ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_uel_args.f)
# the plastic-increment control needs a declared plastic strain: without one the option is refused (exit 2), not
# silently ineffective
ldfcz_add_deck_test(NAME robust_options_plastic_undeclared DECK ${LDFCZ_DECKS}/single/user_umat_files.inp EXIT 2
  USER ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_files/umat_fixed.f,${CMAKE_CURRENT_SOURCE_DIR}/regression/user_files/elastic_helper.f90
  OPTIONS "--max-plastic-increment 0.01")
# every argument of the UMAT calls against Abaqus' documented values, with and without NLGEOM
ldfcz_add_deck_test(NAME deck_umat_arguments DECK ${LDFCZ_DECKS}/single/umat_arguments.inp CASE umat_arguments
  USER ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_args.f)
ldfcz_add_deck_test(NAME deck_umat_arguments_small DECK ${LDFCZ_DECKS}/single/umat_arguments_small.inp
  CASE umat_arguments_small USER ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_args.f)

# --user as Abaqus builds user code: preprocessing, lower-case include, two files, an object file, WRITE(7) to
# JOB.msg, lazy binding, LLVM flang through --fc, a user include file named under another case, zeros after NPROPS
add_test(NAME deck_user_files COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_user_files.py
  --exe $<TARGET_FILE:ldfcz> --decks ${LDFCZ_DECKS} --fixtures ${CMAKE_CURRENT_SOURCE_DIR}/regression
  --out ${LDFCZ_RUNS}/deck_user_files)
set_tests_properties(deck_user_files PROPERTIES LABELS "deck" TIMEOUT 300)

# one-file Abaqus drop-ins: compiled the Abaqus way (gfortran, LLVM flang), UEL + UMAT linked together, and run by
# --user on the peel deck against the built-in routines
# In the Debug configuration every source has the same flags: the drop-in compiled with them (--fflags) must give
# the built-in result bit for bit.
string(TOUPPER "${CMAKE_BUILD_TYPE}" _ldfcz_cfg)
set(_dropin_exact "")
set(_dropin_fflags "")
if(_ldfcz_cfg STREQUAL "DEBUG" AND CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  set(_dropin_exact --exact)
  string(STRIP "${CMAKE_Fortran_FLAGS} ${CMAKE_Fortran_FLAGS_DEBUG}" _dropin_fflags)
endif()
add_test(NAME dropins_abaqus COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_dropins.py
  --exe $<TARGET_FILE:ldfcz> --dropins ${PROJECT_BINARY_DIR}/dropin --include ${PROJECT_SOURCE_DIR}/host/abaqus
  --marc-include ${CMAKE_CURRENT_SOURCE_DIR}/support/marc --marc-stubs ${CMAKE_CURRENT_SOURCE_DIR}/support/marc/marc_test_stubs.f
  --deck ${LDFCZ_DECKS}/peel/peel_ps.inp --out ${LDFCZ_RUNS}/dropins_abaqus "--fflags=${_dropin_fflags}" ${_dropin_exact})
set_tests_properties(dropins_abaqus PROPERTIES LABELS "package" TIMEOUT 600)

# the CMake package: install, find_package(ldfcz) from another project, call UEL and UMAT; pkg-config
add_test(NAME package_find_ldfcz COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/package/check_package.sh ${PROJECT_BINARY_DIR}
  ${LDFCZ_RUNS}/package_find_ldfcz ${CMAKE_Fortran_COMPILER})
set_tests_properties(package_find_ldfcz PROPERTIES LABELS "package" TIMEOUT 300)

# model structure and syntax (tests/regression/check_assembly.py): two instances of a part, one translated and
# rotated, tied in the assembly, against closed form and the deck flattened by hand; decks in Abaqus/CAE's style
# (decks/cae) against closed forms
foreach(case assembly cae generate)
  add_test(NAME deck_structure_${case} COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_assembly.py
    --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/structure_${case} --decks ${LDFCZ_DECKS} --case ${case})
  set_tests_properties(deck_structure_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# *NODE PRINT / *EL PRINT tables in JOB.dat (per printed increment, FREQUENCY, TOTALS, SUMMARY, all nodes)
add_test(NAME deck_print_tables COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_print.py
  --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/print_tables)
set_tests_properties(deck_print_tables PROPERTIES LABELS "deck" TIMEOUT 300)
# *ORIENTATION: an orthotropic UMAT with turned axes under turned loading against the unturned one (small strain
# with the closed form, NLGEOM, a rigid rotation after a stretch) (tests/regression/check_orientation.py)
foreach(case small nlgeom rigid instance)
  add_test(NAME deck_orientation_${case} COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_orientation.py
    --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/orientation_${case} --case ${case}
    --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_ortho.f90)
  set_tests_properties(deck_orientation_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
  # the same cases with the host's *ELASTIC, TYPE=ENGINEERING CONSTANTS of the UMAT's constants
  add_test(NAME deck_orientation_elastic_${case} COMMAND Python3::Interpreter
    ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_orientation.py --exe $<TARGET_FILE:ldfcz>
    --out ${LDFCZ_RUNS}/orientation_elastic_${case} --case ${case} --material elastic)
  set_tests_properties(deck_orientation_elastic_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# *ELASTIC (ORTHOTROPIC, ENGINEERING CONSTANTS, ANISOTROPIC, LAMINA, temperature-dependent) and *EXPANSION (ISO,
# ORTHO over temperature) against closed forms and twin decks (tests/regression/check_materials.py)
foreach(case compliance twins temperature lamina)
  add_test(NAME deck_elastic_${case} COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_materials.py
    --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/elastic_${case} --case ${case})
  set_tests_properties(deck_elastic_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# hybrid names read as the constant-dilatation types: C3D8H against an independent constant-pressure mixed solution
# of a nearly incompressible cantilever, its C3D8 twin, the names refused (tests/regression/check_hybrid.py)
add_test(NAME deck_hybrid_names COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_hybrid.py
  --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/hybrid_names)
set_tests_properties(deck_hybrid_names PROPERTIES LABELS "deck" TIMEOUT 300)
# Abaqus' lenient input forms against their explicit twins, bit for bit (tests/regression/check_leniency.py)
add_test(NAME deck_leniency COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_leniency.py
  --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/leniency)
set_tests_properties(deck_leniency PROPERTIES LABELS "deck" TIMEOUT 300)
# which routine a *USER MATERIAL / *USER ELEMENT runs: the stop without --user or declaration, the declared built-in
# one, the user's over a declaration (tests/regression/check_routines.py)
foreach(case stop builtin user)
  add_test(NAME deck_routines_${case} COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_routines.py
    --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/routines_${case} --case ${case}
    --umat-deck ${PROJECT_SOURCE_DIR}/decks/single/c3d8_umat_uniaxial.inp
    --uel-deck ${PROJECT_SOURCE_DIR}/decks/single/cohesive_block.inp
    --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_umat_neohooke.f90
    --user-deck ${PROJECT_SOURCE_DIR}/decks/single/quadratic_rotation.inp)
  set_tests_properties(deck_routines_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# *TRANSFORM: boundary conditions, concentrated loads, *EQUATION terms and printed nodal output in local node systems
# (a skewed roller, a cylinder with a prescribed radial displacement against Lame, a local CLOAD against the rotated
# global one) (tests/regression/check_transform.py)
foreach(case roller roller_nlgeom instance cylinder cload)
  add_test(NAME deck_transform_${case} COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_transform.py
    --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/transform_${case} --case ${case})
  set_tests_properties(deck_transform_${case} PROPERTIES LABELS "deck" TIMEOUT 300)
endforeach()
# *BOUNDARY, USER: prescribed values from the user subroutine DISP (--user), every argument against the documented
# values and the response against the closed form (tests/regression/check_boundary_user.py)
add_test(NAME deck_boundary_user COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_boundary_user.py
  --exe $<TARGET_FILE:ldfcz> --out ${LDFCZ_RUNS}/boundary_user --user ${CMAKE_CURRENT_SOURCE_DIR}/regression/user_disp.f)
set_tests_properties(deck_boundary_user PROPERTIES LABELS "deck" TIMEOUT 300)

# Messages and Abaqus' command line (issue 37 items 4-5): suggestions for misspelt keywords and parameters (and the
# keyword table against the reader's dispatch), job=/input=/user=/cpus=/interactive and refused words, a --user
# compile error's records, CAE boilerplate as notes in JOB.log, every cutback named in JOB.log
add_test(NAME deck_messages COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_messages.py
  --exe $<TARGET_FILE:ldfcz> --decks ${LDFCZ_DECKS} --user-src ${CMAKE_CURRENT_SOURCE_DIR}/regression
  --reader ${PROJECT_SOURCE_DIR}/host/deck/deck_reader.f90 --out ${LDFCZ_RUNS}/deck_messages)
set_tests_properties(deck_messages PROPERTIES LABELS "deck" TIMEOUT 300 PASS_REGULAR_EXPRESSION "PASS"
  FAIL_REGULAR_EXPRESSION "FAIL|Traceback")

# The frames (issue 37 item 3): continuum and interface blocks (JOB_NNNN.vtm), the damage, nodal averages of the
# patch decks equal to their constant stress and strain, pictures rendered headless (tools/render_frame.py under
# xvfb-run: tools/setup.sh installs xvfb) and checked not blank, the interface drawn without its separated cells
add_test(NAME deck_frames COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/regression/check_frames.py
  --exe $<TARGET_FILE:ldfcz> --decks ${LDFCZ_DECKS} --root ${PROJECT_SOURCE_DIR} --out ${LDFCZ_RUNS}/deck_frames)
set_tests_properties(deck_frames PROPERTIES LABELS "deck" TIMEOUT 600 PASS_REGULAR_EXPRESSION "PASS"
  FAIL_REGULAR_EXPRESSION "FAIL|Traceback")

# Peel scenes (issue 5). The generator's geometry check needs no solver; the short peel runs (tolerances and their
# reasons in tests/regression/check_peel.py) are registered only when the host program is built.
add_test(NAME peel_generator
  COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_peel_generator.py"
          "${PROJECT_SOURCE_DIR}/tools/peel_deck.py" "${CMAKE_CURRENT_BINARY_DIR}/peel_generator")
set_tests_properties(peel_generator PROPERTIES LABELS "peel" TIMEOUT 120)

if(TARGET ldfcz)
  foreach(_case refinement symmetry readings)
    add_test(NAME peel_${_case}
      COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_peel.py" ${_case}
              $<TARGET_FILE:ldfcz> "${CMAKE_CURRENT_BINARY_DIR}/peel_${_case}")
    set_tests_properties(peel_${_case} PROPERTIES LABELS "peel" TIMEOUT 600)
  endforeach()
endif()

# The steady-force estimator (tools/ldfcz_tools/steady_force.py) on synthetic curves with known answers (no solver needed).
add_test(NAME steady_force
  COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_steady_force.py")
set_tests_properties(steady_force PROPERTIES LABELS "peel" TIMEOUT 60)

# The figures of docs/scenes.md, docs/performance.md and of the README's main-job section against the reports they
# cite, and the reports index reports/README.md (no solver needed)
add_test(NAME quoted_figures
  COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_quoted_figures.py" "${PROJECT_SOURCE_DIR}")
set_tests_properties(quoted_figures PROPERTIES LABELS "peel" TIMEOUT 60)

# The MPI benchmark's cost-model refit (benchmarks/bench_mpi.py --refit) on synthetic tables with a known memory and
# element-loop model (no solver, no MPI needed)
add_test(NAME bench_refit
  COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_bench_refit.py"
          "${PROJECT_SOURCE_DIR}/benchmarks" "${CMAKE_CURRENT_BINARY_DIR}/bench_refit")
set_tests_properties(bench_refit PROPERTIES LABELS "tools" TIMEOUT 60 PASS_REGULAR_EXPRESSION "PASS"
  FAIL_REGULAR_EXPRESSION "FAIL")

# Robustness (issue 6): a fast CTest subset of the stability suite, the bad-input cases that check_run.py --bad does not
# cover (command-line option sets, decks rejected by a user routine, fuzz regressions; the malformed decks
# decks/bad/*.inp are registered by host.cmake), a short fixed-seed fuzz run and the SIGKILL flush test.
# The full suite: python3 tools/stability_suite.py --exe <release build>/bin/ldfcz (docs/robustness.md).
if(NOT TARGET ldfcz)
  return()
endif()

set(LDFCZ_ROBUST_RUNS "${CMAKE_CURRENT_BINARY_DIR}/robustness")

# stability cases that take well under a second each in Debug (the full 30-case table runs in ~10 s in Release)
add_test(NAME robust_stability_subset
  COMMAND Python3::Interpreter "${PROJECT_SOURCE_DIR}/tools/stability_suite.py" --exe $<TARGET_FILE:ldfcz>
          --out "${LDFCZ_ROBUST_RUNS}/stability" --no-report --jobs 2
          --only "penetration_10\\.inp" "rotation_90\\.inp" "contact_kc_1e\\+09" "small_delta_1e\\+06"
                 "dtime_cohesive_(ref|1e-12)" "inversion_elastic" "one_increment_50pct_elastic" "peel_brittle\\.inp")
set_tests_properties(robust_stability_subset PROPERTIES LABELS "robustness" TIMEOUT 300)

# bad command lines, properties rejected by the user routines (XIT), inputs that once crashed the reader
file(GLOB robust_cases "${PROJECT_SOURCE_DIR}/decks/bad/options/*.args" "${PROJECT_SOURCE_DIR}/decks/bad/runtime/*.inp"
     "${PROJECT_SOURCE_DIR}/decks/bad/fuzz_regressions/*.inp")
foreach(case IN LISTS robust_cases)
  get_filename_component(name "${case}" NAME_WE)
  get_filename_component(dir "${case}" DIRECTORY)
  get_filename_component(kind "${dir}" NAME)
  add_test(NAME robust_${kind}_${name}
    COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_bad_cases.py" --exe $<TARGET_FILE:ldfcz>
            --case "${case}" --out "${LDFCZ_ROBUST_RUNS}/${kind}_${name}")
  set_tests_properties(robust_${kind}_${name} PROPERTIES LABELS "robustness" TIMEOUT 120)
endforeach()

# mutation fuzzing of the reader: fixed seed, at most 30 s, crashing inputs not saved from CTest
add_test(NAME robust_fuzz_short
  COMMAND Python3::Interpreter "${PROJECT_SOURCE_DIR}/tools/fuzz_decks.py" --exe $<TARGET_FILE:ldfcz>
          --count 300 --time 30 --seed 1 --timeout 3 --no-save)
set_tests_properties(robust_fuzz_short PROPERTIES LABELS "robustness" TIMEOUT 120)

# CSV/STA flushed every increment: SIGKILL a running job three times, every completed row readable
add_test(NAME robust_kill_flush
  COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_kill.py" --exe $<TARGET_FILE:ldfcz>
          --deck "${PROJECT_SOURCE_DIR}/decks/stability/stab_peel_brittle_viscous.inp"
          --out "${LDFCZ_ROBUST_RUNS}/kill")
set_tests_properties(robust_kill_flush PROPERTIES LABELS "robustness" TIMEOUT 200)

# thread safety of the element loop (UMAT, UEL and continuum element called by two threads at once): 1 and 2
# threads give bitwise the same results (coloured assembly); the Debug build also stops on a routine entered by
# two threads without -frecursive (cmake/LdfczCompilerFlags.cmake)
add_test(NAME robust_threads_agree
  COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_threads.py" --exe $<TARGET_FILE:ldfcz>
          --deck "${PROJECT_SOURCE_DIR}/decks/stability/stab_peel_brittle_viscous.inp" --increments 40
          --out "${LDFCZ_ROBUST_RUNS}/threads")
set_tests_properties(robust_threads_agree PROPERTIES LABELS "robustness" TIMEOUT 300)

# no traceback from any tool or driver (issue 37 item 5): every command of tools/, python3 -m ldfcz_tools.NAME, the
# benchmarks and material_point fed a binary file, a folder, an empty file and a CSV with a column missing; identify
# and render_frame by a Python without NumPy / VTK (tests/regression/check_tool_inputs.py)
if(TARGET material_point)
  add_test(NAME robust_tool_inputs
    COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_tool_inputs.py"
            --root "${PROJECT_SOURCE_DIR}" --bin "$<TARGET_FILE_DIR:ldfcz>" --out "${LDFCZ_ROBUST_RUNS}/tool_inputs")
  set_tests_properties(robust_tool_inputs PROPERTIES LABELS "robustness" TIMEOUT 600
    PASS_REGULAR_EXPRESSION "PASS" FAIL_REGULAR_EXPRESSION "FAIL")
endif()

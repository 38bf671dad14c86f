# Identification of the interface parameters from a measured peel curve (issue 21, tools/identify.py): synthetic
# measurements from the plane-strain scene at known (phi, T_max) with noise; tolerances and their reasons in
# tests/regression/check_identify.py. Registered only when the host program is built.
if(TARGET ldfcz)
  foreach(_case recovery_a recovery_b recovery_peel tmax_not_identifiable failed_runs bad_input)
    add_test(NAME identify_${_case}
      COMMAND Python3::Interpreter "${CMAKE_CURRENT_SOURCE_DIR}/regression/check_identify.py" ${_case}
              $<TARGET_FILE:ldfcz> "${CMAKE_CURRENT_BINARY_DIR}/identify_${_case}")
    set_tests_properties(identify_${_case} PROPERTIES LABELS "identify" TIMEOUT 600)
  endforeach()
endif()

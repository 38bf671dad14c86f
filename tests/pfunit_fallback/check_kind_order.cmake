# pFUnit 4 has no ordering assertion whose first argument is of a higher kind than the second (a real64 before an
# integer): such a suite does not compile there, so it must not compile with the fallback either. A one-test suite
# is translated (pfpp.py) and compiled against funit's module twice: with the kinds in an order pFUnit accepts
# (must compile: the check itself works) and reversed (must fail, naming the generic of the ordering assertions).
function(compile_suite first second)
  file(MAKE_DIRECTORY "${WORK}")
  file(WRITE "${WORK}/test_pf_kind_order.pf" "module test_pf_kind_order
  use funit
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none
contains
  @test
  subroutine test_order()
    @assertGreaterThan(${first}, ${second})
  end subroutine test_order
end module test_pf_kind_order
")
  execute_process(COMMAND "${PYTHON}" "${PFPP}" module "${WORK}/test_pf_kind_order.pf" "${WORK}/test_pf_kind_order.F90"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pfpp.py failed on the kind-order suite:\n${out}${err}")
  endif()
  execute_process(COMMAND "${FC}" -c -I "${MODDIR}" -J "${WORK}" -o "${WORK}/test_pf_kind_order.o"
    "${WORK}/test_pf_kind_order.F90" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(rc "${rc}" PARENT_SCOPE)
  set(all "${out}${err}" PARENT_SCOPE)
endfunction()

compile_suite(2 1.0_real64)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "an integer before a real64 (accepted by pFUnit) does not compile:\n${all}")
endif()
compile_suite(2.0_real64 1)
if(rc EQUAL 0)
  message(FATAL_ERROR "a real64 before an integer compiled; pFUnit 4 rejects it")
endif()
string(FIND "${all}" "pf_ordering" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "the compiler's message does not name the ordering assertion's generic:\n${all}")
endif()

# Suites of the continuum elements and the built-in *ELASTIC (host/elements).
if(NOT TARGET ldfcz_elements AND EXISTS "${PROJECT_SOURCE_DIR}/host/elements/CMakeLists.txt")
  add_subdirectory("${PROJECT_SOURCE_DIR}/host/elements" "${PROJECT_BINARY_DIR}/host/elements")
endif()
if(TARGET ldfcz_elements)
  ldfcz_add_pf_suite(NAME test_solid_element PF test_solid_element.pf LINK ldfcz_test_support ldfcz_elements)
  # its test UMATs have Abaqus' argument list, most of which they do not read
  if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
    target_compile_options(test_solid_element PRIVATE -Wno-unused-dummy-argument)
  endif()
  ldfcz_add_pf_suite(NAME test_elastic PF test_elastic.pf LINK ldfcz_elements)
  ldfcz_add_pf_suite(NAME test_point_extrapolation PF test_point_extrapolation.pf LINK ldfcz_elements)
endif()

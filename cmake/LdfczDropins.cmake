# One-file Abaqus drop-ins (tools/make_dropin.py): the modules a routine needs and its adapter in one fixed-form
# file, as Abaqus compiles one user file per job. Generated from the sources at build time into
# <build>/dropin/, installed into <prefix>/share/ldfcz/. Shared modules are renamed per file (_uel, _umat, _all), so
# the UEL and UMAT drop-ins link together without a symbol defined twice.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(LDFCZ_DROPIN_DIR "${PROJECT_BINARY_DIR}/dropin")
set(_common "${PROJECT_SOURCE_DIR}/common/ldfcz_kinds.f90" "${PROJECT_SOURCE_DIR}/common/ldfcz_finite.f90")
set(_uel "${PROJECT_SOURCE_DIR}/uel/cohesive_law.f90" "${PROJECT_SOURCE_DIR}/uel/cohesive_element.f90"
  "${PROJECT_SOURCE_DIR}/uel/uel.f")
set(_umat "${PROJECT_SOURCE_DIR}/umat/leonov_parameters.f90" "${PROJECT_SOURCE_DIR}/umat/leonov.f90"
  "${PROJECT_SOURCE_DIR}/umat/umat.f")
set(_make "${PROJECT_SOURCE_DIR}/tools/make_dropin.py")
set(LDFCZ_DROPINS "")
foreach(kind uel umat all)
  if(kind STREQUAL "uel")
    set(_src ${_common} ${_uel})
    set(_name ldfcz_abaqus_uel.f)
  elseif(kind STREQUAL "umat")
    set(_src ${_common} ${_umat})
    set(_name ldfcz_abaqus_umat.f)
  else()
    set(_src ${_common} ${_uel} ${_umat})
    set(_name ldfcz_abaqus.f)
  endif()
  add_custom_command(OUTPUT "${LDFCZ_DROPIN_DIR}/${_name}"
    COMMAND ${CMAKE_COMMAND} -E make_directory "${LDFCZ_DROPIN_DIR}"
    COMMAND Python3::Interpreter "${_make}" --out "${LDFCZ_DROPIN_DIR}/${_name}" --tag ${kind} ${_src}
    DEPENDS ${_src} "${_make}" COMMENT "one-file drop-in ${_name}" VERBATIM)
  list(APPEND LDFCZ_DROPINS "${LDFCZ_DROPIN_DIR}/${_name}")
endforeach()
add_custom_target(dropins ALL DEPENDS ${LDFCZ_DROPINS})
include(GNUInstallDirs)
install(FILES ${LDFCZ_DROPINS} DESTINATION ${CMAKE_INSTALL_DATADIR}/ldfcz)

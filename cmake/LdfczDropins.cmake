# One-file drop-ins (tools/make_dropin.py): the modules a routine needs and its adapter in one file, as Abaqus
# compiles one user file per job: fixed form (.f, as Abaqus compiles user files) and free form (.f90); for Marc the
# HYPELA2 (ldfcz_marc_hypela2.f), the USELEM (ldfcz_marc_uselem.f) and both (ldfcz_marc.f), fixed form; for open
# hosts the Abaqus utility routines the drop-ins call (ldfcz_open_host_utils.f, .f90). Generated from the sources at
# build time into <build>/dropin/, installed into <prefix>/share/ldfcz/. Shared modules are renamed per file (_uel,
# _umat, _all, ...), so the UEL and UMAT drop-ins link together without a symbol defined twice.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(LDFCZ_DROPIN_DIR "${PROJECT_BINARY_DIR}/dropin")
set(_common "${PROJECT_SOURCE_DIR}/common/ldfcz_kinds.f90" "${PROJECT_SOURCE_DIR}/common/ldfcz_finite.f90")
set(_uel "${PROJECT_SOURCE_DIR}/uel/cohesive_law.f90" "${PROJECT_SOURCE_DIR}/uel/cohesive_element.f90"
  "${PROJECT_SOURCE_DIR}/uel/cohesive_input.f90"
  "${PROJECT_SOURCE_DIR}/uel/uel.f")
set(_umat "${PROJECT_SOURCE_DIR}/umat/leonov_parameters.f90" "${PROJECT_SOURCE_DIR}/umat/leonov.f90"
  "${PROJECT_SOURCE_DIR}/umat/leonov_plane_stress.f90" "${PROJECT_SOURCE_DIR}/umat/umat.f")
set(_make "${PROJECT_SOURCE_DIR}/tools/make_dropin.py")
set(LDFCZ_DROPINS "")
set(_marc_umat "${PROJECT_SOURCE_DIR}/umat/leonov_parameters.f90" "${PROJECT_SOURCE_DIR}/umat/leonov.f90"
  "${PROJECT_SOURCE_DIR}/umat/leonov_marc.f90" "${PROJECT_SOURCE_DIR}/umat/hypela2.f")
set(_marc_uel "${PROJECT_SOURCE_DIR}/uel/cohesive_law.f90" "${PROJECT_SOURCE_DIR}/uel/cohesive_element.f90"
  "${PROJECT_SOURCE_DIR}/uel/cohesive_input.f90" "${PROJECT_SOURCE_DIR}/uel/cohesive_marc.f90"
  "${PROJECT_SOURCE_DIR}/uel/uselem.f")
foreach(kind uel umat all marc marcuel marcall open)
  set(_host abaqus)
  if(kind STREQUAL "uel")
    set(_src ${_common} ${_uel})
    set(_name ldfcz_abaqus_uel)
  elseif(kind STREQUAL "umat")
    set(_src ${_common} ${_umat})
    set(_name ldfcz_abaqus_umat)
  elseif(kind STREQUAL "all")
    set(_src ${_common} ${_uel} ${_umat})
    set(_name ldfcz_abaqus)
  elseif(kind STREQUAL "marc")
    set(_src ${_common} ${_marc_umat})
    set(_name ldfcz_marc_hypela2)
    set(_host marc)
  elseif(kind STREQUAL "marcuel")
    set(_src ${_common} ${_marc_uel})
    set(_name ldfcz_marc_uselem)
    set(_host marc)
  elseif(kind STREQUAL "marcall")
    set(_src ${_common} ${_marc_uel} ${_marc_umat})
    set(_name ldfcz_marc)
    set(_host marc)
  else()
    set(_src "${PROJECT_SOURCE_DIR}/common/open_host_utils.f90")
    set(_name ldfcz_open_host_utils)
    set(_host open)
  endif()
  set(_forms fixed free)
  if(_host STREQUAL "marc")
    set(_forms fixed)
  endif()
  foreach(_form IN LISTS _forms)
    set(_file "${_name}.f")
    if(_form STREQUAL "free")
      set(_file "${_name}.f90")
    endif()
    add_custom_command(OUTPUT "${LDFCZ_DROPIN_DIR}/${_file}"
      COMMAND ${CMAKE_COMMAND} -E make_directory "${LDFCZ_DROPIN_DIR}"
      COMMAND Python3::Interpreter "${_make}" --out "${LDFCZ_DROPIN_DIR}/${_file}" --tag ${kind} --form ${_form}
        --host ${_host} ${_src}
      DEPENDS ${_src} "${_make}" COMMENT "one-file drop-in ${_file}" VERBATIM)
    list(APPEND LDFCZ_DROPINS "${LDFCZ_DROPIN_DIR}/${_file}")
  endforeach()
endforeach()
add_custom_target(dropins ALL DEPENDS ${LDFCZ_DROPINS})
include(GNUInstallDirs)
install(FILES ${LDFCZ_DROPINS} DESTINATION ${CMAKE_INSTALL_DATADIR}/ldfcz)

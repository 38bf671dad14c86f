#[=======================================================================[.rst:
FindMETIS
---------
Find METIS 5 (graph partitioning and fill-reducing orderings).

Hints: ``METIS_ROOT`` / ``METIS_DIR`` (CMake or environment variables), standard prefixes.
Result variables: ``METIS_FOUND``, ``METIS_INCLUDE_DIR``, ``METIS_LIBRARY``, ``METIS_IDXTYPEWIDTH``,
``METIS_VERSION``. Imported target: ``METIS::METIS``.

ldfcz calls METIS from Fortran with 32-bit idx_t (c_int32_t): a METIS built with IDXTYPEWIDTH 64 is reported
as not found, with the reason.
#]=======================================================================]
set(_metis_hints ${METIS_ROOT} ${METIS_DIR} $ENV{METIS_ROOT} $ENV{METIS_DIR})

find_path(METIS_INCLUDE_DIR NAMES metis.h
  HINTS ${_metis_hints}
  PATH_SUFFIXES include include/metis metis)
find_library(METIS_LIBRARY NAMES metis
  HINTS ${_metis_hints}
  PATH_SUFFIXES lib lib64 lib/x86_64-linux-gnu)

set(METIS_IDXTYPEWIDTH "")
if(METIS_INCLUDE_DIR AND EXISTS "${METIS_INCLUDE_DIR}/metis.h")
  file(STRINGS "${METIS_INCLUDE_DIR}/metis.h" _metis_idx REGEX "^#define[ \t]+IDXTYPEWIDTH[ \t]+[0-9]+")
  string(REGEX REPLACE ".*IDXTYPEWIDTH[ \t]+([0-9]+).*" "\\1" METIS_IDXTYPEWIDTH "${_metis_idx}")
  file(STRINGS "${METIS_INCLUDE_DIR}/metis.h" _metis_ver REGEX "^#define[ \t]+METIS_VER_(MAJOR|MINOR|SUBMINOR)[ \t]+[0-9]+")
  set(_metis_parts "")
  foreach(_line IN LISTS _metis_ver)
    string(REGEX REPLACE ".*[ \t]([0-9]+)$" "\\1" _num "${_line}")
    list(APPEND _metis_parts ${_num})
  endforeach()
  list(JOIN _metis_parts "." METIS_VERSION)
endif()

set(_metis_reason "")
if(METIS_IDXTYPEWIDTH AND NOT METIS_IDXTYPEWIDTH STREQUAL "32")
  set(_metis_reason "ldfcz needs METIS with 32-bit idx_t; ${METIS_INCLUDE_DIR}/metis.h has IDXTYPEWIDTH ${METIS_IDXTYPEWIDTH}")
  set(_metis_width_ok FALSE)
else()
  set(_metis_width_ok TRUE)
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(METIS
  REQUIRED_VARS METIS_LIBRARY METIS_INCLUDE_DIR _metis_width_ok
  VERSION_VAR METIS_VERSION
  REASON_FAILURE_MESSAGE "${_metis_reason}")

if(METIS_FOUND AND NOT TARGET METIS::METIS)
  add_library(METIS::METIS UNKNOWN IMPORTED GLOBAL)
  set_target_properties(METIS::METIS PROPERTIES
    IMPORTED_LOCATION "${METIS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${METIS_INCLUDE_DIR}")
endif()
mark_as_advanced(METIS_INCLUDE_DIR METIS_LIBRARY)

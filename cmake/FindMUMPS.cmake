#[=======================================================================[.rst:
FindMUMPS
---------
Find the SEQUENTIAL MUMPS in double precision (dmumps: the solver) and single precision (smumps: factors used as
a GMRES preconditioner, ``ldfcz --factors single``) with its stub MPI library (libseq).

Looks first for Debian's names (libdmumps_seq, libmumps_common_seq, libpord_seq, libmpiseq_seq, headers in
/usr/include and the stub mpif.h in /usr/include/mumps_seq), then for an upstream sequential build (libdmumps,
libmumps_common, libpord, libmpiseq; the stub mpif.h in libseq/).

With ``MUMPS_PARALLEL`` set (the LDFCZ_MPI build) it finds the MPI build instead: Debian's libdmumps, libsmumps,
libmumps_common, libpord and ScaLAPACK (libscalapack-openmpi), headers in /usr/include; the caller links MPI and
takes mpif.h from its MPI (``MUMPS_MPISEQ_INCLUDE_DIR`` is then empty).

Hints: ``MUMPS_ROOT`` / ``MUMPS_DIR`` (CMake or environment variables).
Result variables: ``MUMPS_FOUND``, ``MUMPS_INCLUDE_DIR`` (dmumps_struc.h), ``MUMPS_MPISEQ_INCLUDE_DIR`` (stub
mpif.h), ``MUMPS_LIBRARIES``, ``MUMPS_VERSION``. Imported target: ``MUMPS::MUMPS`` (links LAPACK and BLAS).
#]=======================================================================]
set(_mumps_hints ${MUMPS_ROOT} ${MUMPS_DIR} $ENV{MUMPS_ROOT} $ENV{MUMPS_DIR})

if(MUMPS_PARALLEL)
  find_path(MUMPS_INCLUDE_DIR NAMES dmumps_struc.h HINTS ${_mumps_hints} PATH_SUFFIXES include include/mumps mumps)
  set(_mumps_lib_suffixes lib lib64 lib/x86_64-linux-gnu)
  find_library(MUMPS_DMUMPS_PAR_LIBRARY NAMES dmumps HINTS ${_mumps_hints} PATH_SUFFIXES ${_mumps_lib_suffixes})
  find_library(MUMPS_SMUMPS_PAR_LIBRARY NAMES smumps HINTS ${_mumps_hints} PATH_SUFFIXES ${_mumps_lib_suffixes})
  find_library(MUMPS_COMMON_PAR_LIBRARY NAMES mumps_common HINTS ${_mumps_hints} PATH_SUFFIXES ${_mumps_lib_suffixes})
  find_library(MUMPS_PORD_PAR_LIBRARY NAMES pord HINTS ${_mumps_hints} PATH_SUFFIXES ${_mumps_lib_suffixes})
  find_library(MUMPS_SCALAPACK_LIBRARY NAMES scalapack-openmpi scalapack HINTS ${_mumps_hints}
    PATH_SUFFIXES ${_mumps_lib_suffixes})
  find_package(LAPACK QUIET)
  include(FindPackageHandleStandardArgs)
  find_package_handle_standard_args(MUMPS
    REQUIRED_VARS MUMPS_DMUMPS_PAR_LIBRARY MUMPS_SMUMPS_PAR_LIBRARY MUMPS_COMMON_PAR_LIBRARY MUMPS_SCALAPACK_LIBRARY
                  MUMPS_INCLUDE_DIR LAPACK_FOUND)
  if(MUMPS_FOUND)
    set(MUMPS_MPISEQ_INCLUDE_DIR "")
    set(MUMPS_LIBRARIES ${MUMPS_DMUMPS_PAR_LIBRARY} ${MUMPS_SMUMPS_PAR_LIBRARY} ${MUMPS_COMMON_PAR_LIBRARY})
    if(MUMPS_PORD_PAR_LIBRARY)
      list(APPEND MUMPS_LIBRARIES ${MUMPS_PORD_PAR_LIBRARY})
    endif()
    list(APPEND MUMPS_LIBRARIES ${MUMPS_SCALAPACK_LIBRARY})
    if(NOT TARGET MUMPS::MUMPS)
      add_library(MUMPS::MUMPS INTERFACE IMPORTED GLOBAL)
      set_target_properties(MUMPS::MUMPS PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "${MUMPS_LIBRARIES};${LAPACK_LIBRARIES}")
    endif()
  endif()
  mark_as_advanced(MUMPS_DMUMPS_PAR_LIBRARY MUMPS_SMUMPS_PAR_LIBRARY MUMPS_COMMON_PAR_LIBRARY MUMPS_PORD_PAR_LIBRARY
    MUMPS_SCALAPACK_LIBRARY)
  return()
endif()

find_path(MUMPS_INCLUDE_DIR NAMES dmumps_struc.h
  HINTS ${_mumps_hints}
  PATH_SUFFIXES include include/mumps mumps)
# The stub mpif.h of the sequential library: never a real MPI's.
find_path(MUMPS_MPISEQ_INCLUDE_DIR NAMES mpif.h
  HINTS ${_mumps_hints} ${MUMPS_INCLUDE_DIR}
  PATH_SUFFIXES mumps_seq include/mumps_seq libseq include/libseq
  NO_DEFAULT_PATH)
if(NOT MUMPS_MPISEQ_INCLUDE_DIR)
  find_path(MUMPS_MPISEQ_INCLUDE_DIR NAMES mpif.h PATHS /usr/include /usr/local/include
    PATH_SUFFIXES mumps_seq libseq NO_DEFAULT_PATH)
endif()

set(_mumps_lib_suffixes lib lib64 lib/x86_64-linux-gnu libseq)
find_library(MUMPS_DMUMPS_LIBRARY NAMES dmumps_seq dmumps HINTS ${_mumps_hints} PATH_SUFFIXES ${_mumps_lib_suffixes})
find_library(MUMPS_SMUMPS_LIBRARY NAMES smumps_seq smumps HINTS ${_mumps_hints} PATH_SUFFIXES ${_mumps_lib_suffixes})
find_library(MUMPS_COMMON_LIBRARY NAMES mumps_common_seq mumps_common HINTS ${_mumps_hints}
  PATH_SUFFIXES ${_mumps_lib_suffixes})
find_library(MUMPS_PORD_LIBRARY NAMES pord_seq pord HINTS ${_mumps_hints} PATH_SUFFIXES ${_mumps_lib_suffixes})
find_library(MUMPS_MPISEQ_LIBRARY NAMES mpiseq_seq mpiseq HINTS ${_mumps_hints} PATH_SUFFIXES ${_mumps_lib_suffixes})

# Debian's libdmumps.so is the MPI build: pair it with a stub only when no _seq variant exists, and say so.
if(MUMPS_DMUMPS_LIBRARY MATCHES "dmumps_seq")
  set(MUMPS_SEQUENTIAL_NAMES TRUE)
else()
  set(MUMPS_SEQUENTIAL_NAMES FALSE)
endif()

set(MUMPS_VERSION "")
if(MUMPS_INCLUDE_DIR AND EXISTS "${MUMPS_INCLUDE_DIR}/dmumps_c.h")
  file(STRINGS "${MUMPS_INCLUDE_DIR}/dmumps_c.h" _mumps_ver REGEX "^#define[ \t]+MUMPS_VERSION[ \t]+\"")
  string(REGEX REPLACE ".*MUMPS_VERSION[ \t]+\"([0-9.]+)\".*" "\\1" MUMPS_VERSION "${_mumps_ver}")
endif()

# Full library paths (not the LAPACK::LAPACK target, which is local to the directory that found it).
find_package(LAPACK QUIET)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS
  REQUIRED_VARS MUMPS_DMUMPS_LIBRARY MUMPS_SMUMPS_LIBRARY MUMPS_COMMON_LIBRARY MUMPS_MPISEQ_LIBRARY MUMPS_INCLUDE_DIR
                MUMPS_MPISEQ_INCLUDE_DIR LAPACK_FOUND
  VERSION_VAR MUMPS_VERSION)

if(MUMPS_FOUND)
  set(MUMPS_LIBRARIES ${MUMPS_DMUMPS_LIBRARY} ${MUMPS_SMUMPS_LIBRARY} ${MUMPS_COMMON_LIBRARY})
  if(MUMPS_PORD_LIBRARY)
    list(APPEND MUMPS_LIBRARIES ${MUMPS_PORD_LIBRARY})
  endif()
  list(APPEND MUMPS_LIBRARIES ${MUMPS_MPISEQ_LIBRARY})
  if(NOT TARGET MUMPS::MUMPS)
    add_library(MUMPS::MUMPS INTERFACE IMPORTED GLOBAL)
    # The stub mpif.h directory comes first so that no real MPI's mpif.h is picked up.
    set_target_properties(MUMPS::MUMPS PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_MPISEQ_INCLUDE_DIR};${MUMPS_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES "${MUMPS_LIBRARIES};${LAPACK_LIBRARIES}")
  endif()
endif()
mark_as_advanced(MUMPS_INCLUDE_DIR MUMPS_MPISEQ_INCLUDE_DIR MUMPS_DMUMPS_LIBRARY MUMPS_SMUMPS_LIBRARY MUMPS_COMMON_LIBRARY
  MUMPS_PORD_LIBRARY MUMPS_MPISEQ_LIBRARY)

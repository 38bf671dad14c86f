# Compiler flags of ldfcz: warnings everywhere, a Debug build that traps invalid operations, division by zero
# and overflow, and checks bounds (the tests use it), an optimised Release build.
# The project's own sources build without a warning; tools/test.sh (and so CI) turns them into errors. Off by default
# so that a user's newer compiler, with warnings this one does not know, still builds.
option(LDFCZ_WERROR "Treat the compiler warnings of ldfcz's own sources as errors (tools/test.sh sets it)" OFF)
if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  # Two of -Wall/-Wextra's checks stay off, each for a reason that held at every place it flagged (gfortran 12,
  # counted with them on over the sources, suites and tools: 26 and 4 places):
  # -Wcompare-reals flags every == and /= between reals; the code compares exactly on purpose: against a 0 that
  #   guards a division or means "none" (a zero load, a GMRES breakdown), against a property's default (THICK = 1),
  #   for a tie between equal values, or to check a result bit for bit.
  # -Wmaybe-uninitialized (optimised builds only) depends on the optimiser's flow analysis: of its 4 places two were
  #   ours and are fixed (an *NGEN flag set on one branch, a 1-entry SVARS passed unset to a UEL without state), two
  #   are gfortran's own temporaries that no source line names (an allocatable's bounds, a type's default
  #   initialisation in ALLOCATE). -Wuninitialized (the certain case) stays on.
  set(LDFCZ_FORTRAN_WARNINGS -Wall -Wextra -fimplicit-none -Wno-compare-reals -Wno-maybe-uninitialized)
  # Every routine may run on several threads at once (the OpenMP element loop calls the element, UEL and UMAT
  # code of libraries built without -fopenmp): local variables on the stack (-frecursive, what -fopenmp implies,
  # and Abaqus' -auto for user code) instead of static storage for large local arrays; also keeps the Debug
  # build's recursion check from firing when two threads are in the same routine.
  add_compile_options($<$<COMPILE_LANGUAGE:Fortran>:-frecursive>)
  set(CMAKE_Fortran_FLAGS_DEBUG "-g -O0 -fcheck=all -ffpe-trap=invalid,zero,overflow -fbacktrace -finit-real=snan")
  set(CMAKE_Fortran_FLAGS_RELEASE "-O2")
  set(CMAKE_Fortran_FLAGS_RELWITHDEBINFO "-O2 -g -fbacktrace")
  # Fixed-form Abaqus-style sources (ABA_PARAM.INC's implicit typing) are compiled without -fimplicit-none.
  set(LDFCZ_FIXED_FORM_FLAGS -fno-implicit-none -ffixed-line-length-132)
  # The hot kernels of the element loop (the Leonov update, the continuum element and its tangent kernel) at -O3
  # in the optimised configurations: gfortran 12 vectorises their fixed-size loops only there (no -ffast-math:
  # IEEE semantics kept; results change at round-off through other inlining). Measured in docs/performance.md.
  set(LDFCZ_HOT_FLAGS "$<$<CONFIG:Release,RelWithDebInfo>:-O3>")
elseif(CMAKE_Fortran_COMPILER_ID MATCHES "LLVMFlang|Flang")
  set(LDFCZ_FORTRAN_WARNINGS "")
  set(CMAKE_Fortran_FLAGS_DEBUG "-g -O0")
  set(CMAKE_Fortran_FLAGS_RELEASE "-O2")
  set(LDFCZ_FIXED_FORM_FLAGS "")
else()
  set(LDFCZ_FORTRAN_WARNINGS "")
  set(LDFCZ_FIXED_FORM_FLAGS "")
endif()
if(NOT DEFINED LDFCZ_HOT_FLAGS)
  set(LDFCZ_HOT_FLAGS "")
endif()
# The C sources (a few thin wrappers of C libraries) under the same rule.
if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
  set(LDFCZ_C_WARNINGS -Wall -Wextra)
else()
  set(LDFCZ_C_WARNINGS "")
endif()
if(LDFCZ_WERROR)
  if(LDFCZ_FORTRAN_WARNINGS)
    list(APPEND LDFCZ_FORTRAN_WARNINGS -Werror)
  endif()
  if(LDFCZ_C_WARNINGS)
    list(APPEND LDFCZ_C_WARNINGS -Werror)
  endif()
endif()

# Apply the project's warnings to a target's own sources.
function(ldfcz_warnings target)
  target_compile_options(${target} PRIVATE $<$<COMPILE_LANGUAGE:Fortran>:${LDFCZ_FORTRAN_WARNINGS}>
    $<$<COMPILE_LANGUAGE:C>:${LDFCZ_C_WARNINGS}>)
endfunction()

#[[ ldfcz_add_shared_twin(<static target> [LINK <shared targets>...])
    A shared library <target>_shared (lib<name>.so beside lib<name>.a) built from the same sources with the same
    per-file flags, its module files kept apart (modules_shared) so the two builds never write the same .mod.
    Call it in the directory that defines the static target (source-file properties are per directory). ]]
function(ldfcz_add_shared_twin target)
  cmake_parse_arguments(T "" "" "LINK" ${ARGN})
  get_target_property(srcs ${target} SOURCES)
  add_library(${target}_shared SHARED ${srcs})
  set_target_properties(${target}_shared PROPERTIES OUTPUT_NAME ${target} INSTALL_RPATH "$ORIGIN"
    Fortran_MODULE_DIRECTORY "${PROJECT_BINARY_DIR}/modules_shared/${target}")
  get_target_property(incs ${target} INCLUDE_DIRECTORIES)
  if(incs)
    target_include_directories(${target}_shared PRIVATE ${incs})
  endif()
  target_link_libraries(${target}_shared PUBLIC ${T_LINK})
  target_include_directories(${target}_shared PUBLIC $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/modules_shared/${target}>)
  ldfcz_warnings(${target}_shared)
endfunction()

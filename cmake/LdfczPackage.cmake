# The CMake package of the user routines: `cmake --install` puts the static libraries of the cores and their Abaqus
# adapters, the Fortran module files, ABA_PARAM.INC, the one-file drop-ins and ldfczConfig.cmake (imported targets
# ldfcz::kinds, ldfcz::uel, ldfcz::umat, ldfcz::abaqus_utils and their shared twins ldfcz::*_shared) plus ldfcz.pc
# for pkg-config into the prefix.
# Another project: find_package(ldfcz REQUIRED) and target_link_libraries(app PRIVATE ldfcz::uel ldfcz::umat
# ldfcz::abaqus_utils) (the last provides XIT, STDB_ABQERR, ... outside Abaqus; inside Abaqus leave it out).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(LDFCZ_INSTALL_MODDIR "${CMAKE_INSTALL_INCLUDEDIR}/ldfcz/modules")
set(LDFCZ_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/ldfcz")
set_target_properties(ldfcz_kinds PROPERTIES EXPORT_NAME kinds)
set_target_properties(ldfcz_uel PROPERTIES EXPORT_NAME uel)
set_target_properties(ldfcz_umat PROPERTIES EXPORT_NAME umat)
set_target_properties(ldfcz_abaqus_utils PROPERTIES EXPORT_NAME abaqus_utils)
target_include_directories(ldfcz_kinds PUBLIC $<INSTALL_INTERFACE:${LDFCZ_INSTALL_MODDIR}>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/ldfcz>)
# shared twins (ldfcz::uel_shared, ...): the same code as lib*.so, for codes that load user routines at run time
foreach(t kinds uel umat abaqus_utils)
  set_target_properties(ldfcz_${t}_shared PROPERTIES EXPORT_NAME ${t}_shared)
  target_include_directories(ldfcz_${t}_shared PUBLIC $<INSTALL_INTERFACE:${LDFCZ_INSTALL_MODDIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/ldfcz>)
endforeach()
install(TARGETS ldfcz_kinds ldfcz_uel ldfcz_umat ldfcz_abaqus_utils ldfcz_kinds_shared ldfcz_uel_shared
  ldfcz_umat_shared ldfcz_abaqus_utils_shared EXPORT ldfczTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(mod ldfcz_kinds ldfcz_finite cohesive_law cohesive_element cohesive_input cohesive_marc leonov_parameters leonov leonov_marc
            abaqus_host_state abaqus_tensor_utils)
  install(FILES "${CMAKE_Fortran_MODULE_DIRECTORY}/${mod}.mod" DESTINATION ${LDFCZ_INSTALL_MODDIR} OPTIONAL)
endforeach()
install(EXPORT ldfczTargets NAMESPACE ldfcz:: DESTINATION ${LDFCZ_INSTALL_CMAKEDIR})
file(WRITE "${PROJECT_BINARY_DIR}/ldfczConfig.cmake.in" [=[
@PACKAGE_INIT@
include(CMakeFindDependencyMacro)
if(@LDFCZ_WITH_OPENMP@)
  find_dependency(OpenMP COMPONENTS Fortran)
endif()
include("${CMAKE_CURRENT_LIST_DIR}/ldfczTargets.cmake")
set_and_check(ldfcz_DROPIN_DIR "@PACKAGE_CMAKE_INSTALL_DATADIR@/ldfcz")
set_and_check(ldfcz_ABAQUS_INCLUDE_DIR "@PACKAGE_CMAKE_INSTALL_INCLUDEDIR@/ldfcz")
]=])
configure_package_config_file("${PROJECT_BINARY_DIR}/ldfczConfig.cmake.in" "${PROJECT_BINARY_DIR}/ldfczConfig.cmake"
  INSTALL_DESTINATION ${LDFCZ_INSTALL_CMAKEDIR} PATH_VARS CMAKE_INSTALL_DATADIR CMAKE_INSTALL_INCLUDEDIR)
write_basic_package_version_file("${PROJECT_BINARY_DIR}/ldfczConfigVersion.cmake" VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/ldfczConfig.cmake" "${PROJECT_BINARY_DIR}/ldfczConfigVersion.cmake"
  DESTINATION ${LDFCZ_INSTALL_CMAKEDIR})
# relocatable: the prefix is found from where the .pc file lies (pkg-config's pcfiledir)
file(RELATIVE_PATH LDFCZ_PC_TO_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
file(WRITE "${PROJECT_BINARY_DIR}/ldfcz.pc.in" [=[
prefix=${pcfiledir}/@LDFCZ_PC_TO_PREFIX@
libdir=${prefix}/@CMAKE_INSTALL_LIBDIR@
includedir=${prefix}/@CMAKE_INSTALL_INCLUDEDIR@/ldfcz
Name: ldfcz
Description: LDF cohesive element (Abaqus UEL) and compressible Leonov PET material (UMAT, HYPELA2)
Version: @PROJECT_VERSION@
Cflags: -I${includedir} -I${includedir}/modules
Libs: -L${libdir} -lldfcz_uel -lldfcz_umat -lldfcz_abaqus_utils -lldfcz_kinds -lpthread
]=])
configure_file("${PROJECT_BINARY_DIR}/ldfcz.pc.in" "${PROJECT_BINARY_DIR}/ldfcz.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/ldfcz.pc" DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
install(FILES "${LDFCZ_ABAQUS_INCLUDE}/SMAAspUserSubroutines.hdr" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ldfcz)

# Install rules and the package config that makes find_package(edyn) work from a prefix.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS edyn EXPORT edynTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/edyn DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT edynTargets NAMESPACE edyn:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/edyn)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/edynConfig.cmake.in
  ${PROJECT_BINARY_DIR}/edynConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/edyn)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/edynConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/edynConfig.cmake ${PROJECT_BINARY_DIR}/edynConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/edyn)

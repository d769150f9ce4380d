# Install rules and the package config, so another project can
#   find_package(Prism REQUIRED COMPONENTS spectral)
#   target_link_libraries(app PRIVATE prism::spectral)
# and link only the layers it needs.
include(CMakePackageConfigHelpers)
set(PRISM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Prism)

install(EXPORT PrismTargets NAMESPACE prism:: DESTINATION ${PRISM_CMAKE_DIR})
configure_package_config_file(cmake/PrismConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/PrismConfig.cmake INSTALL_DESTINATION ${PRISM_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)  # for Prism_DATA_DIR, Prism_SHADER_DIR and Prism_SCENE_DIR
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/PrismConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/PrismConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/PrismConfigVersion.cmake
        DESTINATION ${PRISM_CMAKE_DIR})
install(DIRECTORY data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/prism/data)
install(DIRECTORY scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/prism/scenes)

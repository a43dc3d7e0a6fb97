# The installable CMake package: find_package(GradientShadows 0.2) gives GradientShadows::engine, ::content and
# ::shadows (static libraries, their dependencies found by the package config) and the executables as
# GradientShadows::gs-scenetest and so on. Everything is installed relative to the prefix, so the installed tree
# can be moved. docs/INTEGRATING.md walks through it.
include(CMakePackageConfigHelpers)

install(EXPORT GradientShadowsTargets NAMESPACE GradientShadows:: DESTINATION ${GS_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/GradientShadowsConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/GradientShadowsConfig.cmake
  INSTALL_DESTINATION ${GS_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_LIBDIR GS_INSTALL_DATADIR)
# 0.x releases make no compatibility promise between minor versions.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/GradientShadowsConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/GradientShadowsConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/GradientShadowsConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/FindOpenSubdivCPU.cmake
        DESTINATION ${GS_INSTALL_CMAKEDIR})

# The content scenes: data for the tools' scene names and for hosts' scene tests.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/content DESTINATION ${GS_INSTALL_DATADIR})

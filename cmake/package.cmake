# find_package(SSS) for other projects: SSSConfig.cmake finds the VTK modules that the
# interfaces of SSS::Translucency and SSS::Headless name, then loads the exported target and its VTK module
# properties (for vtk_module_autoinit). sss_core is linked into the shared library privately,
# so it is neither exported nor installed.
include(CMakePackageConfigHelpers)

set(SSS_VTK_COMPONENTS)
foreach(target IN ITEMS Translucency Headless)
  get_target_property(sss_interface_links ${target} INTERFACE_LINK_LIBRARIES)
  foreach(link IN LISTS sss_interface_links)
    if(link MATCHES "^VTK::(.+)$")
      list(APPEND SSS_VTK_COMPONENTS "${CMAKE_MATCH_1}")
    endif()
  endforeach()
endforeach()
list(REMOVE_DUPLICATES SSS_VTK_COMPONENTS)
string(JOIN " " SSS_VTK_COMPONENTS ${SSS_VTK_COMPONENTS})
set(SSS_VTK_VERSION "${VTK_MAJOR_VERSION}.${VTK_MINOR_VERSION}")

set(sss_cmake_destination "lib/cmake/sss")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/SSSConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/${sss_cmake_destination}/SSSConfig.cmake"
  INSTALL_DESTINATION "${sss_cmake_destination}")
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/${sss_cmake_destination}/SSSConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES
  "${CMAKE_BINARY_DIR}/${sss_cmake_destination}/SSSConfig.cmake"
  "${CMAKE_BINARY_DIR}/${sss_cmake_destination}/SSSConfigVersion.cmake"
  DESTINATION "${sss_cmake_destination}" COMPONENT development)

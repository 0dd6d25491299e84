# The ParaView plugin is a second build (paraview/CMakeLists.txt) of the same sources against
# the VTK that ParaView 5.11 brings: it cannot share this build's targets, whose VTK is
# Debian's 9.1. It is built into build/paraview with this build and installed with it.
set(SSS_PARAVIEW_PYTHON_ROOT "${CMAKE_CURRENT_SOURCE_DIR}/.deps/python3-paraview" CACHE PATH
  "Where python3-paraview is unpacked when it is not installed (scripts/setup.sh)")
find_file(SSS_PARAVIEW_CONFIG paraview-config.cmake
  PATHS "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-5.11" NO_DEFAULT_PATH)
if(NOT SSS_PARAVIEW_CONFIG)
  message(FATAL_ERROR "ParaView 5.11 (Debian's paraview-dev) is not installed: install it "
    "(scripts/setup.sh does) or configure with -DSSS_PARAVIEW_PLUGIN=OFF")
endif()
include(ExternalProject)
set(SSS_PARAVIEW_BUILD_DIR "${CMAKE_BINARY_DIR}/paraview")
ExternalProject_Add(sss_paraview_plugin
  SOURCE_DIR "${CMAKE_CURRENT_SOURCE_DIR}/paraview"
  BINARY_DIR "${SSS_PARAVIEW_BUILD_DIR}"
  CMAKE_ARGS
    "-DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}"
    "-DCMAKE_INSTALL_PREFIX=${CMAKE_INSTALL_PREFIX}"
    "-DSSS_PARAVIEW_PYTHON_ROOT=${SSS_PARAVIEW_PYTHON_ROOT}"
  INSTALL_COMMAND ""
  BUILD_ALWAYS ON
  USES_TERMINAL_BUILD ON)
set(SSS_PARAVIEW_PLUGIN_FILE
  "${SSS_PARAVIEW_BUILD_DIR}/lib/paraview-5.11/plugins/TranslucentPointClouds/TranslucentPointClouds.so")
install(CODE "
  execute_process(COMMAND \"${CMAKE_COMMAND}\" --install \"${SSS_PARAVIEW_BUILD_DIR}\"
    --prefix \"\${CMAKE_INSTALL_PREFIX}\" RESULT_VARIABLE status)
  if(status)
    message(FATAL_ERROR \"installing the ParaView plugin failed\")
  endif()")

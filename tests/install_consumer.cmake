# cmake -DBUILD_DIR=... -DWORK_DIR=... -DCONSUMER_SOURCE=... -DGENERATOR=... -DCXX_COMPILER=...
#       [-DPYTHON=... -DPYTHON_DESTINATION=...] -P install_consumer.cmake
# Installs the build into WORK_DIR/prefix, then configures, builds and runs tests/consumer
# against that prefix alone (CMAKE_PREFIX_PATH), and checks that both the package and the
# library's OSMesa shim were found there rather than in the build tree; with PYTHON, also
# that the installed Python package imports from the prefix.
set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT exit_code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${exit_code}):\n${out}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

function(expect text what)
  string(FIND "${output}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${what}: no '${text}' in:\n${output}")
  endif()
endfunction()

run("install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
run("configuring the consumer" "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE}" -B "${WORK_DIR}/build"
  -G "${GENERATOR}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" -DCMAKE_BUILD_TYPE=Release
  "-DCMAKE_PREFIX_PATH=${prefix}")
expect("SSS_DIR: ${prefix}/" "the package is not the installed one")
run("building the consumer" "${CMAKE_COMMAND}" --build "${WORK_DIR}/build")
run("the consumer of SSS::PCL" "${WORK_DIR}/build/sss_consumer_pcl")
message(STATUS "${output}")
run("the consumer" "${WORK_DIR}/build/sss_consumer")
message(STATUS "${output}")
get_filename_component(real_prefix "${prefix}" REALPATH)
expect("OSMesa shim: ${real_prefix}/" "the installed library does not use the installed shim")

if(PYTHON)
  run("importing the installed Python package" "${CMAKE_COMMAND}" -E env
    "PYTHONPATH=${prefix}/${PYTHON_DESTINATION}" "${PYTHON}" -c
    "import sss\nprint('sss from', sss.__file__)\nprint(sss.vtkSubsurfacePass().GetClassName())")
  message(STATUS "${output}")
  expect("sss from ${prefix}/${PYTHON_DESTINATION}/sss/" "Python imported another sss package")
endif()
if(PARAVIEW_PLUGIN)
  if(NOT EXISTS "${prefix}/${PARAVIEW_PLUGIN}")
    message(FATAL_ERROR "the ParaView plugin was not installed: no ${prefix}/${PARAVIEW_PLUGIN}")
  endif()
  message(STATUS "ParaView plugin installed: ${prefix}/${PARAVIEW_PLUGIN}")
endif()

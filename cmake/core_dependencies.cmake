# What core/ builds with: Eigen, FLANN's header-only index (its headers call LZ4) and OpenMP.
# Shared by the main build and the ParaView plugin's (paraview/CMakeLists.txt).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_path(FLANN_INCLUDE_DIR flann/flann.hpp REQUIRED)
find_library(LZ4_LIBRARY lz4 REQUIRED)
add_library(sss_flann INTERFACE)
target_include_directories(sss_flann SYSTEM INTERFACE ${FLANN_INCLUDE_DIR})
target_link_libraries(sss_flann INTERFACE ${LZ4_LIBRARY})
find_package(OpenMP REQUIRED COMPONENTS CXX)

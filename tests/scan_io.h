// Test support: the shared real scans as surfel clouds (ASCII PLY meshes, optionally gzipped).
#pragma once

#include <string>

#include "surfel_cloud.h"

namespace sss::test {

// Path of a file in the shared data folder, or "" when it is absent.
std::string shared_data(const std::string& name);

// Vertices of an ASCII PLY mesh with area-weighted vertex normals from its faces and a
// disc radius of 0.8 times the mean edge length (closes the holes between vertices).
SurfelCloud load_ply_mesh(const std::string& path);

}  // namespace sss::test

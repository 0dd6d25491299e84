// sss_render's input: a .ply / .ply.gz mesh (its vertices become surfels) or a .pcd cloud
// (normals from the file, or estimated with PCL), as a validated surfel cloud.
#pragma once

#include <string>

#include "surfel_cloud.h"

namespace sss::cli {

struct LoadedCloud {
  SurfelCloud cloud;       // scene units, validated; radius 0 for "from the spacing"
  std::string description;  // what was read and what was dropped
};

// Throws std::runtime_error naming the file and what is wrong (unreadable, unknown
// extension, no points, no finite points, too few points for normals).
LoadedCloud load_cloud(const std::string& path);

}  // namespace sss::cli

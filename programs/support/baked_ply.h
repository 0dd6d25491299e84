// The --bake output: a binary PLY with each point's position, normal and outgoing radiance
// (also a cloud with normals for programs that read PLY, ParaView among them).
#pragma once

#include <string>
#include <vector>

#include "surfel_cloud.h"

namespace sss::cli {

// One vertex per point (double x, y, z; float nx, ny, nz; float red, green, blue). Written
// whole or not at all; throws std::runtime_error on failure.
void write_baked_ply(const std::vector<Eigen::Vector3d>& positions,
                     const std::vector<Eigen::Vector3d>& normals, const std::vector<Rgb>& Lo,
                     const std::string& path);

}  // namespace sss::cli

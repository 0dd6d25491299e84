// sss_render's input: any file the PCL glue reads (PCD, PLY, PLY.gz, OBJ, ASCII point lists; a
// mesh's vertices or samples of its surface) as a validated surfel cloud for the CPU reference
// and the GPU path.
#pragma once

#include <cstddef>
#include <string>

#include "surfel_cloud.h"

namespace sss::cli {

struct LoadedCloud {
  SurfelCloud cloud;        // scene units, validated; radius = mean point spacing
  std::string description;  // what was read and what was dropped
  std::size_t isolated = 0;  // points left out as isolated
  double largest_isolation = 0.0;
  bool denoised = false;  // points on the measured surface (sssPclSurfels.h)
  double noise_median = 0.0, noise_p90 = 0.0;  // depth noise measured, scene units
};

// mesh_samples > 0 samples that many points on a PLY or OBJ mesh's surface; memory_cap (bytes,
// 0: the loader's default) bounds what the file may claim. Throws sss::InputError naming the
// file and what is wrong (unreadable, unknown extension, a header that claims more than the
// file holds or the cap allows, a malformed line, no points, no finite points, too few points
// for normals).
// isolation_ratio > 0 leaves out the points isolated above it (sssPclSurfels.h), 0 keeps them;
// denoise moves the points onto the surface they measured (SurfelOptions::denoise).
LoadedCloud load_cloud(const std::string& path, std::size_t mesh_samples = 0,
                       std::size_t memory_cap = 0, double isolation_ratio = 5.0,
                       bool denoise = true);

}  // namespace sss::cli

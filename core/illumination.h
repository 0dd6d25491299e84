// The light's view (the paper's step 1): an illumination map rendered from each directional
// light over the surfel discs with a depth test. Its texels are the far field's lit source
// elements, each carrying E dA of eq. 15-16; its depths tell the near field which points of a
// receiver's local surface the light reaches.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "disc_raster.h"
#include "dipole.h"
#include "local_surface.h"
#include "local_surfels.h"
#include "material.h"

namespace sss {

struct DirectionalLight {
  Eigen::Vector3d direction{0, 0, 1};  // from the object towards the light
  double irradiance = 1.0;             // on a surface facing the light

  // Throws std::invalid_argument for a zero or non-finite direction or a negative or
  // non-finite irradiance.
  void validate() const;
};

struct IlluminationSettings {
  // Texel edge as a fraction of the smallest z_r of the material: below 1 the sources are finer
  // than the kernel's narrowest feature and a point sum over them converges. On curved scans
  // the error is first order in the texel (it comes from where the lit area ends, at the
  // terminator, where a texel covers texel / cos(theta_i) of surface): on the bunny z_r / 2
  // differs from z_r / 4 by 1 % mean, and z_r / 4 from z_r / 8 by 0.4 %.
  double texel_per_z_r = 0.25;
  // Largest map side; a larger object gets coarser texels, whose area the source tree then
  // integrates by splitting them near each receiver.
  int max_map_size = 4096;
};

struct IlluminationSamples {
  std::vector<Eigen::Vector3d> position;  // local mm, on the local surface of the disc seen
  std::vector<Eigen::Vector3d> normal;    // unit, turned towards the light
  std::vector<Rgb> power;                 // E dA per channel: irradiance * Ft(eta, theta_i) * texel area
  std::vector<std::uint16_t> light;       // which light's map the sample came from
  std::vector<OrthoView> maps;            // one per light
  std::vector<DiscHits> hits;             // per light: the disc each texel sees, and its depth
  std::vector<DirectionalLight> lights;   // as given, directions normalised
  std::size_t size() const { return position.size(); }
};

// The illumination map of eq. 15 as point sources. Only what a light sees is lit
// (self-shadowing), and the cosine of eq. 15 cancels against the texel's surface area
// texel_area / cos(theta_i). Normals are turned towards the light, so a cloud with
// inconsistently oriented normals is lit on the side the light sees. Where the surfels carry
// a curvature, each texel's point and normal are taken on its disc's local surface
// (local_surface.h) rather than on the flat disc; texels whose lifted normal turns away from
// the light (past the terminator) carry no light.
// The point the map sees at texel (i, j) (which must hit a disc), on the local surface of
// that disc when the surfels carry a curvature (clamped at one over the disc radius), with its
// normal there (the disc's own orientation, not turned towards the light).
SurfacePoint seen_point(const LocalSurfels& surfels, const OrthoView& map, const DiscHits& hits,
                        int i, int j);

IlluminationSamples illuminate(const LocalSurfels& surfels, const Material& material,
                               const std::vector<DirectionalLight>& lights,
                               const IlluminationSettings& settings);

}  // namespace sss

// Step 1, the light's view: an illumination map rendered from each directional light over the
// surfel discs with a depth test, each disc of the radius that closes the surface, at least
// the cells' (LocalSurfels::disc_radius), so that light does not leak through gaps between
// them. Each texel keeps the disc it sees and how far along the light that disc is; the
// irradiance step (surfel_irradiance.h) asks it which points of a surfel's cell the light
// reaches (self-shadowing comes for free).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "disc_raster.h"
#include "local_surface.h"
#include "local_surfels.h"

namespace sss {

struct DirectionalLight {
  Eigen::Vector3d direction{0, 0, 1};  // from the object towards the light
  double irradiance = 1.0;             // on a surface facing the light

  // Throws std::invalid_argument for a zero or non-finite direction or a negative or
  // non-finite irradiance.
  void validate() const;
};

struct LightMapSettings {
  // Texel edge over the disc radius: a surfel's cell is then several texels across, so the
  // fraction of it the light reaches (surfel_irradiance.h) is resolved below the surfel size.
  // Halving a sixteenth moves the dragon's B (marble, 200 mm) by 0.15 % mean, 3 % at p99;
  // halving an eighth moved it by 0.39 % and 7.6 %, in cells that thin parts shadow.
  double texel_per_radius = 0.0625;
  // Largest map side; a larger scene gets coarser texels.
  int max_map_size = 4096;
};

struct LightMaps {
  std::vector<OrthoView> maps;           // one per light
  std::vector<DiscHits> hits;            // per light: the disc each texel sees, and its depth
  std::vector<DirectionalLight> lights;  // as given, directions normalised
  std::size_t size() const { return maps.size(); }
};

// Throws std::invalid_argument for a bad light or setting.
LightMaps render_light_maps(const LocalSurfels& surfels, const std::vector<DirectionalLight>& lights,
                            const LightMapSettings& settings);

// The point the map sees at texel (i, j) (which must hit a disc), on the local surface of
// that disc when the surfels carry a curvature (clamped at one over the disc radius), with its
// normal there (the disc's own orientation).
SurfacePoint seen_point(const LocalSurfels& surfels, const OrthoView& map, const DiscHits& hits,
                        int i, int j);

// Whether the light of `map` reaches the point y of a surfel's cell, whose cosine to the light
// is cos_theta and whose thickness (local_surface.h) is `thickness`: the local surface of the
// disc seen at y's texel passes within visibility_tolerance of y along the light, or the
// texel sees no disc at all (y lies on its own disc at a silhouette that the texel's centre
// missed: nothing stands in front of it).
bool light_reaches(const LocalSurfels& surfels, const OrthoView& map, const DiscHits& hits,
                   const Eigen::Vector3d& towards_light, const Eigen::Vector3d& y,
                   double cos_theta, double thickness);

}  // namespace sss

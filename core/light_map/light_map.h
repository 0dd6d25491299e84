// Step 1, the light's view: an illumination map rendered from each light over the surfel discs with
// a depth test (along parallel rays for a directional light, from its position for a point light:
// the light's projection is the one thing a new kind of light adds), each disc of the radius that
// closes the surface, at least the cells' (LocalSurfels::disc_radius), so that light does not leak
// through gaps between them. Each texel keeps the disc it sees and how far along the light that
// disc is; the irradiance step (surfel_irradiance.h) asks it which points of a surfel's cell the
// light reaches (self-shadowing comes for free).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "disc_raster.h"
#include "local_surface.h"
#include "local_surfels.h"
#include "perspective_view.h"

namespace sss {

// A light of the scene, in the cloud's frame and units, as VTK's lights are: directional, or
// positional (a point light, or a spot below a cone angle of 90 degrees) whose irradiance falls
// off with VTK's attenuation and spot exponent.
struct Light {
  Eigen::Vector3d direction{0, 0, 1};  // from the focal point towards the light
  double irradiance = 1.0;             // on a surface facing the light (positional: before
                                       // attenuation and spot)
  bool positional = false;
  Eigen::Vector3d position{0, 0, 0};     // positional: where it is
  Eigen::Vector3d attenuation{1, 0, 0};  // positional: a0 + a1 d + a2 d^2, d in cloud units
  double cone_angle = 180.0;             // positional: a spot's half-angle (degrees) below 90
  double exponent = 1.0;                 // positional: a spot's cos^exponent falloff

  // Throws std::invalid_argument for a zero or non-finite direction, a negative or non-finite
  // irradiance, or a positional light's bad position, attenuation, cone or exponent.
  void validate() const;
  bool operator==(const Light& o) const;
};

// A light in the surfels' local frame (mm), as the light maps and the irradiance use it.
struct LocalLight {
  bool positional = false;
  Eigen::Vector3d direction{0, 0, 1};    // from the focal point towards the light, unit
  Eigen::Vector3d position{0, 0, 0};     // positional: mm
  double irradiance = 1.0;
  Eigen::Vector3d attenuation{1, 0, 0};  // positional: a0 + a1 d + a2 d^2, d in mm
  double cone_cos = -1.0;                // positional: a spot lights only cos > cone_cos ...
  double exponent = 1.0;                 // ... by cos^exponent (cone_cos -1: no spot)

  static LocalLight of(const Light& light, const LocalFrame& frame);
  // The unit direction from y towards the light.
  Eigen::Vector3d towards(const Eigen::Vector3d& y) const;
  // The irradiance on a surface at y facing the light (VTK's attenuation and spot for a
  // positional light).
  double irradiance_at(const Eigen::Vector3d& y) const;
};

// How one light sees the surfels: along parallel rays (a directional light) or from a point.
struct LightView {
  bool from_point = false;
  OrthoView ortho;              // directional
  PerspectiveView perspective;  // point light

  int width() const { return from_point ? perspective.width : ortho.width; }
  int height() const { return from_point ? perspective.height : ortho.height; }
  // Texel edge (mm): a point light's at the nearest point it sees.
  double texel_mm() const {
    return from_point ? perspective.pixel * perspective.nearest : ortho.pixel;
  }
  // The texel y falls in; false outside the map.
  bool texel_of(const Eigen::Vector3d& y, int& i, int& j) const;
  // Where texel (i, j)'s ray meets the disc it sees (which it must).
  Eigen::Vector3d hit_point(const DiscHits& hits, int i, int j) const;
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

// The view of `light` over the surfels: texels `texel` mm wide (a point light's at the nearest
// point it sees), at most max_size a side. Throws std::invalid_argument for a point light among
// the points (PerspectiveView::fit_pixel).
LightView fit_light_view(const LocalSurfels& surfels, const LocalLight& light, double texel,
                         int max_size);

struct LightMaps {
  std::vector<LightView> views;     // one per light
  std::vector<DiscHits> hits;       // per light: the disc each texel sees, and its depth
  std::vector<LocalLight> lights;   // in the surfels' frame
  std::size_t size() const { return views.size(); }
};

// Throws std::invalid_argument for a bad light or setting, or a point light among the points.
LightMaps render_light_maps(const LocalSurfels& surfels, const std::vector<Light>& lights,
                            const LightMapSettings& settings);

// The point the map sees at texel (i, j) (which must hit a disc), on the local surface of
// that disc when the surfels carry a curvature (clamped at one over the disc radius), with its
// normal there (the disc's own orientation).
SurfacePoint seen_point(const LocalSurfels& surfels, const LightView& view, const DiscHits& hits,
                        int i, int j);

// Whether the light of `view` reaches the point y of a surfel's cell, whose cosine to the light
// is cos_theta and whose thickness (local_surface.h) is `thickness`: the local surface of the
// disc seen at y's texel passes within visibility_tolerance of y along the light, for the
// thickness plus the seen surfel's noise height (the seen surface too may stand that far off
// where it was measured: a disc the noise left off its own neighbours is not an occluder), or the
// texel sees no disc at all (y lies on its own disc at a silhouette that the texel's centre
// missed: nothing stands in front of it).
bool light_reaches(const LocalSurfels& surfels, const LightView& view, const DiscHits& hits,
                   const Eigen::Vector3d& towards_light, const Eigen::Vector3d& y,
                   double cos_theta, double thickness);

}  // namespace sss

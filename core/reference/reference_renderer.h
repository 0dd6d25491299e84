// The CPU reference: eq. 16 evaluated at every surfel in double precision and in parallel;
// the ground truth for the GPU path. Each surfel stands for its cell (surfel_cells.h) lit with
// the irradiance averaged over it (surfel_irradiance.h: 64 samples, 4096 where an edge crosses
// the cell, against a light map of texels a sixteenth of a disc radius). B = near field + far
// field, split by NearFarSplit: the near field by weights integrated exactly over each
// neighbour's cell on the receiver's local surface (near_field.h), the far field summed over
// the lit cells beyond by the source tree (source_tree.h), each cell split near the receiver.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "light_map.h"
#include "local_surfels.h"
#include "near_far_split.h"
#include "near_field.h"
#include "progress.h"
#include "source_tree.h"
#include "surfel_cells.h"
#include "surfel_cloud.h"
#include "surfel_index.h"
#include "surfel_irradiance.h"

namespace sss {

struct ReferenceSettings {
  LightMapSettings light_map;
  int irradiance_samples = 64;   // per cell and light
  int irradiance_refined = 4096;  // where those disagree (an edge crosses the cell); on the
                                  // airborne tile, against 256 / 4096, 1024 left B 2.2 % off at
                                  // p99 and 4096 0.8 %
  SourceTreeSettings tree;
  // Empty: B at every surfel. Otherwise only at these surfels (indices into the validated
  // cloud); the others are NaN. Large scans are compared on a sample of their points.
  std::vector<std::size_t> receivers;
  Progress progress;  // optional
};

struct RadianceStats {
  std::size_t surfels = 0;
  std::size_t lit_cells = 0;       // surfels with light, summed over the lights
  double texel_mm = 0.0;           // light-map texel of the first light
  int map_width = 0, map_height = 0;
  std::size_t near_entries = 0;    // near-field weights, all receivers
  double near_reach_mm = 0.0;      // the near field's table holds the cells within it
  bool far_field = false;          // whether cells beyond it matter
  double seconds_geometry = 0, seconds_light = 0, seconds_tree = 0, seconds_surfels = 0;
};

// Per-surfel radiance before the outgoing Fresnel factor: Lo(x, wo) = Ft(eta, wo) * B(x).
struct SurfelRadiance {
  std::vector<Rgb> B;  // one per surfel of the validated cloud
  RadianceStats stats;
};

// Everything the reference needs for one cloud, material and set of lights: B at the surfels
// asked for.
class ReferenceSolver {
 public:
  // The cloud must have been validated (SurfelCloud::validate); throws std::invalid_argument
  // for a bad material, light or setting.
  ReferenceSolver(const SurfelCloud& cloud, const Material& material,
                  const std::vector<Light>& lights,
                  const ReferenceSettings& settings = {});

  // B (eq. 17) at the k-th receiver asked for (the k-th surfel when none were named).
  Rgb B(std::size_t k) const;
  // The near field alone at the k-th receiver.
  Rgb near_B(std::size_t k) const;
  // The lit cells alone, summed by the source tree over those farther than `beyond` mm, at a
  // point in scene units (the far field's sum, open to tests).
  Rgb sources_B_at(const Eigen::Vector3d& scene_point, double beyond = 0.0) const;

  const std::vector<std::size_t>& receivers() const { return receivers_; }
  const LocalSurfels& surfels() const { return surfels_; }
  const SurfelCells& cells() const { return cells_; }
  const LightMaps& light_maps() const { return maps_; }
  const SurfelIrradiance& irradiance() const { return E_; }
  const NearFarSplit& split() const { return split_; }
  const NearFieldWeights& near_weights() const { return weights_; }
  const SourceTree& tree() const;
  const RadianceStats& stats() const { return stats_; }

 private:
  LocalSurfels surfels_;
  std::unique_ptr<SurfelIndex> index_;
  SurfelCells cells_;
  LightMaps maps_;
  SurfelIrradiance E_;
  std::vector<Rgb> E_total_;
  NearFarSplit split_;
  Dipole dipole_;
  std::vector<std::size_t> receivers_;
  NearFieldWeights weights_;
  PointSources sources_;
  SourceTreeSettings tree_settings_;
  mutable std::once_flag tree_built_;
  mutable std::unique_ptr<SourceTree> tree_;
  RadianceStats stats_;
};

// The lit cells as sources of the far field: one per surfel and light with light, at the
// surfel's point, its normal turned towards that light, a disc of its cell's area.
PointSources cell_sources(const LocalSurfels& surfels, const std::vector<double>& area,
                          const LightMaps& light, const SurfelIrradiance& E);

SurfelRadiance render_reference(const SurfelCloud& cloud, const Material& material,
                                const std::vector<Light>& lights,
                                const ReferenceSettings& settings = {});

}  // namespace sss

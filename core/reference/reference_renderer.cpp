#include "reference_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "local_surface.h"
#include "parallel_points.h"
#include "stopwatch.h"
#include "surfel_cells.h"

namespace sss {

PointSources cell_sources(const LocalSurfels& surfels, const std::vector<double>& area,
                          const LightMaps& light, const SurfelIrradiance& E) {
  PointSources sources;
  for (std::size_t li = 0; li < light.size(); ++li) {
    for (std::size_t j = 0; j < surfels.size(); ++j) {
      const Rgb& e = E[li][j];
      if (!(e[0] > 0.0 || e[1] > 0.0 || e[2] > 0.0) || !(area[j] > 0.0)) continue;
      const Eigen::Vector3d l = light.lights[li].towards(surfels.positions[j]);
      const Eigen::Vector3d n = surfels.normals[j].dot(l) < 0.0 ? Eigen::Vector3d(-surfels.normals[j])
                                                                : surfels.normals[j];
      Eigen::Vector3d t1, t2;
      tangent_frame(n, t1, t2);
      const double side = std::sqrt(area[j] / 3.14159265358979323846);  // the cell as a disc
      sources.position.push_back(surfels.positions[j]);
      sources.normal.push_back(n);
      sources.power.push_back({e[0] * area[j], e[1] * area[j], e[2] * area[j]});
      sources.edge_u.push_back(side * t1);
      sources.edge_v.push_back(side * t2);
    }
  }
  return sources;
}

ReferenceSolver::ReferenceSolver(const SurfelCloud& cloud, const Material& material,
                                 const std::vector<Light>& lights,
                                 const ReferenceSettings& settings)
    : dipole_(material), tree_settings_(settings.tree) {
  for (std::size_t i : settings.receivers) {
    if (i >= cloud.size()) {
      std::ostringstream msg;
      msg << "[sss::ReferenceSolver] receiver " << i << " of a cloud of " << cloud.size()
          << " surfels";
      throw std::invalid_argument(msg.str());
    }
  }
  if (settings.irradiance_samples < 1)
    throw std::invalid_argument("[sss::ReferenceSolver] irradiance_samples must be >= 1");
  Stopwatch clock;
  surfels_ = LocalSurfels::from(cloud, material.mm_per_unit);
  index_ = std::make_unique<SurfelIndex>(surfels_.positions);
  cells_ = surfel_cells(surfels_, *index_);
  split_ = NearFarSplit::choose(dipole_, surfels_.cell_radius > 0.0 ? surfels_.cell_radius : 1.0,
                                settings.tree.kernel_tolerance);
  receivers_ = settings.receivers;
  if (receivers_.empty()) {
    receivers_.resize(cloud.size());
    for (std::size_t i = 0; i < receivers_.size(); ++i) receivers_[i] = i;
  }
  weights_ = near_field_weights(surfels_, cells_, *index_, dipole_, split_.reach, receivers_);
  stats_.seconds_geometry = clock.lap();
  maps_ = render_light_maps(surfels_, lights, settings.light_map);
  E_ = surfel_irradiance(surfels_, cells_.area, material, maps_, settings.irradiance_samples,
                         std::max(settings.irradiance_samples, settings.irradiance_refined));
  E_total_ = total_irradiance(E_, surfels_.size());
  sources_ = cell_sources(surfels_, cells_.area, maps_, E_);
  stats_.seconds_light = clock.lap();
  stats_.surfels = surfels_.size();
  stats_.lit_cells = sources_.size();
  if (!maps_.views.empty()) {
    stats_.texel_mm = maps_.views[0].texel_mm();
    stats_.map_width = maps_.views[0].width();
    stats_.map_height = maps_.views[0].height();
  }
  stats_.near_entries = weights_.source.size();
  stats_.near_reach_mm = split_.reach;
  stats_.far_field = split_.has_far;
  if (split_.has_far) {
    tree();
    stats_.seconds_tree = clock.lap();
  }
}

const SourceTree& ReferenceSolver::tree() const {
  std::call_once(tree_built_, [&] {
    tree_ = std::make_unique<SourceTree>(sources_, dipole_, tree_settings_);
  });
  return *tree_;
}

Rgb ReferenceSolver::near_B(std::size_t k) const { return weights_.B(k, E_total_); }

Rgb ReferenceSolver::B(std::size_t k) const {
  Rgb b = near_B(k);
  if (split_.has_far) {
    const Rgb far = tree().B(surfels_.positions[receivers_[k]], split_.reach);
    for (int c = 0; c < 3; ++c) b[c] += far[c];
  }
  return b;
}

Rgb ReferenceSolver::sources_B_at(const Eigen::Vector3d& scene_point, double beyond) const {
  return tree().B(surfels_.frame.to_mm(scene_point), beyond);
}

SurfelRadiance render_reference(const SurfelCloud& cloud, const Material& material,
                                const std::vector<Light>& lights,
                                const ReferenceSettings& settings) {
  const ReferenceSolver solver(cloud, material, lights, settings);
  SurfelRadiance result;
  result.stats = solver.stats();
  Stopwatch clock;
  std::vector<std::size_t> rows(solver.receivers().size());
  for (std::size_t k = 0; k < rows.size(); ++k) rows[k] = k;
  const std::vector<Rgb> values =
      evaluate_indices(rows, [&](std::size_t k) { return solver.B(k); }, settings.progress);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  result.B.assign(cloud.size(), Rgb{nan, nan, nan});
  for (std::size_t k = 0; k < rows.size(); ++k) result.B[solver.receivers()[k]] = values[k];
  result.stats.seconds_surfels = clock.lap();
  return result;
}

}  // namespace sss

#include "reference_renderer.h"

#include <limits>
#include <sstream>
#include <stdexcept>

#include "parallel_points.h"
#include "stopwatch.h"

namespace sss {

void RadianceStats::record_sources(const IlluminationSamples& samples, std::size_t surfel_count) {
  surfels = surfel_count;
  lit_samples = samples.size();
  if (!samples.maps.empty()) {
    texel_mm = samples.maps[0].pixel;
    map_width = samples.maps[0].width;
    map_height = samples.maps[0].height;
  }
}

ReferenceSolver::ReferenceSolver(const SurfelCloud& cloud, const Material& material,
                                 const std::vector<DirectionalLight>& lights,
                                 const ReferenceSettings& settings)
    : dipole_(material), tree_settings_(settings.tree) {
  Stopwatch clock;
  surfels_ = LocalSurfels::from(cloud, material.mm_per_unit);
  stats_.seconds_geometry = clock.lap();
  samples_ = illuminate(surfels_, material, lights, settings.illumination);
  stats_.seconds_illumination = clock.lap();
  const double texel = samples_.maps.empty() ? 0.0 : samples_.maps[0].pixel;
  const double r0 = settings.r0_mm > 0.0 ? settings.r0_mm
                                         : NearFarSplit::minimum_r0(surfels_.radius, texel);
  split_ = NearFarSplit::choose(dipole_, r0, settings.tree.kernel_tolerance);
  near_ = std::make_unique<NearField>(surfels_, material, samples_, split_.near, split_.reach,
                                      settings.near);
  stats_.record_sources(samples_, surfels_.size());
  stats_.near_nodes = static_cast<std::size_t>(near_->quadrature().node_count());
  stats_.split_r0_mm = split_.has_far ? split_.far.r0 : 0.0;
  stats_.split_r1_mm = split_.reach;
  if (split_.has_far) {
    tree();
    stats_.seconds_tree = clock.lap();
  }
}

const SourceTree& ReferenceSolver::tree() const {
  std::call_once(tree_built_, [&] {
    tree_ = std::make_unique<SourceTree>(samples_, dipole_, tree_settings_);
  });
  return *tree_;
}

Rgb ReferenceSolver::B(std::size_t index) const {
  Rgb b = near_->B(index);
  if (split_.has_far) {
    const Rgb far = tree().B(surfels_.positions[index], split_.far);
    for (int c = 0; c < 3; ++c) b[c] += far[c];
  }
  return b;
}

Rgb ReferenceSolver::sources_B_at(const Eigen::Vector3d& scene_point,
                                  const KernelWindow& window) const {
  return tree().B(surfels_.frame.to_mm(scene_point), window);
}

SurfelRadiance render_reference(const SurfelCloud& cloud, const Material& material,
                                const std::vector<DirectionalLight>& lights,
                                const ReferenceSettings& settings) {
  for (std::size_t i : settings.receivers) {
    if (i >= cloud.size()) {
      std::ostringstream msg;
      msg << "[sss::render_reference] receiver " << i << " of a cloud of " << cloud.size()
          << " surfels";
      throw std::invalid_argument(msg.str());
    }
  }
  const ReferenceSolver solver(cloud, material, lights, settings);
  SurfelRadiance result;
  result.stats = solver.stats();
  Stopwatch clock;
  std::vector<std::size_t> all;
  const std::vector<std::size_t>* receivers = &settings.receivers;
  if (receivers->empty()) {
    all.resize(cloud.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    receivers = &all;
  }
  const std::vector<Rgb> values =
      evaluate_indices(*receivers, [&](std::size_t i) { return solver.B(i); }, settings.progress);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  result.B.assign(cloud.size(), Rgb{nan, nan, nan});
  for (std::size_t k = 0; k < receivers->size(); ++k) result.B[(*receivers)[k]] = values[k];
  result.stats.seconds_surfels = clock.lap();
  return result;
}

}  // namespace sss

#include "grid_renderer.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "parallel_points.h"
#include "stopwatch.h"

namespace sss {

SurfelRadiance render_grid(const SurfelCloud& cloud, const Material& material,
                           const std::vector<DirectionalLight>& lights,
                           const GridSettings& settings) {
  if (!(settings.near_field_cells >= 0.0) || !std::isfinite(settings.near_field_cells)) {
    std::ostringstream msg;
    msg << "[sss::render_grid] near_field_cells = " << settings.near_field_cells
        << " must be finite and >= 0";
    throw std::invalid_argument(msg.str());
  }
  const ReferenceSolver solver(cloud, material, lights, settings.illumination, settings.tree);
  const LocalSurfels& surfels = solver.surfels();
  SurfelRadiance result;
  result.stats = solver.stats();
  Stopwatch clock;
  const VirtualGrid grid = VirtualGrid::build(surfels, Dipole(material), settings.grid);
  result.stats.virtual_points = grid.points().size();
  result.stats.grid_level = grid.level();
  result.stats.grid_spacing_mm = grid.spacing();

  const bool split = settings.near_field_cells > 0.0;
  const double r0 = settings.near_field_cells * grid.spacing();
  const KernelWindow far = split ? KernelWindow::far(r0, 2 * r0) : KernelWindow::all();
  const KernelWindow near = KernelWindow::near(r0, 2 * r0);
  const std::size_t total = grid.points().size() + (split ? surfels.size() : 0);
  auto report = [&](std::size_t offset) -> Progress {
    if (!settings.progress) return {};
    return [&, offset](std::size_t done, std::size_t) { settings.progress(offset + done, total); };
  };
  const std::vector<Rgb> virtual_B = evaluate_points(
      grid.points(), [&](const Eigen::Vector3d& x) { return solver.tree().B(x, far); },
      report(0));
  result.stats.seconds_virtual_points = clock.lap();

  result.B.assign(surfels.size(), Rgb{0.0, 0.0, 0.0});
  if (split) {
    result.B = evaluate_points(
        surfels.positions, [&](const Eigen::Vector3d& x) { return solver.tree().B(x, near); },
        report(grid.points().size()));
  }
  for (std::size_t i = 0; i < surfels.size(); ++i) {
    Rgb far_part;
    grid.interpolate(virtual_B, surfels.positions[i], far_part);
    for (int c = 0; c < 3; ++c) result.B[i][c] += far_part[c];
  }
  result.stats.seconds_surfels = clock.lap();
  return result;
}

}  // namespace sss

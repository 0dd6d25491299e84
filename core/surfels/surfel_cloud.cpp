#include "surfel_cloud.h"

#include "surfel_index.h"


#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sss {

void Bounds::extend(const Eigen::Vector3d& p) {
  if (empty) {
    min = max = p;
    empty = false;
    return;
  }
  min = min.cwiseMin(p);
  max = max.cwiseMax(p);
}

Eigen::Vector3d Bounds::frame_origin() const {
  const Eigen::Vector3d c = center();
  const double largest = extent().maxCoeff();
  if (empty || !(largest > 0.0) || !std::isfinite(largest)) return c;
  const int step_exponent = std::ilogb(largest) - 12;
  Eigen::Vector3d origin;
  for (int k = 0; k < 3; ++k)
    origin[k] = std::ldexp(std::round(std::ldexp(c[k], -step_exponent)), step_exponent);
  return origin;
}

std::string CloudReport::summary() const {
  std::ostringstream s;
  s << "kept " << kept << " of " << input << " points";
  if (dropped() > 0) {
    s << "; dropped " << nonfinite_position << " with non-finite position, " << nonfinite_normal
      << " with non-finite normal, " << zero_normal << " with zero normal";
  }
  if (renormalised > 0) s << "; renormalised " << renormalised << " normals";
  return s.str();
}

CloudReport SurfelCloud::validate() {
  if (normals.size() != positions.size()) {
    std::ostringstream msg;
    msg << "[sss::SurfelCloud::validate] " << normals.size() << " normals for "
        << positions.size() << " positions";
    throw std::invalid_argument(msg.str());
  }
  if (!albedo.empty() && albedo.size() != positions.size()) {
    std::ostringstream msg;
    msg << "[sss::SurfelCloud::validate] " << albedo.size() << " albedo values for "
        << positions.size() << " positions";
    throw std::invalid_argument(msg.str());
  }
  if (!radii.empty() && radii.size() != positions.size()) {
    std::ostringstream msg;
    msg << "[sss::SurfelCloud::validate] " << radii.size() << " radii for " << positions.size()
        << " positions";
    throw std::invalid_argument(msg.str());
  }
  for (std::size_t i = 0; i < radii.size(); ++i) {
    if (!std::isfinite(radii[i]) || radii[i] <= 0.0) {
      std::ostringstream msg;
      msg << "[sss::SurfelCloud::validate] radius " << radii[i] << " of point " << i
          << " must be finite and > 0";
      throw std::invalid_argument(msg.str());
    }
  }
  if (!positions.empty() && (!std::isfinite(radius) || radius <= 0.0)) {
    std::ostringstream msg;
    msg << "[sss::SurfelCloud::validate] radius = " << radius << " must be finite and > 0";
    throw std::invalid_argument(msg.str());
  }
  const bool had_index = input_index.size() == positions.size();
  CloudReport report;
  report.input = positions.size();
  std::size_t out = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!albedo.empty()) {
      for (double a : albedo[i]) {
        if (!(a >= 0.0 && a <= 1.0)) {
          std::ostringstream msg;
          msg << "[sss::SurfelCloud::validate] albedo " << a << " of point " << i
              << " must be in [0, 1]";
          throw std::invalid_argument(msg.str());
        }
      }
    }
    if (!positions[i].allFinite()) {
      ++report.nonfinite_position;
      continue;
    }
    if (!normals[i].allFinite()) {
      ++report.nonfinite_normal;
      continue;
    }
    const double length = normals[i].norm();
    if (!(length > 1e-12)) {
      ++report.zero_normal;
      continue;
    }
    if (std::fabs(length - 1.0) > 1e-9) ++report.renormalised;
    positions[out] = positions[i];
    normals[out] = normals[i] / length;
    if (!albedo.empty()) albedo[out] = albedo[i];
    if (!radii.empty()) radii[out] = radii[i];
    const std::size_t original = had_index ? input_index[i] : i;
    if (input_index.size() <= out) input_index.resize(out + 1);
    input_index[out] = original;
    ++out;
  }
  positions.resize(out);
  normals.resize(out);
  if (!albedo.empty()) albedo.resize(out);
  if (!radii.empty()) radii.resize(out);
  input_index.resize(out);
  report.kept = out;
  return report;
}

Bounds SurfelCloud::bounds() const {
  Bounds b;
  for (const auto& p : positions) b.extend(p);
  return b;
}

double SurfelCloud::mean_spacing() const {
  if (positions.size() < 2) return 0.0;
  return sss::mean_spacing(positions, SurfelIndex(positions));
}

}  // namespace sss

#include "near_far_split.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sss {

NearFarSplit NearFarSplit::choose(const Dipole& dipole, double disc_radius, double kernel_tolerance) {
  if (!std::isfinite(disc_radius) || !(disc_radius > 0.0)) {
    std::ostringstream msg;
    msg << "[sss::NearFarSplit] disc radius = " << disc_radius << " mm must be finite and > 0";
    throw std::invalid_argument(msg.str());
  }
  NearFarSplit split;
  split.reach = 2.0 * disc_radius;
  split.has_far = dipole.max_support_radius(kernel_tolerance) > split.reach - disc_radius;
  return split;
}

}  // namespace sss

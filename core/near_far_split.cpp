#include "near_far_split.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sss {

NearFarSplit NearFarSplit::choose(const Dipole& dipole, double min_r0, double kernel_tolerance) {
  if (!std::isfinite(min_r0) || !(min_r0 > 0.0)) {
    std::ostringstream msg;
    msg << "[sss::NearFarSplit] r0 = " << min_r0 << " mm must be finite and > 0";
    throw std::invalid_argument(msg.str());
  }
  NearFarSplit split;
  const double support = dipole.max_support_radius(kernel_tolerance);
  if (support <= 2.0 * min_r0) {
    split.near = KernelWindow::all();
    split.reach = support > 0.0 ? support : min_r0;
    split.has_far = false;
    return split;
  }
  split.near = KernelWindow::near(min_r0, 2.0 * min_r0);
  split.far = KernelWindow::far(min_r0, 2.0 * min_r0);
  split.reach = 2.0 * min_r0;
  split.has_far = true;
  return split;
}

double NearFarSplit::minimum_r0(double disc_radius) { return disc_radius; }

}  // namespace sss

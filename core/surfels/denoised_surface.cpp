#include "denoised_surface.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "local_surface.h"
#include "surfel_index.h"

namespace sss {

void DenoiseSettings::check() const {
  if (noise_neighbours < 8)
    throw std::invalid_argument("denoising: noise_neighbours must be at least 8, not " +
                                std::to_string(noise_neighbours));
  if (max_neighbours < noise_neighbours || max_neighbours > 1024)
    throw std::invalid_argument("denoising: max_neighbours must be from noise_neighbours to "
                                "1024, not " + std::to_string(max_neighbours));
  if (!(normal_tolerance > 0.0 && normal_tolerance <= 0.5))
    throw std::invalid_argument("denoising: the normal tolerance must be in (0, 0.5] radians, "
                                "not " + std::to_string(normal_tolerance));
}

std::string DenoiseReport::summary() const {
  char text[256];
  std::snprintf(text, sizeof text,
                "noise %.3g (p90 %.3g) at spacing %.3g, fits of %d points (largest %d), "
                "largest shift %.3g, %zu beside a crease, %zu fitted in their neighbours' frame",
                median_noise, p90_noise, median_spacing, median_neighbours, largest_neighbours,
                largest_shift, beside_crease, in_neighbours_frame);
  return text;
}

namespace {

// Tukey's biweight constant: tau = 4.685 sigma keeps 95 % of a least-squares fit's efficiency
// under Gaussian noise (3 sigma measured the noise 20 % low).
constexpr double kTukey = 4.685;
// A quadric is fitted only where the variance of its slope at the point (from the plane's
// inliers' spread) stays below this many times a plane's. Beyond, its terms across follow what
// the neighbours do not constrain: on a floor seen at grazing incidence, whose rows lie far apart
// and whose range noise moves each row's points along the scanner's cone, the quadric takes the
// cone and tilts by the grazing angle. Fits beside a box's edge reach tens (10 there bent them);
// 1000 leaves the Kinect scenes' fits all but unchanged.
constexpr double kQuadricSlopeVariance = 1000.0;

// The quadric's slope stands where its squared difference from the plane's exceeds this many
// times that difference's variance summed over both axes (where the axes vary alike, a
// chi-squared of 2 degrees beyond 12: by chance at e^-6, 0.25 % of a plane's points).
constexpr double kSlopeTest = 6.0;

struct PatchFit {
  Eigen::Vector3d position, normal;
  double noise = 0.0;  // RMS of the last fit's residuals over its k - 6 degrees of freedom
};

double median_of(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

Eigen::Vector3d plane_normal(const std::vector<Eigen::Vector3d>& positions,
                             const std::vector<std::size_t>& near) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t j : near) mean += positions[j];
  mean /= static_cast<double>(near.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (std::size_t j : near) scatter += (positions[j] - mean) * (positions[j] - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  return solver.eigenvectors().col(0);
}

// The fit of the header around p = positions[i] in the frame of `first_normal`, over the
// `keep` candidates nearest to p along its tangent plane, heights within `height_noise`
// counted as on it; `noise_floor` is tau's floor.
PatchFit fit_once(const std::vector<Eigen::Vector3d>& positions, std::size_t i,
                  const std::vector<std::size_t>& candidates, std::size_t keep,
                  const Eigen::Vector3d& first_normal, double noise_floor, double height_noise) {
  const Eigen::Vector3d& p = positions[i];
  const Eigen::Vector3d n = first_normal.normalized();
  Eigen::Vector3d t1, t2;
  tangent_frame(n, t1, t2);
  std::vector<std::pair<double, std::size_t>> by_tangent;
  by_tangent.reserve(candidates.size());
  for (std::size_t j : candidates) {
    const Eigen::Vector3d d = positions[j] - p;
    const double off = std::max(0.0, std::fabs(d.dot(n)) - height_noise);
    by_tangent.emplace_back(d.squaredNorm() - d.dot(n) * d.dot(n) + off * off, j);
  }
  const std::size_t m = std::min(keep, by_tangent.size());
  std::partial_sort(by_tangent.begin(), by_tangent.begin() + static_cast<long>(m),
                    by_tangent.end());
  const double reach = std::sqrt(std::max(0.0, by_tangent[m - 1].first));
  PatchFit fit{p, n, 0.0};
  if (!(reach > 0.0)) return fit;
  // Offsets over the reach, so that the normal equations are well scaled.
  std::vector<Eigen::Matrix<double, 6, 1>> basis(m);
  std::vector<double> residual(m), height(m), weight(m);
  for (std::size_t k = 0; k < m; ++k) {
    const Eigen::Vector3d d = (positions[by_tangent[k].second] - p) / reach;
    const double x = d.dot(t1), y = d.dot(t2);
    basis[k] << 1.0, x, y, x * x, x * y, y * y;
    height[k] = residual[k] = d.dot(n);
  }
  // Neighbours along a line (or at one place) span no plane: no normal.
  Eigen::Matrix2d spread = Eigen::Matrix2d::Zero();
  for (std::size_t k = 0; k < m; ++k)
    spread += basis[k].segment<2>(1) * basis[k].segment<2>(1).transpose();
  const Eigen::Vector2d extent =
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(spread).eigenvalues();
  if (!(extent[0] > 1e-4 * extent[1])) {
    fit.normal.setZero();
    return fit;
  }
  int quadric_terms = m >= 12 ? 6 : 3;
  Eigen::Matrix<double, 6, 1> coefficients = Eigen::Matrix<double, 6, 1>::Zero();
  // Least squares of the first `terms` coefficients with the weights; false when singular.
  // A plane (3 terms) builds only its 3 x 3 normal equations.
  const auto solve = [&](int terms) {
    coefficients.setZero();
    if (terms == 6) {
      Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
      Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
      for (std::size_t k = 0; k < m; ++k) {
        if (weight[k] <= 0.0) continue;
        normal_matrix.noalias() += weight[k] * basis[k] * basis[k].transpose();
        rhs.noalias() += weight[k] * height[k] * basis[k];
      }
      const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(normal_matrix);
      if (solver.info() != Eigen::Success) return false;
      coefficients = solver.solve(rhs);
    } else {
      Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
      Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
      for (std::size_t k = 0; k < m; ++k) {
        if (weight[k] <= 0.0) continue;
        const auto plane_basis = basis[k].head<3>();
        normal_matrix.noalias() += weight[k] * plane_basis * plane_basis.transpose();
        rhs.noalias() += weight[k] * height[k] * plane_basis;
      }
      const Eigen::LDLT<Eigen::Matrix3d> solver(normal_matrix);
      if (solver.info() != Eigen::Success) return false;
      coefficients.head<3>() = solver.solve(rhs);
    }
    if (!coefficients.allFinite()) return false;
    for (std::size_t k = 0; k < m; ++k) residual[k] = height[k] - basis[k].dot(coefficients);
    return true;
  };
  thread_local std::vector<double> magnitude;
  const auto robust_noise = [&](bool only_weighted) {
    magnitude.clear();
    for (std::size_t k = 0; k < m; ++k)
      if (!only_weighted || weight[k] > 0.0) magnitude.push_back(std::fabs(residual[k]));
    if (magnitude.empty()) return 0.0;
    const auto middle = magnitude.begin() + static_cast<long>(magnitude.size() / 2);
    std::nth_element(magnitude.begin(), middle, magnitude.end());
    return 1.4826 * *middle;
  };
  // Weights from the residuals: the biweight, or (hard) 1 inside tau and 0 beyond.
  const auto weigh = [&](double tau, bool hard) {
    std::size_t kept = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const double u = residual[k] / tau;
      weight[k] = std::fabs(u) >= 1.0 ? 0.0 : hard ? 1.0 : (1.0 - u * u) * (1.0 - u * u);
      kept += weight[k] > 0.0;
    }
    return kept;
  };
  // Under the current weights: the variances of the plane's and the quadric's slope at p over
  // sigma^2 (the slope entries of each (A^T W A)^-1, summed over both axes), and the plane's
  // slope (NaN where its normal equations are singular).
  struct SlopeSpread {
    double plane = 0.0, quadric = 0.0;
    Eigen::Vector2d plane_slope;
  };
  const auto slope_spread = [&]() {
    Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t k = 0; k < m; ++k) {
      if (weight[k] <= 0.0) continue;
      normal_matrix.noalias() += weight[k] * basis[k] * basis[k].transpose();
      rhs.noalias() += weight[k] * height[k] * basis[k];
    }
    const Eigen::Matrix3d plane_matrix = normal_matrix.topLeftCorner<3, 3>();
    const Eigen::Matrix3d plane_inverse = plane_matrix.inverse();
    const Eigen::Matrix<double, 6, 6> quadric_inverse = normal_matrix.inverse();
    const Eigen::LDLT<Eigen::Matrix3d> plane_solver(plane_matrix);
    SlopeSpread spread;
    spread.plane = plane_inverse(1, 1) + plane_inverse(2, 2);
    spread.quadric = quadric_inverse(1, 1) + quadric_inverse(2, 2);
    spread.plane_slope = plane_solver.info() == Eigen::Success
                           ? Eigen::Vector2d(plane_solver.solve(rhs.head<3>()).segment<2>(1))
                           : Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
    return spread;
  };
  // Whether the quadric's slope at p, weighted as the last plane was, varies at most
  // kQuadricSlopeVariance times as much as the plane's.
  const auto quadric_slope_holds = [&]() {
    const SlopeSpread spread = slope_spread();
    return std::isfinite(spread.quadric) && spread.quadric > 0.0 &&
           spread.quadric <= kQuadricSlopeVariance * spread.plane;
  };
  // The slope at p: the quadric's, or the plane's over the same neighbours where the two differ
  // by less than the noise of their difference (a Hausman test: the plane's slope varies less,
  // and the quadric's extrapolates where the neighbours lie on one side of p, at a scan's edge).
  // Both are unbiased on a plane, so Var(quadric - plane) = Var(quadric) - Var(plane), each
  // sigma^2 (`variance`) times its slope spread.
  const auto take_plane_slope_within_noise = [&](double variance) {
    const SlopeSpread spread = slope_spread();
    const double difference_variance = variance * (spread.quadric - spread.plane);
    if (difference_variance > 0.0 && spread.plane_slope.allFinite() &&
        (coefficients.segment<2>(1) - spread.plane_slope).squaredNorm() <
          kSlopeTest * difference_variance)
      coefficients.segment<2>(1) = spread.plane_slope;
  };
  // Planes with tau halved each round pick p's own face; quadrics then follow its curvature;
  // the last fit weighs every point within tau alike, so that the residuals measure the noise.
  double tau = std::max({0.5, kTukey * robust_noise(false), noise_floor / reach});
  constexpr int kPlaneRounds = 4, kQuadricRounds = 3;
  for (int round = 0; round < kPlaneRounds + kQuadricRounds; ++round) {
    const bool plane = round < kPlaneRounds;
    if (round == kPlaneRounds && quadric_terms == 6 && !quadric_slope_holds()) quadric_terms = 3;
    if (weigh(tau, false) < 5u || !solve(plane ? 3 : quadric_terms)) break;
    tau = std::max({plane ? 0.5 * tau : 0.0, kTukey * robust_noise(true), noise_floor / reach,
                    1e-9});
  }
  const std::size_t kept = weigh(tau, true);
  if (kept >= static_cast<std::size_t>(quadric_terms) + 2 && solve(quadric_terms)) {
    double sum2 = 0.0;
    for (std::size_t k = 0; k < m; ++k) sum2 += weight[k] * residual[k] * residual[k];
    const double variance = sum2 / static_cast<double>(kept - quadric_terms);
    fit.noise = reach * std::sqrt(variance);
    if (quadric_terms == 6) take_plane_slope_within_noise(variance);
  }
  const Eigen::Vector3d normal = n - coefficients[1] * t1 - coefficients[2] * t2;
  // A point over twice the floor (9.4 sigma; twice tau on the first fit, which does not know
  // the noise yet) off the fitted surface is not on it (a flying pixel, a corner the quadric
  // rounds off): it stays where it is, with its first normal.
  const double allowed = 2.0 * (noise_floor > 0.0 ? noise_floor / reach : tau);
  if (!normal.allFinite() || !(normal.norm() > 0.0) || !(std::fabs(coefficients[0]) <= allowed))
    return fit;
  fit.position = p + coefficients[0] * reach * n;
  fit.normal = normal.normalized();
  return fit;
}

// fit_once, then once more in the frame of the normal it found when that turned by over 5
// degrees (the tangential choice of neighbours follows the frame).
PatchFit fit_patch(const std::vector<Eigen::Vector3d>& positions, std::size_t i,
                   const std::vector<std::size_t>& candidates, std::size_t keep,
                   const Eigen::Vector3d& first_normal, double noise_floor, double height_noise) {
  const PatchFit fit =
    fit_once(positions, i, candidates, keep, first_normal, noise_floor, height_noise);
  if (fit.normal.isZero() ||
      std::fabs(fit.normal.dot(first_normal.normalized())) > std::cos(5.0 * M_PI / 180.0))
    return fit;
  return fit_once(positions, i, candidates, keep, fit.normal, noise_floor, height_noise);
}

// The crease pass: heights within max(tau, this many nearest-point distances) of a candidate
// plane count as on it (a clean scan measures no noise).
constexpr double kCreaseHeightFloor = 0.25;
// A neighbour whose normal turns more than this from a plane is on another face.
constexpr double kCreaseAngle = 30.0 * M_PI / 180.0;
// The plane of a neighbour's normal is taken when its neighbours' biweight support beats that of
// the point's own normal by this factor.
constexpr double kCreaseMargin = 1.2;
// The candidates: the fitted normals of at most this many neighbours spread over the
// neighbourhood, less those within kCandidateAngle of one already scored (they score alike).
constexpr int kCreaseCandidates = 32;
constexpr double kCandidateAngle = 5.0 * M_PI / 180.0;

// Whether unit normals a and b (either sign) turn less than kCreaseAngle from each other.
bool same_face(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::fabs(a.dot(b)) > std::cos(kCreaseAngle);
}

// Whether normals[j] turns more than kCreaseAngle from normals[i] (a zero normal turns not).
bool turned(const std::vector<Eigen::Vector3d>& normals, std::size_t i, std::size_t j) {
  return !normals[i].isZero() && !normals[j].isZero() && !same_face(normals[i], normals[j]);
}

// The unit normal of the plane that p = positions[i] lies on beside a crease, among the fitted
// surfaces (fitted_positions, normals) of up to kCreaseCandidates of `near` and i's own: each
// scored by how many of `near` a plane through p with its normal holds (within tau, by Tukey's
// biweight, counting only those whose normal turns less than kCreaseAngle from it, each weighted
// by exp(-d^2 / scale2) of its distance d, so that p's own face counts most) times the biweight
// of p's height over that surface. i's own normal unless another's score beats it by
// kCreaseMargin.
Eigen::Vector3d crease_plane(const std::vector<Eigen::Vector3d>& positions,
                             const std::vector<Eigen::Vector3d>& fitted_positions,
                             const std::vector<Eigen::Vector3d>& normals, std::size_t i,
                             const std::vector<std::size_t>& near, double tau, double scale2) {
  const auto biweight = [&](double height) {
    const double u = height / tau;
    return std::fabs(u) < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
  };
  thread_local std::vector<double> closeness;
  closeness.clear();
  for (std::size_t j : near)
    closeness.push_back(std::exp(-(positions[j] - positions[i]).squaredNorm() / scale2));
  const auto score = [&](std::size_t from) {
    const Eigen::Vector3d& c = normals[from];
    double sum = 0.0;
    for (std::size_t k = 0; k < near.size(); ++k) {
      const std::size_t j = near[k];
      if (same_face(normals[j], c))
        sum += biweight((positions[j] - positions[i]).dot(c)) * closeness[k];
    }
    return sum * biweight((positions[i] - fitted_positions[from]).dot(c));
  };
  const double own = score(i);
  double best = own;
  std::size_t chosen = i;
  thread_local std::vector<Eigen::Vector3d> scored;
  scored.assign(1, normals[i]);
  const std::size_t stride = std::max<std::size_t>(1, near.size() / kCreaseCandidates);
  for (std::size_t k = 0; k < near.size(); k += stride) {
    const Eigen::Vector3d& c = normals[near[k]];
    if (c.isZero() || std::any_of(scored.begin(), scored.end(), [&](const Eigen::Vector3d& s) {
          return std::fabs(s.dot(c)) > std::cos(kCandidateAngle);
        }))
      continue;
    scored.push_back(c);
    const double candidate = score(near[k]);
    if (candidate > best) {
      best = candidate;
      chosen = near[k];
    }
  }
  return best > kCreaseMargin * own ? normals[chosen] : normals[i];
}

// A first normal (k0 nearest, where noise of one spacing makes the neighbourhood about as thick as
// it is wide) that under this share of its neighbours' first normals lie within kCreaseAngle of
// is not trusted as the frame of the second fit.
constexpr double kSharedShare = 0.25;

// The direction most of the first normals of `near` (less i) share, the principal axis of
// Sum n_j n_j^T (the majority face beside a crease, not an average of two faces), when under
// kSharedShare of them lie within kCreaseAngle of i's own; else zero. A first fit can be wrong by
// 90 degrees, and a fit in that frame does not undo it, as it chooses its neighbours along the
// wrong plane.
Eigen::Vector3d unshared_first_normal_alternative(const std::vector<Eigen::Vector3d>& first_normals,
                                                  std::size_t i,
                                                  const std::vector<std::size_t>& near) {
  std::size_t sharing = 0, counted = 0;
  Eigen::Matrix3d structure = Eigen::Matrix3d::Zero();
  for (std::size_t j : near) {
    if (j == i || first_normals[j].isZero()) continue;
    ++counted;
    sharing += same_face(first_normals[i], first_normals[j]);
    structure += first_normals[j] * first_normals[j].transpose();
  }
  if (counted == 0 || static_cast<double>(sharing) >= kSharedShare * static_cast<double>(counted))
    return Eigen::Vector3d::Zero();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(structure).eigenvectors().col(2);
}

// body(i) for every point, in chunks so that progress is reported from this thread; `offset`
// and `total` place this pass in the whole.
template <typename Body>
void for_each_point(long n, const Body& body, const Progress& progress, std::size_t offset,
                    std::size_t total) {
  constexpr long kChunk = 8192;
  for (long start = 0; start < n; start += kChunk) {
    const long end = std::min(n, start + kChunk);
#pragma omp parallel for schedule(dynamic, 64)
    for (long i = start; i < end; ++i) body(static_cast<std::size_t>(i));
    if (progress) progress(offset + static_cast<std::size_t>(end), total);
  }
}

}  // namespace

DenoisedSurface denoise_surface(const std::vector<Eigen::Vector3d>& positions,
                                const DenoiseSettings& settings, DenoiseReport* report,
                                const Progress& progress) {
  settings.check();
  const std::size_t n = positions.size();
  DenoisedSurface out;
  out.positions = positions;
  out.normals.assign(n, Eigen::Vector3d::Zero());
  out.noise.assign(n, 0.0f);
  out.neighbours.assign(n, 0);
  if (report) *report = DenoiseReport{};
  const int k0 = settings.noise_neighbours;
  if (!settings.enabled || n <= static_cast<std::size_t>(k0)) return out;

  const SurfelIndex index(positions);
  std::vector<double> raw_noise(n, 0.0), density(n, 0.0), nearest(n, 0.0);
  std::vector<Eigen::Vector3d> first_normal(n);
  // First fit: the noise, the density and a normal from the k0 nearest.
  for_each_point(static_cast<long>(n), [&](std::size_t i) {
    std::vector<std::size_t> near;
    index.nearest(positions[i], 2 * k0 + 1, near);
    const double farthest = (positions[near[std::min<std::size_t>(k0, near.size() - 1)]] -
                             positions[i]).norm();
    density[i] = farthest > 0.0 ? k0 / (M_PI * farthest * farthest) : 0.0;
    for (std::size_t j : near)
      if (j != i && (positions[j] - positions[i]).squaredNorm() > 0.0) {
        nearest[i] = (positions[j] - positions[i]).norm();
        break;
      }
    const std::vector<std::size_t> nearest_few(near.begin(),
                                               near.begin() + std::min<long>(12, near.size()));
    const PatchFit fit = fit_patch(positions, i, near, static_cast<std::size_t>(k0) + 1,
                                   plane_normal(positions, nearest_few), 0.0,
                                   std::numeric_limits<double>::infinity());
    raw_noise[i] = fit.noise;
    first_normal[i] = fit.normal;
  }, progress, 0, 3 * n);

  // Second fit: the noise as the median over the same neighbours, k from it.
  std::vector<char> may_be_beside_crease(n, 0), in_neighbours_frame(n, 0);
  for_each_point(static_cast<long>(n), [&](std::size_t i) {
    std::vector<std::size_t> near;
    index.nearest(positions[i], k0 + 1, near);
    std::vector<double> around;
    around.reserve(near.size());
    for (std::size_t j : near) around.push_back(raw_noise[j]);
    const double noise = median_of(around);
    const double wanted =
      2.5 * noise * std::sqrt(M_PI * density[i]) / settings.normal_tolerance;
    const int k = static_cast<int>(std::clamp(std::ceil(wanted), static_cast<double>(k0),
                                              static_cast<double>(settings.max_neighbours)));
    out.noise[i] = static_cast<float>(noise);
    out.neighbours[i] = k;
    if (first_normal[i].isZero()) return;
    const Eigen::Vector3d alternative = unshared_first_normal_alternative(first_normal, i, near);
    index.nearest(positions[i], 2 * k + 1, near);
    const auto fit_in = [&](const Eigen::Vector3d& frame) {
      return fit_patch(positions, i, near, static_cast<std::size_t>(k) + 1, frame,
                       kTukey * noise, kTukey * noise);
    };
    PatchFit fit = fit_in(first_normal[i]);
    if (!alternative.isZero()) {  // the frame whose fit leaves the smaller residuals
      const PatchFit other = fit_in(alternative);
      if (!other.normal.isZero() && (fit.normal.isZero() || other.noise < fit.noise)) {
        fit = other;
        in_neighbours_frame[i] = 1;
      }
    }
    out.positions[i] = fit.position;
    out.normals[i] = fit.normal;
    may_be_beside_crease[i] = std::any_of(near.begin(), near.end(), [&](std::size_t j) {
      return turned(first_normal, i, j);
    });
  }, progress, n, 3 * n);

  // Third pass, over the points some of whose neighbours' first normals turn by over
  // kCreaseAngle from theirs, in two rounds (the second over those the first found beside a
  // crease by the fitted normals, now with their neighbours' corrected ones): a point beside a
  // crease is fitted again over the neighbours on its own face, those whose normal turns less
  // than kCreaseAngle from the plane that the most of them lie on (crease_plane; its own normal
  // unless another is clearly better supported).
  std::vector<char> beside_crease(n, 0);
  std::vector<std::size_t> points;
  for (std::size_t i = 0; i < n; ++i)
    if (may_be_beside_crease[i]) points.push_back(i);
  for (int round = 0; round < 2; ++round) {
    const std::vector<Eigen::Vector3d> fitted_normals = out.normals;
    const std::vector<Eigen::Vector3d> fitted_positions = out.positions;
    for_each_point(static_cast<long>(points.size()), [&](std::size_t k) {
      const std::size_t i = points[k];
      if (fitted_normals[i].isZero()) return;
      std::vector<std::size_t> near;
      index.nearest(positions[i], 2 * out.neighbours[i] + 1, near);
      if (std::none_of(near.begin(), near.end(),
                       [&](std::size_t j) { return turned(fitted_normals, i, j); }))
        return;  // no crease within reach
      beside_crease[i] = 1;
      const double tau = std::max(kTukey * static_cast<double>(out.noise[i]),
                                  kCreaseHeightFloor * nearest[i]);
      const Eigen::Vector3d plane = crease_plane(positions, fitted_positions, fitted_normals, i,
                                                 near, tau, k0 / (M_PI * density[i]));
      std::vector<std::size_t> on_face;
      for (std::size_t j : near)
        if (same_face(fitted_normals[j], plane)) on_face.push_back(j);
      if (on_face.size() == near.size() || on_face.size() < static_cast<std::size_t>(k0 / 2))
        return;
      const PatchFit fit = fit_patch(positions, i, on_face,
                                     static_cast<std::size_t>(out.neighbours[i]) + 1, plane,
                                     kTukey * out.noise[i], kTukey * out.noise[i]);
      if (fit.normal.isZero()) return;
      out.positions[i] = fit.position;
      out.normals[i] = fit.normal;
    }, round == 0 ? progress : Progress{}, 2 * n, 3 * n);
    points.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (beside_crease[i]) points.push_back(i);
  }
  if (progress) progress(3 * n, 3 * n);
  if (report) {
    report->points = n;
    report->beside_crease = points.size();
    report->in_neighbours_frame = static_cast<std::size_t>(
        std::count(in_neighbours_frame.begin(), in_neighbours_frame.end(), 1));
    std::vector<double> noise(out.noise.begin(), out.noise.end());
    std::sort(noise.begin(), noise.end());
    report->median_noise = noise[n / 2];
    report->p90_noise = noise[static_cast<std::size_t>(0.9 * static_cast<double>(n - 1))];
    report->median_spacing = median_of(nearest);
    std::vector<int> counts = out.neighbours;
    std::nth_element(counts.begin(), counts.begin() + static_cast<long>(n / 2), counts.end());
    report->median_neighbours = counts[n / 2];
    report->largest_neighbours = *std::max_element(counts.begin(), counts.end());
    for (std::size_t i = 0; i < n; ++i)
      report->largest_shift =
        std::max(report->largest_shift, (out.positions[i] - positions[i]).norm());
  }
  return out;
}

}  // namespace sss

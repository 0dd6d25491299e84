// The denoised surface (core/surfels/denoised_surface.h) on cases with known answers: a plane, a
// sphere and a box's edge sampled at random with Gaussian depth noise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <random>

#include "denoised_surface.h"

namespace sss {
namespace {

constexpr double kDegree = M_PI / 180.0;

// Points at random on the square [-side/2, side/2]^2 at one per spacing^2, heights noisy.
std::vector<Eigen::Vector3d> noisy_plane(double side, double spacing, double noise,
                                         unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> across(-0.5 * side, 0.5 * side);
  std::normal_distribution<double> depth(0.0, noise);
  std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(side * side / (spacing * spacing)));
  for (Eigen::Vector3d& p : points) p = Eigen::Vector3d(across(random), across(random), depth(random));
  return points;
}

struct PlaneResult {
  double height_rms = 0.0, mean_tilt = 0.0, p99_tilt = 0.0, noise = 0.0;
};

// Over the points more than `margin` inside the square's edge.
PlaneResult on_the_plane(const DenoisedSurface& s, double side, double margin) {
  PlaneResult r;
  std::vector<double> tilts;
  double noise = 0.0;
  for (std::size_t i = 0; i < s.positions.size(); ++i) {
    if (s.positions[i].head<2>().cwiseAbs().maxCoeff() > 0.5 * side - margin) continue;
    r.height_rms += s.positions[i].z() * s.positions[i].z();
    tilts.push_back(std::acos(std::min(1.0, std::fabs(s.normals[i].z()))));
    noise += s.noise[i];
  }
  const double count = static_cast<double>(tilts.size());
  r.height_rms = std::sqrt(r.height_rms / count);
  for (double t : tilts) r.mean_tilt += t / count;
  std::sort(tilts.begin(), tilts.end());
  r.p99_tilt = tilts[static_cast<std::size_t>(0.99 * (count - 1))];
  r.noise = noise / count;
  return r;
}

// Noise from none to one spacing: the measured noise is the depth noise (within 15 %); the
// points come back onto the plane, RMS height under half the noise (a quadric's value at the
// centre of k points at random in a disc varies by about 4.5 sigma^2 / k: 0.43 sigma at the
// smallest fit, k = 24); mean tilt under 2 degrees, p99 under 6 (the fit is sized for a
// plane's 1.15 degrees; the quadric's slope varies more), where the noise left 5-14 degrees.
TEST(DenoisedSurface, NoisyPlaneComesBackFlat) {
  constexpr double kSide = 200.0, kSpacing = 3.4;
  for (double fraction : {0.0, 0.1, 0.3, 1.0}) {
    const double noise = fraction * kSpacing;
    const auto points = noisy_plane(kSide, kSpacing, noise, 3);
    DenoiseReport report;
    const DenoisedSurface s = denoise_surface(points, {}, &report);
    const PlaneResult r = on_the_plane(s, kSide, 20.0 * kSpacing);
    std::printf("[ denoised plane ] noise %.2f spacings: measured %.3f mm of %.3f, height RMS "
                "%.3f mm, tilt mean %.2f p99 %.2f degrees; %s\n",
                fraction, r.noise, noise, r.height_rms, r.mean_tilt / kDegree,
                r.p99_tilt / kDegree, report.summary().c_str());
    EXPECT_NEAR(r.noise, noise, 0.15 * noise + 1e-9);
    EXPECT_LE(r.height_rms, 0.5 * noise + 1e-9);
    EXPECT_LT(r.mean_tilt, 2.0 * kDegree);
    EXPECT_LT(r.p99_tilt, 6.0 * kDegree);
  }
}

// A sphere of radius 100 sampled at random, radial noise of 0.3 spacings: the points come back
// to the sphere (RMS radius error under half the noise, as on the plane) with their radial
// normals (mean tilt under 2 degrees): the quadric follows the curvature.
TEST(DenoisedSurface, NoisySphereKeepsItsRadius) {
  constexpr double kRadius = 100.0, kSpacing = 3.4, kNoise = 0.3 * kSpacing;
  std::mt19937 random(5);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const auto count = static_cast<std::size_t>(4.0 * M_PI * kRadius * kRadius / (kSpacing * kSpacing));
  std::vector<Eigen::Vector3d> points(count);
  for (Eigen::Vector3d& p : points) {
    const Eigen::Vector3d u = Eigen::Vector3d(gauss(random), gauss(random), gauss(random)).normalized();
    p = (kRadius + kNoise * gauss(random)) * u;
  }
  const DenoisedSurface s = denoise_surface(points, {});
  double radius_rms = 0.0, tilt = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double off = s.positions[i].norm() - kRadius;
    radius_rms += off * off / count;
    tilt += std::acos(std::min(1.0, std::fabs(s.normals[i].dot(s.positions[i].normalized())))) / count;
  }
  radius_rms = std::sqrt(radius_rms);
  std::printf("[ denoised sphere ] noise %.2f mm: radius RMS %.3f mm, mean tilt %.2f degrees\n",
              kNoise, radius_rms, tilt / kDegree);
  EXPECT_LT(radius_rms, 0.5 * kNoise);
  EXPECT_LT(tilt, 2.0 * kDegree);
}

// With noise of one spacing a first fit's 24 points are about as thick as they are wide, and one
// in a few thousand comes out about 90 degrees wrong. On a plane 2 m across, points at random
// 10 mm apart with noise of 10 mm, no normal beyond one fit's reach (100 mm) from the edge tilts
// by over 8 degrees, five times the mean (the second fit in the wrong frame alone left 3 there,
// up to 15 degrees).
TEST(DenoisedSurface, NoFirstFitTurnedOverCarriesIntoTheSurface) {
  constexpr double kSide = 2000.0, kSpacing = 10.0, kMargin = 100.0;
  const DenoisedSurface s = denoise_surface(noisy_plane(kSide, kSpacing, kSpacing, 17), {});
  std::size_t tilted = 0, inside = 0;
  double largest = 0.0;
  for (std::size_t i = 0; i < s.positions.size(); ++i) {
    if (s.positions[i].head<2>().cwiseAbs().maxCoeff() > 0.5 * kSide - kMargin) continue;
    const double tilt = std::acos(std::min(1.0, std::fabs(s.normals[i].z())));
    tilted += tilt > 8.0 * kDegree;
    largest = std::max(largest, tilt);
    ++inside;
  }
  std::printf("[ turned-over first fits ] %zu of %zu normals tilted over 8 degrees, largest %.1f\n",
              tilted, inside, largest / kDegree);
  EXPECT_EQ(tilted, 0u);
}

// A scan's open edge: the neighbours of a point there lie on one side of it, where a quadric's
// slope extrapolates (it varies several times more than at the centre of its points) and a
// plane's does not; a plane fitted over a half disc varies about 1.5 times as much as over a
// whole one. On a plane 1 m across, points at random 10 mm apart: within one spacing of the
// edge, mean tilt under 1.5 times the interior's bar (3 degrees) and under 2 % of the normals
// over 8 degrees, at noise up to 0.3 spacings: 1.2 and 1.8 degrees, under 1 % (with the
// quadric's slope alone 3.1 and 4.9 degrees, 3.6 % and 17 %). Not met at noise of one spacing
// (printed): 3.3 degrees, 7 % over 8 (7.2 degrees, 34 % with the quadric's slope alone).
TEST(DenoisedSurface, ScanEdgeKeepsItsNormals) {
  constexpr double kSide = 1000.0, kSpacing = 10.0;
  for (double fraction : {0.1, 0.3, 1.0}) {
    const auto points = noisy_plane(kSide, kSpacing, fraction * kSpacing, 23);
    const DenoisedSurface s = denoise_surface(points, {});
    for (double band : {1.0, 2.0}) {
      std::vector<double> tilts;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const double from_edge = 0.5 * kSide - points[i].head<2>().cwiseAbs().maxCoeff();
        if (from_edge < (band - 1.0) * kSpacing || from_edge >= band * kSpacing) continue;
        tilts.push_back(std::acos(std::min(1.0, std::fabs(s.normals[i].z()))));
      }
      double mean = 0.0;
      std::size_t over = 0;
      for (double t : tilts) {
        mean += t / static_cast<double>(tilts.size());
        over += t > 8.0 * kDegree;
      }
      const double share = static_cast<double>(over) / static_cast<double>(tilts.size());
      std::printf("[ scan edge ] noise %.1f spacings, %.0f-%.0f spacings from the edge: tilt "
                  "mean %.2f degrees, %zu of %zu over 8\n",
                  fraction, band - 1.0, band, mean / kDegree, over, tilts.size());
      if (fraction > 0.5) continue;
      EXPECT_LT(mean, 3.0 * kDegree);
      EXPECT_LT(share, 0.02);
    }
  }
}

// A box's 90 degree edge along y: the face z = 0 over x < 0 and the face x = 0 below it, each
// sampled at random at one point per spacing^2 with depth noise along its own normal. Returns
// the tilt of each point's normal from its face's, binned by the distance from the edge in
// spacings ([0, 1), [1, 2), [2, 3), ...), as mean and largest.
struct CreaseTilts {
  std::vector<double> mean, largest, p99;
};

CreaseTilts crease_tilts(double spacing, double noise, bool concave, unsigned seed) {
  constexpr double kSide = 120.0;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> along(-0.5 * kSide, 0.5 * kSide), off(0.0, kSide);
  std::normal_distribution<double> depth(0.0, noise > 0.0 ? noise : 1.0);
  const auto per_face = static_cast<std::size_t>(kSide * kSide / (spacing * spacing));
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> face_normal;
  for (int face = 0; face < 2; ++face)
    for (std::size_t k = 0; k < per_face; ++k) {
      const double h = noise > 0.0 ? depth(random) : 0.0;
      const double u = off(random), y = along(random);
      points.push_back(face == 0 ? Eigen::Vector3d(-u, y, h)
                                 : Eigen::Vector3d(h, y, concave ? u : -u));
      face_normal.push_back(face == 0 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX());
    }
  const DenoisedSurface s = denoise_surface(points, {});
  constexpr int kBins = 6;
  std::vector<std::vector<double>> tilts(kBins);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points[i];
    // Away from the box's other edges (a quarter of the side), by the distance along the face.
    const double from_edge = std::max(-p.x(), concave ? p.z() : -p.z());
    if (std::fabs(p.y()) > 0.25 * kSide || from_edge > 0.75 * kSide) continue;
    const int bin = static_cast<int>(from_edge / spacing);
    if (bin >= kBins) continue;
    tilts[bin].push_back(std::acos(std::min(1.0, std::fabs(s.normals[i].dot(face_normal[i])))));
  }
  CreaseTilts r;
  for (auto& t : tilts) {
    std::sort(t.begin(), t.end());
    double mean = 0.0;
    for (double v : t) mean += v / static_cast<double>(t.size());
    r.mean.push_back(mean);
    r.largest.push_back(t.back());
    r.p99.push_back(t[static_cast<std::size_t>(0.99 * static_cast<double>(t.size() - 1))]);
  }
  return r;
}

// Real features stay: on both faces of a box's 90 degree edge, convex and concave, the normals
// of the points farther than one spacing from it stay within a few degrees of their face's
// (mean under 3 degrees, p99 under 6: the plane's p99, its mean raised by a quarter for the
// fits' neighbours that the edge cuts off) at noise up to 0.3 spacings. At noise of one spacing
// the fits reach 8 spacings and a point within the noise band (4.685 sigma, 5 spacings) lies
// within the noise of both faces' planes: some there take the other face's normal, and beyond it
// the normals lean by up to 4 degrees on average; no point beyond the band turns by 10 degrees.
TEST(DenoisedSurface, BoxEdgeKeepsBothFacesNormals) {
  constexpr double kSpacing = 3.4;
  for (unsigned seed : {7u, 9u})
    for (bool concave : {false, true})
      for (double fraction : {0.0, 0.1, 0.3, 1.0}) {
        const CreaseTilts r = crease_tilts(kSpacing, fraction * kSpacing, concave, seed);
        const bool noisiest = fraction == 1.0;
        for (std::size_t bin = 0; bin < r.mean.size(); ++bin) {
          std::printf("[ box edge ] seed %u, %s, noise %.1f spacings, %zu-%zu spacings from the "
                      "edge: tilt mean %.2f p99 %.2f largest %.2f degrees\n", seed,
                      concave ? "concave" : "convex", fraction, bin, bin + 1,
                      r.mean[bin] / kDegree, r.p99[bin] / kDegree, r.largest[bin] / kDegree);
          if (bin < (noisiest ? 5u : 1u)) continue;
          if (noisiest) {
            EXPECT_LT(r.largest[bin], 10.0 * kDegree) << seed << " " << concave << " " << bin;
            continue;
          }
          EXPECT_LT(r.mean[bin], 3.0 * kDegree) << seed << " " << concave << " " << fraction;
          EXPECT_LT(r.p99[bin], 6.0 * kDegree) << seed << " " << concave << " " << fraction;
        }
      }
}

// A floor a terrestrial scanner 1.5 m above it sees at grazing incidence: its rings 5-20 m out
// (elevation steps of 5 mrad, so a ring's points lie 10 times closer than the rings there), with
// 3 mm range noise. Range noise moves each point along its ray, so a ring's noisy points lie on
// the scanner's cone through it, tilted from the floor by the grazing angle: only the rows beside
// it tell the floor. The normals between 7 and 18 m stay within a degree of the floor's (the
// quadric took the cone: 5-6.4 degrees between 13 and 17 m, up to 7).
TEST(DenoisedSurface, FloorScannedAtGrazingIncidenceStaysFlat) {
  constexpr double kHeight = 1500.0, kStep = 0.005, kNoise = 3.0;
  std::mt19937 random(3);
  std::normal_distribution<double> range_noise(0.0, kNoise);
  std::vector<Eigen::Vector3d> points;
  const Eigen::Vector3d station(0.0, 0.0, kHeight);
  for (double elevation = std::atan(kHeight / 20000.0); elevation < std::atan(kHeight / 5000.0);
       elevation += kStep)
    for (double azimuth = -M_PI / 6; azimuth < M_PI / 6; azimuth += kStep) {
      const Eigen::Vector3d ray(std::cos(elevation) * std::cos(azimuth),
                                std::cos(elevation) * std::sin(azimuth), -std::sin(elevation));
      points.push_back(station + (kHeight / std::sin(elevation) + range_noise(random)) * ray);
    }
  const DenoisedSurface s = denoise_surface(points, {});
  std::vector<double> tilts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double along = points[i].head<2>().norm();
    if (along < 7000.0 || along > 18000.0 ||
        std::fabs(std::atan2(points[i].y(), points[i].x())) > M_PI / 6 - 0.1)
      continue;
    tilts.push_back(std::acos(std::min(1.0, std::fabs(s.normals[i].z()))));
  }
  ASSERT_GT(tilts.size(), 1000u);
  double mean = 0.0;
  for (double t : tilts) mean += t / static_cast<double>(tilts.size());
  const double largest = *std::max_element(tilts.begin(), tilts.end());
  std::printf("[ grazing floor ] %zu points 7-18 m out: tilt mean %.3f, largest %.3f degrees\n",
              tilts.size(), mean / kDegree, largest / kDegree);
  EXPECT_LT(largest, 1.0 * kDegree);
}

TEST(DenoisedSurface, DisabledOrTooFewPointsLeavesThePoints) {
  const auto points = noisy_plane(20.0, 2.0, 0.5, 1);
  DenoiseSettings off;
  off.enabled = false;
  EXPECT_EQ(denoise_surface(points, off).positions, points);
  const std::vector<Eigen::Vector3d> few(points.begin(), points.begin() + 10);
  EXPECT_EQ(denoise_surface(few, {}).positions, few);
  DenoiseSettings bad;
  bad.normal_tolerance = 0.0;
  EXPECT_THROW(denoise_surface(points, bad), std::invalid_argument);
}

}  // namespace
}  // namespace sss

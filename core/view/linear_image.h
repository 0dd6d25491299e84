// An RGB image of linear radiance with a coverage mask; row 0 is the bottom row.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "error_metric.h"
#include "material.h"

namespace sss {

struct LinearImage {
  int width = 0, height = 0;
  std::vector<Rgb> radiance;          // background 0
  std::vector<std::uint8_t> covered;  // 1 where a surfel was seen

  LinearImage() = default;
  LinearImage(int w, int h)
      : width(w), height(h), radiance(static_cast<std::size_t>(w) * h, Rgb{0, 0, 0}),
        covered(static_cast<std::size_t>(w) * h, 0) {}
  Rgb& at(int i, int j) { return radiance[static_cast<std::size_t>(j) * width + i]; }
  const Rgb& at(int i, int j) const { return radiance[static_cast<std::size_t>(j) * width + i]; }
  double max_value() const;
};

// Portable float map (RGB, little-endian, bottom row first). Written to a temporary file that
// is renamed into place, so the file is whole or absent. Throws std::runtime_error on failure.
void write_pfm(const LinearImage& image, const std::string& path);
LinearImage read_pfm(const std::string& path);

// 8-bit sRGB, top row first (for PNG writers), white = `white` (<= 0: the image maximum).
std::vector<std::uint8_t> to_srgb8_top_down(const LinearImage& image, double white = 0.0);

// The metric over pixels covered in both images; throws std::invalid_argument for sizes
// that differ.
ErrorStats compare_images(const LinearImage& test, const LinearImage& reference);

}  // namespace sss

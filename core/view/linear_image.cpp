#include "linear_image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "tone_map.h"
#include "whole_file.h"

namespace sss {

double LinearImage::max_value() const {
  double m = 0.0;
  for (std::size_t k = 0; k < radiance.size(); ++k)
    if (covered[k])
      for (double v : radiance[k])
        if (std::isfinite(v)) m = std::max(m, v);
  return m;
}

void write_pfm(const LinearImage& image, const std::string& path) {
  write_whole_file(path, [&](std::ostream& out) {
    out << "PF\n" << image.width << ' ' << image.height << "\n-1.0\n";
    std::vector<float> row(3 * static_cast<std::size_t>(image.width));
    for (int j = 0; j < image.height; ++j) {
      for (int i = 0; i < image.width; ++i)
        for (int c = 0; c < 3; ++c) row[3 * i + c] = static_cast<float>(image.at(i, j)[c]);
      out.write(reinterpret_cast<const char*>(row.data()),
                static_cast<std::streamsize>(row.size() * sizeof(float)));
    }
  });
}

LinearImage read_pfm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int width = 0, height = 0;
  double scale = 0.0;
  if (!(in >> magic >> width >> height >> scale) || magic != "PF" || width <= 0 || height <= 0 ||
      scale >= 0.0)
    throw std::runtime_error("[sss::read_pfm] " + path + " is not a little-endian RGB PFM");
  in.get();
  LinearImage image(width, height);
  std::vector<float> row(3 * static_cast<std::size_t>(width));
  for (int j = 0; j < height; ++j) {
    if (!in.read(reinterpret_cast<char*>(row.data()),
                 static_cast<std::streamsize>(row.size() * sizeof(float))))
      throw std::runtime_error("[sss::read_pfm] " + path + " is truncated");
    for (int i = 0; i < width; ++i) {
      for (int c = 0; c < 3; ++c) image.at(i, j)[c] = row[3 * i + c];
      image.covered[static_cast<std::size_t>(j) * width + i] =
          row[3 * i] > 0 || row[3 * i + 1] > 0 || row[3 * i + 2] > 0;
    }
  }
  return image;
}

std::vector<std::uint8_t> to_srgb8_top_down(const LinearImage& image, double white) {
  if (!(white > 0.0)) white = image.max_value();
  std::vector<std::uint8_t> rgb(3 * static_cast<std::size_t>(image.width) * image.height);
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i)
      for (int c = 0; c < 3; ++c)
        rgb[3 * (static_cast<std::size_t>(image.height - 1 - j) * image.width + i) + c] =
            to_srgb8(image.at(i, j)[c], white);
  return rgb;
}

ErrorStats compare_images(const LinearImage& test, const LinearImage& reference) {
  if (test.width != reference.width || test.height != reference.height) {
    std::ostringstream msg;
    msg << "[sss::compare_images] sizes differ: " << test.width << "x" << test.height << " and "
        << reference.width << "x" << reference.height;
    throw std::invalid_argument(msg.str());
  }
  std::vector<std::uint8_t> both(test.covered.size());
  for (std::size_t k = 0; k < both.size(); ++k) both[k] = test.covered[k] && reference.covered[k];
  return compare_radiance(test.radiance, reference.radiance, both);
}

}  // namespace sss

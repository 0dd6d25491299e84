// PNG output through VTK's writer, whole or not at all.
#pragma once

#include <string>

#include "linear_image.h"

namespace sss::cli {

// Tone-mapped sRGB (white = the image's largest value). Throws std::runtime_error on failure.
void write_png(const LinearImage& image, const std::string& path);

}  // namespace sss::cli

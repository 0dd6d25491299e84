// PNG output through VTK's writer, whole or not at all.
#pragma once

#include <string>

class vtkImageData;

namespace sss::cli {

// Writes 8-bit RGB(A) image data. Throws std::runtime_error on failure.
void write_png(vtkImageData* pixels, const std::string& path);

}  // namespace sss::cli

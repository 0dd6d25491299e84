#include "png_output.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace sss::cli {

void write_png(const LinearImage& image, const std::string& path) {
  const std::vector<std::uint8_t> top_down = to_srgb8_top_down(image);
  vtkNew<vtkImageData> pixels;
  pixels->SetDimensions(image.width, image.height, 1);
  pixels->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(pixels->GetScalarPointer());
  const std::size_t row = 3 * static_cast<std::size_t>(image.width);
  for (int j = 0; j < image.height; ++j)  // VTK's row 0 is the bottom row
    std::memcpy(out + j * row, top_down.data() + (image.height - 1 - j) * row, row);
  const std::string partial = path + ".partial";
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(partial.c_str());
  writer->SetInputData(pixels);
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::ifstream(partial).good() ||
      std::rename(partial.c_str(), path.c_str()) != 0) {
    std::remove(partial.c_str());
    throw std::runtime_error("cannot write " + path);
  }
}

}  // namespace sss::cli

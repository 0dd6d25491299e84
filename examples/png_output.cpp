#include "png_output.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace sss::cli {

void write_png(vtkImageData* pixels, const std::string& path) {
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

#include "png_output.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>

#include "whole_file.h"

namespace sss::cli {

void write_png(vtkImageData* pixels, const std::string& path) {
  write_whole_file_named(path, [&](const std::string& temporary) {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(temporary.c_str());
    writer->SetInputData(pixels);
    writer->Write();
    return writer->GetErrorCode() == 0;
  });
}

}  // namespace sss::cli

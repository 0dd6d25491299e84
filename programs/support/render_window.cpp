#include "render_window.h"

#include "cli_options.h"

#include <vtkEGLSurfacelessRenderWindow.h>
#include <vtkOSMesaRenderWindow.h>
#include <vtkRenderWindow.h>

#include <cstdlib>
#include <stdexcept>

namespace sss::cli {

void prepare_backend(const std::string& backend, int argc, char** argv) {
  if (backend != "osmesa") return;
  std::string why;
  if (!vtkOSMesaRenderWindow::EnsureProcessIsOSMesaReady(argc, argv, why))
    throw std::runtime_error("--backend osmesa: " + why);
}

vtkSmartPointer<vtkRenderWindow> make_render_window(const std::string& backend, int width,
                                                   int height, int gpu) {
  if (backend == "egl") {
    auto window = vtkSmartPointer<vtkEGLSurfacelessRenderWindow>::New();
    if (gpu >= 0) window->SetDeviceIndex(gpu);
    if (gpu == kSurfacelessPlatform) window->UseDevicePlatformOff();
    window->SetSize(width, height);
    if (!window->IsContextValid())
      throw std::runtime_error("--backend egl: " + window->GetLastError());
    return window;
  }
  if (gpu != -1) throw std::runtime_error("--gpu: only --backend egl chooses a device");
  if (backend == "osmesa") {
    auto window = vtkSmartPointer<vtkOSMesaRenderWindow>::New();
    window->SetSize(width, height);
    if (!window->IsContextValid())
      throw std::runtime_error("--backend osmesa: " + window->GetLastError());
    return window;
  }
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
    throw std::runtime_error("--backend x: DISPLAY is not set; use --backend egl or osmesa");
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  return window;
}

}  // namespace sss::cli

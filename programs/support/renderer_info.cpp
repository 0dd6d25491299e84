#include "renderer_info.h"

#include <vtkEGLSurfacelessRenderWindow.h>
#include <vtkOSMesaRenderWindow.h>
#include <vtkRenderWindow.h>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace sss::cli {

namespace {
// The value of the line "OpenGL <what> string:  value" of VTK's capability report.
std::string reported(const std::string& report, const std::string& what) {
  std::istringstream lines(report);
  const std::string key = "OpenGL " + what + " string:";
  for (std::string line; std::getline(lines, line);) {
    if (line.compare(0, key.size(), key) != 0) continue;
    const std::size_t start = line.find_first_not_of(' ', key.size());
    return start == std::string::npos ? "(unknown)" : line.substr(start);
  }
  return "(unknown)";
}

bool names_a_cpu_rasteriser(std::string renderer) {
  std::transform(renderer.begin(), renderer.end(), renderer.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "software rasterizer"})
    if (renderer.find(name) != std::string::npos) return true;
  return false;
}
}  // namespace

std::string RendererInfo::summary() const {
  return gl_renderer + ", OpenGL " + gl_version + ", " + gl_vendor + "; " + context;
}

std::string RendererInfo::warning() const {
  if (!hardware_idle) return "";
  return "warning: a software renderer (" + gl_renderer +
         ") draws although a hardware EGL device is listed; choose the card with --gpu N "
         "(SSS_EGL_DEVICE=N for scripts)";
}

RendererInfo renderer_info(vtkRenderWindow* window) {
  RendererInfo info;
  const char* text = window->ReportCapabilities();
  const std::string report = text ? text : "";
  info.gl_vendor = reported(report, "vendor");
  info.gl_renderer = reported(report, "renderer");
  info.gl_version = reported(report, "version");
  info.software = names_a_cpu_rasteriser(info.gl_renderer);
  if (auto* egl = vtkEGLSurfacelessRenderWindow::SafeDownCast(window)) {
    info.context = egl->GetDisplayDescription();
    info.hardware_idle = info.software && egl->GetDevicesFound().find("hardware") != std::string::npos;
  } else if (vtkOSMesaRenderWindow::SafeDownCast(window)) {
    info.context = "OSMesa";
  } else {
    info.context = "X (GLX)";
  }
  return info;
}

}  // namespace sss::cli

// Which OpenGL implementation draws a window: GL_VENDOR, GL_RENDERER, GL_VERSION and how the
// context was made (the EGL device or platform, OSMesa, or X), for the programs' outputs, and
// whether a software renderer draws while a graphics card was there to use.
#pragma once

#include <string>

class vtkRenderWindow;

namespace sss::cli {

struct RendererInfo {
  std::string gl_vendor, gl_renderer, gl_version;
  std::string context;        // "EGL device 0 of 1 (software)", "OSMesa", "X (GLX)"
  bool software = false;      // a CPU rasteriser (llvmpipe, softpipe, swrast)
  bool hardware_idle = false;  // software draws although an EGL hardware device is listed

  // "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6, Mesa; EGL device 0 of 1
  // (software)".
  std::string summary() const;
  // A warning for stderr when hardware_idle, else "".
  std::string warning() const;
};

// The window's context must exist (after make_render_window or a first Render).
RendererInfo renderer_info(vtkRenderWindow* window);

}  // namespace sss::cli

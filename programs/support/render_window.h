// The OpenGL context sss_render draws in: OSMesa, EGL surfaceless or an X window.
#pragma once

#include <vtkSmartPointer.h>

#include <string>

class vtkRenderWindow;

namespace sss::cli {

// For "osmesa", call before anything else in main: the process may re-execute itself with
// libOSMesa loaded first (see vtkOSMesaRenderWindow). Throws std::runtime_error.
void prepare_backend(const std::string& backend, int argc, char** argv);

// An offscreen window of the given size whose context is valid; for "egl", on EGL device
// `gpu` (-1: the first hardware device, else the software one; vtkEGLSurfacelessRenderWindow;
// or cli_options.h's kSurfacelessPlatform).
// Throws std::runtime_error naming the backend and why it failed (no DISPLAY for x, no usable
// EGL device, ...).
vtkSmartPointer<vtkRenderWindow> make_render_window(const std::string& backend, int width,
                                                   int height, int gpu = -1);

}  // namespace sss::cli

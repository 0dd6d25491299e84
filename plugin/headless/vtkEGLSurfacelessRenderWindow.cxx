#include "vtkEGLSurfacelessRenderWindow.h"

#include "vtkHeadlessGLInternals.h"
#include "vtkObjectFactory.h"
#include "vtk_glew.h"

// Keep X11 headers (and their macros such as None/Bool/Status) out.
#ifndef EGL_NO_X11
#define EGL_NO_X11
#endif
#ifndef MESA_EGL_NO_X11_HEADERS
#define MESA_EGL_NO_X11_HEADERS
#endif
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <mutex>
#include <sstream>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

namespace
{
bool HasToken(const char* list, const char* name)
{
  if (!list || !name)
  {
    return false;
  }
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
  {
    const bool startOk = (p == list) || p[-1] == ' ';
    const bool endOk = p[n] == '\0' || p[n] == ' ';
    if (startOk && endOk)
    {
      return true;
    }
  }
  return false;
}

const char* EGLErrorString(EGLint err)
{
  switch (err)
  {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown EGL error";
  }
}

std::string EGLErrorText()
{
  std::ostringstream s;
  const EGLint e = eglGetError();
  s << EGLErrorString(e) << " (0x" << std::hex << e << ")";
  return s.str();
}

// All windows share one initialized EGLDisplay per platform; EGL has no
// reference counting on eglInitialize/eglTerminate, so count users here and
// terminate when the last window releases its context.
std::mutex DisplayMutex;
int DisplayUsers = 0;

void ReleaseDisplay(EGLDisplay dpy)
{
  std::lock_guard<std::mutex> lock(DisplayMutex);
  if (DisplayUsers > 0 && --DisplayUsers == 0)
  {
    eglTerminate(dpy);
  }
}
}

vtkStandardNewMacro(vtkEGLSurfacelessRenderWindow);

//------------------------------------------------------------------------------
vtkEGLSurfacelessRenderWindow::vtkEGLSurfacelessRenderWindow()
  : Display(nullptr)
  , SurfacelessPlatform(false)
{
  this->SetWindowName("vtkEGLSurfacelessRenderWindow");
}

//------------------------------------------------------------------------------
vtkEGLSurfacelessRenderWindow::~vtkEGLSurfacelessRenderWindow()
{
  // Release our GL objects and the context while the hooks still exist.
  this->Finalize();
}

//------------------------------------------------------------------------------
bool vtkEGLSurfacelessRenderWindow::CreateContext()
{
  const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!clientExt)
  {
    eglGetError(); // EGL < 1.5 without EGL_EXT_client_extensions: not an error
  }

  EGLDisplay dpy = EGL_NO_DISPLAY;
  EGLint eglMajor = 0, eglMinor = 0;
  this->SurfacelessPlatform = false;
  std::string displayErrors;

  if (HasToken(clientExt, "EGL_MESA_platform_surfaceless"))
  {
    dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (dpy == EGL_NO_DISPLAY && HasToken(clientExt, "EGL_EXT_platform_base"))
    {
      auto getPlatformDisplayEXT = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
      if (getPlatformDisplayEXT)
      {
        dpy = getPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      }
    }
    if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &eglMajor, &eglMinor))
    {
      this->SurfacelessPlatform = true;
    }
    else
    {
      displayErrors += "surfaceless platform display: " + EGLErrorText() + "; ";
      dpy = EGL_NO_DISPLAY;
    }
  }
  else
  {
    displayErrors += "EGL_MESA_platform_surfaceless not offered by libEGL; ";
  }

  if (dpy == EGL_NO_DISPLAY)
  {
    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &eglMajor, &eglMinor))
    {
      displayErrors += "default display: " + EGLErrorText();
      this->Fail("No EGL display could be initialized (" + displayErrors + ").");
      return false;
    }
  }

  {
    std::lock_guard<std::mutex> lock(DisplayMutex);
    ++DisplayUsers;
  }
  this->Display = dpy;

  auto failAndRelease = [&](const std::string& why) {
    ReleaseDisplay(dpy);
    this->Display = nullptr;
    this->Fail(why);
    return false;
  };

  const char* dpyExt = eglQueryString(dpy, EGL_EXTENSIONS);
  if (!HasToken(dpyExt, "EGL_KHR_surfaceless_context"))
  {
    return failAndRelease("EGL display lacks EGL_KHR_surfaceless_context.");
  }
  if (!eglBindAPI(EGL_OPENGL_API))
  {
    return failAndRelease("eglBindAPI(EGL_OPENGL_API) failed: " + EGLErrorText() +
      " (the EGL driver offers no desktop OpenGL).");
  }

  // A config only matters for window surfaces; we never create one. Accept
  // any OpenGL-renderable config, or none at all with EGL_KHR_no_config_context.
  EGLConfig config = nullptr;
  {
    const EGLint attribs[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
      EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_NONE };
    EGLint n = 0;
    if (!eglChooseConfig(dpy, attribs, &config, 1, &n) || n < 1)
    {
      config = nullptr;
      if (!HasToken(dpyExt, "EGL_KHR_no_config_context"))
      {
        return failAndRelease("No EGL config with EGL_OPENGL_BIT: " + EGLErrorText());
      }
    }
  }

  const int versions[][2] = { { 4, 5 }, { 3, 3 }, { 3, 2 } };
  EGLContext ctx = EGL_NO_CONTEXT;
  std::string ctxErrors;
  for (const auto& v : versions)
  {
    const EGLint attribs[] = { EGL_CONTEXT_MAJOR_VERSION, v[0], EGL_CONTEXT_MINOR_VERSION, v[1],
      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    ctx = eglCreateContext(dpy, config ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (ctx != EGL_NO_CONTEXT)
    {
      break;
    }
    ctxErrors += std::to_string(v[0]) + "." + std::to_string(v[1]) + ": " + EGLErrorText() + "; ";
  }
  if (ctx == EGL_NO_CONTEXT)
  {
    return failAndRelease("eglCreateContext failed for OpenGL core 4.5/3.3/3.2 (" + ctxErrors + ").");
  }

  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx))
  {
    const std::string err = EGLErrorText();
    eglDestroyContext(dpy, ctx);
    return failAndRelease("eglMakeCurrent(EGL_NO_SURFACE) failed: " + err);
  }

  vtkHeadlessGL::CurrentOwner() = this;

  // Make sure the process' GL symbols reach this context (they would not if
  // they were bound to a non-Mesa OSMesa/GL implementation).
  const GLubyte* version = glGetString(GL_VERSION);
  if (!version)
  {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    vtkHeadlessGL::CurrentOwner() = nullptr;
    eglDestroyContext(dpy, ctx);
    return failAndRelease("EGL context is current but glGetString(GL_VERSION) returned NULL: "
                          "the process' GL entry points are bound to another implementation.");
  }
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 32)
  {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    vtkHeadlessGL::CurrentOwner() = nullptr;
    eglDestroyContext(dpy, ctx);
    return failAndRelease(std::string("EGL context reports OpenGL ") +
      reinterpret_cast<const char*>(version) + ", VTK needs 3.2 or later.");
  }
  GLint dims[2] = { 0, 0 };
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
  this->ScreenSize[0] = dims[0];
  this->ScreenSize[1] = dims[1];

  this->Context = ctx;
  this->ContextMajor = major;
  this->ContextMinor = minor;
  return true;
}

//------------------------------------------------------------------------------
void vtkEGLSurfacelessRenderWindow::DestroyContext()
{
  EGLDisplay dpy = static_cast<EGLDisplay>(this->Display);
  eglDestroyContext(dpy, static_cast<EGLContext>(this->Context));
  ReleaseDisplay(dpy);
  this->Display = nullptr;
}

//------------------------------------------------------------------------------
bool vtkEGLSurfacelessRenderWindow::MakeContextCurrent()
{
  if (eglQueryAPI() != EGL_OPENGL_API)
  {
    eglBindAPI(EGL_OPENGL_API);
  }
  EGLDisplay dpy = static_cast<EGLDisplay>(this->Display);
  EGLContext ctx = static_cast<EGLContext>(this->Context);
  if (eglGetCurrentContext() == ctx)
  {
    if (vtkHeadlessGL::CurrentOwner() == this)
    {
      return true;
    }
    // EGL still reports our context while another context (e.g. OSMesa in
    // the same thread) took over Mesa's GL dispatch: bind again for real.
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx))
  {
    this->Fail("eglMakeCurrent failed: " + EGLErrorText() +
      " (is the context current in another thread?)");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkEGLSurfacelessRenderWindow::ReleaseContext()
{
  eglMakeCurrent(
    static_cast<EGLDisplay>(this->Display), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

//------------------------------------------------------------------------------
bool vtkEGLSurfacelessRenderWindow::IsContextCurrent()
{
  if (eglQueryAPI() != EGL_OPENGL_API)
  {
    eglBindAPI(EGL_OPENGL_API);
  }
  return eglGetCurrentContext() == static_cast<EGLContext>(this->Context);
}

//------------------------------------------------------------------------------
bool vtkEGLSurfacelessRenderWindow::ReportContext(std::ostream& s)
{
  EGLDisplay dpy = static_cast<EGLDisplay>(this->Display);
  s << "EGL platform:  "
    << (this->SurfacelessPlatform ? "surfaceless (EGL_PLATFORM_SURFACELESS_MESA)"
                                  : "eglGetDisplay(EGL_DEFAULT_DISPLAY)")
    << "\n";
  s << "EGL version:  " << eglQueryString(dpy, EGL_VERSION) << "\n";
  s << "EGL vendor:  " << eglQueryString(dpy, EGL_VENDOR) << "\n";
  s << "OpenGL context:  core profile " << this->ContextMajor << "." << this->ContextMinor
    << ", no default framebuffer\n";
  return true;
}

//------------------------------------------------------------------------------
void* vtkEGLSurfacelessRenderWindow::GetGenericDisplayId()
{
  return this->Display;
}

//------------------------------------------------------------------------------
void vtkEGLSurfacelessRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SurfacelessPlatform: " << this->SurfacelessPlatform << "\n";
  os << indent << "Display: " << this->Display << "\n";
}

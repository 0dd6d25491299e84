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

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

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

// One EGL device as eglQueryDevicesEXT lists it (EGL_EXT_device_enumeration).
struct DeviceInfo
{
  EGLDeviceEXT device = nullptr;
  bool software = false;  // Mesa marks its CPU renderer with EGL_MESA_device_software
  std::string file;       // the DRM node (EGL_EXT_device_drm), empty for none
  std::string name;       // vendor and renderer (EGL_EXT_device_query_name), when offered
};

std::vector<DeviceInfo> QueryDevices(const char* clientExt)
{
  std::vector<DeviceInfo> found;
  if (!HasToken(clientExt, "EGL_EXT_device_enumeration") &&
    !HasToken(clientExt, "EGL_EXT_device_base"))
  {
    return found;
  }
  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto queryString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
    eglGetProcAddress("eglQueryDeviceStringEXT"));
  EGLint count = 0;
  if (!queryDevices || !queryString || !queryDevices(0, nullptr, &count) || count <= 0)
  {
    eglGetError();
    return found;
  }
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (!queryDevices(count, devices.data(), &count))
  {
    eglGetError();
    return found;
  }
  devices.resize(static_cast<std::size_t>(std::max<EGLint>(count, 0)));
  for (EGLDeviceEXT device : devices)
  {
    DeviceInfo info;
    info.device = device;
    const char* ext = queryString(device, EGL_EXTENSIONS);
    info.software = HasToken(ext, "EGL_MESA_device_software");
    if (HasToken(ext, "EGL_EXT_device_drm"))
    {
      const char* file = queryString(device, EGL_DRM_DEVICE_FILE_EXT);
      info.file = file ? file : "";
    }
    if (HasToken(ext, "EGL_EXT_device_query_name"))
    {
      const char* vendor = queryString(device, EGL_VENDOR);
      const char* renderer = queryString(device, EGL_RENDERER_EXT);
      info.name = std::string(vendor ? vendor : "") + (vendor && renderer ? " " : "") +
        (renderer ? renderer : "");
    }
    eglGetError();  // a string a device does not offer is not an error here
    found.push_back(info);
  }
  return found;
}

std::string DescribeDevice(const std::vector<DeviceInfo>& devices, std::size_t i)
{
  const DeviceInfo& d = devices[i];
  std::string text = "EGL device " + std::to_string(i) + " of " + std::to_string(devices.size()) +
    " (" + (d.software ? "software" : "hardware");
  if (!d.file.empty())
  {
    text += ", " + d.file;
  }
  if (!d.name.empty())
  {
    text += ", " + d.name;
  }
  return text + ")";
}

std::string DescribeDevices(const std::vector<DeviceInfo>& devices)
{
  if (devices.empty())
  {
    return "no EGL device is listed (libEGL offers no EGL_EXT_device_enumeration, or no driver "
           "has a device)";
  }
  std::string text;
  for (std::size_t i = 0; i < devices.size(); ++i)
  {
    text += (i ? "; " : "") + DescribeDevice(devices, i);
  }
  return text;
}

// The device a DeviceIndex of -1 or `requested` asks for: `requested` when >= 0, else the
// first hardware device, else the first device. -1 when there is none.
int ChooseDevice(const std::vector<DeviceInfo>& devices, int requested)
{
  if (requested >= 0)
  {
    return requested < static_cast<int>(devices.size()) ? requested : -1;
  }
  for (std::size_t i = 0; i < devices.size(); ++i)
  {
    if (!devices[i].software)
    {
      return static_cast<int>(i);
    }
  }
  return devices.empty() ? -1 : 0;
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
  if (const char* device = std::getenv("SSS_EGL_DEVICE"))
  {
    char* end = nullptr;
    if (std::strcmp(device, "surfaceless") == 0)
    {
      this->UseDevicePlatform = false;
      return;
    }
    const long index = std::strtol(device, &end, 10);
    if (*device && end && *end == '\0' && index >= 0 && index < 1024)
    {
      this->DeviceIndex = static_cast<int>(index);
    }
    else
    {
      this->DeviceIndex = kBadDeviceVariable;
    }
  }
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
  this->DisplayDescription.clear();
  this->SoftwareWhileHardwarePresent = false;
  std::string displayErrors;

  // First choice: a device of EGL's device platform, hardware before Mesa's software one.
  const std::vector<DeviceInfo> devices = QueryDevices(clientExt);
  this->DevicesFound = DescribeDevices(devices);
  if (this->DeviceIndex == kBadDeviceVariable)
  {
    this->Fail(std::string("SSS_EGL_DEVICE=") + std::getenv("SSS_EGL_DEVICE") +
      " is neither a device number (0, 1, ...) nor \"surfaceless\"; devices found: " +
      this->DevicesFound + ".");
    return false;
  }
  const bool devicePlatform = HasToken(clientExt, "EGL_EXT_platform_device");
  if (this->DeviceIndex >= 0 || (this->UseDevicePlatform && devicePlatform))
  {
    const int chosen = devicePlatform ? ChooseDevice(devices, this->DeviceIndex) : -1;
    if (chosen >= 0)
    {
      dpy = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[chosen].device, nullptr);
      if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &eglMajor, &eglMinor))
      {
        this->DisplayDescription = DescribeDevice(devices, static_cast<std::size_t>(chosen));
        this->SoftwareWhileHardwarePresent = devices[chosen].software &&
          std::any_of(devices.begin(), devices.end(), [](const DeviceInfo& d) { return !d.software; });
      }
      else
      {
        displayErrors += DescribeDevice(devices, static_cast<std::size_t>(chosen)) + ": " +
          EGLErrorText() + "; ";
        dpy = EGL_NO_DISPLAY;
      }
    }
    if (dpy == EGL_NO_DISPLAY && this->DeviceIndex >= 0)
    {
      this->Fail("EGL device " + std::to_string(this->DeviceIndex) + " cannot be used (" +
        (devicePlatform ? displayErrors : std::string("libEGL offers no EGL_EXT_platform_device; ")) +
        "devices found: " + this->DevicesFound + ").");
      return false;
    }
  }

  if (dpy == EGL_NO_DISPLAY && HasToken(clientExt, "EGL_MESA_platform_surfaceless"))
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
      this->DisplayDescription = "EGL surfaceless platform (EGL_PLATFORM_SURFACELESS_MESA)";
    }
    else
    {
      displayErrors += "surfaceless platform display: " + EGLErrorText() + "; ";
      dpy = EGL_NO_DISPLAY;
    }
  }
  else if (dpy == EGL_NO_DISPLAY)
  {
    displayErrors += "EGL_MESA_platform_surfaceless not offered by libEGL; ";
  }

  if (dpy == EGL_NO_DISPLAY)
  {
    dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &eglMajor, &eglMinor))
    {
      displayErrors += "default display: " + EGLErrorText();
      this->Fail("No EGL display could be initialized (" + displayErrors +
        "; devices found: " + this->DevicesFound + ").");
      return false;
    }
    this->DisplayDescription = "EGL default display (eglGetDisplay(EGL_DEFAULT_DISPLAY))";
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
  s << "EGL display:  " << this->DisplayDescription << "\n";
  s << "EGL devices:  " << this->DevicesFound << "\n";
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
  os << indent << "DeviceIndex: " << this->DeviceIndex << "\n";
  os << indent << "UseDevicePlatform: " << this->UseDevicePlatform << "\n";
  os << indent << "DisplayDescription: " << this->DisplayDescription << "\n";
  os << indent << "DevicesFound: " << this->DevicesFound << "\n";
  os << indent << "SurfacelessPlatform: " << this->SurfacelessPlatform << "\n";
  os << indent << "Display: " << this->Display << "\n";
}

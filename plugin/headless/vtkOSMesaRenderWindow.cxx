#include "vtkOSMesaRenderWindow.h"

#include "vtkHeadlessGLInternals.h"
#include "vtkObjectFactory.h"
#include "vtk_glew.h"

// Types and enums only: libOSMesa is opened with dlopen (see GetOSMesaAPI).
// glew.h #undefs GLAPI/GLAPIENTRY, which osmesa.h uses for its prototypes.
#ifndef GLAPI
#define GLAPI extern
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#include <GL/osmesa.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#ifndef SSS_OSMESA_SONAME
#define SSS_OSMESA_SONAME "libOSMesa.so.8"
#endif

namespace
{
const char* const ReexecMarker = "SSS_OSMESA_REEXEC";
const char* const SavedPreload = "SSS_OSMESA_SAVED_LD_PRELOAD";
const char* const ShimEnv = "SSS_OSMESA_SHIM";
const char* const ShimFileName = "libsss_osmesa_shim.so";

struct OSMesaAPI
{
  void* Handle = nullptr;
  OSMesaContext (*CreateContextAttribs)(const int*, OSMesaContext) = nullptr;
  GLboolean (*MakeCurrent)(OSMesaContext, void*, GLenum, GLsizei, GLsizei) = nullptr;
  void (*DestroyContext)(OSMesaContext) = nullptr;
  OSMesaContext (*GetCurrentContext)() = nullptr;
  OSMESAproc (*GetProcAddress)(const char*) = nullptr;
  void (*GetIntegerv)(GLint, GLint*) = nullptr;
  std::string Error;
  bool Valid = false;
};

template <typename T>
bool Resolve(void* handle, const char* name, T& fn)
{
  fn = reinterpret_cast<T>(dlsym(handle, name));
  return fn != nullptr;
}

// libOSMesa is opened RTLD_LOCAL: loading it must not change how the rest of
// the process binds GL symbols. In a prepared process the already loaded
// (preloaded or linked) copy is returned by dlopen.
const OSMesaAPI& GetOSMesaAPI()
{
  static const OSMesaAPI api = []() {
    OSMesaAPI a;
    const char* candidates[] = { SSS_OSMESA_SONAME,
#ifdef SSS_OSMESA_LIBRARY
      SSS_OSMESA_LIBRARY,
#endif
      "libOSMesa.so" };
    for (const char* name : candidates)
    {
      a.Handle = dlopen(name, RTLD_NOW | RTLD_LOCAL);
      if (a.Handle)
      {
        break;
      }
      const char* err = dlerror();
      a.Error += std::string(err ? err : name) + "; ";
    }
    if (!a.Handle)
    {
      a.Error = "cannot load libOSMesa: " + a.Error;
      return a;
    }
    if (!Resolve(a.Handle, "OSMesaCreateContextAttribs", a.CreateContextAttribs) ||
      !Resolve(a.Handle, "OSMesaMakeCurrent", a.MakeCurrent) ||
      !Resolve(a.Handle, "OSMesaDestroyContext", a.DestroyContext) ||
      !Resolve(a.Handle, "OSMesaGetCurrentContext", a.GetCurrentContext) ||
      !Resolve(a.Handle, "OSMesaGetProcAddress", a.GetProcAddress) ||
      !Resolve(a.Handle, "OSMesaGetIntegerv", a.GetIntegerv))
    {
      a.Error = "libOSMesa lacks OSMesaCreateContextAttribs (Mesa >= 11.2 needed)";
      return a;
    }
    a.Valid = true;
    return a;
  }();
  return api;
}

std::string LibraryOf(const void* addr)
{
  Dl_info info;
  if (addr && dladdr(addr, &info) && info.dli_fname)
  {
    return info.dli_fname;
  }
  return "(unknown)";
}

std::string RealPath(const std::string& path)
{
  char buf[PATH_MAX];
  return realpath(path.c_str(), buf) ? std::string(buf) : std::string();
}

std::vector<std::string> ReadSelfCmdline()
{
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  std::string cur;
  for (char c : all)
  {
    if (c == '\0')
    {
      args.push_back(cur);
      cur.clear();
    }
    else
    {
      cur += c;
    }
  }
  if (!cur.empty())
  {
    args.push_back(cur);
  }
  return args;
}

// Puts LD_PRELOAD back to what it was before the re-exec so that child
// processes do not inherit the OSMesa preload.
void RestoreEnvironment()
{
  if (!std::getenv(ReexecMarker))
  {
    return;
  }
  const char* saved = std::getenv(SavedPreload);
  if (saved)
  {
    setenv("LD_PRELOAD", saved, 1);
  }
  else
  {
    unsetenv("LD_PRELOAD");
  }
  unsetenv(SavedPreload);
  unsetenv(ReexecMarker);
}

bool ReexecAttempted = false;

// A process built with AddressSanitizer's shared runtime must keep that runtime first among
// its libraries, so the re-exec preloads it ahead of the shim; empty for other processes.
std::string SanitizerRuntime()
{
  const std::string runtime = LibraryOf(dlsym(RTLD_DEFAULT, "__asan_init"));
  return runtime.find("libasan") != std::string::npos ? runtime : std::string();
}
}

vtkStandardNewMacro(vtkOSMesaRenderWindow);

//------------------------------------------------------------------------------
// Process preparation
//------------------------------------------------------------------------------
std::string vtkOSMesaRenderWindow::FindOSMesaLibrary()
{
  const OSMesaAPI& api = GetOSMesaAPI();
  if (!api.Valid)
  {
    return std::string();
  }
  return RealPath(LibraryOf(reinterpret_cast<const void*>(api.CreateContextAttribs)));
}

//------------------------------------------------------------------------------
std::string vtkOSMesaRenderWindow::FindShimLibrary()
{
  std::vector<std::string> candidates;
  if (const char* env = std::getenv(ShimEnv))
  {
    candidates.emplace_back(env);
  }
  // Next to the library that contains this class: build/lib in the build tree, the
  // install prefix's library folder once installed.
  std::string self =
    LibraryOf(reinterpret_cast<const void*>(&vtkOSMesaRenderWindow::FindShimLibrary));
  const std::size_t slash = self.rfind('/');
  if (slash != std::string::npos)
  {
    candidates.push_back(self.substr(0, slash + 1) + ShimFileName);
  }
#ifdef SSS_OSMESA_SHIM_PATH
  candidates.emplace_back(SSS_OSMESA_SHIM_PATH);
#endif
  for (const std::string& c : candidates)
  {
    if (!c.empty() && access(c.c_str(), R_OK) == 0)
    {
      return RealPath(c);
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkOSMesaRenderWindow::GetPreloadValue(std::string* why)
{
  const std::string shim = FindShimLibrary();
  const std::string osmesa = FindOSMesaLibrary();
  if (shim.empty() || osmesa.empty())
  {
    if (why)
    {
      *why = shim.empty() ? std::string("sss_osmesa_shim library not found (set ") + ShimEnv + ")"
                          : GetOSMesaAPI().Error;
    }
    return std::string();
  }
  return shim + ":" + osmesa;
}

//------------------------------------------------------------------------------
bool vtkOSMesaRenderWindow::IsProcessOSMesaReady(std::string* why)
{
  std::string reason;
  auto fail = [&](const std::string& r) {
    if (why)
    {
      *why = r;
    }
    return false;
  };
  const OSMesaAPI& api = GetOSMesaAPI();
  if (!api.Valid)
  {
    return fail(api.Error);
  }
  // GL 1.x functions VTK and GLEW call directly: the process must bind them
  // to libOSMesa, not to glvnd's libOpenGL/libGL.
  const char* direct[] = { "glGetString", "glGetIntegerv", "glClear", "glViewport", "glReadPixels",
    "glTexImage2D", "glDrawArrays", "glEnable" };
  for (const char* name : direct)
  {
    void* bound = dlsym(RTLD_DEFAULT, name);
    void* mesa = dlsym(api.Handle, name);
    if (!bound || bound != mesa)
    {
      return fail(std::string(name) + " is bound to " + LibraryOf(bound) + ", not libOSMesa");
    }
  }
  // GLEW loads everything else through glXGetProcAddressARB.
  using GetProc = void (*(*)(const GLubyte*))();
  auto gpa = reinterpret_cast<GetProc>(dlsym(RTLD_DEFAULT, "glXGetProcAddressARB"));
  if (!gpa)
  {
    return fail("no glXGetProcAddressARB in the process");
  }
  const char* loaded[] = { "glGenFramebuffers", "glBlendFuncSeparate", "glGetStringi" };
  for (const char* name : loaded)
  {
    auto viaProcess = reinterpret_cast<void*>(gpa(reinterpret_cast<const GLubyte*>(name)));
    auto viaOSMesa = reinterpret_cast<void*>(api.GetProcAddress(name));
    if (!viaOSMesa || viaProcess != viaOSMesa)
    {
      return fail(std::string("glXGetProcAddressARB comes from ") +
        LibraryOf(reinterpret_cast<const void*>(gpa)) + ", not from the sss_osmesa_shim");
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOSMesaRenderWindow::EnsureProcessIsOSMesaReady(int argc, char** argv, std::string& why)
{
  why.clear();
  std::string notReady;
  if (IsProcessOSMesaReady(&notReady))
  {
    RestoreEnvironment();
    return true;
  }
  if (std::getenv(ReexecMarker) || ReexecAttempted)
  {
    why = "process was re-executed with LD_PRELOAD but is still not OSMesa-ready: " + notReady;
    RestoreEnvironment();
    ReexecAttempted = true;
    return false;
  }
  ReexecAttempted = true;

  std::string locate;
  const std::string preload = GetPreloadValue(&locate);
  if (preload.empty())
  {
    why = "cannot prepare the process for OSMesa: " + locate;
    return false;
  }

  // Arguments: main()'s argv, or /proc/self/cmdline.
  std::vector<std::string> storage;
  std::vector<char*> args;
  if (argv && argc > 0)
  {
    for (int i = 0; i < argc; ++i)
    {
      args.push_back(argv[i]);
    }
  }
  else
  {
    storage = ReadSelfCmdline();
    for (std::string& s : storage)
    {
      args.push_back(&s[0]);
    }
  }
  if (args.empty())
  {
    why = "cannot determine the command line for re-execution";
    return false;
  }
  args.push_back(nullptr);

  const char* old = std::getenv("LD_PRELOAD");
  if (old)
  {
    setenv(SavedPreload, old, 1);
  }
  const std::string runtime = SanitizerRuntime();
  const std::string first = runtime.empty() ? preload : runtime + ":" + preload;
  const std::string value = (old && *old) ? first + ":" + old : first;
  setenv("LD_PRELOAD", value.c_str(), 1);
  setenv(ReexecMarker, "1", 1);

  std::fflush(stdout);
  std::fflush(stderr);
  execv("/proc/self/exe", args.data());

  // only reached when execv failed
  why = std::string("execv(/proc/self/exe) failed: ") + std::strerror(errno) + " (" + notReady +
    ")";
  RestoreEnvironment();
  return false;
}

//------------------------------------------------------------------------------
// Window
//------------------------------------------------------------------------------
vtkOSMesaRenderWindow::vtkOSMesaRenderWindow()
  : BufferType(GL_UNSIGNED_BYTE)
  , UseFloatBuffer(false)
{
  this->BufferSize[0] = this->BufferSize[1] = 0;
  this->SetWindowName("vtkOSMesaRenderWindow");
}

//------------------------------------------------------------------------------
vtkOSMesaRenderWindow::~vtkOSMesaRenderWindow()
{
  // Release our GL objects and the context while the hooks still exist.
  this->Finalize();
}

//------------------------------------------------------------------------------
bool vtkOSMesaRenderWindow::BindBuffer()
{
  const OSMesaAPI& api = GetOSMesaAPI();
  const int w = this->Size[0] > 0 ? this->Size[0] : 1;
  const int h = this->Size[1] > 0 ? this->Size[1] : 1;
  const GLenum type = this->UseFloatBuffer ? GL_FLOAT : GL_UNSIGNED_BYTE;
  OSMesaContext ctx = static_cast<OSMesaContext>(this->Context);

  if (this->Buffer.empty() || w != this->BufferSize[0] || h != this->BufferSize[1] ||
    type != this->BufferType)
  {
    const std::size_t bytes =
      static_cast<std::size_t>(w) * h * 4 * (type == GL_FLOAT ? sizeof(GLfloat) : 1);
    std::vector<unsigned char> fresh(bytes);
    if (!api.MakeCurrent(ctx, fresh.data(), type, w, h))
    {
      this->Fail("OSMesaMakeCurrent failed for a " + std::to_string(w) + "x" + std::to_string(h) +
        " buffer");
      return false;
    }
    this->Buffer.swap(fresh); // old buffer freed only after the rebind
    this->BufferSize[0] = w;
    this->BufferSize[1] = h;
    this->BufferType = type;
  }
  else if (api.GetCurrentContext() != ctx || vtkHeadlessGL::CurrentOwner() != this)
  {
    if (!api.MakeCurrent(ctx, this->Buffer.data(), type, w, h))
    {
      this->Fail("OSMesaMakeCurrent failed");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOSMesaRenderWindow::CreateContext()
{
  const OSMesaAPI& api = GetOSMesaAPI();
  if (!api.Valid)
  {
    this->Fail(api.Error);
    return false;
  }
  std::string why;
  if (!vtkOSMesaRenderWindow::IsProcessOSMesaReady(&why))
  {
    std::string preload = vtkOSMesaRenderWindow::GetPreloadValue();
    this->Fail("the process is not prepared for OSMesa (" + why +
      "). Call vtkOSMesaRenderWindow::EnsureProcessIsOSMesaReady() at the start of main(), "
      "launch with LD_PRELOAD=" +
      (preload.empty() ? std::string("<libsss_osmesa_shim.so>:<libOSMesa.so.8>") : preload) +
      ", or link sss_osmesa_shim and OSMesa ahead of VTK (-Wl,--no-as-needed).");
    return false;
  }

  const int versions[][2] = { { 4, 5 }, { 3, 3 }, { 3, 2 } };
  OSMesaContext ctx = nullptr;
  for (const auto& v : versions)
  {
    const int attribs[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
      OSMESA_STENCIL_BITS, 8, OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
      OSMESA_CONTEXT_MAJOR_VERSION, v[0], OSMESA_CONTEXT_MINOR_VERSION, v[1], 0 };
    ctx = api.CreateContextAttribs(attribs, nullptr);
    if (ctx)
    {
      break;
    }
  }
  if (!ctx)
  {
    this->Fail("OSMesaCreateContextAttribs failed for OpenGL core 4.5/3.3/3.2");
    return false;
  }
  this->Context = ctx;
  if (!this->BindBuffer())
  {
    api.DestroyContext(ctx);
    this->Context = nullptr;
    return false;
  }
  vtkHeadlessGL::CurrentOwner() = this;

  const GLubyte* version = glGetString(GL_VERSION);
  GLint major = 0, minor = 0;
  if (version)
  {
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
  }
  if (!version || major * 10 + minor < 32)
  {
    api.MakeCurrent(nullptr, nullptr, 0, 0, 0);
    vtkHeadlessGL::CurrentOwner() = nullptr;
    api.DestroyContext(ctx);
    this->Context = nullptr;
    this->Buffer.clear();
    this->BufferSize[0] = this->BufferSize[1] = 0;
    this->Fail(version ? std::string("OSMesa context reports OpenGL ") +
          reinterpret_cast<const char*>(version) + ", VTK needs 3.2 or later"
                       : std::string("glGetString(GL_VERSION) returned NULL in the OSMesa context"));
    return false;
  }
  GLint maxW = 0, maxH = 0;
  api.GetIntegerv(OSMESA_MAX_WIDTH, &maxW);
  api.GetIntegerv(OSMESA_MAX_HEIGHT, &maxH);
  this->ScreenSize[0] = maxW;
  this->ScreenSize[1] = maxH;

  this->ContextMajor = major;
  this->ContextMinor = minor;
  return true;
}

//------------------------------------------------------------------------------
void vtkOSMesaRenderWindow::DestroyContext()
{
  GetOSMesaAPI().DestroyContext(static_cast<OSMesaContext>(this->Context));
  std::vector<unsigned char>().swap(this->Buffer);
  this->BufferSize[0] = this->BufferSize[1] = 0;
}

//------------------------------------------------------------------------------
bool vtkOSMesaRenderWindow::MakeContextCurrent()
{
  return this->BindBuffer();
}

//------------------------------------------------------------------------------
void vtkOSMesaRenderWindow::ReleaseContext()
{
  GetOSMesaAPI().MakeCurrent(nullptr, nullptr, 0, 0, 0);
}

//------------------------------------------------------------------------------
bool vtkOSMesaRenderWindow::IsContextCurrent()
{
  return GetOSMesaAPI().GetCurrentContext() == static_cast<OSMesaContext>(this->Context);
}

//------------------------------------------------------------------------------
void vtkOSMesaRenderWindow::ResizeDrawable()
{
  this->BindBuffer(); // reallocates to the new size and rebinds
}

//------------------------------------------------------------------------------
bool vtkOSMesaRenderWindow::ReportContext(std::ostream& s)
{
  if (!this->Initialized)
  {
    s << "vtkOSMesaRenderWindow: GL initialization failed (" << this->LastError << ")\n";
    return false;
  }
  s << "OSMesa library:  " << vtkOSMesaRenderWindow::FindOSMesaLibrary() << "\n";
  s << "OSMesa buffer:  " << this->BufferSize[0] << "x" << this->BufferSize[1] << " RGBA "
    << (this->BufferType == GL_FLOAT ? "float" : "unsigned byte") << "\n";
  s << "OpenGL context:  core profile " << this->ContextMajor << "." << this->ContextMinor << "\n";
  return true;
}

//------------------------------------------------------------------------------
void vtkOSMesaRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BufferSize: " << this->BufferSize[0] << "x" << this->BufferSize[1] << "\n";
  os << indent << "UseFloatBuffer: " << this->UseFloatBuffer << "\n";
}

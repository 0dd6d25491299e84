/**
 * @class   vtkOSMesaRenderWindow
 * @brief   Off-screen OpenGL render window backed by an OSMesa (Mesa
 *          software) core-profile context; needs no X server and no GPU.
 *
 * Debian's VTK 9.1 is built for X11 with the system GLEW. VTK calls GL 1.x
 * functions directly (bound to glvnd's libOpenGL at load time) and loads all
 * other GL functions through GLEW, i.e. through glXGetProcAddressARB from
 * glvnd's libGLX. Neither reaches an OSMesa context, so glewInit() fails with
 * "Missing GL version" unless the *process* resolves
 *   - the GL symbols from libOSMesa.so.8 and
 *   - glXGetProcAddressARB from the sss_osmesa_shim library
 *     (forwarding to OSMesaGetProcAddress)
 * ahead of libOpenGL/libGL/libGLX. Two ways to get there:
 *
 *  1. Call EnsureProcessIsOSMesaReady(argc, argv, why) first thing in main().
 *     When the process is not ready it re-executes itself (/proc/self/exe)
 *     with LD_PRELOAD=<shim>:<libOSMesa.so.8>[:old LD_PRELOAD] and a marker
 *     variable (no loops); in the re-executed process it restores the
 *     original LD_PRELOAD so child processes are unaffected.
 *  2. Link a dedicated executable with the shim and OSMesa first:
 *       -Wl,--no-as-needed sss_osmesa_shim -lOSMesa -Wl,--as-needed <VTK...>
 *
 * libOSMesa itself is opened with dlopen(RTLD_LOCAL) by this class, so
 * merely linking this class never changes how an unprepared process binds
 * GL (EGL/GLX users are unaffected). In an unprepared process the window
 * reports the problem once (vtkErrorMacro, IsContextValid() == false,
 * GetLastError()) and rendering is a no-op.
 *
 * The OSMesa color buffer (RGBA, unsigned byte or float, window size,
 * reallocated on SetSize) only backs the default framebuffer; rendering and
 * read-back go through VTK's framebuffer objects (see vtkHeadlessRenderWindow).
 */

#ifndef vtkOSMesaRenderWindow_h
#define vtkOSMesaRenderWindow_h

#include "sssHeadlessModule.h"
#include "vtkHeadlessRenderWindow.h"

#include <string> // for std::string
#include <vector> // for std::vector

class SSSHEADLESS_EXPORT vtkOSMesaRenderWindow : public vtkHeadlessRenderWindow
{
public:
  static vtkOSMesaRenderWindow* New();
  vtkTypeMacro(vtkOSMesaRenderWindow, vtkHeadlessRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Process preparation (see class documentation).
   *
   * IsProcessOSMesaReady() checks that the GL symbols and
   * glXGetProcAddressARB the process binds come from libOSMesa / the shim.
   *
   * EnsureProcessIsOSMesaReady() returns true when the process is ready, and
   * otherwise re-executes it with the right LD_PRELOAD (it only returns,
   * with false and a reason, when that is impossible or did not help).
   * argv must be main()'s NULL-terminated argv; pass argv == nullptr to use
   * /proc/self/cmdline (e.g. from an embedded interpreter). Call it before
   * creating threads or doing work that must not be repeated.
   *
   * GetPreloadValue() gives the LD_PRELOAD value to launch a program by hand.
   * FindShimLibrary() takes $SSS_OSMESA_SHIM, else libsss_osmesa_shim.so next
   * to this library (build or install tree), else the build tree's copy.
   */
  static bool IsProcessOSMesaReady(std::string* why = nullptr);
  static bool EnsureProcessIsOSMesaReady(int argc, char** argv, std::string& why);
  static std::string GetPreloadValue(std::string* why = nullptr);
  static std::string FindOSMesaLibrary();
  static std::string FindShimLibrary();
  ///@}

  ///@{
  /**
   * Use a GL_FLOAT instead of a GL_UNSIGNED_BYTE RGBA OSMesa buffer
   * (takes effect at the next MakeCurrent()).
   */
  vtkSetMacro(UseFloatBuffer, bool);
  vtkGetMacro(UseFloatBuffer, bool);
  vtkBooleanMacro(UseFloatBuffer, bool);
  ///@}

  /**
   * The OSMesa color buffer, as an opaque pointer.
   */
  void* GetOSMesaBuffer() { return this->Buffer.empty() ? nullptr : this->Buffer.data(); }

protected:
  vtkOSMesaRenderWindow();
  ~vtkOSMesaRenderWindow() override;

  bool CreateContext() override;
  void DestroyContext() override;
  bool MakeContextCurrent() override;
  void ReleaseContext() override;
  bool IsContextCurrent() override;
  void ResizeDrawable() override;
  bool ReportContext(std::ostream& os) override;
  const char* GetBackendName() const override { return "OSMesa"; }

  bool BindBuffer();

  std::vector<unsigned char> Buffer;
  int BufferSize[2];
  unsigned int BufferType;
  bool UseFloatBuffer;

private:
  vtkOSMesaRenderWindow(const vtkOSMesaRenderWindow&) = delete;
  void operator=(const vtkOSMesaRenderWindow&) = delete;
};

#endif

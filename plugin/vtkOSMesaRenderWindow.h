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
 * reallocated on SetSize) only backs the default framebuffer: VTK renders
 * into its own framebuffer objects (OffScreenRendering on, frame blit mode
 * NoBlit) and all read-back (vtkWindowToImageFilter, GetPixelData,
 * GetRGBAPixelData) goes through those objects.
 */

#ifndef vtkOSMesaRenderWindow_h
#define vtkOSMesaRenderWindow_h

#include "sssTranslucencyModule.h"
#include "vtkGenericOpenGLRenderWindow.h"

#include <string> // for std::string
#include <vector> // for std::vector

class SSSTRANSLUCENCY_EXPORT vtkOSMesaRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkOSMesaRenderWindow* New();
  vtkTypeMacro(vtkOSMesaRenderWindow, vtkGenericOpenGLRenderWindow);
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
   */
  static bool IsProcessOSMesaReady(std::string* why = nullptr);
  static bool EnsureProcessIsOSMesaReady(int argc, char** argv, std::string& why);
  static std::string GetPreloadValue(std::string* why = nullptr);
  static std::string FindOSMesaLibrary();
  static std::string FindShimLibrary();
  ///@}

  ///@{
  /**
   * Context management (overrides of the virtuals that
   * vtkGenericOpenGLRenderWindow otherwise forwards to observer events).
   */
  void Initialize() override;
  void Finalize() override;
  void MakeCurrent() override;
  bool IsCurrent() override;
  void ReleaseCurrent() override;
  vtkTypeBool IsDirect() override;
  ///@}

  /**
   * Returns 1 when an OSMesa core >= 3.2 context works in this process.
   */
  int SupportsOpenGL() override;

  /**
   * OSMesa details followed by VTK's OpenGL report.
   */
  const char* ReportCapabilities() override;

  ///@{
  /**
   * Rendering entry points; all are no-ops without a valid context.
   */
  void Start() override;
  void Render() override;
  void Frame() override;
  void OpenGLInit() override;
  ///@}

  /**
   * Resizes the window and its OSMesa buffer (rebinding it when the context
   * is current).
   */
  void SetSize(int width, int height) override;
  using vtkGenericOpenGLRenderWindow::SetSize;

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
   * The OSMesaContext and the OSMesa color buffer, as opaque pointers.
   */
  void* GetGenericContext() override;
  void* GetOSMesaBuffer() { return this->Buffer.empty() ? nullptr : this->Buffer.data(); }

  bool IsContextValid();
  const std::string& GetLastError() const { return this->LastError; }
  int GetContextMajorVersion() const { return this->ContextMajor; }
  int GetContextMinorVersion() const { return this->ContextMinor; }

protected:
  vtkOSMesaRenderWindow();
  ~vtkOSMesaRenderWindow() override;

  bool EnsureContext();
  bool CreateContext();
  void DestroyContext();
  bool BindBuffer();
  void Fail(const std::string& why);

  void OpenGLInitContext() override;
  int ReadPixels(
    const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right) override;

  void* Context;
  std::vector<unsigned char> Buffer;
  int BufferSize[2];
  unsigned int BufferType;
  bool UseFloatBuffer;
  bool ContextAttempted;
  bool ContextValid;
  int ContextMajor;
  int ContextMinor;
  std::string LastError;
  std::string CapabilitiesReport;

private:
  vtkOSMesaRenderWindow(const vtkOSMesaRenderWindow&) = delete;
  void operator=(const vtkOSMesaRenderWindow&) = delete;
};

#endif

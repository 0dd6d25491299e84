/**
 * @class   vtkEGLSurfacelessRenderWindow
 * @brief   Off-screen OpenGL render window backed by an EGL context on the
 *          Mesa "surfaceless" platform (no X server, no GBM device needed).
 *
 * Debian's VTK 9.1 is built for X11 with the system GLEW and has no EGL
 * render window. This class subclasses vtkGenericOpenGLRenderWindow and owns
 * an EGL context itself:
 *
 *  - display: eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA,
 *    EGL_DEFAULT_DISPLAY), falling back to eglGetDisplay(EGL_DEFAULT_DISPLAY);
 *  - API: desktop OpenGL, core profile, 4.5 then 3.3 then 3.2;
 *  - made current with EGL_NO_SURFACE (EGL_KHR_surfaceless_context).
 *
 * There is no default framebuffer: VTK renders into its own framebuffer
 * objects (OffScreenRendering is on, the frame blit mode is NoBlit) and all
 * pixel read-back goes through those objects (vtkWindowToImageFilter,
 * GetPixelData, GetRGBAPixelData work as usual).
 *
 * The context is created lazily on the first Initialize(), MakeCurrent(),
 * Render(), SupportsOpenGL() or ReportCapabilities(). When no context can be
 * made the class reports one vtkErrorMacro, IsContextValid() returns false,
 * GetLastError() explains why, and rendering becomes a no-op (never a crash).
 *
 * GLEW (built for GLX) returns GLEW_ERROR_NO_GLX_DISPLAY from glewInit() after
 * it has loaded all GL entry points; vtkOpenGLRenderWindow::OpenGLInitContext()
 * would print "GLEW could not be initialized: Unknown error" and leave the
 * window half-initialized on every frame. This class overrides
 * OpenGLInitContext() and accepts exactly that code when the GL part loaded.
 *
 * The context is bound to the thread that calls MakeCurrent(); use one window
 * per thread or call ReleaseCurrent() before rendering from another thread.
 */

#ifndef vtkEGLSurfacelessRenderWindow_h
#define vtkEGLSurfacelessRenderWindow_h

#include "sssTranslucencyModule.h"
#include "vtkGenericOpenGLRenderWindow.h"

#include <string> // for std::string

class SSSTRANSLUCENCY_EXPORT vtkEGLSurfacelessRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkEGLSurfacelessRenderWindow* New();
  vtkTypeMacro(vtkEGLSurfacelessRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

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
   * Returns 1 when an EGL OpenGL core context >= 3.2 can be (or was) created.
   * Creates the context on first use; the reason for a 0 is available in
   * GetOpenGLSupportMessage() and GetLastError().
   */
  int SupportsOpenGL() override;

  /**
   * EGL details (platform, EGL version/vendor) followed by VTK's OpenGL report.
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
   * EGLContext / EGLDisplay as opaque pointers (nullptr when invalid).
   */
  void* GetGenericContext() override;
  void* GetGenericDisplayId() override;

  /**
   * True once a context has been created successfully and not destroyed.
   * Tries to create the context if that has not been attempted yet.
   */
  bool IsContextValid();

  /**
   * Human-readable reason of the last failure ("" if none).
   */
  const std::string& GetLastError() const { return this->LastError; }

  ///@{
  /**
   * Context information (valid after a successful context creation).
   */
  int GetContextMajorVersion() const { return this->ContextMajor; }
  int GetContextMinorVersion() const { return this->ContextMinor; }
  bool GetUsesSurfacelessPlatform() const { return this->SurfacelessPlatform; }
  ///@}

protected:
  vtkEGLSurfacelessRenderWindow();
  ~vtkEGLSurfacelessRenderWindow() override;

  bool EnsureContext();
  bool CreateContext();
  void DestroyContext();
  void Fail(const std::string& why);

  void OpenGLInitContext() override;
  int ReadPixels(
    const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right) override;

  void* Display;
  void* Context;
  bool ContextAttempted;
  bool ContextValid;
  bool SurfacelessPlatform;
  int ContextMajor;
  int ContextMinor;
  std::string LastError;
  std::string CapabilitiesReport;

private:
  vtkEGLSurfacelessRenderWindow(const vtkEGLSurfacelessRenderWindow&) = delete;
  void operator=(const vtkEGLSurfacelessRenderWindow&) = delete;
};

#endif

/**
 * @class   vtkEGLSurfacelessRenderWindow
 * @brief   Off-screen OpenGL render window backed by an EGL context on the
 *          Mesa "surfaceless" platform (no X server, no GBM device needed).
 *
 * Debian's VTK 9.1 is built for X11 with the system GLEW and has no EGL
 * render window. This vtkHeadlessRenderWindow owns an EGL context itself:
 *
 *  - display: eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA,
 *    EGL_DEFAULT_DISPLAY), falling back to eglGetDisplay(EGL_DEFAULT_DISPLAY);
 *  - API: desktop OpenGL, core profile, 4.5 then 3.3 then 3.2;
 *  - made current with EGL_NO_SURFACE (EGL_KHR_surfaceless_context).
 *
 * Context handling, lazy creation, error reporting and the GLEW work-around
 * are those of vtkHeadlessRenderWindow. There is no default framebuffer.
 */

#ifndef vtkEGLSurfacelessRenderWindow_h
#define vtkEGLSurfacelessRenderWindow_h

#include "sssHeadlessModule.h"
#include "vtkHeadlessRenderWindow.h"

class SSSHEADLESS_EXPORT vtkEGLSurfacelessRenderWindow : public vtkHeadlessRenderWindow
{
public:
  static vtkEGLSurfacelessRenderWindow* New();
  vtkTypeMacro(vtkEGLSurfacelessRenderWindow, vtkHeadlessRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * EGLDisplay as an opaque pointer (nullptr when invalid).
   */
  void* GetGenericDisplayId() override;

  /**
   * True when the display is on EGL_PLATFORM_SURFACELESS_MESA (valid after a
   * successful context creation).
   */
  bool GetUsesSurfacelessPlatform() const { return this->SurfacelessPlatform; }

protected:
  vtkEGLSurfacelessRenderWindow();
  ~vtkEGLSurfacelessRenderWindow() override;

  bool CreateContext() override;
  void DestroyContext() override;
  bool MakeContextCurrent() override;
  void ReleaseContext() override;
  bool IsContextCurrent() override;
  void ResizeDrawable() override {} // no drawable: VTK's framebuffers follow Size
  bool ReportContext(std::ostream& os) override;
  const char* GetBackendName() const override { return "EGL"; }

  void* Display;
  bool SurfacelessPlatform;

private:
  vtkEGLSurfacelessRenderWindow(const vtkEGLSurfacelessRenderWindow&) = delete;
  void operator=(const vtkEGLSurfacelessRenderWindow&) = delete;
};

#endif

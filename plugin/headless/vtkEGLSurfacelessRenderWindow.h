/**
 * @class   vtkEGLSurfacelessRenderWindow
 * @brief   Off-screen OpenGL render window backed by an EGL context with no
 *          surface (no X server needed), on a graphics card where there is one.
 *
 * Debian's VTK 9.1 is built for X11 with the system GLEW and has no EGL
 * render window. This vtkHeadlessRenderWindow owns an EGL context itself:
 *
 *  - display: a device of EGL's device platform (EGL_EXT_device_enumeration,
 *    EGL_EXT_platform_device), the first hardware device before a software one
 *    (Mesa marks its CPU renderer with EGL_MESA_device_software), or the one
 *    DeviceIndex or the environment variable SSS_EGL_DEVICE names; then
 *    eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY);
 *    then eglGetDisplay(EGL_DEFAULT_DISPLAY). GetDisplayDescription() says which
 *    was used;
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

#include <string>

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

  ///@{
  /**
   * Which EGL device draws, as eglQueryDevicesEXT lists them (set before the
   * context exists). -1 (default): the first hardware device, else the first
   * device (Mesa's software renderer), falling back to the surfaceless platform
   * and the default display. N >= 0: device N, and the context fails, naming
   * the devices found, when it cannot be used. The environment variable
   * SSS_EGL_DEVICE sets the default for scripts: a device number, or
   * "surfaceless" for UseDevicePlatformOff.
   */
  vtkSetClampMacro(DeviceIndex, int, -1, 1023);
  vtkGetMacro(DeviceIndex, int);
  ///@}

  ///@{
  /**
   * Whether an automatic choice (DeviceIndex -1) tries EGL's device platform
   * first (default on); off starts at the surfaceless platform.
   */
  vtkSetMacro(UseDevicePlatform, bool);
  vtkGetMacro(UseDevicePlatform, bool);
  vtkBooleanMacro(UseDevicePlatform, bool);
  ///@}

  /**
   * After the context exists: the display it was made on, e.g. "EGL device 0
   * of 2 (hardware, /dev/dri/renderD128)" or "EGL surfaceless platform ...".
   */
  std::string GetDisplayDescription() const { return this->DisplayDescription; }
  /** Every EGL device listed when the context was made, one description each. */
  std::string GetDevicesFound() const { return this->DevicesFound; }
  /** True when a software device draws although a hardware one was listed. */
  bool GetSoftwareWhileHardwarePresent() const { return this->SoftwareWhileHardwarePresent; }

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
  int DeviceIndex = -1;
  bool UseDevicePlatform = true;
  std::string DisplayDescription;
  std::string DevicesFound;
  bool SoftwareWhileHardwarePresent = false;
  static constexpr int kBadDeviceVariable = -2;  // SSS_EGL_DEVICE holds no device number

private:
  vtkEGLSurfacelessRenderWindow(const vtkEGLSurfacelessRenderWindow&) = delete;
  void operator=(const vtkEGLSurfacelessRenderWindow&) = delete;
};

#endif

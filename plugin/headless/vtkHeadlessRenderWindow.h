/**
 * @class   vtkHeadlessRenderWindow
 * @brief   Abstract off-screen OpenGL render window that owns its context
 *          (base of vtkEGLSurfacelessRenderWindow and vtkOSMesaRenderWindow).
 *
 * Subclasses create, bind and destroy a native core-profile (>= 3.2) context
 * through the protected hooks; this class does the rest:
 *
 *  - OffScreenRendering is on and the frame blit mode is NoBlit: VTK renders
 *    into its own framebuffer objects and all pixel read-back goes through
 *    them (vtkWindowToImageFilter, GetPixelData, GetRGBAPixelData);
 *  - the context is created lazily on the first Initialize(), MakeCurrent(),
 *    Render(), SupportsOpenGL() or ReportCapabilities(); when that fails the
 *    window reports one vtkErrorMacro, IsContextValid() returns false,
 *    GetLastError() explains why, and rendering is a no-op (never a crash);
 *  - GLEW (built for GLX) returns GLEW_ERROR_NO_GLX_DISPLAY from glewInit()
 *    after loading all GL entry points; vtkOpenGLRenderWindow would print
 *    "GLEW could not be initialized: Unknown error" and leave the window
 *    half-initialized on every frame, so OpenGLInitContext() is overridden to
 *    accept exactly that code when the GL part loaded.
 *
 * The context is bound to the thread that calls MakeCurrent(); use one window
 * per thread or call ReleaseCurrent() before rendering from another thread.
 */

#ifndef vtkHeadlessRenderWindow_h
#define vtkHeadlessRenderWindow_h

#include "sssHeadlessModule.h"
#include "vtkGenericOpenGLRenderWindow.h"

#include <string> // for std::string

class SSSHEADLESS_EXPORT vtkHeadlessRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  vtkTypeMacro(vtkHeadlessRenderWindow, vtkGenericOpenGLRenderWindow);
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
   * Returns 1 when a core >= 3.2 context can be (or was) created. Creates the
   * context on first use; the reason for a 0 is available in
   * GetOpenGLSupportMessage() and GetLastError().
   */
  int SupportsOpenGL() override;

  /**
   * Backend details followed by VTK's OpenGL report.
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
   * Resizes the window and the backend's drawable, if any (rebinding it when
   * the context is current; otherwise it follows at the next MakeCurrent()).
   */
  void SetSize(int width, int height) override;
  using vtkGenericOpenGLRenderWindow::SetSize;

  /**
   * The native context as an opaque pointer (nullptr when invalid).
   */
  void* GetGenericContext() override;

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
   * Context version (valid after a successful context creation).
   */
  int GetContextMajorVersion() const { return this->ContextMajor; }
  int GetContextMinorVersion() const { return this->ContextMinor; }
  ///@}

protected:
  vtkHeadlessRenderWindow();
  ~vtkHeadlessRenderWindow() override;

  ///@{
  /**
   * Backend hooks.
   *
   * CreateContext() creates the context, makes it current (owner: this
   * window), sets Context, ContextMajor/Minor and ScreenSize and returns true;
   * on failure it calls Fail() and leaves nothing behind.
   * DestroyContext() destroys the (non-null, already released) Context.
   * MakeContextCurrent() binds Context in this thread (false after Fail()).
   * ReleaseContext() unbinds it; IsContextCurrent() asks the backend whether
   * it is bound. ResizeDrawable() follows a SetSize() while current.
   * ReportContext() writes the backend's lines of ReportCapabilities() and
   * returns false to end the report there. GetBackendName() names the API.
   *
   * Subclass destructors must call Finalize(): the hooks are gone by the
   * time this class's destructor runs.
   */
  virtual bool CreateContext() = 0;
  virtual void DestroyContext() = 0;
  virtual bool MakeContextCurrent() = 0;
  virtual void ReleaseContext() = 0;
  virtual bool IsContextCurrent() = 0;
  virtual void ResizeDrawable() = 0;
  virtual bool ReportContext(std::ostream& os) = 0;
  virtual const char* GetBackendName() const = 0;
  ///@}

  bool EnsureContext();
  void Fail(const std::string& why);

  void OpenGLInitContext() override;
  int ReadPixels(
    const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right) override;

  void* Context;
  bool ContextAttempted;
  bool ContextValid;
  int ContextMajor;
  int ContextMinor;
  std::string LastError;
  std::string CapabilitiesReport;

private:
  vtkHeadlessRenderWindow(const vtkHeadlessRenderWindow&) = delete;
  void operator=(const vtkHeadlessRenderWindow&) = delete;
};

#endif

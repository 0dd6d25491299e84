#include "vtkHeadlessRenderWindow.h"

#include "vtkHeadlessGLInternals.h"
#include "vtk_glew.h"

#include <sstream>

//------------------------------------------------------------------------------
vtkHeadlessRenderWindow::vtkHeadlessRenderWindow()
  : Context(nullptr)
  , ContextAttempted(false)
  , ContextValid(false)
  , ContextMajor(0)
  , ContextMinor(0)
{
  // Render into VTK's framebuffer objects; never blit to framebuffer 0
  // (absent or a mere backing buffer).
  this->SetOffScreenRendering(1);
  this->Mapped = 1;
  this->FrameBlitMode = vtkOpenGLRenderWindow::NoBlit;
  this->Size[0] = 300;
  this->Size[1] = 300;
}

//------------------------------------------------------------------------------
vtkHeadlessRenderWindow::~vtkHeadlessRenderWindow() = default;

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Fail(const std::string& why)
{
  // Report each distinct failure once so that a broken setup does not flood
  // the log on every frame.
  if (why != this->LastError)
  {
    this->LastError = why;
    vtkErrorMacro(<< why);
  }
}

//------------------------------------------------------------------------------
bool vtkHeadlessRenderWindow::EnsureContext()
{
  if (!this->ContextValid && !this->ContextAttempted)
  {
    this->ContextAttempted = true;
    if (this->CreateContext())
    {
      this->ContextValid = true;
      this->LastError.clear();
      // A fresh context: VTK must run glewInit/state setup again.
      this->Initialized = false;
      this->ContextCreationTime.Modified();
    }
  }
  return this->ContextValid;
}

//------------------------------------------------------------------------------
bool vtkHeadlessRenderWindow::IsContextValid()
{
  return this->EnsureContext();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Initialize()
{
  // An explicit Initialize() retries after an earlier failure.
  if (!this->ContextValid)
  {
    this->ContextAttempted = false;
  }
  if (!this->EnsureContext())
  {
    return;
  }
  this->MakeCurrent();
  if (!this->Initialized)
  {
    this->OpenGLInit();
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::OpenGLInit()
{
  if (!this->EnsureContext())
  {
    return;
  }
  this->MakeCurrent();
  this->OpenGLInitContext();
  if (!this->Initialized)
  {
    return; // reported; never run VTK's state setup without GL entry points
  }
  // vtkGenericOpenGLRenderWindow -> vtkOpenGLRenderWindow::OpenGLInit():
  // OpenGLInitContext() (now a no-op) + OpenGLInitState() + glFlush().
  this->Superclass::OpenGLInit();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::OpenGLInitContext()
{
  if (!this->Initialized && this->ContextValid)
  {
    const std::string why = vtkHeadlessGL::InitGlewWithoutGLX();
    if (!why.empty())
    {
      this->GlewInitValid = false;
      this->Fail(why);
      return;
    }
    this->GlewInitValid = true;
    this->Initialized = true;
    this->MaximumHardwareLineWidth =
      vtkHeadlessGL::QueryMaximumHardwareLineWidth(this->LineSmoothing != 0);
  }
  this->Superclass::OpenGLInitContext();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Finalize()
{
  if (this->ContextValid)
  {
    this->MakeCurrent();
    if (this->IsCurrent())
    {
      // release renderers, shader cache, framebuffers, ... in our context
      this->Superclass::Finalize();
    }
  }
  if (this->Context)
  {
    if (this->IsContextCurrent())
    {
      this->ReleaseContext();
    }
    if (vtkHeadlessGL::CurrentOwner() == this)
    {
      vtkHeadlessGL::CurrentOwner() = nullptr;
    }
    this->DestroyContext();
  }
  this->Context = nullptr;
  this->ContextValid = false;
  this->ContextAttempted = false;
  this->Initialized = false;
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::MakeCurrent()
{
  if (this->EnsureContext() && this->MakeContextCurrent())
  {
    vtkHeadlessGL::CurrentOwner() = this;
  }
}

//------------------------------------------------------------------------------
bool vtkHeadlessRenderWindow::IsCurrent()
{
  return this->ContextValid && vtkHeadlessGL::CurrentOwner() == this && this->IsContextCurrent();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::ReleaseCurrent()
{
  if (this->IsCurrent())
  {
    this->ReleaseContext();
    vtkHeadlessGL::CurrentOwner() = nullptr;
  }
}

//------------------------------------------------------------------------------
vtkTypeBool vtkHeadlessRenderWindow::IsDirect()
{
  return this->ContextValid ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::SetSize(int width, int height)
{
  this->Superclass::SetSize(width, height);
  if (this->ContextValid && this->IsCurrent())
  {
    this->ResizeDrawable();
  }
}

//------------------------------------------------------------------------------
int vtkHeadlessRenderWindow::SupportsOpenGL()
{
  const std::string backend = this->GetBackendName();
  this->OpenGLSupportTested = true;
  if (!this->EnsureContext())
  {
    this->OpenGLSupportResult = 0;
    this->OpenGLSupportMessage = "No " + backend + " OpenGL context: " + this->LastError;
    return 0;
  }
  // CreateContext() already rejected anything below core 3.2.
  this->OpenGLSupportResult = 1;
  this->OpenGLSupportMessage = backend + " OpenGL core " + std::to_string(this->ContextMajor) +
    "." + std::to_string(this->ContextMinor) + " context available.";
  return 1;
}

//------------------------------------------------------------------------------
const char* vtkHeadlessRenderWindow::ReportCapabilities()
{
  std::ostringstream s;
  if (!this->EnsureContext())
  {
    s << this->GetClassName() << ": no context (" << this->LastError << ")\n";
  }
  else
  {
    this->Initialize(); // makes current and runs VTK's GL init once
    if (this->ReportContext(s))
    {
      const char* gl = this->Superclass::ReportCapabilities();
      s << (gl ? gl : "");
    }
  }
  this->CapabilitiesReport = s.str();
  return this->CapabilitiesReport.c_str();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Start()
{
  this->Initialize();
  if (this->ContextValid && this->Initialized)
  {
    this->Superclass::Start();
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Render()
{
  if (!this->EnsureContext())
  {
    return; // the failure has been reported once; rendering is a no-op
  }
  this->Initialize();
  if (this->Initialized)
  {
    this->Superclass::Render();
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Frame()
{
  if (this->ContextValid && this->Initialized)
  {
    this->Superclass::Frame();
  }
}

//------------------------------------------------------------------------------
int vtkHeadlessRenderWindow::ReadPixels(
  const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right)
{
  if (!this->EnsureContext() || !this->Initialized)
  {
    return VTK_ERROR;
  }
  this->MakeCurrent();
  return this->Superclass::ReadPixels(rect, front, glFormat, glType, data, right);
}

//------------------------------------------------------------------------------
void* vtkHeadlessRenderWindow::GetGenericContext()
{
  return this->Context;
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ContextValid: " << this->ContextValid << "\n";
  os << indent << "ContextVersion: " << this->ContextMajor << "." << this->ContextMinor << "\n";
  os << indent << "Context: " << this->Context << "\n";
  os << indent << "LastError: " << (this->LastError.empty() ? "(none)" : this->LastError)
     << "\n";
}

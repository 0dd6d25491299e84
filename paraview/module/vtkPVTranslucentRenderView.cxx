#include "vtkPVTranslucentRenderView.h"

#include "vtkSubsurfacePass.h"

#include "vtkObjectFactory.h"
#include "vtkPVSynchronizedRenderer.h"

vtkStandardNewMacro(vtkPVTranslucentRenderView);

vtkPVTranslucentRenderView::vtkPVTranslucentRenderView()
{
  // Inside IceT's compositing pass when there are several ranks, the renderer's pass otherwise.
  this->SynchronizedRenderers->SetRenderPass(this->Subsurface);
}

vtkPVTranslucentRenderView::~vtkPVTranslucentRenderView() = default;

void vtkPVTranslucentRenderView::SetQualityPreset(const char* name)
{
  if (!name || !this->Subsurface->SetQualityPreset(name))
  {
    vtkErrorMacro(<< "QualityPreset: '" << (name ? name : "")
                  << "' is not a quality preset: use interactive, balanced or accurate");
    return;
  }
  this->Modified();
}

void vtkPVTranslucentRenderView::SetExposure(double exposure)
{
  this->Subsurface->SetExposure(exposure);
  this->Modified();
}

vtkSubsurfacePass* vtkPVTranslucentRenderView::GetSubsurfacePass()
{
  return this->Subsurface;
}

void vtkPVTranslucentRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "QualityPreset: " << this->Subsurface->GetQualityPresetAsString() << "\n";
  os << indent << "Exposure: " << this->Subsurface->GetExposure() << "\n";
}

#include "vtkPVTranslucentRenderView.h"

#include "vtkPVSubsurfacePieces.h"
#include "vtkSubsurfacePass.h"

#include "vtkLogger.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVSynchronizedRenderer.h"

vtkStandardNewMacro(vtkPVTranslucentRenderView);

vtkPVTranslucentRenderView::vtkPVTranslucentRenderView()
{
  // Inside IceT's compositing pass when there are several ranks, the renderer's pass otherwise.
  this->SynchronizedRenderers->SetRenderPass(this->Subsurface);
  // Several ranks: each holds a piece, and light visibility is reduced over all of them.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    vtkNew<vtkPVSubsurfacePieces> pieces;
    this->Subsurface->SetPieces(pieces);
  }
}

vtkPVTranslucentRenderView::~vtkPVTranslucentRenderView() = default;

void vtkPVTranslucentRenderView::Render(bool interactive, bool skip_rendering)
{
  if (!skip_rendering && !this->HasRendered)
  {
    // The first frame creates the window's context, which PrepareFrame needs.
    this->Superclass::Render(interactive, skip_rendering);
    this->HasRendered = true;
  }
  if (!skip_rendering)
  {
    this->Subsurface->PrepareFrame(this->GetRenderer());
    if (auto* pieces = vtkPVSubsurfacePieces::SafeDownCast(this->Subsurface->GetPieces()))
    {
      // What this rank put into the reductions for this frame (light maps, on a light move).
      vtkVLog(vtkLogger::VERBOSITY_1, "rank " << pieces->GetLocalPiece() << ": "
        << pieces->GetBytesReduced() - this->BytesReducedBefore << " bytes reduced this frame");
      this->BytesReducedBefore = pieces->GetBytesReduced();
    }
  }
  this->Superclass::Render(interactive, skip_rendering);
}

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

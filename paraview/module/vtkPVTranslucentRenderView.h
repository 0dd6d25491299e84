/**
 * @class vtkPVTranslucentRenderView
 * @brief ParaView's "Translucent Render View": a render view whose renderer draws through a
 * vtkSubsurfacePass, so that "Translucent Surfels" representations scatter the view's lights.
 *
 * Everything else is ParaView's render view (lights, camera, IceT compositing over MPI, which
 * composites the pass's output with its depth). Over MPI the pass's light maps are reduced
 * over the ranks (vtkPVSubsurfacePieces), so that one rank's piece shadows another's. The pass's settings are the view's: a quality
 * preset and the exposure of the tone mapping.
 */
#ifndef vtkPVTranslucentRenderView_h
#define vtkPVTranslucentRenderView_h

#include "sssParaViewModule.h"

#include "vtkNew.h"
#include "vtkPVRenderView.h"

class vtkSubsurfacePass;

class SSSPARAVIEW_EXPORT vtkPVTranslucentRenderView : public vtkPVRenderView
{
public:
  static vtkPVTranslucentRenderView* New();
  vtkTypeMacro(vtkPVTranslucentRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** interactive, balanced (the default) or accurate (vtkSubsurfacePass::SetQualityPreset). */
  void SetQualityPreset(const char* name);
  /** sRGB(clamp(Exposure * Lo)) for translucent pixels (default 1). */
  void SetExposure(double exposure);

  vtkSubsurfacePass* GetSubsurfacePass();

protected:
  vtkPVTranslucentRenderView();
  ~vtkPVTranslucentRenderView() override;

  // Steps 1-2 on every rank before the frame (vtkSubsurfacePass::PrepareFrame): their
  // reductions over ranks are collective, and IceT draws only the ranks whose piece it sees.
  void Render(bool interactive, bool skip_rendering) override;

  vtkNew<vtkSubsurfacePass> Subsurface;
  bool HasRendered = false;
  vtkIdType BytesReducedBefore = 0;

private:
  vtkPVTranslucentRenderView(const vtkPVTranslucentRenderView&) = delete;
  void operator=(const vtkPVTranslucentRenderView&) = delete;
};

#endif

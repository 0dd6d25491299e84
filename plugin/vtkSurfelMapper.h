/**
 * @class vtkSurfelMapper
 * @brief Draws a vtkPolyData's points as oriented discs (surfels) of one radius.
 *
 * Each point with a finite position and normal becomes a disc in the plane its normal defines.
 * Discs are expanded on the GPU into quads that lie in that plane, so depth is exact and there
 * is no point-size limit at close zoom. On its own the mapper shades discs with a two-sided
 * Lambert term under a headlight, using point colours (ScalarVisibility) or the actor's
 * colour. With a vtkTranslucentMaterial on the actor and a vtkSubsurfacePass in the renderer,
 * the pass supplies each surfel's radiance instead (it follows vtkOpenGLRenderPass's shader
 * replacement protocol). Cells are ignored: every point is a surfel.
 *
 * Points need 3-component point normals; points with a non-finite position or normal, or a
 * zero normal, are left out (the report says how many).
 */
#ifndef vtkSurfelMapper_h
#define vtkSurfelMapper_h

#include "sssTranslucencyModule.h"

#include "vtkPolyDataMapper.h"

#include <memory>
#include <string>

class vtkOpenGLRenderWindow;

namespace sss
{
struct PreparedSurfels;
}

class SSSTRANSLUCENCY_EXPORT vtkSurfelMapper : public vtkPolyDataMapper
{
public:
  static vtkSurfelMapper* New();
  vtkTypeMacro(vtkSurfelMapper, vtkPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Disc radius in scene units. 0 (the default) uses RadiusScale times the mean distance from
   * a point to its nearest neighbour.
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * The automatic radius over the mean point spacing (default 1.5). At 1 the discs of a
   * uniformly sampled surface touch, but seen from the light at grazing angles they leave
   * gaps through which the far side is lit, which is wrong and slows the pass down.
   */
  vtkSetClampMacro(RadiusScale, double, 0.01, 100.0);
  vtkGetMacro(RadiusScale, double);
  ///@}

  /** The radius in use (scene units) after the last update; 0 before the first. */
  double GetEffectiveRadius();

  /** Surfels drawn: input points with a finite position and normal. */
  vtkIdType GetNumberOfSurfels();

  /** Why nothing is drawn (no points, no normals), or an empty string. */
  std::string GetInputProblem();

  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

#ifndef __VTK_WRAP__
  /**
   * Brings the prepared surfels up to date with the input and returns them (for the pass).
   * Positions stay in scene units; the GPU buffers hold them relative to the bounds centre.
   */
  const sss::PreparedSurfels& UpdateSurfels(vtkActor* act);
  /** The time the prepared surfels last changed. */
  vtkMTimeType GetSurfelsTime() const;
#endif

protected:
  vtkSurfelMapper();
  ~vtkSurfelMapper() override;

  double Radius = 0.0;
  double RadiusScale = 1.5;

private:
  vtkSurfelMapper(const vtkSurfelMapper&) = delete;
  void operator=(const vtkSurfelMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif

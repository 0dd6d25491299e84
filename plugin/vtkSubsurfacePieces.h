/**
 * @class vtkSubsurfacePieces
 * @brief The other pieces of a cloud split over processes, as vtkSubsurfacePass needs them.
 *
 * Light visibility is global: a surfel is in shadow when any piece stands between it and the
 * light. With pieces set, the pass fits each light map over all pieces (the union of their
 * extents along the light) and keeps, in each texel, the surface nearest the light over all
 * of them: its own map's texels that another piece's surface is nearer in become shadow. The
 * sources near a piece (within the kernel's reach) are not this class's business: they come as
 * ghost surfels (vtkSurfelMapper). A subclass reduces over its processes, e.g. the ParaView
 * plugin's over MPI; every process must render the same translucent actors in the same order,
 * also with an empty piece, since each reduction is collective.
 */
#ifndef vtkSubsurfacePieces_h
#define vtkSubsurfacePieces_h

#include "sssTranslucencyModule.h"

#include "vtkObject.h"

class SSSTRANSLUCENCY_EXPORT vtkSubsurfacePieces : public vtkObject
{
public:
  vtkTypeMacro(vtkSubsurfacePieces, vtkObject);

  /** How many pieces (processes) the cloud is split into; 1 is the whole scene. */
  virtual int GetNumberOfPieces() = 0;

  ///@{
  /** The element-wise minimum over all pieces, in place. Collective. */
  virtual void MinimumOverPieces(double* values, vtkIdType count) = 0;
  virtual void MinimumOverPieces(float* values, vtkIdType count) = 0;
  ///@}

protected:
  vtkSubsurfacePieces() = default;
  ~vtkSubsurfacePieces() override = default;

private:
  vtkSubsurfacePieces(const vtkSubsurfacePieces&) = delete;
  void operator=(const vtkSubsurfacePieces&) = delete;
};

#endif

/**
 * @class vtkPVSubsurfacePieces
 * @brief The ranks of ParaView's global controller as the pieces of vtkSubsurfacePass: its
 * light maps reduced over MPI, so that a rank's piece shadows the others'.
 */
#ifndef vtkPVSubsurfacePieces_h
#define vtkPVSubsurfacePieces_h

#include "sssParaViewModule.h"

#include "vtkSubsurfacePieces.h"

class vtkMultiProcessController;

class SSSPARAVIEW_EXPORT vtkPVSubsurfacePieces : public vtkSubsurfacePieces
{
public:
  static vtkPVSubsurfacePieces* New();
  vtkTypeMacro(vtkPVSubsurfacePieces, vtkSubsurfacePieces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int GetNumberOfPieces() override;
  /** This rank's piece (its rank in the global controller). */
  int GetLocalPiece();
  void MinimumOverPieces(double* values, vtkIdType count) override;
  void MinimumOverPieces(float* values, vtkIdType count) override;

  /** Bytes this rank has sent in reductions since it was made (its share of the traffic). */
  vtkGetMacro(BytesReduced, vtkIdType);

protected:
  vtkPVSubsurfacePieces() = default;
  ~vtkPVSubsurfacePieces() override = default;

  vtkIdType BytesReduced = 0;

private:
  vtkPVSubsurfacePieces(const vtkPVSubsurfacePieces&) = delete;
  void operator=(const vtkPVSubsurfacePieces&) = delete;
};

#endif

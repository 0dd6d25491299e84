/**
 * @class vtkTranslucentSurfelsRepresentation
 * @brief ParaView's "Translucent Surfels": a point set with point normals drawn as surfels
 * of a translucent material (vtkSurfelMapper with a vtkTranslucentMaterial).
 *
 * The subsurface scattering itself is computed by the vtkSubsurfacePass of a
 * vtkPVTranslucentRenderView ("Translucent Render View"), from the view's lights; in another
 * render view the surfels are drawn opaque. Under MPI each rank keeps its piece and receives,
 * as ghost surfels, the points of the other ranks within the kernel's reach of it
 * (sssGhostSurfels.h): the near and the far field of each surfel are then complete, and the
 * view composites the ranks' images with IceT. Inputs without point normals are refused with
 * a message on the rank that holds them; an empty piece takes part in the exchange.
 */
#ifndef vtkTranslucentSurfelsRepresentation_h
#define vtkTranslucentSurfelsRepresentation_h

#include "sssParaViewModule.h"

#include "vtkNew.h"
#include "vtkPVDataRepresentation.h"

#include <string>

class vtkActor;
class vtkPolyData;
class vtkSurfelMapper;
class vtkTranslucentMaterial;

class SSSPARAVIEW_EXPORT vtkTranslucentSurfelsRepresentation : public vtkPVDataRepresentation
{
public:
  static vtkTranslucentSurfelsRepresentation* New();
  vtkTypeMacro(vtkTranslucentSurfelsRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void SetVisibility(bool visible) override;

  ///@{
  /**
   * The material: a preset name (marble, skimmilk, ketchup, ... as vtkTranslucentMaterial
   * knows them) or "custom", which takes SigmaA, SigmaSPrime and Eta (per mm). Default marble.
   */
  void SetMaterialName(const char* name);
  const char* GetMaterialName() const { return this->MaterialName.c_str(); }
  void SetSigmaA(double r, double g, double b);
  void SetSigmaSPrime(double r, double g, double b);
  void SetEta(double eta);
  ///@}

  /** Millimetres per scene unit (default 1: the cloud is in mm; 1000 for a scan in metres). */
  void SetMillimetresPerUnit(double mm);

  /** Ghost surfels of the last update, and the bytes this rank sent for them. */
  vtkGetMacro(GhostsReceived, vtkIdType);
  vtkGetMacro(GhostsSent, vtkIdType);
  vtkGetMacro(GhostBytesSent, vtkIdType);

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkTranslucentSurfelsRepresentation();
  ~vtkTranslucentSurfelsRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

  // Applies the custom coefficients when the material is "custom".
  void UpdateMaterial();

  std::string MaterialName;
  double CustomSigmaA[3];
  double CustomSigmaSPrime[3];
  double CustomEta;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkSurfelMapper> Mapper;
  vtkNew<vtkTranslucentMaterial> Material;
  vtkNew<vtkPolyData> Surfels;  // this rank's piece, then its ghosts
  vtkIdType GhostsReceived = 0;
  vtkIdType GhostsSent = 0;
  vtkIdType GhostBytesSent = 0;

private:
  vtkTranslucentSurfelsRepresentation(const vtkTranslucentSurfelsRepresentation&) = delete;
  void operator=(const vtkTranslucentSurfelsRepresentation&) = delete;
};

#endif

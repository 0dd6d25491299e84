#include "vtkTranslucentSurfelsRepresentation.h"

#include "sssGhostSurfels.h"
#include "vtkSurfelMapper.h"
#include "vtkTranslucentMaterial.h"

#include "vtkActor.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLogger.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPVView.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

#include "material.h"
#include "surfel_cloud.h"

#include <algorithm>

vtkStandardNewMacro(vtkTranslucentSurfelsRepresentation);

namespace
{

// The near field reaches two disc radii and a disc radius is at most a few mean spacings
// (vtkSurfelMapper's automatic radius); ghosts cover it with room to spare.
constexpr double kNearFieldSpacings = 8.0;

// The point normals of `input`: its active normals, else a 3-component array named "Normals".
vtkDataArray* point_normals(vtkPointSet* input)
{
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  if (!normals)
  {
    normals = input->GetPointData()->GetArray("Normals");
  }
  return normals && normals->GetNumberOfComponents() == 3 ? normals : nullptr;
}

double mean_spacing(vtkPointSet* input)
{
  sss::SurfelCloud cloud;
  cloud.positions.resize(static_cast<std::size_t>(input->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    cloud.positions[static_cast<std::size_t>(i)] = Eigen::Vector3d(p[0], p[1], p[2]);
  }
  return cloud.mean_spacing();
}

}

vtkTranslucentSurfelsRepresentation::vtkTranslucentSurfelsRepresentation()
{
  // The material starts as the default preset (material_presets.def), as the XML's defaults.
  this->MaterialName = sss::kDefaultPreset;
  this->CustomEta = this->Material->GetEta();
  std::copy_n(this->Material->GetSigmaA(), 3, this->CustomSigmaA);
  std::copy_n(this->Material->GetSigmaSPrime(), 3, this->CustomSigmaSPrime);
  this->Material->ApplyTo(this->Actor);
  this->Mapper->ScalarVisibilityOff();
  this->Actor->SetMapper(this->Mapper);
}

vtkTranslucentSurfelsRepresentation::~vtkTranslucentSurfelsRepresentation() = default;

void vtkTranslucentSurfelsRepresentation::SetVisibility(bool visible)
{
  this->Superclass::SetVisibility(visible);
  this->Actor->SetVisibility(visible);
}

void vtkTranslucentSurfelsRepresentation::SetMaterialName(const char* name)
{
  if (!name || this->MaterialName == name)
  {
    return;
  }
  if (std::string(name) != "custom" && !this->Material->SetPreset(name))
  {
    vtkErrorMacro(<< "TranslucentMaterial: unknown material '" << name
                  << "'; use custom or a preset of vtkTranslucentMaterial");
    return;
  }
  this->MaterialName = name;
  this->UpdateMaterial();
  this->MarkModified();
}

void vtkTranslucentSurfelsRepresentation::SetSigmaA(double r, double g, double b)
{
  this->CustomSigmaA[0] = r;
  this->CustomSigmaA[1] = g;
  this->CustomSigmaA[2] = b;
  this->UpdateMaterial();
}

void vtkTranslucentSurfelsRepresentation::SetSigmaSPrime(double r, double g, double b)
{
  this->CustomSigmaSPrime[0] = r;
  this->CustomSigmaSPrime[1] = g;
  this->CustomSigmaSPrime[2] = b;
  this->UpdateMaterial();
}

void vtkTranslucentSurfelsRepresentation::SetEta(double eta)
{
  this->CustomEta = eta;
  this->UpdateMaterial();
}

void vtkTranslucentSurfelsRepresentation::UpdateMaterial()
{
  if (this->MaterialName != "custom")
  {
    return;
  }
  this->Material->SetSigmaA(this->CustomSigmaA[0], this->CustomSigmaA[1], this->CustomSigmaA[2]);
  this->Material->SetSigmaSPrime(
    this->CustomSigmaSPrime[0], this->CustomSigmaSPrime[1], this->CustomSigmaSPrime[2]);
  this->Material->SetEta(this->CustomEta);
  const std::string problem = this->Material->Validate();
  if (!problem.empty())
  {
    vtkErrorMacro(<< "TranslucentMaterial custom: " << problem);
  }
  this->MarkModified();
}

void vtkTranslucentSurfelsRepresentation::SetMillimetresPerUnit(double mm)
{
  if (!(mm > 0.0))
  {
    vtkErrorMacro(<< "MillimetresPerUnit must be > 0, not " << mm);
    return;
  }
  this->Material->SetMillimetresPerUnit(mm);
  this->MarkModified();
}

int vtkTranslucentSurfelsRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkTranslucentSurfelsRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Every rank reaches the exchange below, whatever its piece holds: it is collective.
  vtkNew<vtkPolyData> piece;
  vtkPointSet* input = inputVector[0]->GetNumberOfInformationObjects() == 1
    ? vtkPointSet::GetData(inputVector[0], 0)
    : nullptr;
  if (input && input->GetNumberOfPoints() > 0)
  {
    if (vtkDataArray* normals = point_normals(input))
    {
      piece->SetPoints(input->GetPoints());
      piece->GetPointData()->SetNormals(normals);
    }
    else
    {
      vtkErrorMacro(<< "Translucent Surfels: the input (" << input->GetNumberOfPoints()
                    << " points) has no point normals (3-component point data, active normals "
                       "or an array named Normals); compute them first, e.g. with Generate "
                       "Surface Normals on a mesh or PCL's normal estimation on a scan");
    }
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  double reach = 0.0;
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    // The spacing (a k-d tree over the piece) only matters when there are other pieces.
    const double spacing = piece->GetNumberOfPoints() > 0 ? mean_spacing(piece) : 0.0;
    const double kernel_mm = this->Material->GetKernelReachMillimetres();
    reach = kernel_mm / this->Material->GetMillimetresPerUnit() + kNearFieldSpacings * spacing;
  }
  const sss::GhostReport ghosts =
    sss::add_ghost_surfels(controller, piece, reach, this->Surfels);
  // Each rank draws its own piece (distributed rendering is required below), so the mapper
  // takes it here, before the view's first frame prepares steps 1-2.
  this->Mapper->SetInputData(this->Surfels);
  this->GhostsReceived = ghosts.received;
  this->GhostsSent = ghosts.sent;
  this->GhostBytesSent = static_cast<vtkIdType>(ghosts.bytes_sent);
  if (ghosts.received > 0 || ghosts.sent > 0)
  {
    vtkLog(INFO, << "rank " << controller->GetLocalProcessId() << ": " << ghosts.own
                  << " own surfels, " << ghosts.received << " ghosts received, " << ghosts.sent
                  << " sent (" << ghosts.bytes_sent << " bytes)");
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkTranslucentSurfelsRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    // Each rank renders its own piece: its ghosts must not be gathered onto another rank.
    vtkPVView::SetPiece(inInfo, this, this->Surfels);
    vtkPVRenderView::SetRequiresDistributedRendering(inInfo, this, true);
    double bounds[6];
    this->Surfels->GetBounds(bounds);
    if (this->Surfels->GetNumberOfPoints() > 0)
    {
      vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds);
    }
  }
  return 1;
}

bool vtkTranslucentSurfelsRepresentation::AddToView(vtkView* view)
{
  if (auto* render_view = vtkPVRenderView::SafeDownCast(view))
  {
    render_view->GetRenderer()->AddActor(this->Actor);
    return this->Superclass::AddToView(view);
  }
  return false;
}

bool vtkTranslucentSurfelsRepresentation::RemoveFromView(vtkView* view)
{
  if (auto* render_view = vtkPVRenderView::SafeDownCast(view))
  {
    render_view->GetRenderer()->RemoveActor(this->Actor);
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

void vtkTranslucentSurfelsRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaterialName: " << this->MaterialName << "\n";
  os << indent << "MillimetresPerUnit: " << this->Material->GetMillimetresPerUnit() << "\n";
  os << indent << "Surfels (with ghosts): " << this->Surfels->GetNumberOfPoints() << "\n";
  os << indent << "GhostsReceived: " << this->GhostsReceived << "\n";
  os << indent << "GhostsSent: " << this->GhostsSent << "\n";
}

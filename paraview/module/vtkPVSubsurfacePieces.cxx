#include "vtkPVSubsurfacePieces.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"

#include <vector>

vtkStandardNewMacro(vtkPVSubsurfacePieces);

int vtkPVSubsurfacePieces::GetNumberOfPieces()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller ? controller->GetNumberOfProcesses() : 1;
}

void vtkPVSubsurfacePieces::MinimumOverPieces(double* values, vtkIdType count)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2 || count < 1)
  {
    return;
  }
  std::vector<double> mine(values, values + count);
  controller->AllReduce(mine.data(), values, count, vtkCommunicator::MIN_OP);
  this->BytesReduced += count * static_cast<vtkIdType>(sizeof(double));
}

void vtkPVSubsurfacePieces::MinimumOverPieces(float* values, vtkIdType count)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2 || count < 1)
  {
    return;
  }
  std::vector<float> mine(values, values + count);
  controller->AllReduce(mine.data(), values, count, vtkCommunicator::MIN_OP);
  this->BytesReduced += count * static_cast<vtkIdType>(sizeof(float));
}

void vtkPVSubsurfacePieces::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfPieces: " << this->GetNumberOfPieces() << "\n";
  os << indent << "BytesReduced: " << this->BytesReduced << "\n";
}

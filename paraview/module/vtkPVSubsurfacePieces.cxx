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

int vtkPVSubsurfacePieces::GetLocalPiece()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller ? controller->GetLocalProcessId() : 0;
}

namespace
{

// MIN over the global controller's ranks, in place; returns the bytes this rank sent.
template <typename T>
vtkIdType reduce_minimum(T* values, vtkIdType count)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2 || count < 1)
  {
    return 0;
  }
  std::vector<T> mine(values, values + count);
  controller->AllReduce(mine.data(), values, count, vtkCommunicator::MIN_OP);
  return count * static_cast<vtkIdType>(sizeof(T));
}

}

void vtkPVSubsurfacePieces::MinimumOverPieces(double* values, vtkIdType count)
{
  this->BytesReduced += reduce_minimum(values, count);
}

void vtkPVSubsurfacePieces::MinimumOverPieces(float* values, vtkIdType count)
{
  this->BytesReduced += reduce_minimum(values, count);
}

void vtkPVSubsurfacePieces::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfPieces: " << this->GetNumberOfPieces() << "\n";
  os << indent << "BytesReduced: " << this->BytesReduced << "\n";
}

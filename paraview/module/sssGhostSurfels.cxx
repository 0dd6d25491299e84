#include "sssGhostSurfels.h"

#include "vtkCommunicator.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <limits>
#include <vector>

namespace sss
{
namespace
{

constexpr int kGhostTag = 94017;

bool inside(const double p[3], const double* box)
{
  return p[0] >= box[0] && p[0] <= box[1] && p[1] >= box[2] && p[1] <= box[3] &&
    p[2] >= box[4] && p[2] <= box[5];
}

// The points of `piece` inside `box` (none for an empty box), with their normals.
vtkSmartPointer<vtkPolyData> points_inside(vtkPolyData* piece, const double* box)
{
  auto subset = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkDataArray* given = piece->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
  {
    double p[3];
    piece->GetPoint(i, p);
    if (inside(p, box))
    {
      points->InsertNextPoint(p);
      double n[3];
      given->GetTuple(i, n);
      normals->InsertNextTuple(n);
    }
  }
  subset->SetPoints(points);
  subset->GetPointData()->SetNormals(normals);
  return subset;
}

// Appends `from`'s points and normals to `points` and `normals`, flagged `flag`.
void append(vtkPolyData* from, unsigned char flag, vtkPoints* points, vtkFloatArray* normals,
  vtkUnsignedCharArray* ghosts)
{
  vtkDataArray* n = from->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < from->GetNumberOfPoints(); ++i)
  {
    points->InsertNextPoint(from->GetPoint(i));
    normals->InsertNextTuple(n->GetTuple(i));
    ghosts->InsertNextValue(flag);
  }
}

}

GhostReport add_ghost_surfels(
  vtkMultiProcessController* controller, vtkPolyData* piece, double reach, vtkPolyData* out)
{
  GhostReport report;
  report.own = piece->GetNumberOfPoints();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  append(piece, 0, points, normals, ghosts);
  if (ranks > 1)
  {
    // This rank's reach: its bounds grown by `reach`; an empty piece reaches nothing.
    std::array<double, 6> box;
    const double inf = std::numeric_limits<double>::infinity();
    box = { inf, -inf, inf, -inf, inf, -inf };
    if (report.own > 0)
    {
      piece->GetBounds(box.data());
      for (int a = 0; a < 3; ++a)
      {
        box[2 * a] -= reach;
        box[2 * a + 1] += reach;
      }
    }
    std::vector<double> boxes(6 * static_cast<std::size_t>(ranks));
    controller->AllGather(box.data(), boxes.data(), 6);
    const int me = controller->GetLocalProcessId();
    // Pairwise, in rank order: the lower rank of each pair sends first, so that blocking sends
    // cannot wait on each other in a cycle.
    for (int other = 0; other < ranks; ++other)
    {
      if (other == me)
      {
        continue;
      }
      vtkSmartPointer<vtkPolyData> outgoing = points_inside(piece, &boxes[6 * other]);
      vtkNew<vtkPolyData> incoming;
      if (me < other)
      {
        controller->Send(outgoing, other, kGhostTag);
        controller->Receive(incoming, other, kGhostTag);
      }
      else
      {
        controller->Receive(incoming, other, kGhostTag);
        controller->Send(outgoing, other, kGhostTag);
      }
      report.sent += outgoing->GetNumberOfPoints();
      report.bytes_sent += static_cast<std::size_t>(outgoing->GetNumberOfPoints()) *
        (3 * sizeof(double) + 3 * sizeof(float));
      if (incoming->GetNumberOfPoints() > 0 && incoming->GetPointData()->GetNormals())
      {
        report.received += incoming->GetNumberOfPoints();
        append(incoming, vtkDataSetAttributes::DUPLICATEPOINT, points, normals, ghosts);
      }
    }
  }
  out->Initialize();
  out->SetPoints(points);
  out->GetPointData()->SetNormals(normals);
  out->GetPointData()->AddArray(ghosts);
  return report;
}

}

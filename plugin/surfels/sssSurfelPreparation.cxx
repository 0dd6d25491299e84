#include "sssSurfelPreparation.h"

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace sss
{
namespace
{

// Puts the kept points that VTK's ghost array marks as duplicates (another piece owns them)
// after the owned ones, keeping each group's order; returns how many are owned.
std::size_t owned_first(SurfelCloud& cloud, vtkPolyData* input)
{
  vtkDataArray* ghosts = input->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName());
  if (!ghosts || ghosts->GetNumberOfComponents() != 1)
  {
    return cloud.size();
  }
  auto is_ghost = [&](std::size_t k) {
    const auto flags = static_cast<unsigned>(ghosts->GetComponent(
      static_cast<vtkIdType>(cloud.input_index[k]), 0));
    return (flags & vtkDataSetAttributes::DUPLICATEPOINT) != 0;
  };
  std::vector<std::size_t> order(cloud.size());
  std::iota(order.begin(), order.end(), std::size_t{ 0 });
  const auto split = std::stable_partition(
    order.begin(), order.end(), [&](std::size_t k) { return !is_ghost(k); });
  const auto owned = static_cast<std::size_t>(split - order.begin());
  if (owned == cloud.size())
  {
    return owned;
  }
  auto permute = [&order](auto& values) {
    if (values.empty())
    {
      return;
    }
    auto copy = values;
    for (std::size_t k = 0; k < order.size(); ++k)
    {
      values[k] = copy[order[k]];
    }
  };
  permute(cloud.positions);
  permute(cloud.normals);
  permute(cloud.radii);
  permute(cloud.input_index);
  return owned;
}

}

PreparedSurfels prepare_surfels(vtkPolyData* input, const RadiusChoice& choice,
  vtkUnsignedCharArray* colours, const std::array<std::uint8_t, 4>& fallback)
{
  PreparedSurfels prepared;
  if (!input || !input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    prepared.error = "the input has no points";
    return prepared;
  }
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    prepared.error = "the input has no point normals (3-component vtkPointData normals); "
                     "compute them first, e.g. with the PCL glue or vtkPCANormalEstimation";
    return prepared;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  vtkDataArray* given = choice.radius_array.empty()
    ? nullptr
    : input->GetPointData()->GetArray(choice.radius_array.c_str());
  if (!choice.radius_array.empty() && (!given || given->GetNumberOfComponents() != 1))
  {
    prepared.error = "the radius array \"" + choice.radius_array +
      "\" is not a 1-component point-data array of the input";
    return prepared;
  }
  SurfelCloud& cloud = prepared.cloud;
  cloud.positions.resize(n);
  cloud.normals.resize(n);
  if (given)
  {
    cloud.radii.resize(n);
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], q[3];
    input->GetPoints()->GetPoint(i, p);
    normals->GetTuple(i, q);
    cloud.positions[i] = Eigen::Vector3d(p[0], p[1], p[2]);
    cloud.normals[i] = Eigen::Vector3d(q[0], q[1], q[2]);
    if (given)
    {
      cloud.radii[i] = given->GetComponent(i, 0);
    }
  }
  cloud.radius = 1.0;  // placeholder until the spacing of the kept points is known
  try
  {
    prepared.report = cloud.validate();
  }
  catch (const std::invalid_argument& e)
  {
    prepared.error = e.what();
    return prepared;
  }
  if (cloud.empty())
  {
    prepared.error = "no point has a finite position and normal (" + prepared.report.summary() + ")";
    return prepared;
  }
  prepared.drawn = owned_first(cloud, input);
  if (choice.radius > 0.0)
  {
    cloud.radius = choice.radius;
    prepared.view_radius = choice.radius;
  }
  else
  {
    const SplatRadii radii =
      choose_splat_radii(cloud, choice.mode, choice.coverage_target, choice.scale);
    cloud.radius = radii.radius;
    prepared.view_radius = radii.view_radius;
    prepared.uncovered = radii.view_uncovered;
    prepared.spacing_spread = radii.spacing_spread;
    if (!given)
    {
      cloud.radii = radii.per_point;
    }
  }
  prepared.per_point_radii = !cloud.radii.empty();
  if (prepared.per_point_radii)
  {
    std::vector<double> sorted = cloud.radii;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    prepared.view_radius = sorted[sorted.size() / 2];
  }
  else
  {
    cloud.radii.assign(cloud.size(), prepared.view_radius);  // the light maps' discs too
  }
  const Eigen::Vector3d c = cloud.bounds().frame_origin();
  prepared.centre = { { c.x(), c.y(), c.z() } };
  prepared.rgba.resize(4 * cloud.size());
  const bool perPoint = colours && colours->GetNumberOfComponents() == 4 &&
    colours->GetNumberOfTuples() == n;
  for (std::size_t k = 0; k < cloud.size(); ++k)
  {
    for (int c4 = 0; c4 < 4; ++c4)
    {
      prepared.rgba[4 * k + c4] = perPoint
        ? colours->GetValue(static_cast<vtkIdType>(4 * cloud.input_index[k] + c4))
        : fallback[c4];
    }
  }
  return prepared;
}

bool radiance_in_surfel_order(
  const PreparedSurfels& surfels, vtkFloatArray* given, std::vector<Rgb>& B)
{
  if (!given || given->GetNumberOfComponents() != 3 ||
    given->GetNumberOfTuples() != static_cast<vtkIdType>(surfels.report.input))
  {
    return false;
  }
  B.resize(surfels.cloud.size());
  for (std::size_t k = 0; k < B.size(); ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      B[k][c] = given->GetValue(static_cast<vtkIdType>(3 * surfels.cloud.input_index[k] + c));
    }
  }
  return true;
}

void radiance_in_input_order(
  const PreparedSurfels& surfels, const std::vector<Rgb>& values, vtkFloatArray* B)
{
  B->SetNumberOfComponents(3);
  B->SetNumberOfTuples(static_cast<vtkIdType>(surfels.report.input));
  B->Fill(std::numeric_limits<float>::quiet_NaN());
  for (std::size_t k = 0; k < values.size() && k < surfels.cloud.input_index.size(); ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      B->SetValue(static_cast<vtkIdType>(3 * surfels.cloud.input_index[k] + c),
        static_cast<float>(values[k][c]));
    }
  }
}

}

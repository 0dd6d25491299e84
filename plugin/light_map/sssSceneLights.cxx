#include "sssSceneLights.h"

#include "sssGpuHelpers.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"

#include <Eigen/Dense>

#include <cmath>

namespace sss
{

std::vector<GpuLight> gather_scene_lights(vtkRenderer* renderer, std::vector<std::string>& notes)
{
  std::vector<GpuLight> lights;
  if (renderer->GetLights()->GetNumberOfItems() == 0 && renderer->GetAutomaticLightCreation())
  {
    renderer->CreateLight();  // the headlight VTK would add later in this frame
  }
  vtkLightCollection* collection = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (!light->GetSwitch() || light->GetIntensity() <= 0.0)
    {
      continue;
    }
    double p[3], f[3], c[3];
    light->GetTransformedPosition(p);
    light->GetTransformedFocalPoint(f);
    light->GetDiffuseColor(c);
    const Eigen::Vector3d position(p[0], p[1], p[2]);
    const Eigen::Vector3d d = position - Eigen::Vector3d(f[0], f[1], f[2]);
    if (!d.allFinite() || d.norm() == 0.0)
    {
      notes.push_back("a light's position equals its focal point; it is left out");
      continue;
    }
    GpuLight g;
    g.light.direction = d.normalized();
    g.light.positional = light->GetPositional() != 0;
    if (g.light.positional)
    {
      double a[3];
      light->GetAttenuationValues(a);
      g.light.position = position;
      g.light.attenuation = Eigen::Vector3d(a[0], a[1], a[2]);
      g.light.cone_angle = light->GetConeAngle();
      g.light.exponent = light->GetExponent();
    }
    const double e = light->GetIntensity();
    g.irradiance = { e * c[0], e * c[1], e * c[2] };
    lights.push_back(g);
  }
  if (lights.size() > static_cast<std::size_t>(kMaxLights))
  {
    notes.push_back(
      "only the first " + std::to_string(kMaxLights) + " lights light translucent actors");
    lights.resize(kMaxLights);
  }
  return lights;
}

double model_scale(vtkMatrix4x4* model_to_world)
{
  return std::cbrt(std::fabs(model_to_world->Determinant()));
}

std::vector<GpuLight> lights_in_model_frame(
  const std::vector<GpuLight>& world, vtkMatrix4x4* model_to_world)
{
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      m(r, c) = model_to_world->GetElement(r, c);
    }
  }
  const Eigen::Matrix3d linear = m.block<3, 3>(0, 0);
  const Eigen::Matrix3d inverse = linear.inverse();
  const double scale = model_scale(model_to_world);
  std::vector<GpuLight> local = world;
  for (GpuLight& g : local)
  {
    g.light.direction = (inverse * g.light.direction).normalized();
    if (g.light.positional)
    {
      g.light.position = inverse * (g.light.position - m.block<3, 1>(0, 3));
      g.light.attenuation[1] *= scale;
      g.light.attenuation[2] *= scale * scale;
    }
  }
  return local;
}

}

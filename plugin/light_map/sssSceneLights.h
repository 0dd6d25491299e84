// The renderer's lights as the translucent actors see them: each switched-on vtkLight (the
// headlight VTK would add included), directional or positional (a point light, or a spot below
// a cone angle of 90 degrees, with VTK's attenuation and exponent), first in world coordinates
// and then in one actor's model frame.
#ifndef sssSceneLights_h
#define sssSceneLights_h

#include "sssLightMaps.h"

#include <string>
#include <vector>

class vtkMatrix4x4;
class vtkRenderer;

namespace sss
{

// At most kMaxLights lights, world frame and units; `notes` says which lights were left out
// and why.
std::vector<GpuLight> gather_scene_lights(vtkRenderer* renderer, std::vector<std::string>& notes);

// World units per model unit of a model matrix (a rotation, a uniform scale and a translation).
double model_scale(vtkMatrix4x4* model_to_world);

// The same lights in the frame of an actor with this model matrix (a rotation, a uniform scale
// and a translation): directions, positions, and attenuation per model unit.
std::vector<GpuLight> lights_in_model_frame(
  const std::vector<GpuLight>& world, vtkMatrix4x4* model_to_world);

}

#endif

#include "sssFarField.h"

#include "sssLitCells.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <algorithm>

namespace sss
{

namespace
{
constexpr int kWalkRoot = 7;  // pyramid level whose nodes the far field's quads start from
}

void add_far_field(vtkOpenGLState* state, vtkOpenGLQuadHelper& quad, vtkShaderProgram* program,
  const LitCells& cells, int lights, const FarFieldSettings& settings)
{
  program->SetUniformf("openingAngle", static_cast<float>(settings.opening_angle));
  program->SetUniformf(
    "maxGroupDiffusionLengths", static_cast<float>(settings.max_group_diffusion_lengths));
  program->SetUniformf("supportRadius", static_cast<float>(settings.support_radius));
  const float reach[3] = { static_cast<float>(settings.size_bound_reach[0]),
    static_cast<float>(settings.size_bound_reach[1]),
    static_cast<float>(settings.size_bound_reach[2]) };
  program->SetUniform3f("sizeBoundReach", reach);
  program->SetUniformi("addNearField", 0);
  program->SetUniformi("addFarField", 1);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFunc(GL_ONE, GL_ONE);
  // One quad per light and node of its pyramid's level kWalkRoot (or its top), so that no
  // fragment walks more than (4^(kWalkRoot + 1) - 1) / 3 nodes: llvmpipe stops a shader
  // invocation's loops after 65,535 iterations in all.
  for (int l = 0; l < lights; ++l)
  {
    const int level = std::min(cells.levels(l) - 1, kWalkRoot);
    program->SetUniformi("walkLight", l);
    for (int y = 0; y < cells.level_height(l, level); ++y)
    {
      for (int x = 0; x < cells.level_width(l, level); ++x)
      {
        const int root[2] = { x, y };
        program->SetUniform2i("walkRoot", root);
        program->SetUniformi("walkRootLevel", level);
        quad.Render();
      }
    }
  }
}

}

#include "sssFarField.h"

#include "sssLitCells.h"

#include "stopwatch.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

namespace sss
{

namespace
{
constexpr int kWalkRoot = 7;  // pyramid level whose nodes the far field's quads start from
}

namespace
{
int walk_root_level(const LitCells& cells, int light)
{
  return std::min(cells.levels(light) - 1, kWalkRoot);
}
}

int far_field_parts(const LitCells& cells, int lights)
{
  int parts = 0;
  for (int l = 0; l < lights; ++l)
  {
    const int level = walk_root_level(cells, l);
    parts += cells.level_width(l, level) * cells.level_height(l, level);
  }
  return parts;
}

void add_far_field(vtkOpenGLState* state, vtkOpenGLQuadHelper& quad, vtkShaderProgram* program,
  const LitCells& cells, int lights, const FarFieldSettings& settings,
  FarFieldProgress& progress, double seconds)
{
  Stopwatch clock;
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
  progress.total = far_field_parts(cells, lights);
  int part = 0;  // this quad's place among all of them
  int drawn_here = 0;
  for (int l = 0; l < lights; ++l)
  {
    const int level = walk_root_level(cells, l);
    const int roots = cells.level_width(l, level) * cells.level_height(l, level);
    program->SetUniformi("walkLight", l);
    program->SetUniformi("walkRootLevel", level);
    for (int k = 0; k < roots; ++k, ++part)
    {
      if (part < progress.drawn || (drawn_here > 0 && clock.seconds() >= seconds))
      {
        continue;  // drawn by an earlier call, or left to a later one
      }
      const int root[2] = { k % cells.level_width(l, level), k / cells.level_width(l, level) };
      program->SetUniform2i("walkRoot", root);
      quad.Render();
      ++progress.drawn;
      ++drawn_here;
      if (std::isfinite(seconds))
      {
        glFinish();
      }
    }
  }
}

}

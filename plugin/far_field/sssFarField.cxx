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
// A quad drawn in parts: its narrowest band of rows, and how much wider than the narrowest
// yet a band may grow.
constexpr int kMostBandsPerQuad = 64;
constexpr int kWidestBand = 4;
}

namespace
{
int walk_root_level(const LitCells& cells, int pyramid)
{
  return std::min(cells.levels(pyramid) - 1, kWalkRoot);
}
}

int far_field_parts(const LitCells& cells)
{
  int parts = 0;
  for (int p = 0; p < cells.pyramids(); ++p)
  {
    const int level = walk_root_level(cells, p);
    parts += cells.level_width(p, level) * cells.level_height(p, level);
  }
  return parts;
}

double FarFieldProgress::share(int rows) const
{
  if (total <= 0)
  {
    return 1.0;
  }
  return (drawn + static_cast<double>(rows_drawn) / std::max(rows, 1)) / total;
}

void FarFieldProgress::fit_band(double took, int rows)
{
  if (took > band_seconds)
  {
    band_rows = std::max(std::max(1, rows / kMostBandsPerQuad),
      static_cast<int>(band_rows * band_seconds / took));
  }
  else if (took < 0.25 * band_seconds)
  {
    // Wider where receivers are cheap (far from the root's cells), but at most kWidestBand
    // times this move's narrowest: the costly rows may follow.
    band_rows = std::min({ rows, 2 * band_rows, kWidestBand * narrowest_band });
  }
  narrowest_band = std::min(narrowest_band, band_rows);
}

void add_far_field(vtkOpenGLState* state, vtkOpenGLQuadHelper& quad, vtkShaderProgram* program,
  const LitCells& cells, int rows, const FarFieldSettings& settings,
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
  const bool in_parts = std::isfinite(seconds);
  // Bands sized to the frame's time; with none, whole quads (a part a frame).
  const bool banded = in_parts && progress.band_seconds > 0.0;
  if (progress.band_rows <= 0 || !banded)
  {
    progress.band_rows = rows;
  }
  if (progress.narrowest_band <= 0)
  {
    progress.narrowest_band = progress.band_rows;
  }
  vtkOpenGLState::ScopedglScissor scissor_saved(state);
  vtkOpenGLState::ScopedglEnableDisable scissor_test_saved(state, GL_SCISSOR_TEST);
  state->vtkglEnable(GL_SCISSOR_TEST);
  GLint viewport[4];
  state->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  if (in_parts)
  {
    glFinish();  // the steps before, so that the first band's time is its own
  }
  // One quad per pyramid and node of its level kWalkRoot (or its top), so that no
  // fragment walks more than (4^(kWalkRoot + 1) - 1) / 3 nodes: llvmpipe stops a shader
  // invocation's loops after 65,535 iterations in all.
  progress.total = far_field_parts(cells);
  int part = 0;  // this quad's place among all of them
  int drawn_here = 0;
  for (int p = 0; p < cells.pyramids(); ++p)
  {
    const int level = walk_root_level(cells, p);
    const int roots = cells.level_width(p, level) * cells.level_height(p, level);
    program->SetUniformi("walkPyramid", p);
    program->SetUniformi("walkRootLevel", level);
    for (int k = 0; k < roots; ++k, ++part)
    {
      if (part < progress.drawn)
      {
        continue;  // drawn by an earlier call
      }
      const int root[2] = { k % cells.level_width(p, level), k / cells.level_width(p, level) };
      program->SetUniform2i("walkRoot", root);
      // The rows left of this quad (all of them unless an earlier call drew some), in bands.
      while (progress.rows_drawn < rows)
      {
        if (drawn_here > 0 && clock.seconds() >= seconds)
        {
          return;  // left to a later call
        }
        const int band = std::min(progress.band_rows, rows - progress.rows_drawn);
        state->vtkglScissor(viewport[0], viewport[1] + progress.rows_drawn, viewport[2], band);
        const double before = clock.seconds();
        quad.Render();
        progress.rows_drawn += band;
        ++drawn_here;
        if (!in_parts)
        {
          continue;
        }
        glFinish();
        if (banded)
        {
          progress.fit_band(clock.seconds() - before, rows);
        }
      }
      progress.rows_drawn = 0;
      ++progress.drawn;
    }
  }
}

}

// Step 2, what a light move changes: each surfel's cell lit through the light maps (its E,
// eq. 15, from several samples over the cell tested for visibility, summed over the lights on
// each side of the surfel: surfel_irradiance_fs.glsl; the cells whose samples disagree lit
// again with more, packed apart: refined_cells_fs.glsl) and, where there is a far field, the
// source pyramids over the surfel list (reduce: lit_cell_sources_fs.glsl,
// pyramid_reduce_fs.glsl): per node the power-weighted point,
// normal and power of the cells under it and their second moments, for the far field's walk
// (far_field.glsl). Eq. 17 is linear in E, so the lights share the pyramids: one holds each
// cell's more lit side, one its other side (one light: a single pyramid), whatever the number
// of lights.
#ifndef sssLitCells_h
#define sssLitCells_h

#include "material.h"
#include "sssGpuHelpers.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace sss
{

class SurfelList;
struct LightMapAtlas;

class LitCells
{
public:
  static constexpr int kSources = 8;  // pyramid textures (at most 8 draw buffers)

  LitCells();
  ~LitCells();

  // The Fresnel table of the material's eta.
  void bake(vtkOpenGLRenderWindow* window, const Material& material);
  // E for the lights of `maps`, from `cell_samples` points per cell and light (eight times as
  // many for a light whose points disagree: an edge crosses the cell; `refined` counts those
  // cells); `disc_radius` (mm) bounds the curvature that lifts a cell's samples.
  bool light(vtkOpenGLRenderWindow* window, const SurfelList& list, const LightMapAtlas& maps,
    double disc_radius, int cell_samples, std::size_t& refined, std::string& error);
  // The upward pass, only where a far field needs it: the source pyramids' finest level from
  // E (both sides of each cell) and the coarser levels from it. `lit` counts the lit cells
  // (twice where both sides are lit).
  bool reduce(vtkOpenGLRenderWindow* window, const SurfelList& list, std::size_t& lit,
    std::string& error);

  // far_field.glsl's and near_field.glsl's textures: E and the pyramids (where reduce() built
  // them), bound for `program`.
  void activate(vtkShaderProgram* program) const;
  void deactivate() const;
  // The pyramids of the last reduce(): 1 for one light, else kMaxPyramids.
  int pyramids() const;
  // Levels of pyramid p: their count and the nodes of a level.
  int levels(int pyramid) const;
  int level_width(int pyramid, int level) const;
  int level_height(int pyramid, int level) const;

  void release(vtkWindow* window);

private:
  struct Rect
  {
    int x, y, width, height;
  };
  void allocate_irradiance(vtkOpenGLRenderWindow* window, int width, int height);
  void allocate_pyramids(vtkOpenGLRenderWindow* window, int width, int height, int pyramids);
  // E on each side, active and bound as frontIrradiance and backIrradiance for `program`.
  void activate_irradiance(vtkShaderProgram* program) const;
  // The cells that the first pass marked in the front's alpha, lit again (with
  // `refined_samples` points for the lights marked, `cell_samples` for the others) in a block
  // of their own and written back by `scatter` (refined_cells_scatter_vs.glsl); returns how
  // many. The light maps, the list and the Fresnel table must be active.
  std::size_t refine(vtkOpenGLRenderWindow* window, const SurfelList& list,
    const LightMapAtlas& maps, double disc_radius, int cell_samples, int refined_samples,
    vtkShaderProgram* scatter);

  // E on the front and back of each surfel (the list's layout), and the pyramids' atlas:
  // point, power, normal, then the moments of points, normals and their cross term.
  // lit_cell_sources_fs.glsl writes the first kCellSources at level 0; a cell's normal is
  // constant, so the others are 0 there.
  static constexpr int kCellSources = 5;
  vtkSmartPointer<vtkTextureObject> E_[2], source_[kSources], fresnel_;
  int atlas_pyramids_ = 0, atlas_width_ = 0, atlas_height_ = 0;
  int lights_ = 0;  // of the last light()
  std::vector<std::vector<Rect>> levels_;  // per pyramid: its levels
  vtkNew<vtkOpenGLFramebufferObject> fbo_;
  std::unique_ptr<vtkOpenGLQuadHelper> irradiance_quad_, refined_quad_, sources_quad_,
    reduce_quad_;
  // The refined cells: their texels (a texture for refined_cells_fs.glsl, a vertex buffer
  // for the scatter back) and their E on each side.
  vtkSmartPointer<vtkTextureObject> refined_cell_, refined_E_[2];
  vtkNew<vtkOpenGLBufferObject> refined_texels_;
  ProgramVAO scatter_vao_;
};

}

#endif

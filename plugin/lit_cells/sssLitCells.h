// Step 2, what a light move changes: each surfel's cell lit through the light maps (its E,
// eq. 15, from several samples over the cell tested for visibility: surfel_irradiance_fs.glsl;
// the cells whose samples disagree lit again with more, packed apart: refined_cells_fs.glsl)
// and each light's source pyramid over the surfel list (pyramid_reduce_fs.glsl): per node the
// power-weighted point, normal and power of the cells under it and their second moments, for
// the far field's walk (far_field.glsl).
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
  // E and the finest level of each light's source pyramid for the lights of `maps`, from
  // `cell_samples` points per cell and light (eight times as many where they disagree: an
  // edge crosses the cell; `refined` counts those cells over all lights); `disc_radius` (mm)
  // bounds the curvature that lifts a cell's samples.
  bool light(vtkOpenGLRenderWindow* window, const SurfelList& list, const LightMapAtlas& maps,
    double disc_radius, int cell_samples, std::size_t& refined, std::string& error);
  // The upward pass: the coarser levels of each pyramid from the finest. `lit` counts the
  // lit cells over all lights.
  void reduce(vtkOpenGLRenderWindow* window, std::size_t& lit);

  // far_field.glsl's and near_field.glsl's textures: the pyramids and E, bound for `program`.
  void activate(vtkShaderProgram* program) const;
  void deactivate() const;
  // Levels of light l's pyramid: their count and the nodes of a level.
  int levels(int light) const;
  int level_width(int light, int level) const;
  int level_height(int light, int level) const;

  void release(vtkWindow* window);

private:
  struct Rect
  {
    int x, y, width, height;
  };
  void allocate(vtkOpenGLRenderWindow* window, int width, int height, int lights);
  // Light l's cells that the first pass marked in E's alpha, lit again with
  // `refined_samples` points in a block of their own and written back by `scatter`
  // (refined_cells_scatter_vs.glsl); returns how many. The light maps, the list and the
  // Fresnel table must be active.
  std::size_t refine(vtkOpenGLRenderWindow* window, const SurfelList& list,
    const LightMapAtlas& maps, double disc_radius, int refined_samples,
    vtkShaderProgram* scatter, int l);

  // Per light atlases: E, and the source pyramid: point, power, normal, then the moments of
  // points, normals and their cross term. The irradiance pass writes the first kCellSources
  // at level 0; a cell's normal is constant, so the others are 0 there.
  static constexpr int kCellSources = 5;
  vtkSmartPointer<vtkTextureObject> E_, source_[kSources], fresnel_;
  int atlas_lights_ = 0, atlas_width_ = 0, atlas_height_ = 0;
  int lights_ = 0;  // of the last light()
  std::vector<std::vector<Rect>> levels_;  // per light: the pyramid's levels
  vtkNew<vtkOpenGLFramebufferObject> fbo_;
  std::unique_ptr<vtkOpenGLQuadHelper> irradiance_quad_, refined_quad_, reduce_quad_;
  // The refined cells: their texels (a texture for refined_cells_fs.glsl, a vertex buffer
  // for the scatter back) and their E.
  vtkSmartPointer<vtkTextureObject> refined_cell_, refined_E_;
  vtkNew<vtkOpenGLBufferObject> refined_texels_;
  ProgramVAO scatter_vao_;
};

}

#endif

// Step 1: the light maps. Each light sees the actor's surfels in a map of its own (core's
// LightView: orthographic along a directional light, perspective from a positional one), all
// lights' maps side by side in one atlas. For the surfel pipeline a texel holds
// the list texel of the surfel the light sees first there; for the paper's method, the point,
// power and normal of eq. 15 (illumination_fs.glsl).
#ifndef sssLightMaps_h
#define sssLightMaps_h

#include "light_map.h"
#include "sssLightMapPieces.h"
#include "material.h"
#include "sssGpuHelpers.h"

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"  // vtkNew of the discs' buffers
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"  // the maps' accessors convert smart pointers

#include <Eigen/Core>
#include <string>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkSubsurfacePieces;
class vtkWindow;

namespace sss
{

struct LocalSurfels;
struct SurfelBuffers;

// A light in the actor's model frame and units, with its colour.
struct GpuLight
{
  Light light;  // its irradiance is 1; `irradiance` holds it per channel
  Rgb irradiance;
  bool operator==(const GpuLight& o) const
  {
    return light == o.light && irradiance == o.irradiance;
  }
};

// What step 1 hands to step 2: the light maps (one atlas) and their lights.
struct LightMapAtlas
{
  vtkTextureObject* surfel = nullptr;  // the seen surfel's list texel; x < 0: none
  struct Map
  {
    int x = 0, y = 0;  // where it lies in the atlas
    LightView view;    // local frame
    LocalLight light;  // local frame; its irradiance is 1
    Rgb irradiance{};
    int width() const { return view.width(); }
    int height() const { return view.height(); }
  };
  std::vector<Map> maps;
};

// What the maps hold and how fine they are.
struct LightMapRequest
{
  bool paper = false;            // the paper's maps: eq. 15 per texel, as fine as they may be
  double texel_per_radius = 0;   // otherwise: texel over the disc radius
  int max_map_size = 0;          // at most this many texels a side (the paper's: 512)
  vtkOpenGLBufferObject* list_texel = nullptr;  // each surfel's list texel (not the paper)
  vtkSubsurfacePieces* pieces = nullptr;  // the cloud's other pieces (not the paper), or none
};

struct LightMapReport
{
  int map_width = 0, map_height = 0;  // the first light's map
  double texel_mm = 0;
  std::vector<std::string> notes;     // lights drawn otherwise than asked, and why
};

class GpuLightMaps
{
public:
  // At a bake: each disc's curvature and radius as the lights see it (beside the shared
  // buffers), the material's eta and whether colours are albedo (the paper's maps).
  void set_surfels(const LocalSurfels& local, const Material& material, bool albedo_from_colour);

  // Draws every light's map of the surfels: `buffers` (scene units, sssSurfelBuffers) with the
  // discs of set_surfels, in `local`'s frame (mm).
  bool render(vtkOpenGLRenderWindow* window, const SurfelBuffers& buffers,
    const LocalSurfels& local, const std::vector<GpuLight>& lights,
    const LightMapRequest& request, LightMapReport& report, std::string& error);

  // A piece without surfels still takes part in the other pieces' reductions of the maps of
  // these lights (sssLightMapPieces.h).
  static void take_part_without_surfels(
    vtkSubsurfacePieces* pieces, const std::vector<GpuLight>& lights, int max_map_size);

  LightMapAtlas atlas() const;
  // The paper's maps: point, power and normal per texel.
  vtkTextureObject* point() const { return point_; }
  vtkTextureObject* power() const { return power_; }
  vtkTextureObject* normal() const { return normal_; }

  void release(vtkWindow* window);

private:
  // How each light's map is fitted: as directional only (the paper's), texels of `texel` mm
  // up to `max_size` a side, over every piece of a split cloud (or none).
  struct MapFit
  {
    bool directional_only;
    double texel;
    int max_size;
    vtkSubsurfacePieces* pieces;
  };
  // Each light's view fitted to the surfels, placed side by side in the atlas (maps_); the
  // atlas's size, and the pieces' fits.
  void lay_out(const LocalSurfels& local, const std::vector<GpuLight>& lights, const MapFit& fit,
    std::vector<PieceMap>& fits, LightMapReport& report, int& atlas_w, int& atlas_h);
  // The maps' program for the request's kind of map, its VAO bound to `buffers` and the
  // discs; nullptr if it did not compile.
  vtkShaderProgram* ready_program(
    vtkOpenGLRenderWindow* window, const SurfelBuffers& buffers, const LightMapRequest& request);
  // Over pieces: keeps in each texel the surface nearest the light over all of them.
  long combine_pieces(vtkSubsurfacePieces* pieces, const std::vector<PieceMap>& fits,
    double reach);
  // Keeps the atlas while it is large enough and at most four times the area needed.
  void allocate(vtkOpenGLRenderWindow* window, bool paper, int width, int height);

  std::vector<LightMapAtlas::Map> maps_;
  int width_ = 0, height_ = 0;
  vtkSmartPointer<vtkTextureObject> point_, power_, normal_, surfel_, depth_;
  vtkNew<vtkOpenGLFramebufferObject> fbo_;
  ProgramVAO vao_;
  // Each disc's curvature (1/mm, clamped at one over the cells' radius, as
  // core/light_map/light_map.cpp does) and radius (mm: the one that closes the surface).
  vtkNew<vtkOpenGLBufferObject> curvatures_, disc_radii_;
  Material material_;
  bool albedo_from_colour_ = false;
};

}

#endif

#include "sssLightMaps.h"

#include "sssMaterialUniforms.h"
#include "sssSurfelBuffers.h"
#include "sss_illumination_fs.h"
#include "sss_light_map_surfel_fs.h"
#include "sss_surfel_gs.h"
#include "sss_surfel_vs.h"

#include "local_surfels.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkSubsurfacePieces.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <Eigen/Dense>

#include <algorithm>
#include <limits>
#include <sstream>

namespace sss
{

namespace
{
// The light maps' vertex shader: the paper's texels lifted by each disc's curvature, or the
// pipeline's carrying the surfel's list texel in the colour. Built once.
std::string VertexShader(bool paper)
{
  std::string vs = sss_surfel_vs;
  vtkShaderProgram::Substitute(vs, "//SSS::Radiance::Dec", "", true);
  vtkShaderProgram::Substitute(vs, "//SSS::Radiance::Impl", "", true);
  vtkShaderProgram::Substitute(
    vs, "//SSS::Shape::Dec", paper ? "in float curvatureMC;" : "in vec2 listTexelMC;", true);
  vtkShaderProgram::Substitute(vs, "//SSS::Shape::Impl",
    paper ? "curvature_gs = curvatureMC;" : "colour_gs = vec4(listTexelMC, 0.0, 0.0);", true);
  return vs;
}

const std::string& LightMapVertexShader(bool paper)
{
  static const std::string vs[2] = { VertexShader(false), VertexShader(true) };
  return vs[paper ? 1 : 0];
}

const std::string& PaperFragmentShader()
{
  static const std::string fs = shader_with_pieces(sss_illumination_fs, "");
  return fs;
}

// A light's map as a GL view of the local frame: its rows (the map's axes), the model-view
// matrix and the projection (a frustum through a positional light's image plane at unit
// distance, or the orthographic box of a directional light's map), `reach` mm deep.
struct MapMatrices
{
  Eigen::Matrix3d rows;
  Eigen::Matrix4d model_to_view, view_to_clip;
};

MapMatrices map_matrices(const LightView& view, double reach)
{
  MapMatrices m;
  if (view.from_point)
  {
    const PerspectiveView& p = view.perspective;
    m.rows << p.u.transpose(), p.v.transpose(), p.w.transpose();
    m.model_to_view = Eigen::Matrix4d::Identity();
    m.model_to_view.block<3, 3>(0, 0) = m.rows;
    m.model_to_view.block<3, 1>(0, 3) = -m.rows * p.eye;
    // A frustum through the map's image plane at unit distance, from half the nearest
    // point's distance to past the farthest.
    const double near = 0.5 * p.nearest, far = (p.eye.norm() + reach) * 2.0;
    const double left = p.corner.x(), right = p.corner.x() + p.width * p.pixel;
    const double bottom = p.corner.y(), top = p.corner.y() + p.height * p.pixel;
    m.view_to_clip = Eigen::Matrix4d::Zero();
    m.view_to_clip(0, 0) = 2.0 / (right - left);
    m.view_to_clip(0, 2) = (right + left) / (right - left);
    m.view_to_clip(1, 1) = 2.0 / (top - bottom);
    m.view_to_clip(1, 2) = (top + bottom) / (top - bottom);
    m.view_to_clip(2, 2) = -(far + near) / (far - near);
    m.view_to_clip(2, 3) = -2.0 * far * near / (far - near);
    m.view_to_clip(3, 2) = -1.0;
  }
  else
  {
    const OrthoView& o = view.ortho;
    m.rows << o.u.transpose(), o.v.transpose(), o.w.transpose();
    m.model_to_view = Eigen::Matrix4d::Identity();
    m.model_to_view.block<3, 3>(0, 0) = m.rows;
    m.view_to_clip = Eigen::Matrix4d::Zero();
    m.view_to_clip(0, 0) = 2.0 / (o.width * o.pixel);
    m.view_to_clip(0, 3) = -2.0 * o.corner.x() / (o.width * o.pixel) - 1.0;
    m.view_to_clip(1, 1) = 2.0 / (o.height * o.pixel);
    m.view_to_clip(1, 3) = -2.0 * o.corner.y() / (o.height * o.pixel) - 1.0;
    m.view_to_clip(2, 2) = -1.0 / reach;
    m.view_to_clip(3, 3) = 1.0;
  }
  return m;
}
}

LightMapAtlas GpuLightMaps::atlas() const
{
  LightMapAtlas a;
  a.surfel = surfel_;
  a.maps = maps_;
  return a;
}

void GpuLightMaps::release(vtkWindow* window)
{
  vao_.release();
  curvatures_->ReleaseGraphicsResources();
  disc_radii_->ReleaseGraphicsResources();
  release_held(window, point_, power_, normal_, surfel_, depth_);
  fbo_->ReleaseGraphicsResources(window);
  width_ = height_ = 0;
}

void GpuLightMaps::allocate(vtkOpenGLRenderWindow* window, bool paper, int width, int height)
{
  // A moving light changes the maps' shapes every frame, and reallocating the textures each
  // time costs more than unused texels.
  const bool fits = width <= width_ && height <= height_;
  const bool oversized = 4.0 * width * height < double(width_) * height_;
  const bool other_kind = paper ? !point_ : !surfel_;
  if (fits && !oversized && !other_kind)
  {
    return;
  }
  if (!oversized)
  {
    width = std::max(width, width_);
    height = std::max(height, height_);
  }
  release_held(window, point_, power_, normal_, surfel_);
  if (paper)
  {
    point_ = float_texture_2d(window, width, height);
    power_ = float_texture_2d(window, width, height);
    normal_ = float_texture_2d(window, width, height);
  }
  else
  {
    surfel_ = float_texture_2d(window, width, height, 2);
  }
  depth_ = vtkSmartPointer<vtkTextureObject>::New();
  depth_->SetContext(window);
  depth_->AllocateDepth(width, height, vtkTextureObject::Float32);
  width_ = width;
  height_ = height;
}

void GpuLightMaps::lay_out(const LocalSurfels& local, const std::vector<GpuLight>& lights,
  const MapFit& fit, std::vector<PieceMap>& fits, LightMapReport& report, int& atlas_w,
  int& atlas_h)
{
  maps_.clear();
  report.notes.clear();
  atlas_w = 0;
  atlas_h = 1;
  for (const GpuLight& light : lights)
  {
    LightMapAtlas::Map map;
    map.light = LocalLight::of(light.light, local.frame);
    map.irradiance = light.irradiance;
    if (map.light.positional && fit.directional_only)
    {
      report.notes.push_back("the paper's method takes a positional light as directional, from "
                             "its focal point towards it");
      map.light.positional = false;
    }
    if (fit.pieces)
    {
      if (map.light.positional)
      {
        report.notes.push_back("a cloud split into pieces takes a positional light as "
                               "directional, from its focal point towards it");
        map.light.positional = false;
      }
      fits.push_back(
        fit_over_pieces(fit.pieces, &local, map.light.direction, fit.texel, fit.max_size));
      map.view = LightView{};
      map.view.ortho = fits.back().view;
    }
    else
    {
      try
      {
        map.view = fit_light_view(local, map.light, fit.texel, fit.max_size);
      }
      catch (const std::invalid_argument& e)  // a point light among the points
      {
        report.notes.push_back(std::string(e.what()) +
          "; it is taken as directional, from its focal point towards it");
        map.light.positional = false;
        map.view = fit_light_view(local, map.light, fit.texel, fit.max_size);
      }
    }
    map.x = atlas_w;
    atlas_w += map.width();
    atlas_h = std::max(atlas_h, map.height());
    maps_.push_back(map);
  }
}

vtkShaderProgram* GpuLightMaps::ready_program(
  vtkOpenGLRenderWindow* window, const SurfelBuffers& buffers, const LightMapRequest& request)
{
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    LightMapVertexShader(request.paper).c_str(),
    request.paper ? PaperFragmentShader().c_str() : sss_light_map_surfel_fs, sss_surfel_gs);
  if (!program)
  {
    return nullptr;
  }
  vtkOpenGLVertexArrayObject* vao = vao_.vao;
  vao->Bind();
  if (vao_.needs(program))
  {
    vao->ReleaseGraphicsResources();
    vao->Bind();
    vao->AddAttributeArray(
      program, buffers.positions, "positionMC", 0, 12, VTK_FLOAT, 3, false);
    vao->AddAttributeArray(program, buffers.normals, "normalMC", 0, 12, VTK_FLOAT, 3, false);
    vao->AddAttributeArray(program, disc_radii_, "radiusMC", 0, 4, VTK_FLOAT, 1, false);
    if (request.paper)
    {
      vao->AddAttributeArray(
        program, buffers.colours, "colourMC", 0, 4, VTK_UNSIGNED_CHAR, 4, true);
      vao->AddAttributeArray(program, curvatures_, "curvatureMC", 0, 4, VTK_FLOAT, 1, false);
    }
    else
    {
      vao->AddAttributeArray(
        program, request.list_texel, "listTexelMC", 0, 8, VTK_FLOAT, 2, false);
    }
    vao_.program = program;
  }
  return program;
}

void GpuLightMaps::set_surfels(
  const LocalSurfels& local, const Material& material, bool albedo_from_colour)
{
  const std::size_t n = local.size();
  std::vector<float> curvature(n), radius(n);
  const double lift_limit = 1.0 / local.cell_radius;
  for (std::size_t i = 0; i < n; ++i)
  {
    curvature[i] = static_cast<float>(std::clamp(local.curvature[i], -lift_limit, lift_limit));
    radius[i] = static_cast<float>(local.disc_radius(i));
  }
  curvatures_->Upload(curvature, vtkOpenGLBufferObject::ArrayBuffer);
  disc_radii_->Upload(radius, vtkOpenGLBufferObject::ArrayBuffer);
  vao_.program = nullptr;  // the attributes are bound anew
  material_ = material;
  albedo_from_colour_ = albedo_from_colour;
}

bool GpuLightMaps::render(vtkOpenGLRenderWindow* window, const SurfelBuffers& buffers,
  const LocalSurfels& local, const std::vector<GpuLight>& lights, const LightMapRequest& request,
  LightMapReport& report, std::string& error)
{
  if (lights.size() > static_cast<std::size_t>(kMaxLights))
  {
    error = "at most " + std::to_string(kMaxLights) + " lights are supported";
    return false;
  }
  const bool paper = request.paper;
  // The paper's map is as fine as its size allows; the surfel pipeline's texels are
  // TexelPerRadius of a disc radius. Either at most the request's size a side.
  const double texel = paper ? 1e-9 : request.texel_per_radius * local.cell_radius;
  const int max_size = request.max_map_size;
  vtkSubsurfacePieces* pieces =
    !paper && request.pieces && request.pieces->GetNumberOfPieces() > 1 ? request.pieces : nullptr;
  std::vector<PieceMap> fits;
  int atlas_w = 0, atlas_h = 1;
  lay_out(local, lights, MapFit{ paper, texel, max_size, pieces }, fits, report, atlas_w, atlas_h);
  atlas_w = std::max(atlas_w, 1);
  int max_texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  if (atlas_w > max_texture || atlas_h > max_texture)
  {
    std::ostringstream msg;
    msg << "the light maps need a " << atlas_w << " x " << atlas_h
        << " texture, over this GL's limit of " << max_texture << "; lower MaxMapSize";
    error = msg.str();
    return false;
  }
  allocate(window, paper, atlas_w, atlas_h);
  report.map_width = maps_.empty() ? 0 : maps_[0].width();
  report.map_height = maps_.empty() ? 0 : maps_[0].height();
  report.texel_mm = maps_.empty() ? 0.0 : maps_[0].view.texel_mm();

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable depth_test(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blending(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  state->PushFramebufferBindings();
  fbo_->SetContext(window);
  fbo_->Bind();
  const int targets = paper ? 3 : 1;
  if (paper)
  {
    fbo_->AddColorAttachment(0, point_);
    fbo_->AddColorAttachment(1, power_);
    fbo_->AddColorAttachment(2, normal_);
  }
  else
  {
    fbo_->AddColorAttachment(0, surfel_);
  }
  fbo_->AddDepthAttachment(depth_);
  fbo_->ActivateDrawBuffers(targets);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglViewport(0, 0, width_, height_);
  const float none = paper ? 0.0f : -1.0f;  // the paper's normal 0, or no surfel
  state->vtkglClearColor(none, none, none, none);
  state->vtkglClearDepth(1.0);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  vtkShaderProgram* program = ready_program(window, buffers, request);
  if (!program)
  {
    error = "the illumination-map shaders did not compile";
    state->PopFramebufferBindings();
    return false;
  }
  set_eta_uniform(program, material_);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  const double reach = 0.5 * local.bounds.extent().norm() + local.max_disc_radius() + 1.0;
  // The shared buffers' scene units to the local frame's mm.
  Eigen::Matrix4d to_mm = Eigen::Matrix4d::Identity();
  to_mm.topLeftCorner<3, 3>() *= local.frame.mm_per_unit;
  for (const LightMapAtlas::Map& map : maps_)
  {
    const MapMatrices m = map_matrices(map.view, reach);
    const Eigen::Matrix4f model_to_view_f = (m.model_to_view * to_mm).cast<float>();
    const Eigen::Matrix4f view_to_clip_f = m.view_to_clip.cast<float>();
    const Eigen::Matrix3f normal_to_view = m.rows.cast<float>();
    const Eigen::Matrix3f view_to_local = m.rows.transpose().cast<float>();
    program->SetUniformMatrix4x4("modelToView", const_cast<float*>(model_to_view_f.data()));
    program->SetUniformMatrix3x3("normalToView", const_cast<float*>(normal_to_view.data()));
    program->SetUniformMatrix4x4("viewToClip", const_cast<float*>(view_to_clip_f.data()));
    program->SetUniformMatrix3x3("viewToLocal", const_cast<float*>(view_to_local.data()));
    program->SetUniformi("perPointRadius", 1);
    program->SetUniformf("modelToViewScale", 1.0f);
    program->SetUniformi("orthographic", map.view.from_point ? 0 : 1);
    const float towards[3] = { static_cast<float>(map.light.direction.x()),
      static_cast<float>(map.light.direction.y()), static_cast<float>(map.light.direction.z()) };
    program->SetUniform3f("towardsLight", towards);
    float power[3];
    for (int c = 0; c < 3; ++c)  // the paper's maps: directional, texels of map.texel_mm()
    {
      power[c] = static_cast<float>(map.irradiance[c] * map.view.texel_mm() * map.view.texel_mm());
    }
    program->SetUniform3f("irradianceArea", power);
    program->SetUniformi("albedoFromColour", albedo_from_colour_ ? 1 : 0);
    const float albedo_as_is[3] = { 1.0f, 0.0f, 1.0f };  // ambient only: colour = colourMC
    program->SetUniform3f("ambientDiffuse", albedo_as_is);
    state->vtkglViewport(map.x, 0, map.width(), map.height());
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(buffers.count));
  }
  vao_.vao->Release();
  if (pieces)
  {
    combine_pieces(pieces, fits, reach);
  }
  fbo_->RemoveColorAttachments(targets);
  fbo_->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  return true;
}

long GpuLightMaps::combine_pieces(
  vtkSubsurfacePieces* pieces, const std::vector<PieceMap>& fits, double reach)
{
  const auto texels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  std::vector<float> depth(texels), surfel(2 * texels);
  fbo_->ActivateReadBuffer(0);
  glReadPixels(0, 0, width_, height_, GL_RG, GL_FLOAT, surfel.data());
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  long foreign = 0;
  for (std::size_t k = 0; k < fits.size(); ++k)
  {
    foreign += mark_foreign_texels(
      pieces, fits[k], reach, depth.data(), surfel.data(), width_, maps_[k].x);
  }
  surfel_->Bind();
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RG, GL_FLOAT, surfel.data());
  surfel_->Deactivate();
  return foreign;
}

void GpuLightMaps::take_part_without_surfels(
  vtkSubsurfacePieces* pieces, const std::vector<GpuLight>& lights, int max_map_size)
{
  if (!pieces || pieces->GetNumberOfPieces() < 2)
  {
    return;
  }
  std::vector<PieceMap> fits;
  for (const GpuLight& light : lights)
  {
    fits.push_back(fit_over_pieces(pieces, nullptr, light.light.direction,
      std::numeric_limits<double>::infinity(), max_map_size));
  }
  for (const PieceMap& fit : fits)
  {
    mark_foreign_texels(pieces, fit, 1.0, nullptr, nullptr, 0, 0);
  }
}

}

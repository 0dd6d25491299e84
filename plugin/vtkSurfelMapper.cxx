#include "vtkSurfelMapper.h"

#include "sssGpuHelpers.h"
#include "sssSurfelBuffers.h"
#include "sssSurfelPreparation.h"
#include "sss_surfel_fs.h"
#include "sss_surfel_normalise_fs.h"
#include "sss_surfel_gs.h"
#include "sss_surfel_vs.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkSurfelMapper);

struct vtkSurfelMapper::Internals
{
  sss::PreparedSurfels Prepared;
  vtkTimeStamp PreparedTime;
  std::string ReportedProblem;
  sss::SurfelBuffers Buffers;  // shared with the views from the lights
  vtkNew<vtkOpenGLBufferObject> Radii;  // the view's, with per-point radii
  // One vertex array per SPLAT_PASS, so that passes do not rebind attributes every frame.
  vtkNew<vtkOpenGLVertexArrayObject> VAO[3];
  vtkShaderProgram* BoundProgram[3] = { nullptr, nullptr, nullptr };

  // Blended splatting: the scene's depth with the splats' pushed back, and the weighted sums.
  vtkNew<vtkOpenGLFramebufferObject> SplatBuffer;
  vtkSmartPointer<vtkTextureObject> SplatDepth, WeightedColour, WeightedNormal;
  int SplatDepthFormat = -1;
  bool WarnedBlit = false;
  std::unique_ptr<vtkOpenGLQuadHelper> NormalisePlain, NormaliseTranslucent;

  // The prepared surfels as vertex buffers (sssSurfelBuffers) and the view's radii.
  void BuildBufferObjects(const sss::PreparedSurfels& prepared);

  void ReleaseSplatBuffers(vtkWindow* window)
  {
    sss::release_held(window, this->SplatDepth, this->WeightedColour, this->WeightedNormal);
    this->SplatBuffer->ReleaseGraphicsResources(window);
    this->NormalisePlain.reset();
    this->NormaliseTranslucent.reset();
  }
};

void vtkSurfelMapper::Internals::BuildBufferObjects(const sss::PreparedSurfels& prepared)
{
  const bool perPoint = prepared.per_point_radii;
  std::vector<float> radii(perPoint ? prepared.cloud.size() : 1, 0.0f);
  if (perPoint)
  {
    std::copy(prepared.cloud.radii.begin(), prepared.cloud.radii.end(), radii.begin());
  }
  this->Buffers.upload(prepared);
  this->Radii->Upload(radii, vtkOpenGLBufferObject::ArrayBuffer);
  for (auto& bound : this->BoundProgram)
  {
    bound = nullptr;
  }
}

vtkSurfelMapper::vtkSurfelMapper()
  : Impl(new Internals)
{
  this->CoverageTarget = sss::kDefaultCoverageTarget;
}

vtkSurfelMapper::~vtkSurfelMapper() = default;

namespace sss
{
// What one frame's splat draws share: the matrices (in double until the model is shifted to
// its bounds centre, so georeferenced coordinates keep their precision in the float buffers),
// the sizes in view units and whether a pass gives the surfels their radiance.
struct SplatView
{
  Eigen::Matrix4f modelToView, viewToClip;
  Eigen::Matrix3f normalToView;
  double scale = 1.0;       // model to view, per unit of length
  bool orthographic = false;
  double pixelSpan = 0.0;   // a pixel in view units (orthographic) or per unit of distance
  float look[3] = { 0, 0, 0 };  // the plain look: ambient, diffuse, opacity
  float radiusVC = 0, blendDepthVC = 0;
  bool perPoint = false;
  std::size_t surfels = 0, drawn = 0;  // all of them, and those this piece owns (first)
  std::vector<vtkOpenGLRenderPass*> passes;
  bool translucent = false;  // a vtkSubsurfacePass gives the radiance
};
}

namespace
{
// One surfel draw: hard discs, the blended splats' visibility or their accumulation
// (surfel_fs.glsl's SPLAT_PASS).
enum SplatPass
{
  SPLAT_DISCS = 0,
  SPLAT_VISIBILITY = 1,
  SPLAT_ACCUMULATION = 2
};

Eigen::Matrix4d ToEigen(vtkMatrix4x4* m)
{
  Eigen::Matrix4d e;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      e(r, c) = m->GetElement(r, c);
    }
  }
  return e;
}

std::vector<vtkOpenGLRenderPass*> RenderPassesOf(vtkActor* act)
{
  std::vector<vtkOpenGLRenderPass*> passes;
  vtkInformation* keys = act ? act->GetPropertyKeys() : nullptr;
  if (keys && keys->Has(vtkOpenGLRenderPass::RenderPasses()))
  {
    const int n = keys->Length(vtkOpenGLRenderPass::RenderPasses());
    for (int i = 0; i < n; ++i)
    {
      if (auto* pass =
            vtkOpenGLRenderPass::SafeDownCast(keys->Get(vtkOpenGLRenderPass::RenderPasses(), i)))
      {
        passes.push_back(pass);
      }
    }
  }
  return passes;
}

void RemoveHooks(std::string& source)
{
  for (const char* hook :
    { "//SSS::Radiance::Dec", "//SSS::Radiance::Impl", "//SSS::Shape::Dec", "//SSS::Shape::Impl" })
  {
    vtkShaderProgram::Substitute(source, hook, "", true);
  }
}

sss::SplatView MakeSplatView(
  vtkRenderer* ren, vtkActor* act, const sss::PreparedSurfels& prepared, double blendDepth)
{
  sss::SplatView view;
  vtkCamera* camera = ren->GetActiveCamera();
  int width, height, x0, y0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  const double aspect = height > 0 ? double(width) / height : 1.0;
  Eigen::Matrix4d shift = Eigen::Matrix4d::Identity();
  shift.block<3, 1>(0, 3) =
    Eigen::Vector3d(prepared.centre[0], prepared.centre[1], prepared.centre[2]);
  const Eigen::Matrix4d modelView =
    ToEigen(camera->GetModelViewTransformMatrix()) * ToEigen(act->GetMatrix());
  view.modelToView = (modelView * shift).cast<float>();
  const Eigen::Matrix3d linear = modelView.block<3, 3>(0, 0);
  view.normalToView = linear.inverse().transpose().cast<float>();
  view.viewToClip = ToEigen(camera->GetProjectionTransformMatrix(aspect, -1, 1)).cast<float>();
  view.scale = std::cbrt(std::fabs(linear.determinant()));
  view.orthographic = camera->GetParallelProjection() != 0;
  view.pixelSpan = height > 0
    ? (view.orthographic ? 2.0 * camera->GetParallelScale()
                         : 2.0 * std::tan(0.5 * camera->GetViewAngle() * M_PI / 180.0)) / height
    : 0.0;
  vtkProperty* property = act->GetProperty();
  view.look[0] = static_cast<float>(property->GetAmbient());
  view.look[1] = static_cast<float>(property->GetDiffuse());
  view.look[2] = static_cast<float>(property->GetOpacity());
  view.radiusVC = static_cast<float>(prepared.view_radius * view.scale);
  view.blendDepthVC = static_cast<float>(blendDepth * prepared.view_radius * view.scale);
  view.perPoint = prepared.per_point_radii;
  view.surfels = prepared.cloud.size();
  view.drawn = prepared.drawn;
  view.passes = RenderPassesOf(act);
  for (vtkOpenGLRenderPass* pass : view.passes)
  {
    auto* source = dynamic_cast<vtkSurfelMapper::RadianceSource*>(pass);
    view.translucent = view.translucent || (source && source->GivesRadianceTo(act));
  }
  return view;
}
}

const sss::PreparedSurfels& vtkSurfelMapper::UpdateSurfels(vtkActor* act)
{
  vtkPolyData* input = this->GetInput();
  vtkMTimeType inputTime = input ? input->GetMTime() : 0;
  vtkMTimeType actorTime = act ? act->GetProperty()->GetMTime() : 0;
  if (this->Impl->PreparedTime > inputTime && this->Impl->PreparedTime > this->GetMTime() &&
    this->Impl->PreparedTime > actorTime && this->Impl->PreparedTime.GetMTime() > 0)
  {
    return this->Impl->Prepared;
  }
  std::array<std::uint8_t, 4> fallback{ { 255, 255, 255, 255 } };
  if (act)
  {
    double rgb[3];
    act->GetProperty()->GetColor(rgb);
    for (int c = 0; c < 3; ++c)
    {
      fallback[c] = static_cast<std::uint8_t>(std::lround(255.0 * rgb[c]));
    }
  }
  vtkUnsignedCharArray* colours =
    input && this->ScalarVisibility ? this->MapScalars(input, 1.0) : nullptr;
  sss::RadiusChoice choice;
  choice.radius = this->Radius;
  choice.scale = this->RadiusScale;
  choice.coverage_target = this->CoverageTarget;
  choice.mode = this->RadiusMode == PER_POINT
    ? sss::SplatRadiusMode::PerPoint
    : (this->RadiusMode == UNIFORM ? sss::SplatRadiusMode::Uniform : sss::SplatRadiusMode::Automatic);
  choice.radius_array = this->RadiusArrayName;
  this->Impl->Prepared = sss::prepare_surfels(input, choice, colours, fallback);
  this->Impl->PreparedTime.Modified();
  const sss::PreparedSurfels& p = this->Impl->Prepared;
  // An empty polydata draws nothing, silently, as VTK's mappers do: ParaView hands one to
  // every rank without a piece and to the client of a pvserver that renders remotely.
  const bool emptyInput = input && input->GetNumberOfPoints() == 0;
  if (!p.error.empty())
  {
    if (p.error != this->Impl->ReportedProblem && !emptyInput)
    {
      vtkErrorMacro(<< "nothing to draw: " << p.error);
    }
  }
  else if (p.report.dropped() > 0)
  {
    vtkWarningMacro(<< "left out " << p.report.dropped() << " of " << p.report.input
                    << " points: " << p.report.summary());
  }
  this->Impl->ReportedProblem = p.error;
  return p;
}

const sss::SurfelBuffers& vtkSurfelMapper::UpdateBuffers(vtkActor* act)
{
  const sss::PreparedSurfels& prepared = this->UpdateSurfels(act);
  Internals& impl = *this->Impl;
  if (prepared.error.empty() && !prepared.cloud.empty() &&
    impl.Buffers.upload_time < impl.PreparedTime)
  {
    impl.BuildBufferObjects(prepared);
  }
  return impl.Buffers;
}

double vtkSurfelMapper::GetEffectiveRadius()
{
  return this->Impl->Prepared.error.empty() ? this->Impl->Prepared.view_radius : 0.0;
}

double vtkSurfelMapper::GetCellRadius()
{
  return this->Impl->Prepared.error.empty() ? this->Impl->Prepared.cloud.radius : 0.0;
}

bool vtkSurfelMapper::GetUsesPerPointRadii()
{
  return this->Impl->Prepared.error.empty() && this->Impl->Prepared.per_point_radii;
}

double vtkSurfelMapper::GetUncoveredFraction()
{
  return this->Impl->Prepared.error.empty() ? this->Impl->Prepared.uncovered : 0.0;
}

const char* vtkSurfelMapper::GetRadiusModeAsString()
{
  switch (this->RadiusMode)
  {
    case UNIFORM:
      return "Uniform";
    case PER_POINT:
      return "PerPoint";
    default:
      return "Automatic";
  }
}

const char* vtkSurfelMapper::GetSplattingAsString()
{
  return this->Splatting == DISCS ? "Discs" : "Blended";
}

vtkIdType vtkSurfelMapper::GetNumberOfSurfels()
{
  return static_cast<vtkIdType>(this->Impl->Prepared.cloud.size());
}

std::string vtkSurfelMapper::GetInputProblem()
{
  return this->Impl->Prepared.error;
}

void vtkSurfelMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin)
  {
    vtkErrorMacro(<< "needs an OpenGL render window");
    return;
  }
  this->UpdateBuffers(act);
  const sss::PreparedSurfels& prepared = this->Impl->Prepared;
  if (!prepared.error.empty() || prepared.cloud.empty())
  {
    return;
  }
  const sss::SplatView view = MakeSplatView(ren, act, prepared, this->BlendDepth);
  vtkOpenGLState* state = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blending(state, GL_BLEND);
  if (this->Splatting == DISCS || !this->DrawBlended(renWin, act, view))
  {
    state->vtkglDisable(GL_BLEND);
    this->DrawSplats(renWin, act, SPLAT_DISCS, view);
  }
}

vtkShaderProgram* vtkSurfelMapper::ReadySplatProgram(
  vtkOpenGLRenderWindow* renWin, vtkActor* act, int splatPass, const sss::SplatView& view)
{
  std::string vs = sss_surfel_vs, gs = sss_surfel_gs, fs = sss_surfel_fs;
  vtkShaderProgram::Substitute(
    fs, "//SSS::Splat::Dec", "#define SPLAT_PASS " + std::to_string(splatPass), true);
  vtkShaderProgram::Substitute(gs, "//SSS::Splat::Dec",
    splatPass == SPLAT_VISIBILITY ? "#define SPLAT_PUSH_BACK"
                                  : (splatPass == SPLAT_ACCUMULATION ? "#define SPLAT_RIM" : ""),
    true);
  for (vtkOpenGLRenderPass* pass : view.passes)
  {
    pass->PreReplaceShaderValues(vs, gs, fs, this, act);
  }
  for (vtkOpenGLRenderPass* pass : view.passes)
  {
    pass->PostReplaceShaderValues(vs, gs, fs, this, act);
  }
  RemoveHooks(vs);
  vtkShaderProgram* program =
    renWin->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), gs.c_str());
  if (!program)
  {
    vtkErrorMacro(<< "the surfel shaders did not compile");
  }
  return program;
}

bool vtkSurfelMapper::DrawSplats(
  vtkOpenGLRenderWindow* renWin, vtkActor* act, int splatPass, const sss::SplatView& view)
{
  vtkShaderProgram* program = this->ReadySplatProgram(renWin, act, splatPass, view);
  if (!program)
  {
    return false;
  }
  Internals& impl = *this->Impl;
  vtkOpenGLVertexArrayObject* vao = impl.VAO[splatPass];
  vao->Bind();
  if (impl.BoundProgram[splatPass] != program)
  {
    vao->ReleaseGraphicsResources();
    vao->Bind();
    vao->AddAttributeArray(
      program, impl.Buffers.positions, "positionMC", 0, 12, VTK_FLOAT, 3, false);
    vao->AddAttributeArray(
      program, impl.Buffers.normals, "normalMC", 0, 12, VTK_FLOAT, 3, false);
    if (program->IsAttributeUsed("colourMC"))
    {
      vao->AddAttributeArray(
        program, impl.Buffers.colours, "colourMC", 0, 4, VTK_UNSIGNED_CHAR, 4, true);
    }
    if (view.perPoint && program->IsAttributeUsed("radiusMC"))
    {
      vao->AddAttributeArray(program, impl.Radii, "radiusMC", 0, 4, VTK_FLOAT, 1, false);
    }
    impl.BoundProgram[splatPass] = program;
  }
  program->SetUniformMatrix4x4("modelToView", const_cast<float*>(view.modelToView.data()));
  program->SetUniformMatrix3x3("normalToView", const_cast<float*>(view.normalToView.data()));
  program->SetUniformMatrix4x4("viewToClip", const_cast<float*>(view.viewToClip.data()));
  program->SetUniformf("radiusVC", view.radiusVC);
  program->SetUniformi("perPointRadius", view.perPoint ? 1 : 0);
  program->SetUniformf("modelToViewScale", static_cast<float>(view.scale));
  program->SetUniformf("blendDepthVC", view.blendDepthVC);
  program->SetUniformi("orthographic", view.orthographic ? 1 : 0);
  program->SetUniformf("pixelSpanVC", static_cast<float>(view.pixelSpan));
  program->SetUniformi("viewFactorPerPixel", splatPass == SPLAT_ACCUMULATION ? 1 : 0);
  program->SetUniform3f("ambientDiffuse", view.look);
  for (vtkOpenGLRenderPass* pass : view.passes)
  {
    if (!pass->SetShaderParameters(program, this, act, vao))
    {
      vtkErrorMacro(<< "a render pass could not set its shader parameters");
      vao->Release();
      return false;
    }
  }
  // Ghosts (another piece's surfels) hide what lies behind them (visibility) and cover pixels
  // (accumulation), so that a piece's edge does not fade like a silhouette; their colour is
  // that piece's.
  const auto owned = static_cast<GLsizei>(view.drawn);
  const auto all = static_cast<GLsizei>(view.surfels);
  program->SetUniformi("coverageOnly", 0);
  glDrawArrays(GL_POINTS, 0, splatPass == SPLAT_VISIBILITY ? all : owned);
  if (splatPass == SPLAT_ACCUMULATION && owned < all)
  {
    program->SetUniformi("coverageOnly", 1);
    glDrawArrays(GL_POINTS, owned, all - owned);
  }
  vao->Release();
  return true;
}

bool vtkSurfelMapper::DrawBlended(
  vtkOpenGLRenderWindow* renWin, vtkActor* act, const sss::SplatView& view)
{
  // Blended splatting in three passes, in buffers of the viewport's size that start from the
  // scene's depth, so that opaque actors drawn before hide the splats behind them.
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  const int w = viewport[2], h = viewport[3];
  if (w < 1 || h < 1)
  {
    return true;
  }
  Internals& impl = *this->Impl;
  vtkOpenGLState* state = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  vtkOpenGLState::ScopedglClearColor clearColor(state);
  {
    vtkOpenGLState::ScopedglViewport savedViewport(state);
    state->PushFramebufferBindings();
    GLint drawn = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawn);
    state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<unsigned int>(drawn));
    // The splats' depth starts as a copy of the scene's, in its format (a depth blit needs
    // equal formats).
    GLint depthType = 0, depthBits = 0;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
      GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &depthType);
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
    const int depthFormat = depthType == GL_FLOAT ? vtkTextureObject::Float32
      : depthBits <= 16                           ? vtkTextureObject::Fixed16
      : depthBits <= 24                           ? vtkTextureObject::Fixed24
                                                  : vtkTextureObject::Fixed32;
    if (!impl.SplatDepth || impl.SplatDepthFormat != depthFormat ||
      impl.SplatDepth->GetWidth() != static_cast<unsigned int>(w) ||
      impl.SplatDepth->GetHeight() != static_cast<unsigned int>(h))
    {
      impl.ReleaseSplatBuffers(renWin);
      impl.SplatDepth = vtkSmartPointer<vtkTextureObject>::New();
      impl.SplatDepth->SetContext(renWin);
      impl.SplatDepth->SetMinificationFilter(vtkTextureObject::Nearest);
      impl.SplatDepth->SetMagnificationFilter(vtkTextureObject::Nearest);
      impl.SplatDepth->AllocateDepth(w, h, depthFormat);
      impl.SplatDepthFormat = depthFormat;
      impl.WeightedColour = sss::float_texture_2d(renWin, w, h);
      impl.WeightedNormal = sss::float_texture_2d(renWin, w, h);
    }
    impl.SplatBuffer->SetContext(renWin);
    impl.SplatBuffer->Bind();
    impl.SplatBuffer->AddColorAttachment(0, impl.WeightedColour);
    impl.SplatBuffer->AddColorAttachment(1, impl.WeightedNormal);
    impl.SplatBuffer->AddDepthAttachment(impl.SplatDepth);
    impl.SplatBuffer->ActivateDrawBuffers(2);
    state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<unsigned int>(drawn));
    while (glGetError() != GL_NO_ERROR)
    {
    }
    glBlitFramebuffer(viewport[0], viewport[1], viewport[0] + w, viewport[1] + h, 0, 0, w, h,
      GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    if (glGetError() != GL_NO_ERROR)
    {
      impl.SplatBuffer->RemoveColorAttachments(2);
      impl.SplatBuffer->RemoveDepthAttachment();
      state->PopFramebufferBindings();
      if (!impl.WarnedBlit)
      {
        vtkWarningMacro(<< "the scene's depth cannot be copied for blended splatting (a "
                           "multisampled framebuffer?); drawing hard discs");
        impl.WarnedBlit = true;
      }
      return false;
    }
    state->vtkglViewport(0, 0, w, h);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LEQUAL);
    state->vtkglDisable(GL_BLEND);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglDepthMask(GL_TRUE);
    // Visibility: the front surface, pushed back by BlendDepth radii.
    bool drawnAll = this->DrawSplats(renWin, act, SPLAT_VISIBILITY, view);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    // The largest coverage of a pixel by a disc goes to the normals' alpha (surfel_fs.glsl).
    // Without per-buffer blend equations (OpenGL 4.0) coverages add up, and silhouettes are
    // drawn without a fade.
    const bool perBufferBlend = GLEW_VERSION_4_0 || GLEW_ARB_draw_buffers_blend;
    if (perBufferBlend)
    {
      glBlendEquationSeparatei(1, GL_FUNC_ADD, GL_MAX);
    }
    // Accumulation of every disc within the offset.
    drawnAll = drawnAll && this->DrawSplats(renWin, act, SPLAT_ACCUMULATION, view);
    if (perBufferBlend)
    {
      glBlendEquationSeparatei(1, GL_FUNC_ADD, GL_FUNC_ADD);
    }
    impl.SplatBuffer->RemoveColorAttachments(2);
    impl.SplatBuffer->RemoveDepthAttachment();
    state->PopFramebufferBindings();
    if (!drawnAll)
    {
      return true;
    }
  }
  this->Normalise(renWin, act, view);
  return true;
}

void vtkSurfelMapper::Normalise(
  vtkOpenGLRenderWindow* renWin, vtkActor* act, const sss::SplatView& view)
{
  // Into the renderer's framebuffer, colour and depth (surfel_normalise_fs.glsl): a
  // translucent actor's pixels as they are (the pass fills in their outgoing radiance), a
  // plain one's blended by their coverage.
  Internals& impl = *this->Impl;
  std::unique_ptr<vtkOpenGLQuadHelper>& quad =
    view.translucent ? impl.NormaliseTranslucent : impl.NormalisePlain;
  // The source is assembled once, when its quad is made.
  std::string fs;
  if (!quad)
  {
    fs = sss_surfel_normalise_fs;
    if (view.translucent)
    {
      std::string noVertexShader, noGeometryShader;
      for (vtkOpenGLRenderPass* pass : view.passes)
      {
        pass->PreReplaceShaderValues(noVertexShader, noGeometryShader, fs, this, act);
      }
    }
    vtkShaderProgram::Substitute(fs, "//SSS::Outgoing::Dec", "", true);
  }
  vtkShaderProgram* normalise = sss::ready_quad(quad, renWin, fs.c_str());
  if (!normalise)
  {
    vtkErrorMacro(<< "the splat normalisation shader did not compile");
    return;
  }
  vtkOpenGLState* state = renWin->GetState();
  if (view.translucent)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(
      GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkTextureObject* inputs[3] = { impl.WeightedColour, impl.WeightedNormal, impl.SplatDepth };
  const char* names[3] = { "weightedColour", "weightedNormal", "splatDepth" };
  for (int k = 0; k < 3; ++k)
  {
    inputs[k]->Activate();
    normalise->SetUniformi(names[k], inputs[k]->GetTextureUnit());
  }
  if (!view.translucent)
  {
    normalise->SetUniform3f("ambientDiffuse", view.look);
  }
  normalise->SetUniformi("orthographic", view.orthographic ? 1 : 0);
  Eigen::Matrix4f clipToView = view.viewToClip.inverse();
  normalise->SetUniformMatrix4x4("clipToView", clipToView.data());
  normalise->SetUniformMatrix4x4("viewToClip", const_cast<float*>(view.viewToClip.data()));
  normalise->SetUniformf("blendDepthVC", view.blendDepthVC);
  for (vtkOpenGLRenderPass* pass : view.passes)
  {
    pass->SetShaderParameters(normalise, this, act, nullptr);  // eta, for Ft
  }
  quad->Render();
  for (vtkTextureObject* t : inputs)
  {
    t->Deactivate();
  }
}

void vtkSurfelMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->Buffers.release();
  this->Impl->Radii->ReleaseGraphicsResources();
  for (int k = 0; k < 3; ++k)
  {
    this->Impl->VAO[k]->ReleaseGraphicsResources();
    this->Impl->BoundProgram[k] = nullptr;
  }
  this->Impl->ReleaseSplatBuffers(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkSurfelMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (0: from coverage)\n";
  os << indent << "RadiusScale: " << this->RadiusScale << "\n";
  os << indent << "CoverageTarget: " << this->CoverageTarget << "\n";
  os << indent << "RadiusMode: " << this->GetRadiusModeAsString() << "\n";
  os << indent << "RadiusArrayName: " << this->RadiusArrayName << "\n";
  os << indent << "Splatting: " << this->GetSplattingAsString() << "\n";
  os << indent << "BlendDepth: " << this->BlendDepth << "\n";
  os << indent << "Surfels: " << this->Impl->Prepared.cloud.size() << "\n";
}

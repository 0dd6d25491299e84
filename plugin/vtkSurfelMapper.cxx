#include "vtkSurfelMapper.h"

#include "sssGpuHelpers.h"
#include "sssSurfelPreparation.h"
#include "sss_dipole.h"
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

#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkSurfelMapper);

struct vtkSurfelMapper::Internals
{
  sss::PreparedSurfels Prepared;
  vtkTimeStamp PreparedTime;
  std::string ReportedProblem;
  vtkNew<vtkOpenGLBufferObject> Positions;
  vtkNew<vtkOpenGLBufferObject> Normals;
  vtkNew<vtkOpenGLBufferObject> Colours;
  vtkNew<vtkOpenGLBufferObject> Radii;
  // One vertex array per SPLAT_PASS, so that passes do not rebind attributes every frame.
  vtkNew<vtkOpenGLVertexArrayObject> VAO[3];
  vtkShaderProgram* BoundProgram[3] = { nullptr, nullptr, nullptr };
  vtkTimeStamp UploadTime;

  // Blended splatting: the scene's depth with the splats' pushed back, and the weighted sums.
  vtkNew<vtkOpenGLFramebufferObject> SplatBuffer;
  vtkSmartPointer<vtkTextureObject> SplatDepth, WeightedColour, WeightedNormal;
  int SplatDepthFormat = -1;
  bool WarnedBlit = false;
  std::unique_ptr<vtkOpenGLQuadHelper> Normalise;

  void ReleaseSplatBuffers(vtkWindow* window)
  {
    sss::release_held(window, this->SplatDepth, this->WeightedColour, this->WeightedNormal);
    this->SplatBuffer->ReleaseGraphicsResources(window);
    this->Normalise.reset();
  }
};

vtkSurfelMapper::vtkSurfelMapper()
  : Impl(new Internals)
{
  this->CoverageTarget = sss::kDefaultCoverageTarget;
}

vtkSurfelMapper::~vtkSurfelMapper() = default;

namespace
{
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
  if (!p.error.empty())
  {
    if (p.error != this->Impl->ReportedProblem)
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

vtkMTimeType vtkSurfelMapper::GetSurfelsTime() const
{
  return this->Impl->PreparedTime.GetMTime();
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
  const sss::PreparedSurfels& prepared = this->UpdateSurfels(act);
  if (!prepared.error.empty() || prepared.cloud.empty())
  {
    return;
  }
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin)
  {
    vtkErrorMacro(<< "needs an OpenGL render window");
    return;
  }
  Internals& impl = *this->Impl;
  const std::size_t n = prepared.cloud.size();

  const bool perPoint = prepared.per_point_radii;
  if (impl.UploadTime < impl.PreparedTime)
  {
    std::vector<float> positions(3 * n), normals(3 * n), radii(perPoint ? n : 1, 0.0f);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        positions[3 * i + c] =
          static_cast<float>(prepared.cloud.positions[i][c] - prepared.centre[c]);
        normals[3 * i + c] = static_cast<float>(prepared.cloud.normals[i][c]);
      }
      if (perPoint)
      {
        radii[i] = static_cast<float>(prepared.cloud.radii[i]);
      }
    }
    impl.Positions->Upload(positions, vtkOpenGLBufferObject::ArrayBuffer);
    impl.Normals->Upload(normals, vtkOpenGLBufferObject::ArrayBuffer);
    impl.Colours->Upload(prepared.rgba, vtkOpenGLBufferObject::ArrayBuffer);
    impl.Radii->Upload(radii, vtkOpenGLBufferObject::ArrayBuffer);
    impl.UploadTime.Modified();
    for (auto& bound : impl.BoundProgram)
    {
      bound = nullptr;
    }
  }

  // Matrices in double: the model is shifted to its bounds centre first, so georeferenced
  // coordinates keep their precision in the float buffers.
  vtkCamera* camera = ren->GetActiveCamera();
  int width, height, x0, y0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  const double aspect = height > 0 ? double(width) / height : 1.0;
  Eigen::Matrix4d shift = Eigen::Matrix4d::Identity();
  shift.block<3, 1>(0, 3) =
    Eigen::Vector3d(prepared.centre[0], prepared.centre[1], prepared.centre[2]);
  const Eigen::Matrix4d modelView =
    ToEigen(camera->GetModelViewTransformMatrix()) * ToEigen(act->GetMatrix());
  const Eigen::Matrix4f modelToView = (modelView * shift).cast<float>();
  const Eigen::Matrix3d linear = modelView.block<3, 3>(0, 0);
  const Eigen::Matrix3f normalToView = linear.inverse().transpose().cast<float>();
  const Eigen::Matrix4f viewToClip =
    ToEigen(camera->GetProjectionTransformMatrix(aspect, -1, 1)).cast<float>();
  const double scale = std::cbrt(std::fabs(linear.determinant()));
  const std::vector<vtkOpenGLRenderPass*> passes = RenderPassesOf(act);
  // A pixel's size in view units (orthographic) or per unit of distance (perspective).
  const bool orthographic = camera->GetParallelProjection() != 0;
  const double pixelSpan = height > 0
    ? (orthographic ? 2.0 * camera->GetParallelScale()
                    : 2.0 * std::tan(0.5 * camera->GetViewAngle() * M_PI / 180.0)) / height
    : 0.0;
  bool radianceFromPass = false;  // a pass (the subsurface pass) gives this actor's colour
  vtkProperty* property = act->GetProperty();
  const float look[3] = { static_cast<float>(property->GetAmbient()),
    static_cast<float>(property->GetDiffuse()), static_cast<float>(property->GetOpacity()) };
  const float blendDepthVC = static_cast<float>(this->BlendDepth * prepared.view_radius * scale);

  // One surfel draw: SPLAT_PASS 0 hard discs, 1 visibility, 2 accumulation (surfel_fs.glsl).
  auto draw = [&](int splatPass) -> bool
  {
    std::string vs = sss_surfel_vs, gs = sss_surfel_gs, fs = sss_surfel_fs;
    vtkShaderProgram::Substitute(
      fs, "//SSS::Splat::Dec", "#define SPLAT_PASS " + std::to_string(splatPass), true);
    vtkShaderProgram::Substitute(
      gs, "//SSS::Splat::Dec",
      splatPass == 1 ? "#define SPLAT_PUSH_BACK" : (splatPass == 2 ? "#define SPLAT_RIM" : ""), true);
    for (vtkOpenGLRenderPass* pass : passes)
    {
      pass->PreReplaceShaderValues(vs, gs, fs, this, act);
    }
    for (vtkOpenGLRenderPass* pass : passes)
    {
      pass->PostReplaceShaderValues(vs, gs, fs, this, act);
    }
    radianceFromPass = vs.find("//SSS::Radiance::Impl") == std::string::npos;
    RemoveHooks(vs);
    vtkShaderProgram* program =
      renWin->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), gs.c_str());
    if (!program)
    {
      vtkErrorMacro(<< "the surfel shaders did not compile");
      return false;
    }
    vtkOpenGLVertexArrayObject* vao = impl.VAO[splatPass];
    vao->Bind();
    if (impl.BoundProgram[splatPass] != program)
    {
      vao->ReleaseGraphicsResources();
      vao->Bind();
      vao->AddAttributeArray(program, impl.Positions, "positionMC", 0, 12, VTK_FLOAT, 3, false);
      vao->AddAttributeArray(program, impl.Normals, "normalMC", 0, 12, VTK_FLOAT, 3, false);
      if (program->IsAttributeUsed("colourMC"))
      {
        vao->AddAttributeArray(program, impl.Colours, "colourMC", 0, 4, VTK_UNSIGNED_CHAR, 4, true);
      }
      if (perPoint && program->IsAttributeUsed("radiusMC"))
      {
        vao->AddAttributeArray(program, impl.Radii, "radiusMC", 0, 4, VTK_FLOAT, 1, false);
      }
      impl.BoundProgram[splatPass] = program;
    }
    program->SetUniformMatrix4x4("modelToView", const_cast<float*>(modelToView.data()));
    program->SetUniformMatrix3x3("normalToView", const_cast<float*>(normalToView.data()));
    program->SetUniformMatrix4x4("viewToClip", const_cast<float*>(viewToClip.data()));
    program->SetUniformf("radiusVC", static_cast<float>(prepared.view_radius * scale));
    program->SetUniformi("perPointRadius", perPoint ? 1 : 0);
    program->SetUniformf("modelToViewScale", static_cast<float>(scale));
    program->SetUniformf("blendDepthVC", blendDepthVC);
    program->SetUniformi("orthographic", orthographic ? 1 : 0);
    program->SetUniformf("pixelSpanVC", static_cast<float>(pixelSpan));
    program->SetUniformi("viewFactorPerPixel", splatPass == 2 ? 1 : 0);
    program->SetUniform3f("ambientDiffuse", look);
    for (vtkOpenGLRenderPass* pass : passes)
    {
      if (!pass->SetShaderParameters(program, this, act, vao))
      {
        vtkErrorMacro(<< "a render pass could not set its shader parameters");
        vao->Release();
        return false;
      }
    }
    // Ghosts (another piece's surfels) hide what lies behind them (1) and cover pixels (2),
    // so that a piece's edge does not fade like a silhouette; their colour is that piece's.
    const auto owned = static_cast<GLsizei>(prepared.drawn);
    program->SetUniformi("coverageOnly", 0);
    glDrawArrays(GL_POINTS, 0, splatPass == 1 ? static_cast<GLsizei>(n) : owned);
    if (splatPass == 2 && prepared.drawn < n)
    {
      program->SetUniformi("coverageOnly", 1);
      glDrawArrays(GL_POINTS, owned, static_cast<GLsizei>(n) - owned);
    }
    vao->Release();
    return true;
  };

  vtkOpenGLState* state = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blending(state, GL_BLEND);
  if (this->Splatting == DISCS)
  {
    state->vtkglDisable(GL_BLEND);
    draw(0);
    return;
  }

  // Blended splatting in three passes, in buffers of the viewport's size that start from the
  // scene's depth, so that opaque actors drawn before hide the splats behind them.
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  const int w = viewport[2], h = viewport[3];
  if (w < 1 || h < 1)
  {
    return;
  }
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
      state->vtkglDisable(GL_BLEND);
      draw(0);
      return;
    }
    state->vtkglViewport(0, 0, w, h);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LEQUAL);
    state->vtkglDisable(GL_BLEND);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglDepthMask(GL_TRUE);
    bool drawnAll = draw(1);  // visibility: the front surface, pushed back by BlendDepth radii
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
    drawnAll = drawnAll && draw(2);  // accumulation of every disc within the offset
    if (perBufferBlend)
    {
      glBlendEquationSeparatei(1, GL_FUNC_ADD, GL_FUNC_ADD);
    }
    impl.SplatBuffer->RemoveColorAttachments(2);
    impl.SplatBuffer->RemoveDepthAttachment();
    state->PopFramebufferBindings();
    if (!drawnAll)
    {
      return;
    }
  }
  // Normalisation into the renderer's framebuffer, colour and depth (surfel_normalise_fs.glsl):
  // a translucent actor's pixels as they are, a plain one's blended by their coverage.
  static const std::string normaliseSource = []
  {
    std::string source = sss_surfel_normalise_fs;
    vtkShaderProgram::Substitute(source, "//SSS::Dipole::Dec", sss_dipole, true);
    return source;
  }();
  vtkShaderProgram* normalise = sss::ready_quad(impl.Normalise, renWin, normaliseSource.c_str());
  if (!normalise)
  {
    vtkErrorMacro(<< "the splat normalisation shader did not compile");
    return;
  }
  if (radianceFromPass)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
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
  normalise->SetUniformi("translucent", radianceFromPass ? 1 : 0);
  normalise->SetUniform3f("ambientDiffuse", look);
  normalise->SetUniformi("orthographic", orthographic ? 1 : 0);
  Eigen::Matrix4f clipToView = viewToClip.inverse();
  normalise->SetUniformMatrix4x4("clipToView", clipToView.data());
  normalise->SetUniformMatrix4x4("viewToClip", const_cast<float*>(viewToClip.data()));
  normalise->SetUniformf("blendDepthVC", blendDepthVC);
  for (vtkOpenGLRenderPass* pass : passes)
  {
    pass->SetShaderParameters(normalise, this, act, nullptr);  // eta, for Ft
  }
  impl.Normalise->Render();
  for (vtkTextureObject* t : inputs)
  {
    t->Deactivate();
  }
}

void vtkSurfelMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->Positions->ReleaseGraphicsResources();
  this->Impl->Normals->ReleaseGraphicsResources();
  this->Impl->Colours->ReleaseGraphicsResources();
  this->Impl->Radii->ReleaseGraphicsResources();
  for (int k = 0; k < 3; ++k)
  {
    this->Impl->VAO[k]->ReleaseGraphicsResources();
    this->Impl->BoundProgram[k] = nullptr;
  }
  this->Impl->ReleaseSplatBuffers(window);
  this->Impl->UploadTime = vtkTimeStamp();
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

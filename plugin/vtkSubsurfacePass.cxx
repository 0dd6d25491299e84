#include "vtkSubsurfacePass.h"

#include "sssGpuHelpers.h"
#include "sssMaterialUniforms.h"
#include "sssSceneLights.h"
#include "sssTranslucentActors.h"
#include "sss_composite_fs.h"
#include "sss_dipole.h"
#include "sss_subsurface_view_dec.h"
#include "sss_subsurface_view_impl.h"
#include "vtkSubsurfacePieces.h"
#include "vtkSurfelMapper.h"

#include "quality_settings.h"
#include "stopwatch.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <set>
#include <vector>

vtkStandardNewMacro(vtkSubsurfacePass);

int vtkSubsurfacePass::GetMaxLights()
{
  return sss::kMaxLights;
}

struct vtkSubsurfacePass::Internals
{
  explicit Internals(vtkSubsurfacePass* self)
    : Actors([this, self](const std::string& message,
               bool error) { this->ReportOnce(self, message, error); },
        [self](const sss::StepReport& report) { self->Record(report); })
  {
  }

  sss::TranslucentActors Actors;
  // Made anew with its textures: a framebuffer object keeps the size of its first attachments
  // (GetLastSize, which the delegate's camera takes as the viewport) after they are replaced.
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  vtkSmartPointer<vtkTextureObject> Colour, Depth;
  std::unique_ptr<vtkOpenGLQuadHelper> Composite;
  vtkNew<vtkFloatArray> Linear;
  std::set<std::string> Reported;
  std::vector<sss::GpuLight> Lights;  // the renderer's, this frame, world frame
  vtkSmartPointer<vtkSubsurfacePieces> Pieces;
  bool Prepared = false;  // PrepareFrame ran steps 1-2; the next Render only draws

  void ReportOnce(vtkSubsurfacePass* self, const std::string& message, bool error)
  {
    if (!this->Reported.insert(message).second)
    {
      return;
    }
    if (error)
    {
      vtkErrorWithObjectMacro(self, << message);
    }
    else
    {
      vtkWarningWithObjectMacro(self, << message);
    }
  }
};

namespace
{
sss::QualitySettings SettingsOf(vtkSubsurfacePass* pass)
{
  sss::QualitySettings q;
  q.strategy = pass->GetKernelStrategy() == vtkSubsurfacePass::PAPER
    ? sss::KernelStrategy::Paper
    : sss::KernelStrategy::NearFar;
  q.texel_per_radius = pass->GetTexelPerRadius();
  q.max_map_size = pass->GetMaxMapSize();
  q.cell_samples = pass->GetCellSamples();
  q.opening_angle = pass->GetOpeningAngle();
  q.max_group_diffusion_lengths = pass->GetMaxGroupDiffusionLengths();
  q.grid_level = pass->GetGridLevel();
  return q;
}

void Apply(vtkSubsurfacePass* pass, const sss::QualitySettings& q)
{
  pass->SetKernelStrategy(
    q.strategy == sss::KernelStrategy::Paper ? vtkSubsurfacePass::PAPER : vtkSubsurfacePass::NEAR_FAR);
  pass->SetTexelPerRadius(q.texel_per_radius);
  pass->SetMaxMapSize(q.max_map_size);
  pass->SetCellSamples(q.cell_samples);
  pass->SetOpeningAngle(q.opening_angle);
  pass->SetMaxGroupDiffusionLengths(q.max_group_diffusion_lengths);
  pass->SetGridLevel(q.grid_level);
}
}

vtkSubsurfacePass::vtkSubsurfacePass()
  : Impl(new Internals(this))
{
  Apply(this, sss::QualitySettings{});
  vtkNew<vtkRenderStepsPass> steps;
  this->SetDelegatePass(steps);
  this->Impl->Linear->SetNumberOfComponents(3);
}

vtkSubsurfacePass::~vtkSubsurfacePass() = default;

void vtkSubsurfacePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* ren = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window || !this->DelegatePass)
  {
    vtkErrorMacro(<< "needs an OpenGL render window and a delegate pass");
    return;
  }
  sss::Stopwatch frameClock;
  if (this->Impl->Prepared)
  {
    this->Impl->Prepared = false;  // PrepareFrame ran steps 1-2 for this frame
  }
  else if (this->Impl->Pieces && this->Impl->Pieces->GetNumberOfPieces() > 1)
  {
    // Collective steps cannot run here (see PrepareFrame): translucent actors draw plain.
    this->Impl->Actors.clear_ready();
  }
  else
  {
    this->GatherLights(ren);
    this->UpdateTranslucentActors(s, window);
  }
  frameClock.lap();  // the view's time starts here
  int width, height, x0, y0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width < 1 || height < 1)
  {
    return;
  }
  this->RenderScene(s, window, width, height);
  if (this->Composite(window, width, height, x0, y0) && !this->Impl->Actors.ready().empty())
  {
    ++this->ViewRuns;
    if (this->MeasureStepTimes)
    {
      glFinish();
    }
    this->LastViewSeconds = frameClock.lap();
  }
}

void vtkSubsurfacePass::SetPieces(vtkSubsurfacePieces* pieces)
{
  if (this->Impl->Pieces != pieces)
  {
    this->Impl->Pieces = pieces;
    this->Modified();
  }
}

vtkSubsurfacePieces* vtkSubsurfacePass::GetPieces()
{
  return this->Impl->Pieces;
}

void vtkSubsurfacePass::PrepareFrame(vtkRenderer* ren)
{
  if (this->RunSteps(ren, "PrepareFrame"))
  {
    this->Impl->Prepared = true;
  }
}

void vtkSubsurfacePass::RunRefinementPart(vtkRenderer* ren)
{
  this->RunSteps(ren, "RunRefinementPart");
}

bool vtkSubsurfacePass::RunSteps(vtkRenderer* ren, const char* caller)
{
  auto* window = ren ? vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) : nullptr;
  if (!window)
  {
    vtkErrorMacro(<< caller << " needs a renderer in an OpenGL render window");
    return false;
  }
  window->MakeCurrent();
  std::vector<vtkProp*> props;
  vtkCollectionSimpleIterator it;
  ren->GetViewProps()->InitTraversal(it);
  while (vtkProp* prop = ren->GetViewProps()->GetNextProp(it))
  {
    if (prop->GetVisibility())
    {
      props.push_back(prop);
    }
  }
  vtkRenderState state(ren);
  state.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  this->GatherLights(ren);
  this->UpdateTranslucentActors(&state, window);
  return true;
}

void vtkSubsurfacePass::GatherLights(vtkRenderer* ren)
{
  std::vector<std::string> notes;
  this->Impl->Lights = sss::gather_scene_lights(ren, notes);
  for (const std::string& note : notes)
  {
    this->Impl->ReportOnce(this, note, false);
  }
}

void vtkSubsurfacePass::UpdateTranslucentActors(const vtkRenderState* s, vtkOpenGLRenderWindow* window)
{
  Internals& impl = *this->Impl;
  const sss::StepContext context{ window, SettingsOf(this), this->MeasureStepTimes,
    impl.Pieces };
  impl.Actors.update(s, context, impl.Lights,
    { this->Refinement, this->RefinementRestSeconds, this->RefinementFrameSeconds });
  this->LastTranslucentActors = static_cast<int>(impl.Actors.ready().size());
  this->RefinementPending = impl.Actors.previewing();
  this->RefinementFailed = impl.Actors.unrefined();
  this->LastPreviewSeconds = impl.Actors.last_preview_seconds();
  this->LastPreviewError = impl.Actors.preview_error();
  this->RefinedShare = this->RefinementPending ? impl.Actors.refined_share() : 1.0;
  this->RefinementPreparing = this->RefinementPending && impl.Actors.preparing();
}

bool vtkSubsurfacePass::IsRefinementPartDue()
{
  return this->Impl->Actors.part_due(
    { this->Refinement, this->RefinementRestSeconds, this->RefinementFrameSeconds });
}

void vtkSubsurfacePass::Record(const sss::StepReport& report)
{
  if (report.bake)
  {
    ++this->BakeRuns;
    this->LastBakeSeconds = report.seconds_bake;
    this->LastNearReachMillimetres = report.near_reach_mm;
    this->LastFarFromMillimetres = report.far_from_mm;
    this->LastNearFieldEntries = static_cast<vtkIdType>(report.near_entries);
    this->LastVirtualPoints = static_cast<vtkIdType>(report.virtual_point_count);
    this->LastGridLevel = report.grid_level;
    this->LastGridSpacingMillimetres = report.grid_spacing_mm;
  }
  if (report.illumination)
  {
    ++this->IlluminationRuns;
    this->LastIlluminationSeconds = report.seconds_illumination;
    this->LastMapWidth = report.map_width;
    this->LastMapHeight = report.map_height;
    this->LastTexelMillimetres = report.texel_mm;
  }
  if (report.surfels)
  {
    ++this->SurfelRuns;
    this->LastSurfelSeconds = report.seconds_surfels;
    this->LastCellSeconds = report.seconds_cells;
    this->LastPyramidSeconds = report.seconds_pyramid;
    this->LastNearFieldSeconds = report.seconds_near;
    this->LastFarFieldSeconds = report.seconds_far;
    this->LastHandOverSeconds = report.seconds_hand_over;
    this->LastLitCells = static_cast<vtkIdType>(report.lit_cells);
    this->LastRefinedCells = static_cast<vtkIdType>(report.refined_cells);
  }
  this->LastSurfels = static_cast<vtkIdType>(report.surfel_count);
}

std::string vtkSubsurfacePass::GetLastLightMoveProfile() const
{
  char line[256];
  std::snprintf(line, sizeof line,
    "map %.3g s, cells %.3g s, pyramid %.3g s, near %.3g s, far %.3g s, hand-over %.3g s",
    this->LastIlluminationSeconds, this->LastCellSeconds, this->LastPyramidSeconds,
    this->LastNearFieldSeconds, this->LastFarFieldSeconds, this->LastHandOverSeconds);
  return line;
}

void vtkSubsurfacePass::RenderScene(
  const vtkRenderState* s, vtkOpenGLRenderWindow* window, int width, int height)
{
  Internals& impl = *this->Impl;
  vtkRenderer* ren = s->GetRenderer();
  if (!impl.Colour || impl.Colour->GetWidth() != static_cast<unsigned int>(width) ||
    impl.Colour->GetHeight() != static_cast<unsigned int>(height))
  {
    if (impl.Colour)
    {
      impl.Colour->ReleaseGraphicsResources(window);
      impl.Depth->ReleaseGraphicsResources(window);
      impl.FrameBuffer->ReleaseGraphicsResources(window);
    }
    impl.FrameBuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    impl.Colour = sss::float_texture_2d(window, width, height);
    impl.Depth = vtkSmartPointer<vtkTextureObject>::New();
    impl.Depth->SetContext(window);
    impl.Depth->SetMinificationFilter(vtkTextureObject::Nearest);
    impl.Depth->SetMagnificationFilter(vtkTextureObject::Nearest);
    impl.Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
  }
  for (vtkActor* actor : impl.Actors.ready())
  {
    vtkOpenGLRenderPass::RenderPasses()->Append(actor->GetPropertyKeys(), this);
  }
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  impl.FrameBuffer->SetContext(window);
  impl.FrameBuffer->Bind();
  impl.FrameBuffer->AddColorAttachment(0, impl.Colour);
  impl.FrameBuffer->AddDepthAttachment(impl.Depth);
  impl.FrameBuffer->ActivateDrawBuffers(1);
  {
    vtkOpenGLState::ScopedglViewport viewport(state);
    vtkOpenGLState::ScopedglScissor scissor(state);
    state->vtkglViewport(0, 0, width, height);
    state->vtkglScissor(0, 0, width, height);
    vtkRenderState inner(ren);
    inner.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
    inner.SetFrameBuffer(impl.FrameBuffer);
    this->DelegatePass->Render(&inner);
    this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  }
  for (vtkActor* actor : impl.Actors.ready())
  {
    vtkOpenGLRenderPass::RenderPasses()->Remove(actor->GetPropertyKeys(), this);
    impl.Actors.state(actor)->surfel_radiance()->Deactivate();
  }
  if (this->CaptureLinearImage)
  {
    std::vector<float> rgba(4 * static_cast<std::size_t>(width) * height);
    impl.FrameBuffer->ActivateReadBuffer(0);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
    impl.Linear->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
    for (vtkIdType p = 0; p < impl.Linear->GetNumberOfTuples(); ++p)
    {
      const bool translucent = rgba[4 * p + 3] > 1.5f;
      for (int c = 0; c < 3; ++c)
      {
        impl.Linear->SetValue(3 * p + c, translucent ? rgba[4 * p + c] : 0.0f);
      }
    }
    this->LinearWidth = width;
    this->LinearHeight = height;
  }
  impl.FrameBuffer->RemoveColorAttachments(1);
  impl.FrameBuffer->RemoveDepthAttachment();
  state->PopFramebufferBindings();
}

bool vtkSubsurfacePass::Composite(
  vtkOpenGLRenderWindow* window, int width, int height, int x0, int y0)
{
  Internals& impl = *this->Impl;
  vtkOpenGLState* state = window->GetState();
  vtkShaderProgram* composite = sss::ready_quad(impl.Composite, window, sss_composite_fs);
  if (!composite)
  {
    vtkErrorMacro(<< "the composite shader did not compile");
    return false;
  }
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blending(state, GL_BLEND);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  state->vtkglViewport(x0, y0, width, height);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDisable(GL_BLEND);
  impl.Colour->Activate();
  impl.Depth->Activate();
  composite->SetUniformi("colourTexture", impl.Colour->GetTextureUnit());
  composite->SetUniformi("depthTexture", impl.Depth->GetTextureUnit());
  composite->SetUniformf("exposure", static_cast<float>(this->Exposure));
  impl.Composite->Render();
  impl.Colour->Deactivate();
  impl.Depth->Deactivate();
  return true;
}

bool vtkSubsurfacePass::PreReplaceShaderValues(std::string& vertexShader, std::string&,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (!vtkSurfelMapper::SafeDownCast(mapper) ||
    !this->GivesRadianceTo(vtkActor::SafeDownCast(prop)))
  {
    return true;
  }
  std::string dec = sss_subsurface_view_dec;
  vtkShaderProgram::Substitute(dec, "//SSS::Dipole::Dec", sss_dipole, true);
  vtkShaderProgram::Substitute(vertexShader, "//SSS::Radiance::Dec", dec, true);
  vtkShaderProgram::Substitute(
    vertexShader, "//SSS::Radiance::Impl", sss_subsurface_view_impl, true);
  // The blended splats' normalisation: Lo = Ft(eta, wo) B (eq. 14).
  vtkShaderProgram::Substitute(fragmentShader, "//SSS::Outgoing::Dec",
    std::string("#define SSS_TRANSLUCENT\n") + sss_dipole, true);
  return true;
}

bool vtkSubsurfacePass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  if (!vtkSurfelMapper::SafeDownCast(mapper) || !this->GivesRadianceTo(actor))
  {
    return true;
  }
  sss::TranslucentActorState& state = *this->Impl->Actors.state(actor);
  vtkTextureObject* radiance = state.surfel_radiance();
  radiance->Activate();
  program->SetUniformi("surfelRadiance", radiance->GetTextureUnit());
  program->SetUniformi("surfelListWidth", state.list_width());
  sss::set_eta_uniform(program, state.material());
  return true;
}

bool vtkSubsurfacePass::GivesRadianceTo(vtkActor* actor)
{
  return this->Impl->Actors.is_ready(actor);
}

void vtkSubsurfacePass::SetPrecomputedRadiance(vtkActor* actor, vtkFloatArray* B)
{
  if (!actor)
  {
    return;
  }
  this->Impl->Actors.set_precomputed(actor, B);
  this->Modified();
}

vtkFloatArray* vtkSubsurfacePass::GetLinearImage()
{
  return this->Impl->Linear;
}

double vtkSubsurfacePass::GetLinearImageQuantile(double q)
{
  vtkFloatArray* linear = this->Impl->Linear;
  std::vector<float> lit;
  for (vtkIdType p = 0; linear && p < linear->GetNumberOfTuples(); ++p)
  {
    const float* Lo = linear->GetPointer(3 * p);
    const float largest = std::max({ Lo[0], Lo[1], Lo[2] });
    if (largest > 0.0f)
    {
      lit.push_back(largest);
    }
  }
  if (lit.empty())
  {
    return 0.0;
  }
  const auto at = lit.begin() +
    static_cast<std::ptrdiff_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(lit.size() - 1));
  std::nth_element(lit.begin(), at, lit.end());
  return *at;
}

bool vtkSubsurfacePass::GetSurfelRadiance(vtkActor* actor, vtkFloatArray* B)
{
  sss::TranslucentActorState* state = this->Impl->Actors.state(actor);
  auto* mapper = actor ? vtkSurfelMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  auto* window = this->Impl->FrameBuffer ? this->Impl->FrameBuffer->GetContext() : nullptr;
  std::vector<sss::Rgb> values;
  if (!state || !mapper || !B || !window || !state->read_surfel_radiance(window, values))
  {
    return false;
  }
  sss::radiance_in_input_order(mapper->UpdateSurfels(actor), values, B);
  return true;
}

void vtkSubsurfacePass::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& impl = *this->Impl;
  impl.Actors.release(w);
  if (impl.Colour)
  {
    impl.FrameBuffer->ReleaseGraphicsResources(w);
    impl.Colour->ReleaseGraphicsResources(w);
    impl.Depth->ReleaseGraphicsResources(w);
    impl.FrameBuffer = nullptr;
    impl.Colour = nullptr;
    impl.Depth = nullptr;
  }
  if (impl.Composite)
  {
    impl.Composite->ReleaseGraphicsResources(w);
    impl.Composite.reset();
  }
  this->Superclass::ReleaseGraphicsResources(w);
}

const char* vtkSubsurfacePass::GetKernelStrategyAsString()
{
  return sss::strategy_name(SettingsOf(this).strategy);
}

bool vtkSubsurfacePass::SetKernelStrategyByName(const std::string& name)
{
  sss::QualitySettings q = SettingsOf(this);
  if (!sss::strategy_from_name(name, q.strategy))
  {
    return false;
  }
  Apply(this, q);
  return true;
}

bool vtkSubsurfacePass::SetQualityPreset(const std::string& name)
{
  try
  {
    Apply(this, sss::QualitySettings::preset(name));
  }
  catch (const std::invalid_argument&)
  {
    return false;
  }
  return true;
}

std::string vtkSubsurfacePass::GetQualityPresetAsString()
{
  return SettingsOf(this).preset_name();
}

void vtkSubsurfacePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KernelStrategy: " << this->GetKernelStrategyAsString() << "\n";
  os << indent << "Pieces: "
     << (this->Impl->Pieces ? this->Impl->Pieces->GetNumberOfPieces() : 1) << "\n";
  os << indent << "TexelPerRadius: " << this->TexelPerRadius << "\n";
  os << indent << "MaxMapSize: " << this->MaxMapSize << "\n";
  os << indent << "CellSamples: " << this->CellSamples << "\n";
  os << indent << "OpeningAngle: " << this->OpeningAngle << "\n";
  os << indent << "MaxGroupDiffusionLengths: " << this->MaxGroupDiffusionLengths << "\n";
  os << indent << "GridLevel: " << this->GridLevel << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "CaptureLinearImage: " << this->CaptureLinearImage << "\n";
  os << indent << "QualityPreset: " << this->GetQualityPresetAsString() << "\n";
  os << indent << "MeasureStepTimes: " << this->MeasureStepTimes << "\n";
  os << indent << "Refinement: " << this->Refinement << " (after " << this->RefinementRestSeconds
     << " s at rest, " << this->RefinementFrameSeconds << " s a frame)\n";
  os << indent << "Runs (bake, illumination, surfels, view): " << this->BakeRuns << " "
     << this->IlluminationRuns << " " << this->SurfelRuns << " " << this->ViewRuns << "\n";
  os << indent << "Last seconds (bake, illumination, surfels, view): " << this->LastBakeSeconds
     << " " << this->LastIlluminationSeconds << " " << this->LastSurfelSeconds << " "
     << this->LastViewSeconds << "\n";
  os << indent << "Last light move: " << this->GetLastLightMoveProfile() << "\n";
  os << indent << "Last map: " << this->LastMapWidth << " x " << this->LastMapHeight << ", texel "
     << this->LastTexelMillimetres << " mm\n";
  os << indent << "Last near field: to " << this->LastNearReachMillimetres << " mm, "
     << this->LastNearFieldEntries << " entries; far field from " << this->LastFarFromMillimetres
     << " mm\n";
  os << indent
     << "Last counts (translucent actors, surfels, lit cells, refined cells, virtual points): "
     << this->LastTranslucentActors << " " << this->LastSurfels << " " << this->LastLitCells
     << " " << this->LastRefinedCells << " " << this->LastVirtualPoints << " (grid level "
     << this->LastGridLevel << ", spacing " << this->LastGridSpacingMillimetres << " mm)\n";
  os << indent << "Linear image: " << this->LinearWidth << " x " << this->LinearHeight << "\n";
}

#include "vtkSurfelMapper.h"

#include "sssSurfelPreparation.h"
#include "sss_surfel_fs.h"
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
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
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
  vtkNew<vtkOpenGLVertexArrayObject> VAO;
  vtkTimeStamp UploadTime;
  vtkShaderProgram* BoundProgram = nullptr;
};

vtkSurfelMapper::vtkSurfelMapper()
  : Impl(new Internals)
{
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
  this->Impl->Prepared = sss::prepare_surfels(input, this->Radius, this->RadiusScale, colours, fallback);
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
  return this->Impl->Prepared.error.empty() ? this->Impl->Prepared.cloud.radius : 0.0;
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

  if (impl.UploadTime < impl.PreparedTime)
  {
    std::vector<float> positions(3 * n), normals(3 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        positions[3 * i + c] =
          static_cast<float>(prepared.cloud.positions[i][c] - prepared.centre[c]);
        normals[3 * i + c] = static_cast<float>(prepared.cloud.normals[i][c]);
      }
    }
    impl.Positions->Upload(positions, vtkOpenGLBufferObject::ArrayBuffer);
    impl.Normals->Upload(normals, vtkOpenGLBufferObject::ArrayBuffer);
    impl.Colours->Upload(prepared.rgba, vtkOpenGLBufferObject::ArrayBuffer);
    impl.UploadTime.Modified();
    impl.BoundProgram = nullptr;
  }

  std::string vs = sss_surfel_vs, gs = sss_surfel_gs, fs = sss_surfel_fs;
  const std::vector<vtkOpenGLRenderPass*> passes = RenderPassesOf(act);
  for (vtkOpenGLRenderPass* pass : passes)
  {
    pass->PreReplaceShaderValues(vs, gs, fs, this, act);
  }
  for (vtkOpenGLRenderPass* pass : passes)
  {
    pass->PostReplaceShaderValues(vs, gs, fs, this, act);
  }
  RemoveHooks(vs);
  vtkShaderProgram* program =
    renWin->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), gs.c_str());
  if (!program)
  {
    vtkErrorMacro(<< "the surfel shaders did not compile");
    return;
  }
  impl.VAO->Bind();
  if (impl.BoundProgram != program)
  {
    impl.VAO->ReleaseGraphicsResources();
    impl.VAO->Bind();
    impl.VAO->AddAttributeArray(program, impl.Positions, "positionMC", 0, 12, VTK_FLOAT, 3, false);
    impl.VAO->AddAttributeArray(program, impl.Normals, "normalMC", 0, 12, VTK_FLOAT, 3, false);
    if (program->IsAttributeUsed("colourMC"))
    {
      impl.VAO->AddAttributeArray(
        program, impl.Colours, "colourMC", 0, 4, VTK_UNSIGNED_CHAR, 4, true);
    }
    impl.BoundProgram = program;
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

  program->SetUniformMatrix4x4("modelToView", const_cast<float*>(modelToView.data()));
  program->SetUniformMatrix3x3("normalToView", const_cast<float*>(normalToView.data()));
  program->SetUniformMatrix4x4("viewToClip", const_cast<float*>(viewToClip.data()));
  program->SetUniformf("radiusVC", static_cast<float>(prepared.cloud.radius * scale));
  program->SetUniformi("orthographic", camera->GetParallelProjection() ? 1 : 0);
  vtkProperty* property = act->GetProperty();
  const float look[3] = { static_cast<float>(property->GetAmbient()),
    static_cast<float>(property->GetDiffuse()), static_cast<float>(property->GetOpacity()) };
  program->SetUniform3f("ambientDiffuse", look);
  for (vtkOpenGLRenderPass* pass : passes)
  {
    if (!pass->SetShaderParameters(program, this, act, impl.VAO))
    {
      vtkErrorMacro(<< "a render pass could not set its shader parameters");
      return;
    }
  }

  vtkOpenGLState* state = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blending(state, GL_BLEND);
  state->vtkglDisable(GL_BLEND);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(n));
  impl.VAO->Release();
}

void vtkSurfelMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->Positions->ReleaseGraphicsResources();
  this->Impl->Normals->ReleaseGraphicsResources();
  this->Impl->Colours->ReleaseGraphicsResources();
  this->Impl->VAO->ReleaseGraphicsResources();
  this->Impl->UploadTime = vtkTimeStamp();
  this->Impl->BoundProgram = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkSurfelMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (0: RadiusScale x mean nearest-neighbour spacing)\n";
  os << indent << "RadiusScale: " << this->RadiusScale << "\n";
  os << indent << "Surfels: " << this->Impl->Prepared.cloud.size() << "\n";
}

// The real-time path with VTK alone (no PCL): a vtkSphereSource, or the PLY file given, becomes
// surfels that vtkSubsurfacePass draws translucent in a plain vtkRenderer, in a headless EGL
// window (no display needed), written to a PNG.
//
//   vtk_translucent_sphere [--output FILE.png] [--material NAME] [--mm-per-unit MM] [FILE.ply]
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkEGLSurfacelessRenderWindow.h>
#include <vtkFloatArray.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkSubsurfacePass.h>
#include <vtkSurfelMapper.h>
#include <vtkTranslucentMaterial.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Options {
  std::string input;  // empty: the sphere
  std::string output = "translucent_sphere.png";
  std::string material = "marble";
  double mm_per_unit = 30.0;  // the sphere (diameter 1) is a 30 mm ball
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--output" && has_value) {
      o.output = argv[++i];
    } else if (arg == "--material" && has_value) {
      o.material = argv[++i];
    } else if (arg == "--mm-per-unit" && has_value) {
      o.mm_per_unit = std::atof(argv[++i]);
      if (!(o.mm_per_unit > 0.0)) throw std::invalid_argument("--mm-per-unit must be positive");
    } else if (arg.rfind("--", 0) != 0 && o.input.empty()) {
      o.input = arg;
    } else {
      throw std::invalid_argument("unexpected argument '" + arg + "'");
    }
  }
  return o;
}

vtkSmartPointer<vtkPolyData> sphere() {
  vtkNew<vtkSphereSource> source;
  source->SetRadius(0.5);
  source->SetThetaResolution(120);
  source->SetPhiResolution(120);
  source->Update();
  return source->GetOutput();
}

// The file's points with point normals, computed from its faces when it has none. VTK 9.1's
// reader crashes on some truncated binary files; render_ply.py shows a way to check first.
vtkSmartPointer<vtkPolyData> read_ply(const std::string& path) {
  if (!vtkPLYReader::CanReadFile(path.c_str()))
    throw std::runtime_error(path + ": missing, unreadable or not a PLY file");
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> cloud = reader->GetOutput();
  if (cloud->GetNumberOfPoints() == 0) throw std::runtime_error(path + ": no points");
  if (cloud->GetPointData()->GetNormals()) return cloud;
  if (cloud->GetNumberOfPolys() == 0)
    throw std::runtime_error(path + ": no normals and no faces to compute them from");
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(cloud);
  normals->ComputeCellNormalsOff();
  normals->SplittingOff();  // one normal per point: splitting would duplicate surfels
  normals->Update();
  return normals->GetOutput();
}


void write_png(vtkRenderWindow* window, const std::string& path) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  const std::string partial = path + ".partial";  // the whole file or nothing
  writer->SetFileName(partial.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0 || std::rename(partial.c_str(), path.c_str()) != 0) {
    std::remove(partial.c_str());
    throw std::runtime_error(path + ": could not be written");
  }
}

void render(const Options& o) {
  vtkSmartPointer<vtkPolyData> surfels = o.input.empty() ? sphere() : read_ply(o.input);
  vtkNew<vtkSurfelMapper> mapper;
  mapper->SetInputData(surfels);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkTranslucentMaterial> material;
  if (!material->SetPreset(o.material.c_str()))
    throw std::runtime_error("unknown material '" + o.material + "'");
  material->SetMillimetresPerUnit(o.mm_per_unit);
  material->ApplyTo(actor);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;  // directional, from above and a little from the left and front
  light->SetLightTypeToSceneLight();
  light->SetPositional(false);
  light->SetFocalPoint(0, 0, 0);
  light->SetPosition(-0.4, 1.0, 0.4);
  renderer->AddLight(light);
  vtkNew<vtkSubsurfacePass> pass;
  pass->CaptureLinearImageOn();
  renderer->SetPass(pass);

  vtkNew<vtkEGLSurfacelessRenderWindow> window;
  window->SetSize(400, 400);
  window->AddRenderer(renderer);
  if (!window->IsContextValid()) throw std::runtime_error("no EGL context: " + window->GetLastError());
  renderer->ResetCamera();
  window->Render();
  if (pass->GetLastTranslucentActors() != 1)
    throw std::runtime_error("nothing was drawn translucent: " + mapper->GetInputProblem());
  const double white = pass->GetLinearImageQuantile(0.995);  // visible radiance shown white
  pass->SetExposure(white > 0.0 ? 1.0 / white : 1.0);
  renderer->GetActiveCamera()->Modified();  // a camera-only change: the view step alone
  window->Render();
  write_png(window, o.output);
  std::printf("%s: %lld surfels (radius %g), %s, %g mm per unit\n", o.output.c_str(),
              static_cast<long long>(mapper->GetNumberOfSurfels()), mapper->GetEffectiveRadius(),
              o.material.c_str(), o.mm_per_unit);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    render(parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vtk_translucent_sphere: %s\n", e.what());
    return 1;
  }
  return 0;
}

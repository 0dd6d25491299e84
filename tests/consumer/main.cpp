// Renders a small translucent sphere with the installed SSS::Translucency and checks that
// pixels are lit; prints where the library finds its OSMesa shim (the install test checks it).
#include <vtkActor.h>
#include <vtkEGLSurfacelessRenderWindow.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkOSMesaRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkSubsurfacePass.h>
#include <vtkSurfelMapper.h>
#include <vtkTranslucentMaterial.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdio>

int main() {
  std::printf("OSMesa shim: %s\n", vtkOSMesaRenderWindow::FindShimLibrary().c_str());

  vtkNew<vtkSphereSource> sphere;  // a 20 mm ball
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(40);
  sphere->Update();
  vtkNew<vtkSurfelMapper> mapper;
  mapper->SetInputData(sphere->GetOutput());
  mapper->SetRadius(0.05);  // wide enough to close the gaps of this sampling
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkTranslucentMaterial> material;
  material->SetPreset("marble");
  material->SetMillimetresPerUnit(20);
  material->ApplyTo(actor);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(false);
  light->SetFocalPoint(0, 0, 0);
  light->SetPosition(0, 0.5, 1);
  renderer->AddLight(light);
  vtkNew<vtkSubsurfacePass> pass;
  pass->SetExposure(4);
  renderer->SetPass(pass);
  vtkNew<vtkEGLSurfacelessRenderWindow> window;
  window->SetSize(64, 64);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  window->Render();

  vtkNew<vtkUnsignedCharArray> rgb;
  window->GetPixelData(0, 0, 63, 63, 0, rgb, 0);
  int lit = 0;
  for (vtkIdType p = 0; p < rgb->GetNumberOfTuples(); ++p)
    if (std::max({rgb->GetValue(3 * p), rgb->GetValue(3 * p + 1), rgb->GetValue(3 * p + 2)}) > 60)
      ++lit;
  std::printf("%d translucent actor(s), %d of 4096 pixels lit\n",
              pass->GetLastTranslucentActors(), lit);
  return pass->GetLastTranslucentActors() == 1 && lit > 200 ? 0 : 1;
}

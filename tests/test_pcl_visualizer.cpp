// The one-call integration in PCLVisualizer's own (offscreen) window, under the Xvfb server
// that CTest starts for this test: the same B as the plain VTK path, a lit image, and a handle
// that changes material, quality, lights and removes the cloud; refinement in the application's
// loop; the light's mouse drag.
#include <gtest/gtest.h>
#include <pcl/point_types.h>
#include <pcl/visualization/pcl_visualizer.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSubsurfacePass.h>
#include <vtkSurfelMapper.h>
#include <vtkTranslucentMaterial.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <chrono>
#include <cmath>

#include "sssPclLightDrag.h"
#include "sssPclPendingEvents.h"
#include "sssPclTranslucentCloud.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

// A sphere of radius 10 (mm) on a latitude-longitude lattice.
pcl::PointCloud<pcl::PointXYZ> sphere(int rings, int segments) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = kPi * i / rings, phi = 2.0 * kPi * j / segments;
      cloud.push_back(pcl::PointXYZ(10 * std::sin(theta) * std::cos(phi),
                                    10 * std::sin(theta) * std::sin(phi), 10 * std::cos(theta)));
    }
  return cloud;
}

std::vector<float> radiance(vtkSubsurfacePass* pass, vtkActor* actor) {
  vtkNew<vtkFloatArray> B;
  EXPECT_TRUE(pass->GetSurfelRadiance(actor, B));
  return std::vector<float>(B->GetPointer(0), B->GetPointer(0) + 3 * B->GetNumberOfTuples());
}

// B of the same surfels, material (a preset's name) and light set up by hand in a plain VTK
// window (an X window here too: one thread cannot switch between GLX and EGL contexts).
std::vector<float> plain_vtk_radiance(const sss::Surfels& surfels, const Eigen::Vector3d& towards_light,
                                      const char* material = "marble") {
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(64, 64);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(false);
  light->SetFocalPoint(0, 0, 0);
  light->SetPosition(towards_light.data());
  renderer->AddLight(light);
  vtkNew<vtkSurfelMapper> mapper;
  mapper->SetInputData(surfels.polydata);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkTranslucentMaterial> preset;
  EXPECT_TRUE(preset->SetPreset(material));
  preset->ApplyTo(actor);
  renderer->AddActor(actor);
  vtkNew<vtkSubsurfacePass> pass;
  renderer->SetPass(pass);
  renderer->ResetCamera();
  window->Render();
  return radiance(pass, actor);
}

double largest_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0.0, peak = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(double(a[i]) - b[i]));
    peak = std::max(peak, double(b[i]));
  }
  return worst / peak;
}

// Mean of the brightest channel over the window's pixels.
double mean_brightness(vtkRenderWindow* window) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  double sum = 0.0;
  const int components = pixels->GetNumberOfComponents();
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
    sum += std::max({pixels->GetValue(components * i), pixels->GetValue(components * i + 1),
                     pixels->GetValue(components * i + 2)});
  return sum / static_cast<double>(pixels->GetNumberOfTuples());
}

TEST(PclVisualizer, OneCallMakesACloudTranslucentInTheVisualizersOwnWindow) {
  pcl::visualization::PCLVisualizer viewer("sss one-call test", false);
  viewer.getRenderWindow()->SetOffScreenRendering(1);
  viewer.setSize(240, 240);
  viewer.setBackgroundColor(0, 0, 0);
  viewer.setShowFPS(false);  // its digits change the brightness from frame to frame
  const Eigen::Vector3d behind(0.3, 0.2, -1.0);
  viewer.getRenderWindow()->Render();
  const double empty = mean_brightness(viewer.getRenderWindow());

  const sss::TranslucentCloud::Ptr handle =
    sss::addTranslucentCloud(viewer, sphere(40, 80), "sphere");
  ASSERT_TRUE(handle);
  EXPECT_TRUE(viewer.contains("sphere"));
  EXPECT_THROW(sss::addTranslucentCloud(viewer, sphere(4, 8), "sphere"), std::invalid_argument);
  handle->setLights({behind});
  viewer.setCameraPosition(0, 0, 60, 0, 0, 0, 0, 1, 0);
  viewer.getRenderWindow()->Render();
  std::printf("%s; %s\n", handle->surfels().summary().c_str(), handle->settingsLine().c_str());

  const std::vector<float> B = radiance(handle->pass(), handle->actor());
  const double difference = largest_difference(B, plain_vtk_radiance(handle->surfels(), behind));
  std::printf("largest B difference to the plain VTK path: %.2e of the peak\n", difference);
  EXPECT_LT(difference, 1e-5);  // the same shaders on the same rasteriser: float rounding only

  handle->autoExpose();
  viewer.getRenderWindow()->Render();
  const double lit = mean_brightness(viewer.getRenderWindow());
  std::printf("mean brightness: %.2f empty, %.2f with the sphere\n", empty, lit);
  EXPECT_GT(lit, empty + 5.0);  // the sphere covers about a fifth of the window and glows

  ASSERT_TRUE(handle->setMaterial("ketchup"));
  EXPECT_FALSE(handle->setMaterial("cheese"));
  viewer.getRenderWindow()->Render();
  const std::vector<float> ketchup = radiance(handle->pass(), handle->actor());
  double red = 0, blue = 0;  // ketchup's blue albedo is 0.02, its red 0.75 (Rd 100x apart)
  for (std::size_t i = 0; i < ketchup.size(); i += 3) red += ketchup[i], blue += ketchup[i + 2];
  std::printf("ketchup: summed B red / blue = %.1f\n", red / blue);
  EXPECT_GT(red, 20.0 * blue);
  handle->setQuality(sss::Quality::Accurate);
  EXPECT_EQ(handle->pass()->GetCellSamples(), 128);
  EXPECT_EQ(handle->pass()->GetMaxMapSize(), 4096);
  EXPECT_EQ(handle->pass()->GetOpeningAngle(), 0.3);
  handle->setQuality(sss::Quality::Balanced);  // the pass's defaults
  vtkNew<vtkSubsurfacePass> defaults;
  EXPECT_EQ(handle->pass()->GetCellSamples(), defaults->GetCellSamples());
  EXPECT_EQ(handle->pass()->GetMaxMapSize(), defaults->GetMaxMapSize());
  EXPECT_EQ(handle->pass()->GetOpeningAngle(), defaults->GetOpeningAngle());

  EXPECT_TRUE(viewer.removeShape("sphere"));
  EXPECT_FALSE(viewer.contains("sphere"));
  handle->remove();
  vtkRenderer* renderer = viewer.getRendererCollection()->GetFirstRenderer();
  EXPECT_EQ(renderer->GetPass(), nullptr);
  viewer.getRenderWindow()->Render();
  EXPECT_EQ(mean_brightness(viewer.getRenderWindow()), empty);  // black again
}

// TranslucentCloud::spinOnce in place of PCL's in an application's loop, with refinement on: a
// change of material and light shows the preview, and the calls that follow (the rest, the bake
// on its thread, then the parts, run between frames) end with the B that the plain VTK path
// computes at once. They draw no frame during the rest or while the bake's thread is at work
// (such a frame would only redraw the preview, taking the processors from the thread).
TEST(PclVisualizer, SpinOnceRefinesToTheBOfAPassThatDoesNot) {
  pcl::visualization::PCLVisualizer viewer("sss refinement test", true);
  viewer.setSize(160, 160);
  viewer.setShowFPS(false);
  const sss::TranslucentCloud::Ptr handle =
    sss::addTranslucentCloud(viewer, sphere(120, 240), "sphere");  // 28,560 points
  ASSERT_TRUE(handle);
  viewer.setCameraPosition(0, 0, 60, 0, 0, 0, 0, 1, 0);
  handle->setRefinement(true);
  const double rest = 1.0;  // s; the rest counts from the preview's steps, inside its frame
  handle->setRefinementRest(rest);
  const Eigen::Vector3d side(1.0, 0.5, 0.5);
  ASSERT_TRUE(handle->setMaterial("skimmilk"));  // a bake anew, which refinement runs on a thread
  handle->setLights({side});
  viewer.getRenderWindow()->Render();
  // The new window's expose events, which redraw it whatever the refinement.
  sss::processPendingEvents(viewer.getRenderWindow()->GetInteractor());
  using Clock = std::chrono::steady_clock;
  const Clock::time_point previewed = Clock::now();
  ASSERT_TRUE(handle->refinementPending()) << "the first frame shows the preview";
  struct Frames {
    int count = 0;
    Clock::time_point last_start;
  } frames;
  vtkNew<vtkCallbackCommand> on_start;
  on_start->SetClientData(&frames);
  on_start->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
    auto* f = static_cast<Frames*>(data);
    ++f->count;
    f->last_start = Clock::now();
  });
  viewer.getRenderWindow()->AddObserver(vtkCommand::StartEvent, on_start);
  int calls = 0, preparing = 0, during_rest = 0, redrawn_while_preparing = 0;
  const Clock::time_point end = Clock::now() + std::chrono::minutes(1);
  while (handle->refinementPending() && Clock::now() < end) {
    const int frames_before = frames.count;
    const bool preparing_before = handle->refinementPreparing();
    handle->spinOnce(viewer);
    ++calls;
    if (handle->refinementPreparing()) ++preparing;
    if (frames.count == frames_before) continue;
    // Half the rest: the preview's frame goes on drawing for a while after its steps.
    if (std::chrono::duration<double>(frames.last_start - previewed).count() < 0.5 * rest)
      ++during_rest;
    if (preparing_before && handle->refinementPreparing()) ++redrawn_while_preparing;
  }
  ASSERT_FALSE(handle->refinementPending()) << "not refined within a minute";
  std::printf("refined after %d calls and %d frames, %d calls while the bake's thread ran\n",
              calls, frames.count, preparing);
  EXPECT_GE(preparing, 1);
  EXPECT_EQ(during_rest, 0) << "frames drawn in the first half of the " << rest << " s rest";
  EXPECT_EQ(redrawn_while_preparing, 0) << "frames that redrew the preview while the bake ran";
  const double difference = largest_difference(radiance(handle->pass(), handle->actor()),
                                               plain_vtk_radiance(handle->surfels(), side, "skimmilk"));
  std::printf("largest B difference to the plain VTK path: %.2e of the peak\n", difference);
  EXPECT_LT(difference, 1e-5);
}

}  // namespace

// Ctrl+Shift and a left drag turns the light by the drag (half a degree a pixel) and leaves the
// camera where it is; a plain drag turns no light and reaches PCL's interactor, which orbits.
TEST(PclVisualizer, CtrlShiftDragTurnsTheLightAndNotTheCamera) {
  pcl::visualization::PCLVisualizer viewer("sss drag test", true);
  viewer.setSize(200, 200);
  viewer.addPointCloud<pcl::PointXYZ>(sphere(10, 20).makeShared(), "sphere");
  viewer.setCameraPosition(0, 0, 60, 0, 0, 0, 0, 1, 0);
  viewer.getRenderWindow()->Render();
  double right = 0, up = 0;
  int turns = 0;
  sss::LightDrag drag(viewer, [&](double r, double u) { right += r, up += u, ++turns; });
  vtkRenderWindowInteractor* in = viewer.getRenderWindow()->GetInteractor();
  vtkCamera* camera = viewer.getRendererCollection()->GetFirstRenderer()->GetActiveCamera();
  const auto drag_with = [in](int control, int shift) {
    const int path[3][2] = {{100, 100}, {120, 90}, {140, 110}};
    in->SetEventInformation(path[0][0], path[0][1], control, shift);
    in->InvokeEvent(vtkCommand::LeftButtonPressEvent);
    for (int i = 1; i < 3; ++i) {
      in->SetEventInformation(path[i][0], path[i][1], control, shift);
      in->InvokeEvent(vtkCommand::MouseMoveEvent);
    }
    in->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
  };
  double before[3], after[3];
  camera->GetPosition(before);
  drag_with(1, 1);
  camera->GetPosition(after);
  EXPECT_EQ(turns, 2);
  EXPECT_DOUBLE_EQ(right, 20.0);  // 40 pixels right
  EXPECT_DOUBLE_EQ(up, 5.0);      // 10 pixels up
  EXPECT_FALSE(drag.dragging());
  for (int k = 0; k < 3; ++k) EXPECT_EQ(after[k], before[k]) << "the camera moved";
  // A release lost (the window lost the grab): the next plain press ends the light's drag.
  in->SetEventInformation(100, 100, 1, 1);
  in->InvokeEvent(vtkCommand::LeftButtonPressEvent);
  EXPECT_TRUE(drag.dragging());
  drag_with(0, 0);
  camera->GetPosition(after);
  EXPECT_FALSE(drag.dragging());
  EXPECT_EQ(turns, 2) << "a plain drag turned the light";
  double moved = 0;
  for (int k = 0; k < 3; ++k) moved += std::abs(after[k] - before[k]);
  EXPECT_GT(moved, 1.0) << "a plain drag should orbit the camera";
}

// The view of the surfel mapper on its own (plain look, EGL): radii from measured coverage close
// randomly sampled and range-thinned surfaces, blended splats are as smooth as a mesh of the
// same surface with silhouettes antialiased, and opaque actors stay in front or behind as their
// depth says.
#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDiskSource.h>
#include <vtkEGLSurfacelessRenderWindow.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkSurfelMapper.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gpu_scene.h"
#include "procedural_shapes.h"
#include "sphere_cases.h"

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 256;

struct Cloud {
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<std::array<unsigned char, 3>> colours;
};

vtkSmartPointer<vtkPolyData> to_polydata(const Cloud& c) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    points->InsertNextPoint(c.points[i].data());
    normals->InsertNextTuple3(c.normals[i].x(), c.normals[i].y(), c.normals[i].z());
    colours->InsertNextTuple3(c.colours[i][0], c.colours[i][1], c.colours[i][2]);
  }
  auto p = vtkSmartPointer<vtkPolyData>::New();
  p->SetPoints(points);
  p->GetPointData()->SetNormals(normals);
  p->GetPointData()->SetScalars(colours);
  return p;
}

// Uniform random points on the unit sphere: the front half (z > 0, towards the camera) red,
// the back half blue, so that a hole in the front shows blue.
Cloud random_sphere(std::size_t n, unsigned seed, bool white = false) {
  Cloud c;
  for (const Eigen::Vector3d& x : sss::test::random_unit_sphere(n, seed)) {
    c.points.push_back(x);
    c.normals.push_back(x);
    c.colours.push_back(white ? std::array<unsigned char, 3>{255, 255, 255}
                        : x.z() > 0.0 ? std::array<unsigned char, 3>{255, 0, 0}
                                      : std::array<unsigned char, 3>{0, 0, 255});
  }
  return c;
}

// A scanner 1 unit above the plane z = 0, stepping `step` radians in azimuth and in the angle
// from the vertical (20 to 70 degrees): rings whose spacing grows with the range.
Cloud scanner_rings(double step) {
  Cloud c;
  for (double a = 20.0 * kPi / 180.0; a < 70.0 * kPi / 180.0; a += step) {
    const double rho = std::tan(a);
    for (double phi = 0.0; phi < 2.0 * kPi - 0.5 * step; phi += step) {
      c.points.emplace_back(rho * std::cos(phi), rho * std::sin(phi), 0.0);
      c.normals.emplace_back(0.0, 0.0, 1.0);
      c.colours.push_back({255, 0, 0});
    }
  }
  return c;
}

// The window's last frame, RGB, rows from the bottom.
std::vector<unsigned char> grab_rgb(vtkRenderWindow* window) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  return std::vector<unsigned char>(scalars->GetPointer(0),
                                    scalars->GetPointer(0) + scalars->GetNumberOfValues());
}

struct View {
  vtkNew<vtkEGLSurfacelessRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  explicit View(double parallel_scale, int size = kSize) {
    window->SetSize(size, size);
    window->AddRenderer(renderer);
    renderer->SetBackground(0, 0, 0);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetPosition(0, 0, 10);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    camera->SetParallelScale(parallel_scale);
    camera->SetClippingRange(1, 20);
  }
  // RGB per pixel, row by row from the bottom.
  std::vector<unsigned char> render() {
    window->Render();
    return grab_rgb(window);
  }
};

vtkSmartPointer<vtkActor> surfel_actor(const Cloud& c, vtkSurfelMapper** mapper_out = nullptr) {
  vtkNew<vtkSurfelMapper> mapper;
  mapper->SetInputData(to_polydata(c));
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.3);
  actor->GetProperty()->SetDiffuse(0.7);
  if (mapper_out) *mapper_out = mapper;
  return actor;
}

// A mesh as a flat, unlit white silhouette, or lit (ambient 0.3, diffuse 0.7 under the headlight).
vtkSmartPointer<vtkActor> mesh_actor(vtkAlgorithm* source, bool lit, double r = 1, double g = 1, double b = 1) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetAmbient(lit ? 0.3 : 1.0);
  actor->GetProperty()->SetDiffuse(lit ? 0.7 : 0.0);
  actor->GetProperty()->SetSpecular(0.0);
  actor->GetProperty()->SetInterpolationToPhong();
  return actor;
}

// The mesh silhouette's pixels, less those within `erode` pixels of its edge.
std::vector<bool> silhouette(const std::vector<unsigned char>& mesh, int erode) {
  std::vector<bool> in(kSize * kSize), out(kSize * kSize, false);
  for (int p = 0; p < kSize * kSize; ++p) in[p] = mesh[3 * p] > 128;
  for (int y = erode; y < kSize - erode; ++y)
    for (int x = erode; x < kSize - erode; ++x) {
      bool all = true;
      for (int dy = -erode; dy <= erode && all; ++dy)
        for (int dx = -erode; dx <= erode && all; ++dx) all = in[(y + dy) * kSize + x + dx];
      out[y * kSize + x] = all;
    }
  return out;
}

// Fraction of the mask's pixels where the front surface (red) is not what shows.
double uncovered(const std::vector<unsigned char>& image, const std::vector<bool>& mask, int* count = nullptr) {
  int inside = 0, open = 0;
  for (int p = 0; p < kSize * kSize; ++p) {
    if (!mask[p]) continue;
    ++inside;
    const int r = image[3 * p], b = image[3 * p + 2];
    if (r < 16 || b >= r) ++open;
  }
  if (count) *count = inside;
  return inside ? double(open) / inside : 1.0;
}

std::vector<unsigned char> mesh_sphere_image(bool lit) {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(256);
  sphere->SetPhiResolution(256);
  View view(1.2);
  view.renderer->AddActor(mesh_actor(sphere, lit));
  return view.render();
}

TEST(GpuSplats, RandomSpheresAreClosedAtThreeDensities) {
  const std::vector<bool> mask = silhouette(mesh_sphere_image(false), 2);
  for (std::size_t n : {4000u, 16000u, 64000u}) {
    const Cloud cloud = random_sphere(n, 11);
    for (int splatting : {vtkSurfelMapper::BLENDED, vtkSurfelMapper::DISCS}) {
      View view(1.2);
      vtkSurfelMapper* mapper = nullptr;
      view.renderer->AddActor(surfel_actor(cloud, &mapper));
      mapper->SetSplatting(splatting);
      int pixels = 0;
      const double open = uncovered(view.render(), mask, &pixels);
      std::printf("random sphere, %zu points, %s: radius %.4f (uncovered area %.3g %%), %.3f %% of "
                  "%d pixels open\n",
                  n, mapper->GetSplattingAsString(), mapper->GetEffectiveRadius(),
                  100.0 * mapper->GetUncoveredFraction(), 100.0 * open, pixels);
      EXPECT_FALSE(mapper->GetUsesPerPointRadii());
      EXPECT_LT(open, 1e-3) << n << " points, " << mapper->GetSplattingAsString();
    }
  }
  // The old rule, 1.5 mean nearest-neighbour spacings, leaves holes the test must see.
  const Cloud cloud = random_sphere(16000, 11);
  View view(1.2);
  vtkSurfelMapper* mapper = nullptr;
  view.renderer->AddActor(surfel_actor(cloud, &mapper));
  const double spacing = 0.5 * std::sqrt(4.0 * kPi / 16000.0);  // Poisson: 1 / (2 sqrt(rho))
  mapper->SetRadius(1.5 * spacing);
  const double open = uncovered(view.render(), mask);
  std::printf("random sphere, 16000 points, radius 1.5 mean spacings: %.2f %% of pixels open\n",
              100.0 * open);
  EXPECT_GT(open, 0.01);
}

TEST(GpuSplats, RangeThinnedPlaneIsClosedWithPerPointRadii) {
  vtkNew<vtkDiskSource> annulus;  // the sampled region, 1 degree in from its first and last rings
  annulus->SetInnerRadius(std::tan(21.0 * kPi / 180.0));
  annulus->SetOuterRadius(std::tan(69.0 * kPi / 180.0));
  annulus->SetCircumferentialResolution(720);
  annulus->SetRadialResolution(4);
  View mesh_view(2.7);
  mesh_view.renderer->AddActor(mesh_actor(annulus, false));
  const std::vector<bool> mask = silhouette(mesh_view.render(), 2);
  const Cloud cloud = scanner_rings(0.006);
  View view(2.7);
  vtkSurfelMapper* mapper = nullptr;
  view.renderer->AddActor(surfel_actor(cloud, &mapper));
  int pixels = 0;
  const double open = uncovered(view.render(), mask, &pixels);
  std::printf("scanner rings, %zu points: per-point radii %s, %.3f %% of %d pixels open\n",
              cloud.points.size(), mapper->GetUsesPerPointRadii() ? "yes" : "no", 100.0 * open, pixels);
  EXPECT_TRUE(mapper->GetUsesPerPointRadii());
  EXPECT_LT(open, 1e-3);
}

// Mean and 99th percentile of the absolute difference between horizontally and vertically
// neighbouring pixels inside the mask (grey level over 255).
std::pair<double, double> roughness(const std::vector<unsigned char>& image, const std::vector<bool>& mask) {
  std::vector<double> d;
  for (int y = 0; y + 1 < kSize; ++y)
    for (int x = 0; x + 1 < kSize; ++x) {
      const int p = y * kSize + x;
      if (!mask[p]) continue;
      if (mask[p + 1]) d.push_back(std::abs(image[3 * p] - image[3 * (p + 1)]) / 255.0);
      if (mask[p + kSize]) d.push_back(std::abs(image[3 * p] - image[3 * (p + kSize)]) / 255.0);
    }
  double mean = 0.0;
  for (double v : d) mean += v / d.size();
  std::sort(d.begin(), d.end());
  return {mean, d[static_cast<std::size_t>(0.99 * (d.size() - 1))]};
}

TEST(GpuSplats, BlendedSpheresAreAsSmoothAsTheMesh) {
  const std::vector<unsigned char> mesh = mesh_sphere_image(true);
  const std::vector<bool> mask = silhouette(mesh_sphere_image(false), 2);
  const auto [mesh_mean, mesh_p99] = roughness(mesh, mask);
  std::printf("mesh sphere: neighbour difference mean %.4f, p99 %.4f\n", mesh_mean, mesh_p99);
  for (int splatting : {vtkSurfelMapper::BLENDED, vtkSurfelMapper::DISCS}) {
    View view(1.2);
    vtkSurfelMapper* mapper = nullptr;
    view.renderer->AddActor(surfel_actor(random_sphere(16000, 5, true), &mapper));
    mapper->SetSplatting(splatting);
    const auto [mean, p99] = roughness(view.render(), mask);
    std::printf("16000 random points, %s: neighbour difference mean %.4f, p99 %.4f\n",
                mapper->GetSplattingAsString(), mean, p99);
    // Bound: within one 8-bit level of the mesh on average and two at the 99th percentile.
    const bool smooth = mean <= mesh_mean + 1.0 / 255.0 && p99 <= mesh_p99 + 2.0 / 255.0;
    if (splatting == vtkSurfelMapper::BLENDED) {
      EXPECT_TRUE(smooth);
    } else {
      EXPECT_FALSE(smooth);  // hard discs show their grain: the measure sees it
    }
  }
}

// Silhouettes against the same scene drawn at 4 x 4 the pixels and averaged down (what a box
// filter of the outline gives), over the pixels whose 16 fine pixels hold both surface and
// `background`: per pixel the largest channel's difference, over 255, averaged.
double silhouette_error(const std::vector<unsigned char>& image, const std::vector<unsigned char>& fine,
                        const std::array<unsigned char, 3>& background) {
  double sum = 0.0;
  int edge = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      double box[3] = {0.0, 0.0, 0.0};
      int surface = 0;
      for (int sy = 0; sy < 4; ++sy)
        for (int sx = 0; sx < 4; ++sx) {
          const unsigned char* c = &fine[3 * ((4 * y + sy) * 4 * kSize + 4 * x + sx)];
          surface += c[0] != background[0] || c[1] != background[1] || c[2] != background[2];
          for (int k = 0; k < 3; ++k) box[k] += c[k] / 16.0;
        }
      if (surface == 0 || surface == 16) continue;
      double worst = 0.0;
      for (int k = 0; k < 3; ++k)
        worst = std::max(worst, std::abs(image[3 * (y * kSize + x) + k] - box[k]) / 255.0);
      sum += worst;
      ++edge;
    }
  return edge > 0 ? sum / edge : 1.0;
}

// A white sphere of splats, unshaded, on black: a pixel's grey level is the share of it the
// splats cover. Blended splats fade their rims over a pixel; hard discs cover a pixel or not,
// about a quarter off on average wherever an edge crosses at a random place.
std::vector<unsigned char> white_sphere(int splatting, int size) {
  View view(1.2, size);
  view.window->SetMultiSamples(0);  // the splats' own edges, not the window's multisampling
  vtkSurfelMapper* mapper = nullptr;
  vtkSmartPointer<vtkActor> actor = surfel_actor(random_sphere(16000, 5, true), &mapper);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  mapper->SetSplatting(splatting);
  view.renderer->AddActor(actor);
  return view.render();
}

// The same under the subsurface pass: a marble sphere (30 mm, 16,000 points) lit from the side
// and front, on white (its rim is dark: Ft falls to 0 at grazing view). The composite fades a
// silhouette pixel into its neighbours behind.
std::vector<unsigned char> translucent_sphere(int splatting, int size) {
  const sss::SurfelCloud sphere = sss::make_fibonacci_sphere(30.0, 16000);
  sss::test::GpuScene scene(sphere, sss::Material::preset("marble"),
                            {{Eigen::Vector3d(0.6, 0.3, 1.0), 1.0}}, Eigen::Vector3d(0, 0, 1),
                            size);
  scene.window->SetMultiSamples(0);
  scene.renderer->SetBackground(1, 1, 1);
  scene.mapper->SetSplatting(splatting);
  scene.window->Render();
  return grab_rgb(scene.window);
}

TEST(GpuSplats, SilhouettesAreAntialiased) {
  for (bool translucent : {false, true}) {
    auto draw = translucent ? translucent_sphere : white_sphere;
    const std::array<unsigned char, 3> background =
        translucent ? std::array<unsigned char, 3>{255, 255, 255} : std::array<unsigned char, 3>{0, 0, 0};
    double error[2];
    for (int splatting : {vtkSurfelMapper::BLENDED, vtkSurfelMapper::DISCS}) {
      const int k = splatting == vtkSurfelMapper::BLENDED ? 0 : 1;
      error[k] = silhouette_error(draw(splatting, kSize), draw(splatting, 4 * kSize), background);
      std::printf("%s, %s: silhouette off the 4 x 4 box filter by %.3f on average\n",
                  translucent ? "marble sphere" : "white sphere, 16000 random points",
                  k == 0 ? "Blended" : "Discs", error[k]);
    }
    if (translucent) {
      EXPECT_LT(error[0], 0.5 * error[1]);  // the edge's contrast varies with the light
    } else {
      EXPECT_LT(error[0], 0.1);
    }
    EXPECT_GT(error[1], 0.2);  // the measure sees hard edges
  }
}

TEST(GpuSplats, OpaqueActorsKeepTheirDepthOrder) {
  // A splat plane (red) at z = 0 between an opaque green square in front (z = 0.5, centre)
  // and an opaque blue plane behind (z = -0.5), added before and after the splats.
  Cloud plane;
  for (int i = -40; i <= 40; ++i)
    for (int j = -40; j <= 40; ++j) {
      plane.points.emplace_back(0.02 * i, 0.02 * j, 0.0);
      plane.normals.emplace_back(0.0, 0.0, 1.0);
      plane.colours.push_back({255, 0, 0});
    }
  for (bool opaque_first : {true, false}) {
    vtkNew<vtkPlaneSource> front, back;
    front->SetOrigin(-0.2, -0.2, 0.5);
    front->SetPoint1(0.2, -0.2, 0.5);
    front->SetPoint2(-0.2, 0.2, 0.5);
    back->SetOrigin(-1.5, -1.5, -0.5);
    back->SetPoint1(1.5, -1.5, -0.5);
    back->SetPoint2(-1.5, 1.5, -0.5);
    View view(1.2);
    vtkSmartPointer<vtkActor> opaque_front = mesh_actor(front, false, 0, 1, 0);
    vtkSmartPointer<vtkActor> opaque_back = mesh_actor(back, false, 0, 0, 1);
    if (opaque_first) {
      view.renderer->AddActor(opaque_front);
      view.renderer->AddActor(opaque_back);
    }
    view.renderer->AddActor(surfel_actor(plane));
    if (!opaque_first) {
      view.renderer->AddActor(opaque_front);
      view.renderer->AddActor(opaque_back);
    }
    const std::vector<unsigned char> image = view.render();
    auto at = [&](double x, double y) {  // world xy to the pixel's RGB
      const int px = static_cast<int>((x / 1.2 + 1.0) * 0.5 * kSize);
      const int py = static_cast<int>((y / 1.2 + 1.0) * 0.5 * kSize);
      const unsigned char* c = &image[3 * (py * kSize + px)];
      return std::array<int, 3>{c[0], c[1], c[2]};
    };
    const auto centre = at(0.0, 0.0), splats = at(0.5, 0.5), outside = at(1.0, 1.0);
    std::printf("opaque %s: centre %d %d %d, splats %d %d %d, beyond them %d %d %d\n",
                opaque_first ? "first" : "last", centre[0], centre[1], centre[2], splats[0],
                splats[1], splats[2], outside[0], outside[1], outside[2]);
    EXPECT_GT(centre[1], 200);
    EXPECT_LT(centre[0], 30);
    EXPECT_GT(splats[0], 50);
    EXPECT_LT(splats[2], 30);
    EXPECT_GT(outside[2], 200);
  }
}

// A window resized after its first frame draws what a new window of that size draws. The pass's
// framebuffer kept its first size as the scene's viewport, so after a resize the image came out
// stretched and cropped (ParaView's split views, any resized VTK window).
TEST(GpuSplats, AResizedWindowDrawsAsANewWindowOfItsSize) {
  const sss::SurfelCloud sphere = sss::make_fibonacci_sphere(30.0, 16000);
  const sss::Material marble = sss::Material::preset("marble");
  const std::vector<sss::Light> light{{Eigen::Vector3d(0.6, 0.3, 1.0), 1.0}};
  sss::test::GpuScene resized(sphere, marble, light, Eigen::Vector3d(0, 0, 1), 2 * kSize);
  sss::test::GpuScene fresh(sphere, marble, light, Eigen::Vector3d(0, 0, 1), kSize);
  resized.window->Render();
  resized.window->SetSize(kSize, kSize / 2);
  resized.window->Render();
  fresh.window->SetSize(kSize, kSize / 2);
  fresh.window->Render();
  const std::vector<unsigned char> a = grab_rgb(resized.window), b = grab_rgb(fresh.window);
  ASSERT_EQ(a.size(), b.size());
  int largest = 0;
  long differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int d = std::abs(int(a[i]) - int(b[i]));
    largest = std::max(largest, d);
    differing += d > 0 ? 1 : 0;
  }
  std::printf("resized against new: %ld of %zu values differ, by at most %d\n", differing,
              a.size(), largest);
  EXPECT_EQ(largest, 0);
}

}  // namespace

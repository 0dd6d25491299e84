// sss_render with --backend osmesa and --backend egl (DISPLAY unset) writes the same image.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "linear_image.h"

namespace {

int render(const std::string& backend, const std::string& stem) {
  const std::string command = std::string("env -u DISPLAY '") + SSS_RENDER_PATH +
                              "' --backend " + backend + " --size 200x160 --output " + stem +
                              ".png --linear " + stem + ".pfm --light-dir 0.2,1,-0.2";
  return std::system(command.c_str());
}

TEST(Backends, OSMesaAndEGLImagesAgree) {
  ASSERT_EQ(render("egl", "backend_egl"), 0);
  ASSERT_EQ(render("osmesa", "backend_osmesa"), 0);
  const sss::LinearImage egl = sss::read_pfm("backend_egl.pfm");
  const sss::LinearImage osmesa = sss::read_pfm("backend_osmesa.pfm");
  const sss::ErrorStats e = sss::compare_images(osmesa, egl);
  std::printf("[ backends ] OSMesa vs EGL: %zu pixels, mean %.2e max %.2e, 8-bit max %.0f\n",
              e.compared, e.mean, e.max, e.srgb8_max);
  EXPECT_GT(e.compared, 1000u);
  EXPECT_LT(e.max, 1e-5);
}

TEST(Backends, XWithoutADisplayFailsWithAClearMessage) {
  const std::string command = std::string("env -u DISPLAY '") + SSS_RENDER_PATH +
                              "' --backend x --output backend_x.png 2> backend_x.err";
  EXPECT_NE(std::system(command.c_str()), 0);
  EXPECT_NE(std::system("grep -q 'DISPLAY is not set' backend_x.err"), 1);
  EXPECT_NE(std::system("test -e backend_x.png"), 0) << "no output file on failure";
}

}  // namespace

// sss_render with --backend osmesa and --backend egl (DISPLAY unset) writes the same image;
// EGL's device platform (the first choice) and Mesa's surfaceless platform draw the same
// image; a device that does not exist is refused naming the devices found; the stats name the
// renderer.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "linear_image.h"

namespace {

int render(const std::string& backend, const std::string& stem, const std::string& extra = "") {
  const std::string command = std::string("env -u DISPLAY -u SSS_EGL_DEVICE '") +
                              SSS_RENDER_PATH + "' --backend " + backend +
                              " --size 200x160 --output " + stem + ".png --linear " + stem +
                              ".pfm --light-dir 0.2,1,-0.2 " + extra;
  return std::system(command.c_str());
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
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

// Here (no graphics card) the device platform lists Mesa's software device alone and draws
// on it: the same image as the surfaceless platform, bit for bit, and the stats say which.
TEST(Backends, EGLDevicePlatformMatchesTheSurfacelessPlatform) {
  ASSERT_EQ(render("egl", "device_default", "--stats device_default.json"), 0);
  ASSERT_EQ(render("egl", "device_surfaceless", "--gpu surfaceless --stats device_surfaceless.json"), 0);
  const std::string on_device = read_text("device_default.json");
  const std::string surfaceless = read_text("device_surfaceless.json");
  std::printf("[ backends ] %s\n", on_device.substr(on_device.find("\"renderer\"")).substr(0, 300).c_str());
  EXPECT_NE(on_device.find("\"context\": \"EGL device 0 of"), std::string::npos);
  EXPECT_NE(surfaceless.find("\"context\": \"EGL surfaceless platform"), std::string::npos);
  for (const char* key : {"\"gl_vendor\": \"", "\"gl_renderer\": \"", "\"gl_version\": \""}) {
    const std::size_t at = on_device.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_NE(on_device[at + std::strlen(key)], '"') << key << " is empty";
  }
  const sss::LinearImage a = sss::read_pfm("device_default.pfm");
  const sss::LinearImage b = sss::read_pfm("device_surfaceless.pfm");
  const sss::ErrorStats e = sss::compare_images(b, a);
  EXPECT_GT(e.compared, 1000u);
  EXPECT_EQ(e.max, 0.0);
}

TEST(Backends, AnEGLDeviceThatDoesNotExistIsRefusedNamingTheDevices) {
  const std::string command = std::string("env -u DISPLAY -u SSS_EGL_DEVICE '") + SSS_RENDER_PATH +
                              "' --gpu 7 --output device_7.png 2> device_7.err";
  EXPECT_NE(std::system(command.c_str()), 0);
  const std::string err = read_text("device_7.err");
  std::printf("[ backends ] %s", err.substr(err.rfind("sss_render:")).c_str());
  EXPECT_NE(err.find("EGL device 7 cannot be used"), std::string::npos);
  EXPECT_NE(err.find("devices found: EGL device 0 of"), std::string::npos);
  EXPECT_NE(std::system("test -e device_7.png"), 0) << "no output file on failure";
  const std::string variable = std::string("env -u DISPLAY SSS_EGL_DEVICE=card '") +
                               SSS_RENDER_PATH + "' --output device_card.png 2> device_card.err";
  EXPECT_NE(std::system(variable.c_str()), 0);
  EXPECT_NE(read_text("device_card.err").find("SSS_EGL_DEVICE=card is neither a device number"),
            std::string::npos);
}

TEST(Backends, XWithoutADisplayFailsWithAClearMessage) {
  const std::string command = std::string("env -u DISPLAY '") + SSS_RENDER_PATH +
                              "' --backend x --output backend_x.png 2> backend_x.err";
  EXPECT_NE(std::system(command.c_str()), 0);
  EXPECT_NE(std::system("grep -q 'DISPLAY is not set' backend_x.err"), 1);
  EXPECT_NE(std::system("test -e backend_x.png"), 0) << "no output file on failure";
}

}  // namespace

// The example scenes in examples/ (the seed lecture notes' OpenGL programs as scene files)
// render, and the first one matches the equation worked by hand.
#include "cli_support.h"

#include <illum/image.h>

#include <gtest/gtest.h>

namespace illum {
namespace {

using test::runIllum;
using test::TempDir;
namespace fs = std::filesystem;

TEST(Examples, EveryExampleRenders) {
  TempDir dir;
  int count = 0;
  for (const auto& entry : fs::directory_iterator(ILLUM_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    const fs::path out = dir / (entry.path().stem().string() + ".png");
    // Few rays per pixel: the path-traced examples ask for hundreds, which only cost time here (and
    // 4 is a multisample count too, for the rasterized ones).
    const auto r = runIllum("render " + entry.path().string() + " --samples 4 -o " + out.string());
    EXPECT_EQ(r.exitCode, 0) << entry.path() << ": " << r.err;
    EXPECT_EQ(r.err, "") << entry.path();  // no warnings either
    EXPECT_TRUE(fs::exists(out)) << entry.path();
  }
  EXPECT_GE(count, 4);
}

// Seed 003's first lighting program: glutSolidSphere(1, 20, 16), one positional light at
// (1, 2, 3, 1) with ambient red, diffuse yellow and specular white, default material.
// At the sphere's pole facing the viewer, P = (0,0,1), N = (0,0,1), L = (1,2,2)/3, N·L = 2/3:
//   R = 0.2·0.2 + 1·0.2 + (2/3)·1·0.8 = 0.7733 → 197
//   G = 0.2·0.2 + 0     + (2/3)·1·0.8 = 0.5733 → 146
//   B = 0.2·0.2                        = 0.04   → 10
// (the material's specular is GL's default black, so no highlight).
TEST(Examples, FirstLightMatchesTheHandWorkedEquation) {
  TempDir dir;
  const auto r = runIllum("render " + (fs::path(ILLUM_EXAMPLES_DIR) / "first_light.json").string() + " -o " +
                          (dir / "out.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image img = readPng(dir / "out.png");
  const std::uint8_t* p = img.pixel(100, 100);  // the image centre, where the pole projects
  EXPECT_EQ(p[0], 197);
  EXPECT_EQ(p[1], 146);
  EXPECT_EQ(p[2], 10);
  EXPECT_EQ(p[3], 255);
}

// examples/whitted.json after Whitted's 1980 figure: the rasterizer draws a dark mirror sphere, a
// black glass sphere and no shadows; Whitted's ray tracer shows the checkerboard in the mirror,
// the scene through the glass and the glass sphere's shadow; Hall's lets light through the glass,
// so the shadow is lighter.
TEST(Examples, WhittedShowsShadowsMirrorsAndGlass) {
  TempDir dir;
  const fs::path scene = fs::path(ILLUM_EXAMPLES_DIR) / "whitted.json";
  const auto render = [&](const std::string& renderer) {
    const fs::path out = dir / (renderer + ".png");
    const auto r = runIllum("render " + scene.string() + " --renderer " + renderer + " -o " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readPng(out);
  };
  const Image raster = render("raster"), whitted = render("whitted"), hall = render("hall");
  for (const Image* image : {&raster, &whitted, &hall}) {
    const std::uint8_t* sky = image->pixel(320, 20);
    EXPECT_EQ(sky[0], 82);  // the background: 0.32, 0.55, 0.88
    EXPECT_EQ(sky[1], 140);
    EXPECT_EQ(sky[2], 224);
  }
  // The mirror sphere's lower half reflects a red square of the floor.
  EXPECT_LT(raster.pixel(390, 250)[0], 30);
  EXPECT_GT(whitted.pixel(390, 250)[0], 150);
  EXPECT_LT(whitted.pixel(390, 250)[1], 80);
  // Through the glass sphere: the rasterizer's black glass, the ray tracer's refracted sky.
  EXPECT_EQ(raster.pixel(260, 290)[2], 0);
  EXPECT_GT(whitted.pixel(260, 290)[2], 150);
  // The glass sphere's shadow on a yellow square: full in Whitted's model, lighter in Hall's.
  const int lit = raster.pixel(220, 320)[0], full = whitted.pixel(220, 320)[0], filtered = hall.pixel(220, 320)[0];
  EXPECT_GT(lit, 180);
  EXPECT_LT(full, lit * 2 / 5);
  EXPECT_GT(filtered, full + 40);
  EXPECT_LT(filtered, lit);
}

}  // namespace
}  // namespace illum

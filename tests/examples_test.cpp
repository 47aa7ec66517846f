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
    const auto r = runIllum("render " + entry.path().string() + " -o " + out.string());
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

}  // namespace
}  // namespace illum

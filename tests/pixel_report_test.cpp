// `--debug-pixel` tells the truth: for every shading frequency, with blending and labels on, the
// report's steps reproduce the fragment, and its "in the file" bytes are the PNG's.
#include "cli_support.h"

#include <illum/image.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <regex>
#include <sstream>

namespace illum {
namespace {

using test::runIllum;
using test::TempDir;
namespace fs = std::filesystem;

const fs::path kScene = fs::path(ILLUM_TEST_SCENES_DIR) / "probe_blend_labels.json";

std::vector<double> numbersAfter(const std::string& text, const std::string& key, std::size_t count) {
  const std::size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos) << key << " in\n" << text;
  std::vector<double> v;
  if (at == std::string::npos) return v;
  std::istringstream in(text.substr(at + key.size()));
  std::string word;
  while (v.size() < count && in >> word) {
    try {
      std::size_t used = 0;
      const double x = std::stod(word, &used);
      if (used > 0) v.push_back(x);
    } catch (const std::exception&) {
    }
  }
  return v;
}

struct Probe {
  std::string report;
  Image image;
};

Probe probe(const std::string& shading, int x, int y) {
  TempDir dir;
  const fs::path out = dir / (shading + ".png");
  const auto r = runIllum("render " + kScene.string() + " --shading " + shading + " --debug-pixel " +
                          std::to_string(x) + "," + std::to_string(y) + " -o " + out.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return {r.out, readPng(out)};
}

void expectFileBytes(const Probe& p, int x, int y) {
  const auto bytes = numbersAfter(p.report, "in the file: bytes", 4);
  ASSERT_EQ(bytes.size(), 4u) << p.report;
  const std::uint8_t* px = p.image.pixel(x, y);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(int(bytes[std::size_t(c)]), int(px[c])) << "channel " << c << "\n" << p.report;
}

class PixelReport : public testing::TestWithParam<std::string> {};

TEST_P(PixelReport, OpaquePixelBytesAreTheFragments) {
  // The cube's left part, clear of the translucent sphere.
  const Probe p = probe(GetParam(), 55, 60);
  expectFileBytes(p, 55, 60);
  const auto fragment = numbersAfter(p.report, "= bytes", 4);
  ASSERT_EQ(fragment.size(), 4u);
  const std::uint8_t* px = p.image.pixel(55, 60);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(int(fragment[std::size_t(c)]), int(px[c]));
}

TEST_P(PixelReport, BlendedPixelSaysSoAndShowsTheFileBytes) {
  const Probe p = probe(GetParam(), 100, 60);  // inside the translucent sphere
  EXPECT_NE(p.report.find("blended over what was there"), std::string::npos) << p.report;
  expectFileBytes(p, 100, 60);
}

TEST_P(PixelReport, LabelledPixelShowsTheLabelInTheFile) {
  // Under the caption: whatever the label drew is what the report says is in the file.
  for (int x = 62; x < 100; x += 3) {
    const Probe p = probe(GetParam(), x, 108);
    expectFileBytes(p, x, 108);
  }
}

TEST_P(PixelReport, StepsReproduceTheLitColour) {
  const Probe p = probe(GetParam(), 55, 60);
  const auto lit = numbersAfter(p.report, GetParam() == "gouraud" ? "lit colour (interpolated):" : "lit colour", 3);
  ASSERT_EQ(lit.size(), 3u) << p.report;
  if (GetParam() == "gouraud") {
    // The interpolated colour is the weights times the three vertex colours used.
    const auto w = numbersAfter(p.report, "perspective-correct weights:", 3);
    ASSERT_EQ(w.size(), 3u);
    EXPECT_NEAR(w[0] + w[1] + w[2], 1, 2e-4);
    std::vector<std::vector<double>> vc;
    std::size_t from = 0;
    for (int i = 0; i < 3; ++i) {
      from = p.report.find("vertex colour used:", from);
      ASSERT_NE(from, std::string::npos);
      vc.push_back(numbersAfter(p.report.substr(from), "vertex colour used:", 3));
      ++from;
    }
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_NEAR(lit[c], w[0] * vc[0][c] + w[1] * vc[1][c] + w[2] * vc[2][c], 3e-4) << c;
  } else {
    // Flat and Phong: the lit colour is the equation's clamped total at the point shown.
    const auto total = numbersAfter(p.report, "total (clamped)", 3);
    ASSERT_EQ(total.size(), 3u);
    for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(lit[c], total[c], 1e-4);
  }
  // Each light's geometry is printed: L, N·L, the lobe's vector and cosine, attenuation and spot.
  for (const char* key : {"L = (", "N·L = ", "attenuation ", "spot factor "})
    EXPECT_NE(p.report.find(key), std::string::npos) << key;
  EXPECT_NE(p.report.find("N·H = "), std::string::npos);  // the scene's model is blinn-phong
}

INSTANTIATE_TEST_SUITE_P(EveryShading, PixelReport, testing::Values("flat", "gouraud", "phong"));

int srgbByte(double byte) {
  const double c = byte / 255;
  return int(std::lround(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055)));
}

// The chain from the fragment to the file on a model preview (8 samples, sRGB): the resolve's
// bytes, the display encoding's (IEC 61966-2-1 of them), the file's.
TEST(PixelChain, ResolveThenDisplayThenTheFile) {
  TempDir dir;
  const fs::path out = dir / "duck.png";
  const auto r = runIllum("render /usr/share/assimp/models/Collada/duck.dae --debug-pixel 500,300 -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("resolve: the mean of the pixel's 8 samples"), std::string::npos) << r.out;
  const auto resolved = numbersAfter(r.out, "blending included: bytes", 4);
  const auto displayed = numbersAfter(r.out, "encoding srgb): bytes", 4);
  ASSERT_EQ(resolved.size(), 4u);
  ASSERT_EQ(displayed.size(), 4u);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(int(displayed[std::size_t(c)]), srgbByte(resolved[std::size_t(c)])) << c;
  const Image image = readPng(out);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(int(displayed[std::size_t(c)]), int(image.pixel(500, 300)[c])) << c;
  expectFileBytes({r.out, image}, 500, 300);
}

// A glTF preview lit by the studio goes through ACES, which the rasterizer applies to each lit
// colour before it is quantised: the report's total says so, its fragment is the tone-mapped
// colour's bytes, and its display step is the encoding alone, whose bytes are the file's.
TEST(PixelChain, ToneMapIsTheFragmentsThenTheEncoding) {
  TempDir dir;
  const fs::path out = dir / "box.png";
  const auto r = runIllum("render /usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb "
                          "--samples 1 --debug-pixel 500,300 -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("total (tone map aces, clamped)"), std::string::npos) << r.out;
  const auto resolved = numbersAfter(r.out, "blending included: bytes", 4);
  const auto displayed = numbersAfter(r.out, "; the tone map was the fragment's): bytes", 4);
  ASSERT_EQ(resolved.size(), 4u) << r.out;
  ASSERT_EQ(displayed.size(), 4u) << r.out;
  for (int c = 0; c < 3; ++c) EXPECT_EQ(int(displayed[std::size_t(c)]), srgbByte(resolved[std::size_t(c)])) << c;
  const Image image = readPng(out);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(int(displayed[std::size_t(c)]), int(image.pixel(500, 300)[c])) << c;
  expectFileBytes({r.out, image}, 500, 300);
}

// On the model's silhouette the samples differ (some on the duck, some on the background); the
// resolve is their mean, channel by channel, as GL's resolve rounds it.
TEST(PixelChain, EverySampleThenTheirMean) {
  TempDir dir;
  std::string report;
  for (int x = 120; x < 200 && report.empty(); ++x) {
    const auto r = runIllum("render /usr/share/assimp/models/Collada/duck.dae --resolution 500,300 --debug-pixel " +
                            std::to_string(x) + ",150 -o " + (dir / "d.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    if (r.out.find(": background: bytes") != std::string::npos && r.out.find(", triangle ") != std::string::npos &&
        r.out.find("    sample 7") != std::string::npos)
      report = r.out;
  }
  ASSERT_FALSE(report.empty()) << "no silhouette pixel on row 150";
  const std::regex sample(R"(    sample \d+ at \([-+.0-9]+, [-+.0-9]+\): .*bytes (\d+) (\d+) (\d+) (\d+))");
  std::array<double, 4> sum{};
  int count = 0;
  for (std::sregex_iterator it(report.begin(), report.end(), sample), end; it != end; ++it, ++count)
    for (int c = 0; c < 4; ++c) sum[std::size_t(c)] += std::stod((*it)[c + 1]);
  ASSERT_EQ(count, 8) << report;
  const auto resolved = numbersAfter(report, "blending included: bytes", 4);
  ASSERT_EQ(resolved.size(), 4u);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(resolved[std::size_t(c)], sum[std::size_t(c)] / 8, 0.51) << c << "\n" << report;
}

// A caption over the pixel is named, and it is why the file's bytes differ from the display step's.
TEST(PixelChain, ALabelOverThePixelIsNamed) {
  TempDir dir;
  const auto r = runIllum("render --debug-pixel 485,25 -o " + (dir / "x.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("drawn over it: the label \"Blinn-Phong: ambient + diffuse (N·L) + specular (N·H)ⁿ\""),
            std::string::npos) << r.out;
  EXPECT_NE(numbersAfter(r.out, "encoding linear): bytes", 4), numbersAfter(r.out, "in the file: bytes", 4));
  // Where no label is, none is named.
  const auto clear = runIllum("render --debug-pixel 480,300 -o " + (dir / "y.png").string());
  EXPECT_EQ(clear.out.find("drawn over it"), std::string::npos) << clear.out;
}

// --debug-point: the pixel a point of an object lands on, reported as --debug-pixel reports it;
// --mark-pixel rings it in the picture and leaves the pixel itself alone.
TEST(PixelChain, APointOfAnObjectAndItsMark) {
  TempDir dir;
  const auto r = runIllum("render --debug-point 0 --mark-pixel -o " + (dir / "marked.png").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(--debug-point 0 lands on pixel \((\d+), (\d+)\))"))) << r.out;
  const int x = std::stoi(m[1]), y = std::stoi(m[2]);
  EXPECT_NE(r.out.find("pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): object 0,"), std::string::npos) << r.out;
  const auto plain = runIllum("render --debug-pixel " + std::to_string(x) + "," + std::to_string(y) + " -o " +
                              (dir / "plain.png").string());
  const Image marked = readPng(dir / "marked.png"), unmarked = readPng(dir / "plain.png");
  int changed = 0;
  for (int j = 0; j < marked.height; ++j)
    for (int i = 0; i < marked.width; ++i) {
      const bool differs = !std::equal(marked.pixel(i, j), marked.pixel(i, j) + 4, unmarked.pixel(i, j));
      changed += differs;
      if (differs) {
        EXPECT_LE(std::hypot(i - x, j - y), 8) << i << "," << j;
      }
    }
  EXPECT_GT(changed, 40);
  EXPECT_TRUE(std::equal(marked.pixel(x, y), marked.pixel(x, y) + 4, unmarked.pixel(x, y)));
  const std::uint8_t* ring = marked.pixel(x + 5, y);
  EXPECT_EQ(int(ring[0]), 255);
  EXPECT_EQ(int(ring[1]), 0);
  EXPECT_EQ(int(ring[2]), 255);
  // Refusals name what is wrong.
  const auto none = runIllum("render --debug-point 9 -o " + (dir / "z.png").string());
  EXPECT_EQ(none.exitCode, 2);
  EXPECT_NE(none.err.find("the scene has 6 objects (0 .. 5)"), std::string::npos) << none.err;
  const auto alone = runIllum("render --mark-pixel -o " + (dir / "z.png").string());
  EXPECT_EQ(alone.exitCode, 2);
  EXPECT_NE(alone.err.find("--mark-pixel"), std::string::npos) << alone.err;
  EXPECT_FALSE(fs::exists(dir / "z.png"));
}

}  // namespace
}  // namespace illum

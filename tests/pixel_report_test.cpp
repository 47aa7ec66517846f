// `--debug-pixel` tells the truth: for every shading frequency, with blending and labels on, the
// report's steps reproduce the fragment, and its "in the file" bytes are the PNG's.
#include "cli_support.h"

#include <illum/image.h>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace illum

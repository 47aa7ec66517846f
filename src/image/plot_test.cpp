#include <illum/plot.h>

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

TEST(Plot, TicksAreRoundNumbersCoveringTheRange) {
  EXPECT_EQ(niceTicks(0, 90, 6), (std::vector<Real>{0, 20, 40, 60, 80}));
  EXPECT_EQ(niceTicks(0, 1, 5), (std::vector<Real>{0, Real(0.2), Real(0.4), Real(0.6), Real(0.8), 1}));
  const std::vector<Real> small = niceTicks(Real(0.013), Real(0.047), 4);
  ASSERT_FALSE(small.empty());
  EXPECT_NEAR(double(small.front()), 0.02, 1e-6);
  EXPECT_NEAR(double(small[1] - small[0]), 0.01, 1e-6);
}

bool near(const Image& image, Vec2 pixel, const Vec3& color) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const std::uint8_t* p = image.pixel(int(pixel.x) + dx, int(pixel.y) + dy);
      bool same = true;
      for (int k = 0; k < 3; ++k) same = same && std::abs(int(p[k]) - int(std::lround(double(color[k] * 255)))) <= 8;
      if (same) return true;
    }
  return false;
}

TEST(Plot, ACurvePassesThroughItsPoints) {
  Image image = plotCanvas(500, 400);
  const Vec3 red(1, 0, 0);
  PlotCurve cosine{"cos", red, {}};
  for (int d = 0; d <= 90; d += 5) cosine.points.push_back({Real(d), std::cos(glm::radians(Real(d)))});
  const PlotFrame f = drawLinePlot(image, 0, 0, 500, 400, "title", "angle", "value", {cosine});
  EXPECT_TRUE(near(image, f.toPixel({60, Real(0.5)}), red));
  EXPECT_TRUE(near(image, f.toPixel({0, 1}), red));
  EXPECT_FALSE(near(image, f.toPixel({60, Real(0.8)}), red));  // not where the curve is not
  EXPECT_NEAR(double(f.min.y), 0, 1e-6);  // y starts at 0 (cos 90° is -4e-8 in float)
}

TEST(Plot, APolarCurveLiesAtItsAngleAndRadius) {
  Image image = plotCanvas(560, 420);
  const Vec3 green(0, 1, 0);
  PlotCurve halfCircle{"r", green, {}};
  for (int d = -90; d <= 90; ++d) halfCircle.points.push_back({Real(d), Real(0.5)});
  const PlotFrame f = drawPolarPlot(image, 0, 0, 560, 420, "lobes", {halfCircle}, {});
  const auto at = [&](Real degrees, Real r) {
    return f.toPixel({std::sin(glm::radians(degrees)) * r, std::cos(glm::radians(degrees)) * r});
  };
  EXPECT_TRUE(near(image, at(0, Real(0.5)), green));
  EXPECT_TRUE(near(image, at(-45, Real(0.5)), green));
  EXPECT_FALSE(near(image, at(0, Real(0.8)), green));
}

}  // namespace
}  // namespace illum

// Multisampling: edges closer to a 64-times supersampled reference as samples grow, a pixel a
// triangle covers whole exactly as one sample draws it (every shading frequency, blending too),
// no halo over a transparent background, and the same bytes on any thread count.
#include "raster/tile/multisample.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <hwy/targets.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace illum {
namespace {

// One triangle of three corners (z = 0), lit per pixel by a close positional light so that its
// colour varies across it, seen by an orthographic camera over [-1, 1]².
Scene triangleScene(int size, Shading shading) {
  Scene s;
  s.width = s.height = size;
  s.shading = shading;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = 2;
  s.lights[0].position = {0.3f, 0.2f, 0.8f, 1};
  s.lights[0].attenuation = {0.5f, 0.5f, 0};
  auto mesh = std::make_shared<Mesh>();
  mesh->positions = {{-0.83f, -0.71f, 0}, {0.77f, -0.33f, 0}, {-0.12f, 0.81f, 0}};
  mesh->normals = {glm::normalize(Vec3(-0.3f, -0.2f, 1)), glm::normalize(Vec3(0.3f, -0.1f, 1)), Vec3(0, 0.3f, 1)};
  mesh->indices = {0, 1, 2};
  Object o;
  o.mesh = mesh;
  o.material.diffuse = {0.9f, 0.6f, 0.3f, 1};
  o.material.specular = {0.5f, 0.5f, 0.5f, 1};
  o.material.shininess = 12;
  s.objects.push_back(o);
  return s;
}

// Distance in pixels from a pixel's centre to the nearest edge of the triangle (negative outside).
double insideBy(const Scene& s, int x, int y) {
  const auto& p = s.objects[0].mesh->positions;
  const double px = (x + 0.5) / s.width * 2 - 1, py = 1 - (y + 0.5) / s.height * 2;  // row 0 at the top
  double nearest = 1e9;
  for (int i = 0; i < 3; ++i) {
    const Vec3 a = p[std::size_t(i)], b = p[std::size_t((i + 1) % 3)];
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double d = (ex * (py - a.y) - ey * (px - a.x)) / std::hypot(ex, ey);  // > 0 left of a→b (inside)
    nearest = std::min(nearest, d * s.width / 2);
  }
  return nearest;
}

TEST(Multisample, AFullyCoveredPixelIsTheOneSampleColour) {
  for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong})
    for (bool blend : {false, true}) {
      Scene s = triangleScene(64, shading);
      s.blend = blend;
      if (blend) s.objects[0].material.diffuse.a = 0.7f;
      const Image one = renderScene(s);
      for (int n : {4, 8, 16}) {
        s.multisample = n;
        const Image many = renderScene(s);
        int covered = 0, edge = 0;
        for (int y = 0; y < s.height; ++y)
          for (int x = 0; x < s.width; ++x) {
            const double d = insideBy(s, x, y);
            if (d > 0.75) {
              ++covered;
              for (int c = 0; c < 4; ++c)
                ASSERT_EQ(many.pixel(x, y)[c], one.pixel(x, y)[c]) << toString(shading) << " " << n << " at " << x << "," << y;
            } else if (d > -0.75) {
              edge += many.pixel(x, y)[0] != one.pixel(x, y)[0];
            }
          }
        EXPECT_GT(covered, 800);
        EXPECT_GT(edge, 20);  // and the edges did change
      }
    }
}

// The box-filtered average of a picture drawn `factor` times larger, as the reference.
Image downsample(const Image& big, int factor) {
  Image out(big.width / factor, big.height / factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int j = 0; j < factor; ++j)
          for (int i = 0; i < factor; ++i) sum += big.pixel(x * factor + i, y * factor + j)[c];
        out.pixel(x, y)[c] = std::uint8_t((sum + factor * factor / 2) / (factor * factor));
      }
  return out;
}

double meanError(const Image& a, const Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) sum += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
  return sum / double(a.rgba.size());
}

TEST(Multisample, EdgesApproachTheSupersampledReference) {
  Scene s = triangleScene(48, Shading::Flat);  // flat: the colour inside is one, only edges differ
  Scene big = s;
  big.width = big.height = 48 * 8;
  const Image reference = downsample(renderScene(big), 8);
  double previous = 1e9;
  for (int n : {1, 4, 8, 16}) {
    s.multisample = n;
    const double e = meanError(renderScene(s), reference);
    if (n == 4) {
      EXPECT_LT(e, 0.5 * previous);
    } else if (n > 4) {
      EXPECT_LT(e, previous * 1.02);
    }
    previous = e;
  }
  EXPECT_LT(previous, 0.3);  // 16 samples: within a third of a level on average
}

TEST(Multisample, NoHaloOverATransparentBackground) {
  for (const Color4& background : {Color4(0, 0, 0, 0), Color4(1, 0, 0, 0)}) {
    Scene s = triangleScene(48, Shading::Flat);
    s.lights.clear();
    s.lightModel.ambient = Color3(0);
    s.objects[0].material.emission = {1, 1, 1, 1};  // white everywhere on the triangle
    s.background = background;
    s.multisample = 8;
    const Image image = renderScene(s);
    int partial = 0;
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x) {
        const std::uint8_t* p = image.pixel(x, y);
        if (p[3] == 0 || p[3] == 255) continue;
        ++partial;
        // Straight alpha: the colour is the triangle's, the coverage is the alpha.
        EXPECT_EQ(p[0], 255);
        EXPECT_EQ(p[1], 255);
        EXPECT_EQ(p[2], 255);
      }
    EXPECT_GT(partial, 40);
  }
}

TEST(Multisample, SameBytesOnEveryThreadCount) {
  Scene s = defaultScene();
  s.width = 320, s.height = 180;
  s.multisample = 4;
  const Image all = renderScene(s);
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(renderScene(s).rgba, all.rgba);
}

// resolvePixel's definition as it reads, divisions and all: colour Σ(c·a) / Σa (Σc / n where no
// sample has alpha), alpha Σa / n, each rounded to nearest (halves up).
std::uint32_t resolvedByTheDefinition(const std::uint32_t* samples, int n) {
  std::uint64_t weighted[3] = {}, plain[3] = {}, alpha = 0;
  for (int s = 0; s < n; ++s) {
    const std::uint64_t a = samples[s] >> 24;
    for (int c = 0; c < 3; ++c) weighted[c] += (samples[s] >> (8 * c) & 0xFF) * a, plain[c] += samples[s] >> (8 * c) & 0xFF;
    alpha += a;
  }
  const auto rounded = [](std::uint64_t sum, std::uint64_t over) { return std::uint32_t((2 * sum + over) / (2 * over)); };
  std::uint32_t out = rounded(alpha, std::uint64_t(n)) << 24;
  for (int c = 0; c < 3; ++c) out |= (alpha > 0 ? rounded(weighted[c], alpha) : rounded(plain[c], std::uint64_t(n))) << (8 * c);
  return out;
}

TEST(Multisample, ResolvingRowsIsResolvingEachPixelOnEveryTarget) {
  // Rows of 37 pixels (a vector's tail too) of 2, 4 and 8 samples: pixels whose samples agree,
  // opaque ones that differ (an edge between two surfaces), translucent ones, in random order;
  // then mostly the first two (whole vectors of pixels resolved at once), a translucent one now
  // and then.
  std::uint32_t state = 2024;
  const auto next = [&] { return state = state * 1664525u + 1013904223u; };
  constexpr int kRows = 3, kCount = 37, kRowPixels = 64;
  constexpr std::uint32_t kBackground = 0xFF302010u;
  for (const bool mostlyOpaque : {false, true})
  for (const int samples : {2, 4, 8}) {
    std::vector<std::uint32_t> src(std::size_t(kRows * kRowPixels * samples));
    for (std::size_t p = 0; p < src.size() / std::size_t(samples); ++p) {
      const std::uint32_t kind = !mostlyOpaque ? next() >> 30 : next() % 60 == 0 ? 3 : next() >> 31;
      const std::uint32_t a = next() | 0xFF000000u, b = next() | 0xFF000000u;
      for (int s = 0; s < samples; ++s) {
        std::uint32_t& w = src[p * std::size_t(samples) + std::size_t(s)];
        if (kind == 0) w = p % 5 == 0 ? kBackground : p % 3 == 0 ? a & 0x80FFFFFFu : a;  // agreeing
        else if (kind == 1) w = (next() & 1) ? a : b;             // opaque, mixed
        else if (kind == 2) w = next();                           // any alpha
        else w = s == 0 ? (a & 0x7FFFFFFFu) : a;                  // one translucent sample
      }
    }
    std::vector<std::uint8_t> expected(std::size_t(kRows * kCount * 4));
    std::size_t expectedUnlike = 0;
    for (int r = 0; r < kRows; ++r)
      for (int x = 0; x < kCount; ++x) {
        const std::uint32_t* pixel = &src[std::size_t((r * kRowPixels + x) * samples)];
        const std::uint32_t w = resolvePixel(pixel, samples);
        EXPECT_EQ(w, resolvedByTheDefinition(pixel, samples));
        std::memcpy(&expected[std::size_t((r * kCount + x) * 4)], &w, 4);
        expectedUnlike += w != kBackground;
      }
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
      hwy::SetSupportedTargetsForTest(target);
      std::vector<std::uint8_t> actual(expected.size());
      const std::size_t unlike =
          resolvePixels(src.data(), samples, kRowPixels, actual.data(), kCount * 4, kCount, kRows, kBackground);
      EXPECT_EQ(actual, expected) << hwy::TargetName(target) << ", " << samples << " samples" << (mostlyOpaque ? ", mostly opaque" : "");
      EXPECT_EQ(unlike, expectedUnlike) << hwy::TargetName(target) << ", " << samples << " samples" << (mostlyOpaque ? ", mostly opaque" : "");
    }
    hwy::SetSupportedTargetsForTest(0);
  }
}

TEST(Multisample, PatternsAreTheStandardOnes) {
  EXPECT_EQ(multisamplePattern(1).size(), 1u);
  for (int n : {4, 8, 16}) {
    const auto p = multisamplePattern(n);
    ASSERT_EQ(p.size(), std::size_t(n));
    for (const SubpixelOffset& o : p) {
      EXPECT_LE(std::abs(o.x), 128);  // inside the pixel (16 samples reach its edge)
      EXPECT_LE(std::abs(o.y), 128);
    }
  }
  EXPECT_EQ(multisamplePattern(4)[0].x, -32);  // Direct3D's (-2, -6)/16, y flipped
  EXPECT_EQ(multisamplePattern(4)[0].y, 96);
}

}  // namespace
}  // namespace illum

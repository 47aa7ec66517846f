#include "image/denoise.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>
#include <oneapi/tbb/global_control.h>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace illum {
namespace {

// A picture of w×h pixels for the denoiser, its guides filled by the callers.
struct Noisy {
  int w, h;
  std::vector<float> color, albedo, normal, variance;
  Noisy(int width, int height)
      : w(width), h(height), color(std::size_t(w * h) * 4, 1.0f), albedo(std::size_t(w * h) * 3, 1.0f),
        normal(std::size_t(w * h) * 3, 0.0f), variance(std::size_t(w * h), 0.0f) {
    for (std::size_t i = 0; i < std::size_t(w * h); ++i) normal[3 * i + 2] = 1;
  }
  std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(w) + std::size_t(x); }
  std::vector<float> filtered() const {
    std::vector<float> out(color.size());
    denoise({w, h, color, albedo, normal, variance}, out);
    return out;
  }
};

// Deterministic noise in [−1, 1].
float noise(std::uint32_t i) {
  i = (i ^ 61u) ^ (i >> 16);
  i *= 9u;
  i ^= i >> 4;
  i *= 0x27d4eb2du;
  i ^= i >> 15;
  return float(i) / float(0xFFFFFFFFu) * 2 - 1;
}

TEST(Denoise, KeepsAConstantPictureAndItsAlpha) {
  Noisy p(37, 23);
  for (std::size_t i = 0; i < p.color.size(); i += 4) p.color[i] = 0.25f, p.color[i + 1] = 0.5f, p.color[i + 2] = 2.0f, p.color[i + 3] = 0.5f;
  const std::vector<float> out = p.filtered();
  for (std::size_t i = 0; i < out.size(); i += 4) {
    EXPECT_NEAR(out[i], 0.25f, 1e-6f);
    EXPECT_NEAR(out[i + 1], 0.5f, 1e-6f);
    EXPECT_NEAR(out[i + 2], 2.0f, 2e-6f);
    EXPECT_EQ(out[i + 3], 0.5f);
  }
}

TEST(Denoise, RemovesNoiseOnAFlatSurface) {
  Noisy p(64, 48);
  const float sigma = 0.1f;
  double before = 0, after = 0;
  for (std::size_t i = 0; i < p.variance.size(); ++i) {
    for (int c = 0; c < 3; ++c) p.color[4 * i + std::size_t(c)] = 0.5f + sigma * noise(std::uint32_t(3 * i) + std::uint32_t(c));
    p.variance[i] = sigma * sigma / 3;  // of a uniform variable in [−σ, σ]
    for (int c = 0; c < 3; ++c) before += std::pow(p.color[4 * i + std::size_t(c)] - 0.5, 2);
  }
  const std::vector<float> out = p.filtered();
  for (std::size_t i = 0; i < p.variance.size(); ++i)
    for (int c = 0; c < 3; ++c) after += std::pow(out[4 * i + std::size_t(c)] - 0.5, 2);
  EXPECT_LT(after, before / 50) << "mean squared error " << before / double(3 * p.variance.size()) << " → "
                                << after / double(3 * p.variance.size());
}

TEST(Denoise, KeepsApartSurfacesOfOneNormalAndAlbedoAtDifferentDepths) {
  // Fins and the gaps between them: the same normal and albedo, the left half 2 away from the eye
  // and bright (0.8), the right half 3 away and dark (0.2), both noisy (±0.3, more than the colour
  // term alone can tell from their difference). With the depth as a guide the column beside the
  // edge keeps its side's mean; without it the dark side is blurred into it.
  Noisy p(64, 48);
  std::vector<float> depth(p.variance.size());
  for (int y = 0; y < p.h; ++y)
    for (int x = 0; x < p.w; ++x) {
      const std::size_t i = p.index(x, y);
      const bool left = x < p.w / 2;
      for (int c = 0; c < 3; ++c)
        p.color[4 * i + std::size_t(c)] = (left ? 0.8f : 0.2f) + 0.3f * noise(std::uint32_t(3 * i) + std::uint32_t(c));
      p.variance[i] = 0.09f / 3;
      depth[i] = left ? 2.0f : 3.0f;
    }
  std::vector<float> guided(p.color.size()), unguided(p.color.size());
  denoise({p.w, p.h, p.color, p.albedo, p.normal, p.variance, depth}, guided);
  denoise({p.w, p.h, p.color, p.albedo, p.normal, p.variance}, unguided);
  const auto columnMean = [&](const std::vector<float>& out, int x) {
    double sum = 0;
    for (int y = 0; y < p.h; ++y) sum += out[4 * p.index(x, y)];
    return sum / p.h;
  };
  for (const auto& [x, mean] : {std::pair(p.w / 2 - 1, 0.8), std::pair(p.w / 2, 0.2)}) {
    const double kept = std::abs(columnMean(guided, x) - mean), blurred = std::abs(columnMean(unguided, x) - mean);
    EXPECT_LT(kept, 0.025) << "column " << x;  // what is left of the noise
    EXPECT_GT(blurred, 2 * kept) << "column " << x;
  }
}

TEST(Denoise, DimsABrightPixelItsNoiseExplainsAndKeepsAConvergedOne) {
  // A flat grey surface with two pixels four times as bright: one whose samples disagree (one rare
  // bright path: a standard error of 1.5 on its mean) on a surface facing elsewhere (as at a
  // silhouette, where no neighbour's guides match and the passes leave it alone), and one whose
  // samples agree (a small highlight, converged). The first is an outlier of its noise and comes
  // out as its brightest neighbour; the second stays.
  Noisy p(48, 32);
  for (std::size_t i = 0; i < p.variance.size(); ++i) {
    for (int c = 0; c < 3; ++c) p.color[4 * i + std::size_t(c)] = 0.5f;
    p.variance[i] = 1e-6f;
  }
  const std::size_t firefly = p.index(10, 10), highlight = p.index(36, 20);
  for (const std::size_t i : {firefly, highlight})
    for (int c = 0; c < 3; ++c) p.color[4 * i + std::size_t(c)] = 2.0f;
  p.variance[firefly] = 1.5f * 1.5f;
  p.normal[3 * firefly] = 1, p.normal[3 * firefly + 2] = 0;
  const std::vector<float> out = p.filtered();
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(out[4 * firefly + std::size_t(c)], 0.5f, 0.01f);
    EXPECT_NEAR(out[4 * highlight + std::size_t(c)], 2.0f, 0.01f);
  }
}

TEST(Denoise, KeepsALoneObjectPixelThatItsNoiseWouldExplain) {
  // A background (nothing hit: normal and albedo 0) of radiance 0.2 and, at one pixel, a surface a
  // pixel wide of albedo 0.5, as bright as 1 (2 divided by its albedo, as the step compares it) and
  // as noisy as a firefly (standard error 1, 0.5 once the variance is blurred 3×3: its excess of
  // 1.8 is within 4 of them). It is the
  // only pixel of its kind around, so the outlier step leaves it be (compared with its background
  // neighbours it came out as 0.2: the object vanished).
  Noisy p(32, 32);
  for (std::size_t i = 0; i < p.variance.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      p.color[4 * i + std::size_t(c)] = 0.2f;
      p.normal[3 * i + std::size_t(c)] = 0.0f;
      p.albedo[3 * i + std::size_t(c)] = 0.0f;
    }
    p.variance[i] = 1e-6f;
  }
  const std::size_t object = p.index(16, 16);
  for (int c = 0; c < 3; ++c) {
    p.color[4 * object + std::size_t(c)] = 1.0f;
    p.albedo[3 * object + std::size_t(c)] = 0.5f;
  }
  p.normal[3 * object + 2] = 1;
  p.variance[object] = 1.0f;
  const std::vector<float> out = p.filtered();
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(out[4 * object + std::size_t(c)], 1.0f, 0.01f);
    EXPECT_NEAR(out[4 * p.index(3, 3) + std::size_t(c)], 0.2f, 0.001f);
  }
}

TEST(Denoise, KeepsAnEdgeWhereTheNormalTurns) {
  // Two walls meeting at x = 32: different normals, different brightness, both noisy.
  Noisy p(64, 32);
  for (int y = 0; y < p.h; ++y)
    for (int x = 0; x < p.w; ++x) {
      const std::size_t i = p.index(x, y);
      const bool right = x >= 32;
      const float value = right ? 0.8f : 0.2f;
      for (int c = 0; c < 3; ++c) p.color[4 * i + std::size_t(c)] = value + 0.05f * noise(std::uint32_t(3 * i) + std::uint32_t(c));
      p.variance[i] = 0.05f * 0.05f / 3;
      p.normal[3 * i] = right ? 1.0f : 0.0f, p.normal[3 * i + 2] = right ? 0.0f : 1.0f;
    }
  const std::vector<float> out = p.filtered();
  for (int y = 0; y < p.h; ++y) {
    EXPECT_NEAR(out[4 * p.index(31, y)], 0.2f, 0.03f) << "row " << y;
    EXPECT_NEAR(out[4 * p.index(32, y)], 0.8f, 0.03f) << "row " << y;
  }
}

TEST(Denoise, FitsPixelsThatHoldTwoSurfaces) {
  // The same two walls, the edge slanted across column 32: there each pixel holds a share α(y) of
  // the left wall and 1 − α of the right, its radiance and normal the same mix of theirs (the
  // normal shorter than 1). Its guides match no neighbour, so only the first-order fit over its
  // neighbours removes its noise: a mix that the guides predict exactly.
  Noisy p(64, 32);
  const float sigma = 0.05f;
  double before = 0, after = 0;
  std::vector<float> exact(p.variance.size());
  for (int y = 0; y < p.h; ++y)
    for (int x = 0; x < p.w; ++x) {
      const std::size_t i = p.index(x, y);
      const float left = x < 32 ? 1.0f : x > 32 ? 0.0f : (float(y) + 0.5f) / float(p.h);
      exact[i] = left * 0.2f + (1 - left) * 0.8f;
      for (int c = 0; c < 3; ++c) p.color[4 * i + std::size_t(c)] = exact[i] + sigma * noise(std::uint32_t(3 * i) + std::uint32_t(c));
      p.variance[i] = sigma * sigma / 3;
      p.normal[3 * i] = 1 - left, p.normal[3 * i + 2] = left;
    }
  const std::vector<float> out = p.filtered();
  for (int y = 1; y + 1 < p.h; ++y) {
    const std::size_t i = p.index(32, y);
    for (int c = 0; c < 3; ++c) {
      before += std::pow(p.color[4 * i + std::size_t(c)] - exact[i], 2);
      after += std::pow(out[4 * i + std::size_t(c)] - exact[i], 2);
    }
  }
  EXPECT_LT(after, before / 5) << "mean squared error on the mixed column " << before / double(3 * (p.h - 2)) << " → "
                               << after / double(3 * (p.h - 2));
  // The pure walls beside it keep their values.
  for (int y = 0; y < p.h; ++y) {
    EXPECT_NEAR(out[4 * p.index(31, y)], 0.2f, 0.03f) << "row " << y;
    EXPECT_NEAR(out[4 * p.index(33, y)], 0.8f, 0.03f) << "row " << y;
  }
}

TEST(Denoise, KeepsTextureDetailThroughTheAlbedo) {
  // A checkerboard texture under even light, without noise: nothing to remove, the pattern stays.
  Noisy p(32, 32);
  for (int y = 0; y < p.h; ++y)
    for (int x = 0; x < p.w; ++x) {
      const std::size_t i = p.index(x, y);
      const float a = (x + y) % 2 ? 0.8f : 0.2f;
      for (int c = 0; c < 3; ++c) p.albedo[3 * i + std::size_t(c)] = a, p.color[4 * i + std::size_t(c)] = 0.7f * a;
    }
  const std::vector<float> out = p.filtered();
  for (std::size_t i = 0; i < p.variance.size(); ++i) EXPECT_NEAR(out[4 * i], p.color[4 * i], 1e-5f) << i;
}

TEST(Denoise, MultipliesTheLightBackByTheTruerAlbedoItIsGiven) {
  // Even light E on a texture whose pixels' few samples saw albedos a (a texture's edges inside
  // the pixels), the guides' truer albedos b taken over more samples: the colour E·a is divided
  // by a, which its samples saw, and multiplied back by b, so E·b comes out; a near-black b or a
  // leaves the colour as it came.
  Noisy p(24, 24);
  std::vector<float> seen(p.albedo.size());
  for (std::size_t i = 0; i < p.variance.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const float a = 0.5f + 0.3f * noise(std::uint32_t(3 * i + c)), b = 0.5f + 0.3f * noise(std::uint32_t(3 * i + c + 7777));
      seen[3 * i + c] = i == 100 ? 0.01f : a;
      p.albedo[3 * i + c] = i == 200 ? 0.01f : b;
      p.color[4 * i + c] = 0.6f * seen[3 * i + c];
    }
  std::vector<float> out(p.color.size());
  denoise({p.w, p.h, p.color, p.albedo, p.normal, p.variance, {}, seen}, out);
  for (std::size_t i = 0; i < p.variance.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const float expected = i == 100 || i == 200 ? p.color[4 * i + c] : 0.6f * p.albedo[3 * i + c];
      EXPECT_NEAR(out[4 * i + c], expected, 1e-5f) << "pixel " << i << " channel " << c;
    }
}

TEST(Denoise, AReflectionFilteredByItsOwnGuidesKeepsItsEdge) {
  // A polished floor (one albedo, one normal: its guides say nothing of what it reflects) whose
  // lower rows reflect an object on the left and the sky on the right, both noisy. Summed and
  // filtered by the floor's guides, the reflection's edge blurs; as a layer guided by what the
  // mirror saw (the object's albedo and normal, the sky's none and its direction) it stays, and
  // rows without a reflection come out as the floor's filter alone gives them.
  const int w = 64, h = 48, top = 16, edge = 32;
  const float sigma = 0.1f, floor = 0.5f, object = 0.15f;
  Noisy surfaces(w, h), reflections(w, h), summed(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = surfaces.index(x, y);
      surfaces.variance[i] = reflections.variance[i] = sigma * sigma / 3;
      summed.variance[i] = 2 * sigma * sigma / 3;
      for (int c = 0; c < 3; ++c) {
        const std::size_t at = 4 * i + std::size_t(c);
        surfaces.color[at] = floor + sigma * noise(std::uint32_t(6 * i) + std::uint32_t(c));
        reflections.color[at] = 0;
        reflections.albedo[3 * i + std::size_t(c)] = 0;
        reflections.normal[3 * i + std::size_t(c)] = 0;
      }
      if (y < top) continue;
      for (int c = 0; c < 3; ++c) {
        const float truth = x < edge ? object : 0.0f;
        reflections.color[4 * i + std::size_t(c)] = truth + sigma * noise(std::uint32_t(6 * i + 3) + std::uint32_t(c));
        reflections.albedo[3 * i + std::size_t(c)] = x < edge ? 1.0f : 0.0f;
      }
      reflections.normal[3 * i + (x < edge ? 0 : 1)] = 1;  // the object's normal; the sky's direction
    }
  for (std::size_t i = 0; i < summed.color.size(); ++i)
    summed.color[i] = i % 4 == 3 ? 1.0f : surfaces.color[i] + reflections.color[i];
  std::vector<float> layered(surfaces.color.size());
  denoiseLayers({w, h, surfaces.color, surfaces.albedo, surfaces.normal, surfaces.variance},
                {w, h, reflections.color, reflections.albedo, reflections.normal, reflections.variance}, layered);
  const std::vector<float> blurred = summed.filtered(), floorAlone = surfaces.filtered();
  // The mean over the reflecting rows of a column's red, against the truth.
  const auto columnError = [&](const std::vector<float>& out, int x) {
    double sum = 0;
    for (int y = top; y < h; ++y) sum += out[4 * surfaces.index(x, y)];
    return std::abs(sum / (h - top) - (floor + (x < edge ? object : 0.0f)));
  };
  for (const int x : {edge - 1, edge}) {
    EXPECT_LT(columnError(layered, x), 0.01) << "column " << x;
    EXPECT_GT(columnError(blurred, x), 0.015) << "column " << x << ": the test's reflection should blur as one layer";
  }
  for (int y = 0; y < top; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) {
        const std::size_t at = 4 * surfaces.index(x, y) + std::size_t(c);
        ASSERT_EQ(layered[at], floorAlone[at]) << x << "," << y;
      }
}

TEST(Denoise, SameBitsOnEveryThreadCountAndSimdTarget) {
  Noisy p(70, 45);
  for (std::size_t i = 0; i < p.variance.size(); ++i) {
    for (int c = 0; c < 3; ++c) p.color[4 * i + std::size_t(c)] = 1 + noise(std::uint32_t(7 * i) + std::uint32_t(c));
    p.variance[i] = 0.3f;
    p.albedo[3 * i] = 0.5f + 0.4f * noise(std::uint32_t(i));
    // Some pixels mixes of two surfaces (a normal shorter than 1), for the first-order fit.
    const float length = i % 7 ? 1.0f : 0.9f + 0.1f * noise(std::uint32_t(11 * i));
    p.normal[3 * i] = 0.6f * length, p.normal[3 * i + 2] = 0.8f * length * (i % 5 ? 1.0f : -1.0f);
    if (i % 11 == 0) p.normal[3 * i] = p.normal[3 * i + 2] = 0;  // misses, a kind of their own to the outliers
  }
  std::vector<float> first;
  {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    first = p.filtered();
  }
  EXPECT_EQ(p.filtered(), first) << "on every thread";
  int targets = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    EXPECT_EQ(p.filtered(), first) << hwy::TargetName(target);
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
}

}  // namespace
}  // namespace illum

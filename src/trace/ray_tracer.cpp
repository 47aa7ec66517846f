#include "trace/ray_tracer.h"

#include "image/denoise.h"
#include "math/unorm8.h"
#include "trace/camera_rays.h"
#include "trace/path_tracer.h"
#include "trace/ray_scene.h"
#include "trace/sampling.h"
#include "trace/whitted.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>

namespace illum {
namespace {

constexpr int kTile = 16;   // pixels on a side of a parallel task
constexpr int kBlock = 4;   // pixels on a side of a primary ray packet

using Clock = std::chrono::steady_clock;

// A sample position's offset in its pixel.
Vec2 jitter(int x, int y, int sample) {
  return {Real(sampleSeed(x, y, sample, 1) >> 40) / Real(1 << 24), Real(sampleSeed(x, y, sample, 2) >> 40) / Real(1 << 24)};
}

struct TileCounts {
  RayCounts rays;
  double primarySeconds = 0;
};

// The path tracer's picture before the denoiser, and its guides: per pixel the mean radiance
// (RGBA), albedo and normal (RGB), and the variance of the mean's luminance.
struct DenoiseBuffers {
  std::vector<float> color, albedo, normal, variance;
  explicit DenoiseBuffers(std::size_t pixels) : color(4 * pixels), albedo(3 * pixels), normal(3 * pixels), variance(pixels) {}
};

// What one pixel's samples add up to, for the denoiser.
struct FeatureSums {
  Color3 albedo{0};
  Vec3 normal{0};
  Real luminance = 0, luminanceSquared = 0;  // of the radiance divided by the albedo (denoise.h)
};

class TracedFrame {
 public:
  // With `denoised`, the path tracer's pixels are kept there for the denoiser instead of written.
  TracedFrame(const Scene& scene, const RayScene& rays, Image& image, PixelProbe* probe, FloatImage* linear,
              DenoiseBuffers* denoised)
      : scene_(scene), rays_(rays), image_(image), linear_(linear), probe_(probe), denoised_(denoised),
        camera_(scene.camera, scene.width, scene.height), tracer_(scene, rays) {
    if (scene.renderer == RendererKind::Path) pathTracer_.emplace(scene, rays);
  }

  void tile(int x0, int y0, TileCounts& counts) const {
    const int x1 = std::min(x0 + kTile, scene_.width), y1 = std::min(y0 + kTile, scene_.height);
    const int samples = samplesPerPixel(scene_);
    std::array<Color4, kTile * kTile> sum;
    sum.fill(Color4(0));
    std::array<FeatureSums, kTile * kTile> features{};
    for (int s = 0; s < samples; ++s)
      for (int by = y0; by < y1; by += kBlock)
        for (int bx = x0; bx < x1; bx += kBlock) block(bx, by, x1, y1, s, x0, y0, sum, features, counts);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const std::size_t t = std::size_t((y - y0) * kTile + (x - x0));
        const Color4 c = sum[t] / Real(samples);
        if (!denoised_) {
          writePixel(x, y, c);
          continue;
        }
        const std::size_t i = std::size_t(y) * std::size_t(scene_.width) + std::size_t(x);
        const FeatureSums& f = features[t];
        for (int k = 0; k < 4; ++k) denoised_->color[4 * i + std::size_t(k)] = float(c[k]);
        for (int k = 0; k < 3; ++k) {
          denoised_->albedo[3 * i + std::size_t(k)] = float(f.albedo[k] / Real(samples));
          denoised_->normal[3 * i + std::size_t(k)] = float(f.normal[k] / Real(samples));
        }
        const Real mean = f.luminance / Real(samples);
        denoised_->variance[i] = float(std::max(Real(0), f.luminanceSquared / Real(samples) - mean * mean) / Real(samples));
      }
  }

  // A pixel's mean value as the picture shows it (the scene's display), and as it is (linear).
  void writePixel(int x, int y, const Color4& c) const {
    std::uint8_t* p = image_.pixel(x, y);
    for (int k = 0; k < 3; ++k) p[k] = toUnorm8(displayValue(c[k], scene_.display));
    p[3] = toUnorm8(c[3]);
    if (linear_)
      for (int k = 0; k < 4; ++k) linear_->pixel(x, y)[k] = float(c[k]);
  }

 private:
  // One 4×4 packet of primary rays (sample `s` of each pixel), then each hit shaded on its own.
  void block(int bx, int by, int x1, int y1, int s, int x0, int y0, std::array<Color4, kTile * kTile>& sum,
             std::array<FeatureSums, kTile * kTile>& features, TileCounts& counts) const {
    std::array<Ray, 16> rays;
    std::array<bool, 16> active;
    std::array<RayHit, 16> hits;
    for (int k = 0; k < 16; ++k) {
      const int x = bx + k % kBlock, y = by + k / kBlock;
      active[std::size_t(k)] = x < x1 && y < y1;
      const Vec2 at = pixelPoint(x, y, s);
      rays[std::size_t(k)] = camera_.through(at.x, at.y);
    }
    const auto start = Clock::now();
    rays_.intersect16(rays.data(), active.data(), hits.data());
    counts.primarySeconds += std::chrono::duration<double>(Clock::now() - start).count();
    for (int k = 0; k < 16; ++k) {
      if (!active[std::size_t(k)]) continue;
      const int x = bx + k % kBlock, y = by + k / kBlock;
      const RayHit& hit = hits[std::size_t(k)];
      const Ray& ray = rays[std::size_t(k)];
      RayCone cone;
      cone.spread = camera_.pixelWidthAt(1) - camera_.pixelWidthAt(0);
      cone.width = camera_.pixelWidthAt(0);
      if (hit.t >= 0 && drawnTexture(*rays_.mesh(hit.object).object)) {
        // The rays through the next pixel right and the next one up (GL's window y is up).
        const Vec2 at = pixelPoint(x, y, s);
        cone.differentials = true;
        cone.right = camera_.through(at.x + 1, at.y);
        cone.up = camera_.through(at.x, at.y - 1);
      }
      const RayHit* first = hit.t >= 0 ? &hit : nullptr;
      Color4& pixel = sum[std::size_t((y - y0) * kTile + (x - x0))];
      if (pathTracer_) {
        // Radiance is averaged as it is: the mean converges to the rendering equation's solution.
        // (A sample that overflowed, say under an emitter of absurd strength, counts as nothing.)
        PathFeatures guides;
        const Color4 radiance =
            pathTracer_->primary(ray, first, cone, counts.rays, sampleSeed(x, y, s, 3), denoised_ ? &guides : nullptr);
        if (!std::isfinite(radiance.r + radiance.g + radiance.b + radiance.a)) continue;
        pixel += radiance;
        if (denoised_) {
          FeatureSums& f = features[std::size_t((y - y0) * kTile + (x - x0))];
          f.albedo += guides.albedo;
          f.normal += guides.normal;
          Color3 demodulated;
          for (int k = 0; k < 3; ++k) demodulated[k] = radiance[k] / Real(demodulationOf(float(guides.albedo[k])));
          const Real l = luminance(demodulated);
          f.luminance += l;
          f.luminanceSquared += l * l;
        }
        continue;
      }
      PixelProbe* probe = probe_ && s == 0 && x == probe_->x && y == probe_->y ? probe_ : nullptr;
      // Each sample as the display shows it: clamped, then averaged.
      pixel += glm::clamp(tracer_.primary(ray, first, cone, counts.rays, probe), Color4(0), Color4(1));
    }
  }

  // Where sample s of pixel (x, y) goes through the image: the centre, or jittered.
  Vec2 pixelPoint(int x, int y, int s) const {
    const Vec2 offset = samplesPerPixel(scene_) == 1 ? Vec2(Real(0.5)) : jitter(x, y, s);
    return {Real(x) + offset.x, Real(y) + offset.y};
  }

  const Scene& scene_;
  const RayScene& rays_;
  Image& image_;
  FloatImage* linear_;
  PixelProbe* probe_;
  DenoiseBuffers* denoised_;
  CameraRays camera_;
  WhittedTracer tracer_;
  std::optional<PathTracer> pathTracer_;
};

}  // namespace

void traceScene(const Scene& scene, Image& image, RenderStats& stats, PixelProbe* probe, FloatImage* linear,
                const std::function<void(double)>& progress, const std::atomic<bool>* cancel) {
  stats = RenderStats{};
  const auto start = Clock::now();
  const RayScene rays(scene);
  stats.bvhMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  stats.trianglesIn = rays.triangleCount();
  if (image.width != scene.width || image.height != scene.height) image = Image(scene.width, scene.height);
  if (probe) probe->hit = false;
  if (linear) *linear = FloatImage{scene.width, scene.height, std::vector<float>(std::size_t(scene.width) * std::size_t(scene.height) * 4), {}};
  const bool denoising = scene.renderer == RendererKind::Path && scene.rayTracing.denoise;
  std::optional<DenoiseBuffers> denoised;
  if (denoising) denoised.emplace(std::size_t(scene.width) * std::size_t(scene.height));
  const TracedFrame frame(scene, rays, image, probe, linear, denoised ? &*denoised : nullptr);
  const int tilesX = (scene.width + kTile - 1) / kTile, tilesY = (scene.height + kTile - 1) / kTile;
  tbb::combinable<TileCounts> counts;
  std::atomic<int> done{0};
  const int tiles = tilesX * tilesY;
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles), [&](const tbb::blocked_range<int>& r) {
    TileCounts& local = counts.local();
    for (int t = r.begin(); t < r.end(); ++t) {
      if (cancel && cancel->load(std::memory_order_relaxed)) return;
      frame.tile(t % tilesX * kTile, t / tilesX * kTile, local);
      if (progress) progress(double(++done) / tiles);
    }
  });
  if (denoised && !(cancel && cancel->load())) {
    std::vector<float> filtered(denoised->color.size());
    denoise({scene.width, scene.height, denoised->color, denoised->albedo, denoised->normal, denoised->variance},
            filtered);
    for (int y = 0; y < scene.height; ++y)
      for (int x = 0; x < scene.width; ++x) {
        const float* c = &filtered[4 * (std::size_t(y) * std::size_t(scene.width) + std::size_t(x))];
        frame.writePixel(x, y, Color4(c[0], c[1], c[2], c[3]));
      }
    if (linear) {
      linear->layers.push_back({"beauty", 4, std::move(denoised->color)});
      linear->layers.push_back({"albedo", 3, std::move(denoised->albedo)});
      linear->layers.push_back({"normal", 3, std::move(denoised->normal)});
    }
  }
  counts.combine_each([&](const TileCounts& c) {
    stats.primaryRays += c.rays.primary;
    stats.secondaryRays += c.rays.secondary;
    stats.shadowRays += c.rays.shadow;
    stats.primaryRaySeconds += c.primarySeconds;
  });
  // Pixels unlike the background, as the rasterizer counts them.
  Color4 background = glm::clamp(scene.background, Color4(0), Color4(1));
  std::uint8_t bg[4];
  for (int k = 0; k < 4; ++k) bg[k] = toUnorm8(k < 3 ? displayValue(background[k], scene.display) : background[k]);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4)
    if (std::memcmp(&image.rgba[i], bg, 4) != 0) ++stats.pixelsDrawn;
}

}  // namespace illum

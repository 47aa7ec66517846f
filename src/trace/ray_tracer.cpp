#include "trace/ray_tracer.h"

#include "image/denoise.h"

#include <illum/display.h>
#include "math/unorm8.h"
#include "trace/camera_rays.h"
#include "trace/path_tracer.h"
#include "trace/ray_scene.h"
#include "trace/sampling.h"
#include "trace/whitted.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <mutex>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <span>

namespace illum {
namespace {

// Whether a ray's hit reads a texture (the diffuse one, or glTF's maps, which a ray always lights
// per point): its primary rays then carry the next pixels' rays, to filter the texels as GL does.
bool readsTextures(const Object& object) { return drawnTexture(object) || mapsDrawn(object, true); }

constexpr int kTile = 16;   // pixels on a side of a parallel task
constexpr int kBlock = 4;   // pixels on a side of a primary ray packet

// Where a pixel's guides are refined (refineGuides): where its samples' albedos differ by more
// than this in a channel, or the mean of their unit normals is shorter than kNormalsAgree (they
// met faces turned apart: two at 90°, one sample of 16 on the second, give 0.94; the same face
// of a curved or normal-mapped surface comes near 1), or their direct light is not exact
// (DirectSums::exact: a highlight or a shadow's edge smaller than the pixel), or only some of
// them hit a surface; over this many samples (the picture's own among them), 4 times the
// picture's, from 32 to 256.
constexpr Real kAlbedoSpread = Real(1) / 64;
constexpr Real kNormalsAgree = Real(0.95);
int guideSamples(int samples) { return samples < 2 ? samples : std::clamp(4 * samples, 32, 256); }

using Clock = std::chrono::steady_clock;

struct TileCounts {
  RayCounts rays;
  double primarySeconds = 0;
};

// The path tracer's picture before the denoiser, and its guides: per pixel the mean of all its
// samples (RGBA, the "beauty" layer), the mean radiance of those that hit something (RGB, and the
// pixel's alpha) and their share of the samples, and over the same samples (the hits: the
// background is laid under the filtered radiance after) the mean albedo and normal (RGB) and the
// variance of the mean's luminance. (Over every sample, a silhouette's guides were shortened by
// the misses and matched no neighbour's: the filter left it noisy.)
// What part mirrors reflected (PathFeatures) is a second such layer, kept where the scene has
// any: its radiance (a share of the hits' mean, taken out of `surface.color`), the guides of what
// the mirrors saw and its variance; filtered apart and added back.
// What the first surface took from point, spot and directional lights (`direct`, mean over the
// hits) is exact but for the pixel's own sampling: it is taken out of the surfaces' layer, not
// filtered, and added back after.
struct DenoiseLayer {
  std::vector<float> color, albedo, normal, variance, depth, demodulation;
  explicit DenoiseLayer(std::size_t pixels)
      : color(4 * pixels), albedo(3 * pixels), normal(3 * pixels), variance(pixels), depth(pixels),
        demodulation(3 * pixels) {}
};
struct DenoiseBuffers {
  std::vector<float> beauty, coverage, direct;
  DenoiseLayer surface, mirrored;
  DenoiseBuffers(std::size_t pixels, bool partMirrors)
      : beauty(4 * pixels), coverage(pixels), direct(3 * pixels), surface(pixels), mirrored(partMirrors ? pixels : 0) {}
};

// One denoiser layer's sums over a pixel's hits: its radiance and the luminance (and its square)
// of the radiance divided by the albedo (denoise.h), each hit counting (0 where it has none of
// this layer); its guides over the hits that have it (`guided`).
struct LayerSums {
  Color3 radiance{0};
  Real luminance = 0, luminanceSquared = 0;
  Color3 albedo{0};
  Vec3 normal{0};
  Real depth = 0;
  int guided = 0;

  void add(const Color3& value, const Color3& guideAlbedo, const Vec3& guideNormal, Real guideDepth, bool guides) {
    radiance += value;
    Color3 demodulated;
    for (int k = 0; k < 3; ++k) demodulated[k] = value[k] / Real(demodulationOf(float(guideAlbedo[k])));
    const Real l = illum::luminance(demodulated);
    luminance += l;
    luminanceSquared += l * l;
    if (!guides) return;
    albedo += guideAlbedo;
    normal += guideNormal;
    depth += guideDepth;
    ++guided;
  }

  // The layer's means into pixel i of `out` (alpha: the pixel's).
  void write(DenoiseLayer& out, std::size_t i, int hitCount, Real alpha) const {
    if (out.variance.empty()) return;  // a layer the scene has no use for
    const Real hits = Real(std::max(hitCount, 1)), guides = Real(std::max(guided, 1));
    for (int k = 0; k < 4; ++k) out.color[4 * i + std::size_t(k)] = float(k < 3 ? radiance[k] / hits : alpha);
    for (int k = 0; k < 3; ++k) {
      out.albedo[3 * i + std::size_t(k)] = float(albedo[k] / guides);
      out.normal[3 * i + std::size_t(k)] = float(normal[k] / guides);
      out.demodulation[3 * i + std::size_t(k)] = out.albedo[3 * i + std::size_t(k)];
    }
    out.depth[i] = float(depth / guides);
    const Real mean = luminance / hits;
    out.variance[i] = float(std::max(Real(0), luminanceSquared / hits - mean * mean) / hits);
  }
};

// The first surface's light from point, spot and directional lights over a pixel's hits: its sum,
// and its luminance's and its square's, to tell whether their mean is exact for the pixel.
struct DirectSums {
  Color3 sum{0};
  Real luminance = 0, luminanceSquared = 0;

  void add(const Color3& direct) {
    const Real l = illum::luminance(direct);
    sum += direct, luminance += l, luminanceSquared += l * l;
  }
  // Whether the mean over `hits` is kept out of the filter: unless the standard error of its
  // mean is over 0.75 of the mean, as where one sample alone of n saw the light (√((n − 1)/n) of
  // it; two of n: √((n − 2)/2n) < 0.71). That one sample saw a highlight smaller than the pixel,
  // or the sliver of a light's edge: exact for itself, noise for the pixel (on a smooth clear
  // coat, 30 times the reference's value at 16 samples), which the filter's outlier pass is for.
  // (2CylinderEngine, ClearCoatTest.gltf at 16 samples, 320×240: 0.00093, 0.0084 with no such
  // rule; 0.00096, 0.00059 with this; 0.00117, 0.00060 with 0.5.)
  bool exact(int hits) const {
    const Real n = Real(std::max(hits, 1)), mean = luminance / n;
    const Real varianceOfMean = std::max(Real(0), luminanceSquared / n - mean * mean) / n;
    return varianceOfMean <= Real(0.75 * 0.75) * mean * mean;
  }
};

// A pixel's guides over more samples than its light was: the mean albedo, normal and distance of
// the first surfaces hit, and the share of the samples that hit one; and over the same samples
// the mean direct light of those surfaces.
struct RefinedGuides {
  Color3 albedo{0};
  Vec3 normal{0};
  Real depth = 0;
  Real coverage = 0;
  Color3 direct{0};
  bool directExact = false;  // DirectSums::exact over those samples
};

// What one pixel's samples add up to: every sample (the background where they miss), and those
// that hit something apart; for the denoiser, its two layers.
struct PixelSums {
  Color4 all{0};
  Color3 hits{0};
  int hitCount = 0;
  LayerSums surface, mirrored;
  // The first surface's light from point, spot and directional lights, and the surfaces' layer
  // with it left in, for where it is not exact (DirectSums::exact).
  DirectSums direct;
  LayerSums surfaceWithDirect;
  // The spread of the hits' first surfaces' albedos, and whether any hit's first surface was
  // wholly ideal (a mirror's or glass's guides lie past it): see refineGuides.
  Color3 albedoLow{std::numeric_limits<Real>::infinity()}, albedoHigh{-std::numeric_limits<Real>::infinity()};
  bool idealFirst = false;
  // The guides and coverage over more samples than the picture's (refineGuides), where taken.
  std::optional<RefinedGuides> refined;

  // Whether the direct light the picture shows is exact: over the refined samples where taken.
  bool directExact() const { return refined ? refined->directExact : direct.exact(hitCount); }
};

class TracedFrame {
 public:
  // With `denoised`, the path tracer's pixels are kept there for the denoiser instead of written.
  TracedFrame(const Scene& scene, const RayScene& rays, Image& image, PixelProbe* probe, FloatImage* linear,
              DenoiseBuffers* denoised)
      : scene_(scene), rays_(rays), image_(image), linear_(linear), probe_(probe), denoised_(denoised),
        camera_(scene.camera, scene.width, scene.height), tracer_(scene, rays),
        // With many samples a pixel, each sample filters textures over a share of the pixel only
        // (1/√samples of its side, at least 1/8, as pbrt-v4 scales its camera's ray
        // differentials): the samples themselves average over the pixel, and a whole pixel's
        // filter on each would blur the texture over two. Denoised, the texture a pixel shows is
        // averaged over its guides' samples (refineGuides, where its samples' albedos differ), so
        // it is their count that says the share: at 16 samples a quarter pixel's filter had
        // blurred the texture's edges towards the next mip level, an error no count of guide
        // samples took out (BoxTextured.gltf's denoised error 0.00012 → 0.00009).
        differentialReach_(std::max(Real(0.125), 1 / std::sqrt(Real(denoised ? guideSamples(samplesPerPixel(scene))
                                                                             : samplesPerPixel(scene))))) {
    if (scene.renderer == RendererKind::Path) pathTracer_.emplace(scene, rays);
  }

  void tile(int x0, int y0, TileCounts& counts) const {
    const int x1 = std::min(x0 + kTile, scene_.width), y1 = std::min(y0 + kTile, scene_.height);
    const int samples = samplesPerPixel(scene_);
    std::array<PixelSums, kTile * kTile> sums{};
    for (int s = 0; s < samples; ++s)
      for (int by = y0; by < y1; by += kBlock)
        for (int bx = x0; bx < x1; bx += kBlock) block(bx, by, x1, y1, s, x0, y0, sums, counts);
    if (denoised_) refineGuides(x0, y0, x1, y1, sums, counts);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const PixelSums& f = sums[std::size_t((y - y0) * kTile + (x - x0))];
        const Color4 c = f.all / Real(samples);
        const Color3 hitMean = f.hitCount > 0 ? f.hits / Real(f.hitCount) : Color3(0);
        const Real coverage = Real(f.hitCount) / Real(samples);
        if (!denoised_) {
          writePixel(x, y, c, hitMean, coverage);
          continue;
        }
        const std::size_t i = std::size_t(y) * std::size_t(scene_.width) + std::size_t(x);
        for (int k = 0; k < 4; ++k) denoised_->beauty[4 * i + std::size_t(k)] = float(c[k]);
        denoised_->coverage[i] = float(coverage);
        const bool exact = f.directExact();
        DenoiseLayer& layer = denoised_->surface;
        (exact ? f.surface : f.surfaceWithDirect).write(layer, i, f.hitCount, c[3]);
        float* albedo = &layer.albedo[3 * i];
        for (int k = 0; k < 3; ++k)
          denoised_->direct[3 * i + std::size_t(k)] = exact ? float(f.direct.sum[k] / Real(std::max(f.hitCount, 1))) : 0.0f;
        if (f.refined) {
          // The direct light, unfiltered, is the refined samples' too.
          for (int k = 0; k < 3; ++k) {
            if (exact) denoised_->direct[3 * i + std::size_t(k)] = float(f.refined->direct[k]);
            albedo[k] = float(f.refined->albedo[k]);
            layer.normal[3 * i + std::size_t(k)] = float(f.refined->normal[k]);
          }
          layer.depth[i] = float(f.refined->depth);
          const Real coverage = f.refined->coverage;
          denoised_->coverage[i] = float(coverage);
          layer.color[4 * i + 3] = float(coverage + scene_.background.a * (1 - coverage));
        }
        f.mirrored.write(denoised_->mirrored, i, f.hitCount, c[3]);
      }
  }

  // A pixel as the picture shows it and as it is (linear): `all` the mean of every sample,
  // `hitMean` that of the samples that hit something, `coverage` their share. A tone map shapes
  // radiance, not the background behind it: under one, the tone-mapped radiance is laid over the
  // background by coverage before the encoding, so that a background pixel has the same bytes from
  // every renderer, tone map or not. Without one, the mean of all samples is shown, as it is.
  void writePixel(int x, int y, const Color4& all, const Color3& hitMean, Real coverage) const {
    std::uint8_t* p = image_.pixel(x, y);
    const Display& display = scene_.display;
    if (coverage == 0) {  // the background alone: its bytes from the colour itself, as every renderer's
      const std::array<std::uint8_t, 4> bytes = backgroundBytes(scene_.background, display);
      std::copy(bytes.begin(), bytes.end(), p);
    }
    for (int k = 0; k < 3 && coverage > 0; ++k) {
      if (display.toneMap == ToneMap::None) {
        p[k] = toUnorm8(displayValue(all[k], display));
        continue;
      }
      const Real background = std::clamp(scene_.background[k], Real(0), Real(1));
      const Real shown = toneMapped(hitMean[k], display.toneMap) * coverage + background * (1 - coverage);
      p[k] = toUnorm8(displayValue(shown, Display{ToneMap::None, display.encoding}));
    }
    if (coverage > 0) p[3] = toUnorm8(all[3]);
    if (linear_)
      for (int k = 0; k < 4; ++k) linear_->pixel(x, y)[k] = float(all[k]);
  }

 private:
  // One 4×4 packet of primary rays (sample `s` of each pixel), then each hit shaded on its own.
  void block(int bx, int by, int x1, int y1, int s, int x0, int y0, std::array<PixelSums, kTile * kTile>& sums,
             TileCounts& counts) const {
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
      const RayCone cone = coneOf(x, y, s, hit);
      const RayHit* first = hit.t >= 0 ? &hit : nullptr;
      PixelSums& pixel = sums[std::size_t((y - y0) * kTile + (x - x0))];
      pixel.hitCount += first ? 1 : 0;
      if (pathTracer_) {
        pathSample(pixel, x, y, s, ray, first, cone, counts);
        continue;
      }
      PixelProbe* probe = probe_ && s == 0 && x == probe_->x && y == probe_->y ? probe_ : nullptr;
      // Each sample as the display shows it: clamped, then averaged.
      const Color4 c = glm::clamp(tracer_.primary(ray, first, cone, counts.rays, probe), Color4(0), Color4(1));
      pixel.all += c;
      if (first) pixel.hits += Color3(c);
    }
  }

  // Sample s of pixel (x, y) path traced, along `ray` to its first hit (null: none), into its sums.
  void pathSample(PixelSums& pixel, int x, int y, int s, const Ray& ray, const RayHit* first, const RayCone& cone,
                  TileCounts& counts) const {
    // Radiance is averaged as it is: the mean converges to the rendering equation's solution.
    // (A sample that overflowed, say under an emitter of absurd strength, counts as nothing.)
    PathFeatures guides;
    const Color4 radiance =
        pathTracer_->primary(ray, first, cone, counts.rays,
                             {sampleSeed(x, y, s, seededSalt(3, seed_)), pixelSeed(x, y, seed_), std::uint32_t(s)},
                             denoised_ ? &guides : nullptr);
    if (!std::isfinite(radiance.r + radiance.g + radiance.b + radiance.a)) return;
    pixel.all += radiance;
    if (first) pixel.hits += Color3(radiance);
    if (denoised_ && first) {
      const Color3 surface = Color3(radiance) - guides.mirroredRadiance;
      pixel.direct.add(guides.direct);
      pixel.surface.add(surface - guides.direct, guides.albedo, guides.normal, guides.depth, true);
      pixel.surfaceWithDirect.add(surface, guides.albedo, guides.normal, guides.depth, true);
      pixel.mirrored.add(guides.mirroredRadiance, guides.mirrorAlbedo, guides.mirrorNormal, 0, guides.mirrored);
      pixel.albedoLow = glm::min(pixel.albedoLow, guides.albedo);
      pixel.albedoHigh = glm::max(pixel.albedoHigh, guides.albedo);
      pixel.idealFirst |= !(idealChance(rays_.mesh(first->object).object->optics) < 1);
    }
  }

  // The cone of sample s of pixel (x, y) whose primary ray made `hit`.
  RayCone coneOf(int x, int y, int s, const RayHit& hit) const {
    RayCone cone;
    cone.spread = camera_.pixelWidthAt(1) - camera_.pixelWidthAt(0);
    cone.width = camera_.pixelWidthAt(0);
    if (hit.t >= 0 && readsTextures(*rays_.mesh(hit.object).object)) {
      // The rays through the next pixel right and the next one up (GL's window y is up), as the
      // rasterizer's derivatives, a share of a pixel away when a pixel takes many samples.
      const Vec2 at = pixelPoint(x, y, s);
      cone.differentials = true;
      cone.right = camera_.through(at.x + differentialReach_, at.y);
      cone.up = camera_.through(at.x, at.y - differentialReach_);
    }
    return cone;
  }

  // The denoiser multiplies the filtered light back by the albedo, and lays it over the background
  // by the coverage, and adds the unfiltered direct light; over the picture's samples all three
  // keep their anti-aliasing's error (a texture's, a silhouette's or a model's edge inside a
  // pixel, seen by 16 samples), which no filter of the light can take out. Where a pixel's
  // samples saw different albedos, faces turned apart (kNormalsAgree), direct light that is not
  // exact, or only some of them a surface, its guides, coverage and direct light are therefore
  // taken over more samples (guideSamples, the next ones of the pixel's stratified sequence), of
  // the first surface only: a primary ray, its material and its shadow rays to the point, spot
  // and directional lights each, no path on. The filtered light itself is still divided by the
  // picture's own albedo, which its samples saw. (A pixel whose samples met a wholly ideal
  // surface keeps its guides: they lie past it.)
  void refineGuides(int x0, int y0, int x1, int y1, std::array<PixelSums, kTile * kTile>& sums,
                    TileCounts& counts) const {
    const int samples = samplesPerPixel(scene_), total = guideSamples(samples);
    if (total <= samples) return;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        PixelSums& f = sums[std::size_t((y - y0) * kTile + (x - x0))];
        const Color3 spread = f.albedoHigh - f.albedoLow;
        const bool differ = std::max({spread.r, spread.g, spread.b}) > kAlbedoSpread;
        const bool bends = glm::length(f.surface.normal) < kNormalsAgree * Real(std::max(f.surface.guided, 1));
        const bool lightDiffers = !f.direct.exact(f.hitCount);
        if (f.hitCount == 0 || f.idealFirst || !(differ || bends || lightDiffers || f.hitCount < samples)) continue;
        Color3 albedo = f.surface.albedo;
        Vec3 normal = f.surface.normal;
        Real depth = f.surface.depth;
        DirectSums direct = f.direct;
        int hitCount = f.hitCount, guided = f.surface.guided;
        bool ideal = false;
        for (int s0 = samples; s0 < total && !ideal; s0 += 16) {
          std::array<Ray, 16> rays;
          std::array<bool, 16> active;
          std::array<RayHit, 16> hits;
          for (int k = 0; k < 16; ++k) {
            active[std::size_t(k)] = s0 + k < total;
            const Vec2 at = pixelPoint(x, y, s0 + k);
            rays[std::size_t(k)] = camera_.through(at.x, at.y);
          }
          rays_.intersect16(rays.data(), active.data(), hits.data());
          for (int k = 0; k < 16 && active[std::size_t(k)]; ++k) {
            ++counts.rays.primary;
            const RayHit& hit = hits[std::size_t(k)];
            if (hit.t < 0) continue;
            ++hitCount;
            const std::optional<SurfaceGuides> g =
                pathTracer_->firstSurfaceGuides(rays[std::size_t(k)], hit, coneOf(x, y, s0 + k, hit), counts.rays);
            if (!g) {
              ideal = true;
              break;
            }
            albedo += g->albedo, normal += g->normal, depth += g->depth, ++guided;
            direct.add(g->direct);
          }
        }
        if (ideal || guided == 0) continue;
        f.refined = RefinedGuides{albedo / Real(guided), normal / Real(guided), depth / Real(guided),
                                  Real(hitCount) / Real(total), direct.sum / Real(hitCount), direct.exact(hitCount)};
      }
  }

  // Where sample s of pixel (x, y) goes through the image: the centre, or stratified over the pixel.
  Vec2 pixelPoint(int x, int y, int s) const {
    const Vec2 offset = samplesPerPixel(scene_) == 1 ? Vec2(Real(0.5)) : pixelSampleOffset(x, y, s, seed_);
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
  Real differentialReach_;  // pixels from a sample to the rays of its texture derivatives
  std::uint32_t seed_ = scene_.rayTracing.seed;  // which picture of the samples (RayTracing::seed)
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
  if (denoising) denoised.emplace(std::size_t(scene.width) * std::size_t(scene.height), hasPartMirrors(scene));
  const TracedFrame frame(scene, rays, image, probe, linear, denoised ? &*denoised : nullptr);
  const int tilesX = (scene.width + kTile - 1) / kTile, tilesY = (scene.height + kTile - 1) / kTile;
  tbb::combinable<TileCounts> counts;
  std::atomic<int> done{0};
  const int tiles = tilesX * tilesY;
  // Fractions go out one at a time and only ever growing: two threads finishing tiles together
  // could otherwise hand them over in the other order.
  std::mutex reporting;
  int reported = 0;
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles), [&](const tbb::blocked_range<int>& r) {
    TileCounts& local = counts.local();
    for (int t = r.begin(); t < r.end(); ++t) {
      if (cancel && cancel->load(std::memory_order_relaxed)) return;
      frame.tile(t % tilesX * kTile, t / tilesX * kTile, local);
      const int finished = ++done;
      if (progress) {
        const std::lock_guard lock(reporting);
        if (finished > reported) reported = finished, progress(double(finished) / tiles);
      }
    }
  });
  if (denoised && !(cancel && cancel->load())) {
    // The radiance of the samples that hit something is filtered (the background stays out of
    // it), then laid over the background by each pixel's coverage.
    const auto input = [&](const DenoiseLayer& layer) {
      return DenoiseInput{scene.width, scene.height, layer.color, layer.albedo,        layer.normal,
                          layer.variance, layer.depth, layer.demodulation};
    };
    std::vector<float> filtered(denoised->surface.color.size());
    if (denoised->mirrored.variance.empty())
      denoise(input(denoised->surface), filtered);
    else
      denoiseLayers(input(denoised->surface), input(denoised->mirrored), filtered);
    for (int y = 0; y < scene.height; ++y)
      for (int x = 0; x < scene.width; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(scene.width) + std::size_t(x);
        const float *c = &filtered[4 * i], *direct = &denoised->direct[3 * i];
        const Real coverage = denoised->coverage[i];
        const Color3 hitMean(c[0] + direct[0], c[1] + direct[1], c[2] + direct[2]);
        const Color3 all = hitMean * coverage + Color3(scene.background) * (1 - coverage);
        frame.writePixel(x, y, Color4(all, c[3]), hitMean, coverage);
      }
    if (linear) {
      linear->layers.push_back({"beauty", 4, std::move(denoised->beauty)});
      linear->layers.push_back({"albedo", 3, std::move(denoised->surface.albedo)});
      linear->layers.push_back({"normal", 3, std::move(denoised->surface.normal)});
      linear->layers.push_back({"direct", 3, std::move(denoised->direct)});
      linear->layers.push_back({"depth", 1, std::move(denoised->surface.depth)});
      if (!denoised->mirrored.variance.empty() && !layerRows(input(denoised->mirrored)).empty()) {
        // What the part mirrors reflected, and its guides.
        const std::vector<float>& rgba = denoised->mirrored.color;
        std::vector<float> rgb(rgba.size() / 4 * 3);
        for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = rgba[i / 3 * 4 + i % 3];
        linear->layers.push_back({"reflection", 3, std::move(rgb)});
        linear->layers.push_back({"reflection.albedo", 3, std::move(denoised->mirrored.albedo)});
        linear->layers.push_back({"reflection.normal", 3, std::move(denoised->mirrored.normal)});
      }
    }
  }
  counts.combine_each([&](const TileCounts& c) {
    stats.primaryRays += c.rays.primary;
    stats.secondaryRays += c.rays.secondary;
    stats.shadowRays += c.rays.shadow;
    stats.primaryRaySeconds += c.primarySeconds;
  });
  // Pixels unlike the background, as the rasterizer counts them.
  const std::array<std::uint8_t, 4> bg = backgroundBytes(scene.background, scene.display);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4)
    if (std::memcmp(&image.rgba[i], bg.data(), 4) != 0) ++stats.pixelsDrawn;
}

}  // namespace illum

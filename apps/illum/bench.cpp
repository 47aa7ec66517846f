// `illum bench [SCENE.json | MODEL] [--frames N] [--threads N]`: how fast illum renders a scene.
// Loading and mesh generation happen once, outside the timing; then one warm-up frame and N timed
// frames; the PNG encoding of the picture is timed on its own. One JSON object on stdout.
#include <illum/image.h>
#include <illum/render.h>

#include "cli_values.h"
#include "commands.h"
#include "scene_options.h"


#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace illum::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct BenchOptions {
  SceneOptions scene;
  int frames = 10;
};

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

int runBench(const BenchOptions& o) {
  const ThreadLimit limit(o.scene);
  const int threads = limit.threads();
  double loadMs = 0;
  const Scene scene = prepareScene(o.scene, &loadMs);

  RenderStats stats;
  Renderer renderer;  // one renderer for every frame, as a batch or a turntable uses it
  Image image;
  renderer.render(scene, image, &stats);  // warm-up: caches, page faults, the renderer's memory
  std::vector<double> frameMs, encodeMs;
  for (int i = 0; i < o.frames; ++i) {
    const auto start = Clock::now();
    renderer.render(scene, image, &stats);
    frameMs.push_back(msSince(start));
  }
  std::size_t pngBytes = 0;
  for (int i = 0; i < std::max(1, std::min(o.frames, 5)); ++i) {
    const auto start = Clock::now();
    pngBytes = encodePng(image).size();
    encodeMs.push_back(msSince(start));
  }
  // The ray tracers' figures: rays of each kind and the primary rays' BVH throughput per core.
  std::string rays;
  if (scene.renderer != RendererKind::Raster) {
    const double seconds = median(frameMs) / 1000;
    const double raysPerSecond = double(stats.primaryRays + stats.secondaryRays + stats.shadowRays) / seconds;
    char buf[600];
    std::snprintf(buf, sizeof buf,
                  "\"renderer\": \"%s\", \"samples\": %d, \"primary_rays\": %llu, \"secondary_rays\": %llu, "
                  "\"shadow_rays\": %llu, \"bvh_ms\": %.1f, \"rays_per_second\": %.0f, \"mrays_per_second\": %.2f, "
                  "\"samples_per_second\": %.0f, \"primary_rays_per_core_second\": %.0f, ",
                  std::string(toString(scene.renderer)).c_str(), samplesPerPixel(scene),
                  (unsigned long long)stats.primaryRays, (unsigned long long)stats.secondaryRays,
                  (unsigned long long)stats.shadowRays, stats.bvhMs, raysPerSecond, raysPerSecond / 1e6,
                  double(stats.primaryRays) / seconds,
                  stats.primaryRaySeconds > 0 ? double(stats.primaryRays) / stats.primaryRaySeconds : 0.0);
    rays = buf;
  }
  std::printf(
      "{%s\"ms_per_frame\": %.3f, \"ms_min\": %.3f, \"encode_ms\": %.3f, \"png_bytes\": %zu, \"load_ms\": %.1f, "
      "\"triangles\": %zu, \"triangles_drawn\": %zu, \"fragments\": %zu, \"pixels\": %zu, \"width\": %d, "
      "\"height\": %d, \"frames\": %d, \"threads\": %d, \"simd\": \"%s\", \"peak_mib\": %.1f}\n",
      rays.c_str(), median(frameMs), *std::min_element(frameMs.begin(), frameMs.end()), median(encodeMs), pngBytes, loadMs,
      stats.trianglesIn, stats.trianglesDrawn, stats.fragmentsShaded, std::size_t(scene.width) * std::size_t(scene.height),
      scene.width, scene.height, o.frames, threads, simdTarget(), peakMemoryMiB());
  return 0;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Time the rendering of a scene or model: one JSON object on stdout");
  cmd->footer("Loading is timed once (load_ms); frames are timed after one warm-up (median ms_per_frame and\n"
              "ms_min); the PNG encoding of the picture separately (encode_ms). See bench/ for comparisons.");
  addSceneOptions(*cmd, o->scene);
  cmd->add_option("--frames", o->frames, "Timed frames after the warm-up")->check(wholeRange(1, 100000))->capture_default_str();
  return [o] { return runBench(*o); };
}

}  // namespace illum::cli

// Google Benchmark micro benches: where the time of a frame goes.
//   BM_Triangles/<pixels per triangle>: a screen of equal triangles, Gouraud-lit (triangles/s);
//   BM_ShadedPixels/<model>/<lights>: a full-screen quad shaded per pixel (pixels/s);
//   BM_EncodePng/<encoder>: the PNG encoding of a rendered 1080p frame (MB/s of RGBA), libdeflate as
//   illum uses it against stb_image_write, the encoder illum used before;
//   BM_EmbreeIncoherent/<scene> and BM_PathTracerRays/<scene>: Embree's own rate of incoherent
//   closest-hit rays on the scene's BVH, against the rays the path tracer traces per second (all
//   kinds: camera, bounces, shadows) on the same scene, both on every core;
//   BM_Denoise: the path tracer's denoiser at 1000×600.
#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

#include "image/denoise.h"
#include "trace/ray_scene.h"
#include "trace/sampling.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <stdexcept>
#include <memory>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

namespace {

using namespace illum;

// A grid of triangles covering a w×h screen, each about `area` pixels, in an orthographic view.
Scene triangleGrid(int w, int h, double area) {
  Scene s;
  s.width = w, s.height = h;
  s.shading = Shading::Gouraud;
  s.camera.projection = Projection::Orthographic;
  s.camera.viewHeight = Real(h);
  s.camera.eye = {Real(w) / 2, Real(h) / 2, 10};
  s.camera.center = {Real(w) / 2, Real(h) / 2, 0};
  const double side = std::sqrt(2 * area);
  const int nx = std::max(1, int(w / side)), ny = std::max(1, int(h / side));
  auto mesh = std::make_shared<Mesh>();
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      mesh->positions.push_back({Real(i * w) / Real(nx), Real(j * h) / Real(ny), 0});
      mesh->normals.push_back({0, 0, 1});
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::uint32_t a = std::uint32_t(j * (nx + 1) + i), b = a + 1, c = a + std::uint32_t(nx + 1), d = c + 1;
      mesh->indices.insert(mesh->indices.end(), {a, b, d, a, d, c});
    }
  Object o;
  o.mesh = mesh;
  s.objects.push_back(o);
  return s;
}

void BM_Triangles(benchmark::State& state) {
  const Scene scene = triangleGrid(1920, 1080, double(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(renderScene(scene));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(scene.objects[0].mesh->triangleCount()));
}
BENCHMARK(BM_Triangles)->Arg(2)->Arg(16)->Arg(128)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ShadedPixels(benchmark::State& state) {
  Scene scene = triangleGrid(1920, 1080, 1e9);
  scene.shading = Shading::Phong;
  scene.model = LightingModel(state.range(0));
  scene.lights.clear();
  for (int i = 0; i < state.range(1); ++i) {
    Light l;
    l.position = {Real(100 * i), 500, 400, 1};
    l.attenuation = {1, 0.001f, 0};
    scene.lights.push_back(l);
  }
  scene.objects[0].material.specular = {0.5, 0.5, 0.5, 1};
  scene.objects[0].material.shininess = 32;
  for (auto _ : state) benchmark::DoNotOptimize(renderScene(scene));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * 1920 * 1080);
}
BENCHMARK(BM_ShadedPixels)
    ->ArgsProduct({{int(LightingModel::BlinnPhong), int(LightingModel::Phong), int(LightingModel::Lambert)}, {1, 8}})
    ->ArgNames({"model", "lights"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  out->insert(out->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
}

void BM_EncodePng(benchmark::State& state) {
  Scene scene = defaultScene();
  scene.width = 1920, scene.height = 1080;
  const Image image = renderScene(scene);
  for (auto _ : state) {
    if (state.range(0) == 0) {
      benchmark::DoNotOptimize(encodePng(image));
    } else {
      std::vector<std::uint8_t> out;
      stbi_write_png_to_func(appendBytes, &out, image.width, image.height, 4, image.rgba.data(), image.width * 4);
      benchmark::DoNotOptimize(out);
    }
  }
  state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(image.rgba.size()));
  state.SetLabel(state.range(0) == 0 ? "libdeflate, sub filter (illum)" : "stb_image_write (before)");
}
BENCHMARK(BM_EncodePng)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The path tracer's denoiser on a 1000×600 picture (a noisy path-traced preview's size), the
// built-in scene: its surfaces alone (Arg 0), and with the floor's and the torus's reflections,
// the second layer the path tracer hands it where part mirrors are (Arg 1).
void BM_Denoise(benchmark::State& state) {
  Scene scene = defaultScene();
  scene.width = 1000, scene.height = 600;
  scene.renderer = RendererKind::Path;
  scene.rayTracing.samples = 4;
  scene.rayTracing.denoise = true;
  FloatImage linear;
  renderScene(scene, nullptr, nullptr, &linear);  // its layers: the denoiser's input
  const auto layer = [&](const char* name) -> const std::vector<float>& {
    for (const FloatLayer& l : linear.layers)
      if (l.name == name) return l.values;
    throw std::runtime_error(name);
  };
  const std::size_t pixels = std::size_t(scene.width) * std::size_t(scene.height);
  const std::vector<float> variance(pixels, 0.01f);
  std::vector<float> reflection(4 * pixels);
  for (std::size_t i = 0; i < pixels; ++i)
    for (std::size_t k = 0; k < 3; ++k) reflection[4 * i + k] = layer("reflection")[3 * i + k];
  const DenoiseInput surfaces{scene.width, scene.height, layer("beauty"), layer("albedo"), layer("normal"), variance, layer("depth")};
  const DenoiseInput reflections{scene.width, scene.height, reflection, layer("reflection.albedo"), layer("reflection.normal"), variance};
  std::vector<float> out(linear.rgba.size());
  for (auto _ : state) {
    if (state.range(0) == 0) {
      denoise(surfaces, out);
    } else {
      denoiseLayers(surfaces, reflections, out);
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetLabel(state.range(0) == 0 ? "surfaces" : "surfaces and reflections");
}
BENCHMARK(BM_Denoise)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The scenes of the ray-rate benches: the built-in scene and the Cornell box.
Scene rayScene(std::int64_t which) {
  if (which == 0) {
    Scene s = defaultScene(LightingModel::BlinnPhong, Shading::Phong, RendererKind::Path);
    s.width = 320, s.height = 180;
    return s;
  }
  Scene s = loadSceneFile(std::string(ILLUM_REPO_DIR) + "/examples/cornell_box.json");
  s.width = s.height = 128;
  return s;
}
const char* raySceneName(std::int64_t which) { return which == 0 ? "built-in" : "cornell_box.json"; }

// Rays with no coherence: from points along random camera rays, 1 to 8 units out, in directions
// uniform over the sphere, as a path's bounces are. Closest hits, one ray at a time.
void BM_EmbreeIncoherent(benchmark::State& state) {
  const Scene scene = rayScene(state.range(0));
  static std::unique_ptr<RayScene> shared;
  if (state.thread_index() == 0) shared = std::make_unique<RayScene>(scene);
  constexpr int kRays = 1 << 16;
  std::vector<Ray> rays(kRays);
  Rng rng(std::uint64_t(state.thread_index()) + 7, 11);
  for (Ray& r : rays) {
    const Vec3 primary = glm::normalize(Vec3(rng.uniform() - Real(0.5), rng.uniform() - Real(0.5), -1));
    r.origin = primary * (1 + 7 * rng.uniform());
    const Real z = 1 - 2 * rng.uniform(), phi = 2 * kPiReal * rng.uniform(), radius = std::sqrt(std::max(Real(0), 1 - z * z));
    r.direction = {radius * std::cos(phi), radius * std::sin(phi), z};
  }
  std::int64_t traced = 0;
  for (auto _ : state) {
    RayHit hit;
    for (const Ray& r : rays) benchmark::DoNotOptimize(shared->intersect(r, hit));
    traced += kRays;
  }
  state.counters["rays_per_second"] = benchmark::Counter(double(traced), benchmark::Counter::kIsRate);
  state.SetLabel(raySceneName(state.range(0)));
}
BENCHMARK(BM_EmbreeIncoherent)->Arg(0)->Arg(1)->Threads(2)->UseRealTime()->Unit(benchmark::kMillisecond);

// The path tracer on the same scene, on every core: every ray it traces, per second of its frame.
void BM_PathTracerRays(benchmark::State& state) {
  Scene scene = rayScene(state.range(0));
  scene.renderer = RendererKind::Path;
  scene.rayTracing.samples = 16;
  std::uint64_t rays = 0;
  for (auto _ : state) {
    RenderStats stats;
    renderScene(scene, &stats);
    rays += stats.primaryRays + stats.secondaryRays + stats.shadowRays;
  }
  state.counters["rays_per_second"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
  state.SetLabel(raySceneName(state.range(0)));
}
BENCHMARK(BM_PathTracerRays)->Arg(0)->Arg(1)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

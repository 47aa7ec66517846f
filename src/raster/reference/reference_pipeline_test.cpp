// The binned, parallel pipeline draws exactly what the reference driver draws (submission order,
// one thread), bit for bit, and the same bytes for every thread count: coverage, depth, shading,
// textures, vertex colours and blending included.
#include "raster/reference/reference_pipeline.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <hwy/targets.h>

#include <filesystem>

namespace illum {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> sceneFiles() {
  std::vector<fs::path> files;
  for (const fs::path& dir : {fs::path(ILLUM_REPO_DIR) / "tests/scenes/parity", fs::path(ILLUM_REPO_DIR) / "tests/scenes",
                             fs::path(ILLUM_REPO_DIR) / "examples"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

Image withThreads(int threads, const Scene& scene) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  return renderScene(scene);
}

TEST(BinnedPipeline, EqualsTheReferenceAndEveryThreadCount) {
  std::vector<std::pair<std::string, Scene>> scenes = {{"built-in", defaultScene()}};
  for (const fs::path& f : sceneFiles()) scenes.push_back({f.filename().string(), loadSceneFile(f)});
  for (auto& named : scenes) named.second.renderer = RendererKind::Raster;  // a ray-traced example, rasterized
  // A big picture spans many tiles; blending shows any change of drawing order.
  Scene wide = defaultScene();
  wide.width = 1000, wide.height = 700, wide.blend = true;
  for (Object& o : wide.objects) o.material.diffuse.a = 0.6f;
  scenes.push_back({"blended 1000x700", wide});
  for (auto& [name, scene] : scenes)
    for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
      scene.shading = shading;
      RenderStats refStats, stats;
      const Image reference = renderSceneReference(scene, &refStats);
      const Image parallel = renderScene(scene, &stats);
      EXPECT_EQ(parallel.rgba, reference.rgba) << name << " " << toString(shading);
      EXPECT_EQ(stats.fragmentsShaded, refStats.fragmentsShaded) << name;
      EXPECT_EQ(stats.trianglesDrawn, refStats.trianglesDrawn) << name;
      EXPECT_EQ(withThreads(1, scene).rgba, parallel.rgba) << name << " on one thread";
      EXPECT_EQ(withThreads(3, scene).rgba, parallel.rgba) << name << " on three threads";
    }
}

// The SIMD kernels are compiled for every target this CPU has (SSE4, AVX2, AVX-512, and the
// portable one): each draws the reference's bytes, so every machine gets the same picture.
TEST(BinnedPipeline, EverySimdTargetDrawsTheSameBytes) {
  std::vector<std::pair<std::string, Scene>> scenes = {{"built-in", defaultScene()}};
  for (const char* file : {"examples/first_light.json", "tests/scenes/parity/near_clip_two_sided.json", "tests/scenes/parity/coloured_lights.json"})
    scenes.push_back({file, loadSceneFile(fs::path(ILLUM_REPO_DIR) / file)});
  int targets = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    for (auto& [name, scene] : scenes)
      for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
        scene.shading = shading;
        EXPECT_EQ(renderScene(scene).rgba, renderSceneReference(scene).rgba)
            << name << " " << toString(shading) << " with " << hwy::TargetName(target);
      }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
}

}  // namespace
}  // namespace illum

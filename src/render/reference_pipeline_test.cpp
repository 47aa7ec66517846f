// The binned, parallel pipeline draws exactly what the reference driver draws (submission order,
// one thread), bit for bit, and the same bytes for every thread count: coverage, depth, shading,
// textures, vertex colours and blending included.
#include "render/reference_render.h"

#include <illum/render.h>
#include <illum/scene.h>

#include <illum/texture.h>

#include <glm/gtc/matrix_transform.hpp>
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

// Dense meshes, whose triangles cover a pixel or two (tiny ones are coloured at setup, without a
// record: tile_raster.h), lit on both sides (the back faces show through a cut-away), beside a
// textured object (whose pixels are coloured after the depth pass) and, with blending, a
// translucent one.
Scene denseScene(bool blend) {
  Scene scene = defaultScene();
  scene.width = 300, scene.height = 200, scene.blend = blend;
  scene.lightModel.twoSided = true;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    scene.objects[i].mesh = std::make_shared<Mesh>(makeSphere(1, 160 + 20 * int(i), 90));
  Image checker(8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      for (int c = 0; c < 4; ++c) checker.pixel(x, y)[c] = (x + y) % 2 || c == 3 ? 255 : 40;
  Object textured = scene.objects.front();
  Mesh cube = makeCube(Real(1.2));
  for (const Vec3& p : cube.positions) cube.uvs.push_back({p.x + p.z, p.y - p.z});
  textured.mesh = std::make_shared<Mesh>(std::move(cube));
  textured.diffuseTexture = std::make_shared<Texture>(checker);
  textured.worldFromObject = glm::translate(Mat4(1), Vec3(0.4f, 0.2f, 0.5f));
  scene.objects.push_back(textured);
  if (blend) {
    Object glass = scene.objects.front();
    glass.material.diffuse.a = 0.5f;
    glass.worldFromObject = glm::translate(Mat4(1), Vec3(-0.5f, -0.3f, 0.8f)) * glm::scale(Mat4(1), Vec3(0.6f));
    scene.objects.push_back(glass);
  }
  return scene;
}

// The scenes both drivers draw: the built-in one and every scene file (a ray-traced example
// rasterized); a big picture of `wide` pixels (it spans many tiles) with blending (which shows any
// change of drawing order); dense meshes; ambient occlusion traced at the points the routes light.
std::vector<std::pair<std::string, Scene>> testScenes(int wideWidth, int wideHeight) {
  std::vector<std::pair<std::string, Scene>> scenes = {{"built-in", defaultScene()}};
  for (const fs::path& f : sceneFiles()) scenes.push_back({f.filename().string(), loadSceneFile(f)});
  for (auto& named : scenes) named.second.renderer = RendererKind::Raster;
  Scene wide = defaultScene();
  wide.width = wideWidth, wide.height = wideHeight, wide.blend = true;
  for (Object& o : wide.objects) o.material.diffuse.a = 0.6f;
  scenes.push_back({"blended " + std::to_string(wideWidth) + "x" + std::to_string(wideHeight), wide});
  scenes.push_back({"dense", denseScene(false)});
  scenes.push_back({"dense, blended", denseScene(true)});
  Scene occluded = defaultScene();
  occluded.width = 240, occluded.height = 180;
  occluded.ambientOcclusion.enabled = true;
  scenes.push_back({"ambient occlusion", occluded});
  return scenes;
}

TEST(BinnedPipeline, EqualsTheReferenceAndEveryThreadCount) {
  for (auto& [name, scene] : testScenes(1000, 700))
    for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
      scene.shading = shading;
      scene.multisample = 1;
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

// Multisampling in one pass (each tile keeping its samples) draws what one whole pass per sample
// position draws, averaged: the reference's way.
TEST(BinnedPipeline, MultisamplingInOnePassEqualsAPassPerSample) {
  std::vector<std::pair<std::string, Scene>> scenes = testScenes(700, 500);
  // Big triangles whose edge values outgrow float lanes (the coverage kernel's double lanes).
  Scene big = defaultScene();
  big.width = 2400, big.height = 300;
  big.camera.fovy = 12;
  scenes.push_back({"big triangles 2400x300", big});
  for (auto& [name, scene] : scenes)
    for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong})
      for (int samples : {4, 8, 16}) {
        // (Every scene at 4 samples; the built-in and the dense ones, whose tiles hold the most
        // edges, at 8 and 16 too.)
        if (samples > 4 && name != "built-in" && name.rfind("dense", 0) != 0) continue;
        if (samples == 16 && shading != Shading::Phong && name.rfind("dense", 0) != 0) continue;
        scene.shading = shading;
        scene.multisample = samples;
        RenderStats refStats, stats;
        const Image reference = renderSceneReference(scene, &refStats);
        const Image parallel = renderScene(scene, &stats);
        EXPECT_EQ(parallel.rgba, reference.rgba) << name << " " << toString(shading) << " " << samples;
        EXPECT_EQ(stats.fragmentsShaded, refStats.fragmentsShaded) << name << " " << samples;
        EXPECT_EQ(withThreads(1, scene).rgba, parallel.rgba) << name << " " << samples << " on one thread";
      }
}

// The SIMD kernels are compiled for every target this CPU has (SSE4, AVX2, AVX-512, and the
// portable one): each draws the reference's bytes, so every machine gets the same picture.
TEST(BinnedPipeline, EverySimdTargetDrawsTheSameBytes) {
  std::vector<std::pair<std::string, Scene>> scenes = {{"built-in", defaultScene()}};
  for (const char* file : {"examples/first_light.json", "tests/scenes/parity/near_clip_two_sided.json", "tests/scenes/parity/coloured_lights.json"})
    scenes.push_back({file, loadSceneFile(fs::path(ILLUM_REPO_DIR) / file)});
  scenes.push_back({"dense", denseScene(true)});
  // Bigger triangles, whose edge values pass 2^24 (the two-row blocks keep them as a multiple of
  // 256 plus a remainder) or 2^32 (double lanes).
  Scene big = defaultScene();
  big.width = 1600, big.height = 1000;
  scenes.push_back({"built-in 1600x1000", big});
  int targets = 0;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    ++targets;
    for (auto& [name, scene] : scenes)
      for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong})
        for (int samples : {1, 4}) {  // multisampled: the dense scene's tiny triangles at every
                                       // sample, the built-in scene's resolve of whole vectors
          if (samples > 1 && name != "dense" && name != "built-in") continue;
          scene.shading = shading;
          scene.multisample = samples;
          EXPECT_EQ(renderScene(scene).rgba, renderSceneReference(scene).rgba)
              << name << " " << toString(shading) << " " << samples << " samples with " << hwy::TargetName(target);
        }
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(targets, 2);
}

}  // namespace
}  // namespace illum

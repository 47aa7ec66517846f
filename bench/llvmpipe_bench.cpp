// The peer's side of the comparison: Mesa's llvmpipe (through OSMesa) drawing what `illum bench`
// draws, the way an application would: meshes in buffer objects once, then per frame clear + draws
// + glFinish. A scene file with fixed-function lighting for flat and Gouraud Blinn-Phong and the
// GLSL program of the parity tests otherwise; a model file as illum prepares its preview (the same
// scene-building code: scene_options.h), drawn by the preview program (llvmpipe_preview.h), with
// --samples through a multisampled framebuffer object. LP_NUM_THREADS sets its threads. Prints one
// JSON object like `illum bench`:
//   llvmpipe_bench SCENE.json|MODEL [--frames N] [--width W --height H] [--shading S] [--samples N]
#include "../tests/mesa_reference.h"
#include "llvmpipe_preview.h"
#include "scene_options.h"

#include <illum/file_names.h>

#include <illum/error.h>
#include <illum/scene.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  if (argc < 2) {
    std::fprintf(stderr, "usage: llvmpipe_bench SCENE.json [--frames N] [--width W] [--height H] [--shading S]\n");
    return 2;
  }
  int frames = 10;
  std::optional<int> width, height, samples;
  std::string shading;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--frames")) frames = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--width")) width = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--height")) height = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--shading")) shading = argv[i + 1];
    else if (!std::strcmp(argv[i], "--samples")) samples = std::atoi(argv[i + 1]);
  }
  try {
    const bool model = !illum::isSceneFileName(argv[1]);
    illum::Scene scene;
    if (model) {
      illum::cli::SceneOptions o;
      o.input = argv[1];
      o.width = width, o.height = height, o.samples = samples, o.shading = shading;
      o.environment = "none";  // the GLSL peer has no image-based light: both draw the light rig alone
      scene = illum::cli::prepareScene(o);
    } else {
      scene = illum::loadSceneFile(argv[1]);
      if (width) scene.width = *width;
      if (height) scene.height = *height;
      if (!shading.empty()) scene.shading = illum::parseShading(shading).value_or(scene.shading);
    }
    const illum::test::MesaPath path = illum::test::mesaPathFor(scene);
    std::unique_ptr<illum::test::MesaSession> session;
    std::unique_ptr<illum::bench::PreviewSession> preview;
    if (model) preview = std::make_unique<illum::bench::PreviewSession>(scene, scene.multisample);
    else session = std::make_unique<illum::test::MesaSession>(scene, path);
    const auto draw = [&] { model ? preview->draw() : session->draw(); };
    draw();  // warm-up: shader compilation, buffer uploads
    std::vector<double> ms;
    for (int f = 0; f < frames; ++f) {
      const auto start = Clock::now();
      draw();
      ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    if (const char* out = std::getenv("ILLUM_PEER_PNG")) illum::writePng(out, model ? preview->image() : session->image());
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.size() % 2 ? sorted[sorted.size() / 2]
                                            : (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]) / 2;
    const char* threads = std::getenv("LP_NUM_THREADS");
    std::printf("{\"ms_per_frame\": %.3f, \"ms_min\": %.3f, \"frames\": %d, \"samples\": %d, \"path\": \"%s\", "
                "\"lp_num_threads\": %s}\n",
                median, sorted.front(), frames, scene.multisample,
                model ? "glsl-preview"
                : path == illum::test::MesaPath::FixedFunction ? "fixed-function"
                : path == illum::test::MesaPath::GlslPerVertex ? "glsl-per-vertex"
                                                                : "glsl-per-pixel",
                threads ? threads : "null");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "llvmpipe_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}

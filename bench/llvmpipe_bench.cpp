// The peer's side of the comparison: Mesa's llvmpipe (through OSMesa) drawing the same scene file
// the way an application would: meshes in buffer objects once, then per frame clear + draws +
// glFinish, fixed-function lighting for flat and Gouraud Blinn-Phong, the GLSL program of the
// parity tests otherwise. LP_NUM_THREADS sets its threads. Prints one JSON object like
// `illum bench`: llvmpipe_bench SCENE.json [--frames N] [--width W --height H] [--shading S]
#include "../tests/mesa_reference.h"

#include <illum/error.h>
#include <illum/scene.h>

#include <algorithm>
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
  std::optional<int> width, height;
  std::string shading;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--frames")) frames = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--width")) width = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--height")) height = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--shading")) shading = argv[i + 1];
  }
  try {
    illum::Scene scene = illum::loadSceneFile(argv[1]);
    if (width) scene.width = *width;
    if (height) scene.height = *height;
    if (!shading.empty()) scene.shading = illum::parseShading(shading).value_or(scene.shading);
    const illum::test::MesaPath path = illum::test::mesaPathFor(scene);
    illum::test::MesaSession session(scene, path);
    session.draw();  // warm-up: shader compilation, buffer uploads
    std::vector<double> ms;
    for (int f = 0; f < frames; ++f) {
      const auto start = Clock::now();
      session.draw();
      ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.size() % 2 ? sorted[sorted.size() / 2]
                                            : (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]) / 2;
    const char* threads = std::getenv("LP_NUM_THREADS");
    std::printf("{\"ms_per_frame\": %.3f, \"ms_min\": %.3f, \"frames\": %d, \"path\": \"%s\", \"lp_num_threads\": %s}\n",
                median, sorted.front(), frames,
                path == illum::test::MesaPath::FixedFunction ? "fixed-function"
                : path == illum::test::MesaPath::GlslPerVertex ? "glsl-per-vertex"
                                                                : "glsl-per-pixel",
                threads ? threads : "null");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "llvmpipe_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}

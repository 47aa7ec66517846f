// libFuzzer target: scene files. Any bytes must parse to a scene or to an InputError, and a parsed
// scene (kept small by tight limits) must render; nothing may crash, hang or leak.
#include <illum/error.h>
#include <illum/render.h>
#include <illum/scene.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  illum::Limits limits;
  limits.maxTriangles = 20'000;
  limits.maxPixels = 64 * 64;
  limits.maxMemoryMiB = 256;
  limits.maxSeconds = 2;
  try {
    illum::Scene scene =
        illum::parseScene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json", "/nonexistent", limits);
    if (illum::cameraFault(scene.camera, illum::Real(scene.width) / illum::Real(scene.height)) ==
        illum::CameraFault::None) {
      // The ray tracers' work grows with samples and depth: a few of each keep every run short.
      scene.rayTracing.samples = std::min(illum::samplesPerPixel(scene), 2);
      scene.rayTracing.maxDepth = std::min(scene.rayTracing.maxDepth, 4);
      (void)illum::renderScene(scene);
    }
  } catch (const illum::InputError&) {
  }
  return 0;
}

// What `illum render` is asked: the scene options, the inputs (one picture, or a batch), and where
// and how the pictures are written.
#pragma once

#include "batch_inputs.h"
#include "scene_options.h"

#include <optional>
#include <string>
#include <vector>

namespace illum::cli {

// The most frames a turntable or light orbit draws (a tenth of a degree a frame).
constexpr int kMaxFrames = 3600;

struct RenderOptions {
  SceneOptions scene;
  std::vector<std::string> inputs;
  std::string output;  // empty: illum.png for one picture, {stem}.png (turntables {stem}.gif) for a batch
  std::string outputDir, debugPixel, shard, format;
  std::string debugPoint;   // --debug-point OBJECT[:x,y,z]: the pixel a point of an object lands on
  bool markPixel = false;   // --mark-pixel: a ring around the reported pixel in the picture
  std::string saveScene;  // --save-scene: the scene drawn, as a scene file
  bool force = false, quiet = false, progress = false, json = false, failFast = false, skipExisting = false;
  int bitDepth = 8, turntable = 0, orbitLight = 0, fps = 15;
  std::optional<int> quality;  // --quality: JPEG and lossy WebP outputs
};

// `illum render` with these options: one picture, or a batch.
int runRender(RenderOptions o);

// Whether the options make a batch rather than one picture.
bool isBatch(const RenderOptions& o);
// Renders every job, each failure reported and counted; the exit status.
int runBatch(const RenderOptions& o, const std::vector<BatchJob>& jobs);

}  // namespace illum::cli

// What `illum render` is asked: the scene options, the inputs (one picture, or a batch), and where
// and how the pictures are written.
#pragma once

#include "batch_inputs.h"
#include "scene_options.h"

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
  bool force = false, quiet = false, progress = false, json = false, failFast = false, skipExisting = false;
  int bitDepth = 8, turntable = 0, orbitLight = 0, fps = 15;
};

// Standard input saved to a temporary file named for --format, removed when this goes.
class StdinFile {
 public:
  explicit StdinFile(const std::string& format);
  ~StdinFile();
  StdinFile(const StdinFile&) = delete;
  StdinFile& operator=(const StdinFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Whether the options make a batch rather than one picture.
bool isBatch(const RenderOptions& o);
// Renders every job, each failure reported and counted; the exit status.
int runBatch(const RenderOptions& o, const std::vector<BatchJob>& jobs);

}  // namespace illum::cli

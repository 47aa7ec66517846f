// illum as a library: draw a scene file, a model file or a scene built in memory to a picture in
// memory, and evaluate the lighting equation, with the command line's options by their names.
//
//   #include <illum/illum.h>
//   illum::Picture p = illum::render("duck.glb", {{"resolution", "320x240"}, {"model", "phong"}});
//   // p.rgba: p.width × p.height RGBA bytes, top row first, the bytes `illum render` would write
//
// find_package(illum) and target_link_libraries(app illum::illum), or pkg-config --libs illum.
// Everything throws illum::InputError (<illum/error.h>) for input it refuses, with the message the
// command line would print (the option, what was expected, what was given), and illum::Error for
// failures of the system.
#pragma once

#include <illum/error.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#define ILLUM_API __attribute__((visibility("default")))

namespace illum {

// "0.1.0": the version of the library, the same as `illum --version`.
ILLUM_API const char* version();

// Options by the command line's long names, dashes or underscores alike, their values as text:
// {{"resolution", "320x240"}, {"camera_azimuth_angle", "30"}, {"edges", "true"}}. docs/cli.md
// lists them; a flag takes "true" or "false". They are checked by the command line's own parser.
using Options = std::vector<std::pair<std::string, std::string>>;

// A picture in memory.
struct Picture {
  int width = 0, height = 0;
  // RGBA, 8 bits a channel, rows top to bottom: the bytes `illum render -o picture.png` writes.
  std::vector<std::uint8_t> rgba;
  // With RenderSettings::linear: RGBA floats in linear light, unclamped (what an .exr holds).
  std::vector<float> linear;
  // What the command line would print as warnings (a texture that could not be read, ...).
  std::vector<std::string> warnings;

  // The picture as a PNG file's bytes.
  ILLUM_API std::vector<std::uint8_t> png() const;
};

struct RenderSettings {
  bool linear = false;  // fill Picture::linear too
  // Called now and then with the fraction done (0..1), from rendering threads; the ray and path
  // tracers report tile by tile.
  std::function<void(double fraction)> progress;
  // Read between tiles: once set, the render stops and throws illum::Error("cancelled").
  const std::atomic<bool>* cancel = nullptr;
};

// A model file read once (in an isolated child process, under the limits the options set), to be
// drawn many times.
class Model {
 public:
  ILLUM_API const std::string& path() const;
  ILLUM_API std::size_t vertexCount() const;
  ILLUM_API std::size_t triangleCount() const;
  ILLUM_API std::size_t materialCount() const;
  ILLUM_API std::size_t textureCount() const;
  ILLUM_API std::array<double, 3> boundsMin() const;
  ILLUM_API std::array<double, 3> boundsMax() const;
  ILLUM_API const std::vector<std::string>& warnings() const;
  // Every mesh of the file in world space, one after the other: x,y,z per vertex, and three vertex
  // indices per triangle into those.
  ILLUM_API std::vector<float> positions() const;
  ILLUM_API std::vector<std::uint32_t> triangles() const;

  struct Impl;
  explicit Model(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
  const std::shared_ptr<const Impl>& impl() const { return impl_; }

 private:
  std::shared_ptr<const Impl> impl_;
};

// Reads a model file (any format illum reads); the options that matter are those of import:
// normals, crease_angle, max_memory, max_triangles, ...
ILLUM_API Model loadModel(const std::string& path, const Options& options = {});

// What to draw: a scene file (.json) or a model file by its path, "" for the built-in scene, a
// model already read, or a scene built in memory.
class Source {
 public:
  Source(std::string path) : path_(std::move(path)) {}
  Source(const char* path) : path_(path) {}
  Source(const Model& model) : model_(model.impl()) {}
  // A scene document (docs/scene-format.md) as JSON text; the files it names are found from baseDir.
  static Source sceneJson(std::string json, std::string baseDir = ".") {
    Source s("");
    s.json_ = std::move(json);
    s.baseDir_ = std::move(baseDir);
    s.isJson_ = true;
    return s;
  }
  const std::string& path() const { return path_; }
  const std::string& json() const { return json_; }
  const std::string& baseDir() const { return baseDir_; }
  bool isJson() const { return isJson_; }
  const std::shared_ptr<const Model::Impl>& model() const { return model_; }

 private:
  std::string path_, json_, baseDir_;
  bool isJson_ = false;
  std::shared_ptr<const Model::Impl> model_;
};

// `illum render INPUT`, the picture in memory.
ILLUM_API Picture render(const Source& input, const Options& options = {}, const RenderSettings& settings = {});
// `illum compare INPUT` (options rows, cols, diff and those of render): the sheet.
ILLUM_API Picture compare(const Source& input, const Options& options = {});
// `illum history INPUT`: the sheet of the input as each model from Wylie (1967) to Kajiya (1986) drew it.
ILLUM_API Picture history(const Source& input, const Options& options = {});

// The terms of the lighting equation at one point for one light (`illum eval`), unclamped but the
// total, which is clamped to [0, 1] as GL clamps it.
struct Terms {
  std::array<double, 3> emission{}, ambient{}, diffuse{}, specular{}, total{};
  double attenuation = 1, spot = 1;
  // Everything `illum eval --json` prints (the vectors, the dot products, the lobe, ...).
  std::string json;
};
ILLUM_API Terms evaluate(const Options& options);
// The same as JSON: one object, or with a sweep (angle_nl = "0:90:5", shininess = "1,10,100") an
// array of them, each with the swept value under the option's name.
ILLUM_API std::string evaluateJson(const Options& options);

}  // namespace illum

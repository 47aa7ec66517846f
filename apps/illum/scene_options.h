// What to render, as the command line says it: the options `render` and `bench` share (input,
// size, lighting model and shading, camera, model-file options, limits), and the scene they make.
#pragma once

#include <illum/import.h>
#include <illum/limits.h>
#include <illum/scene.h>

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <filesystem>
#include <map>
#include <memory>

#include <optional>
#include <string>

namespace illum::cli {

class StdinInput;

// A scene document given in memory rather than as a file (the library's scenes built in code).
struct MemoryScene {
  std::string text;
  std::filesystem::path baseDir;  // where the files it names are found
};

struct SceneOptions {
  std::string input;  // a scene file (.json), a model file, "-" for standard input, or empty for the built-in scene
  std::shared_ptr<const StdinInput> stdinInput;  // what standard input held, when input is "-"
  std::shared_ptr<const MemoryScene> memoryScene;  // with input empty: this scene instead of the built-in one
  std::optional<int> width, height;
  std::string resolution;
  std::string model, shading, background;
  std::string convention;  // a lecture note's way of computing the equation (LightModel::convention)
  std::string toneMap, encoding;
  std::string renderer;  // raster, whitted or hall
  bool noShadows = false;
  std::optional<int> samples, maxDepth, seed;
  bool noBackground = false;
  bool edges = false, grid = false, axes = false;
  bool ambientOcclusion = false, noAmbientOcclusion = false;
  bool denoise = false, noDenoise = false;
  // Image-based lighting: a .hdr map, "studio" (illum's built-in) or "none", and how it is used.
  std::string environment, environmentBackground;
  std::optional<double> environmentRotation, environmentIntensity;
  std::optional<double> pointSize, lineWidth;
  // Model files (f3d's names).
  std::string up, cameraPosition, cameraFocalPoint, cameraViewUp, color;
  std::optional<double> opacity;
  bool geometryOnly = false;
  std::optional<double> viewAngle, azimuth, elevation, zoom, lightIntensity, creaseAngle;
  bool orthographic = false;
  std::string normals;
  // A thumbnail's: a model file with more triangles than the picture has pixels is lit per vertex
  // (Gouraud) unless --shading says otherwise.
  bool denseMeshesPerVertex = false;
  // A preview's physically based materials lit by the studio environment unless --environment says
  // otherwise (a thumbnail goes without: the studio's light costs more than its whole budget).
  bool studioForPhysicallyBased = true;
  bool verbose = false;
  int threads = 0;  // worker threads for rendering; 0: every core
  Limits limits;
};

// Holds oneTBB to the --threads the options ask for, while it lives. The picture is the same for
// every count; --threads 1 runs on the calling thread.
class ThreadLimit {
 public:
  explicit ThreadLimit(const SceneOptions& o);
  int threads() const { return threads_; }

 private:
  int threads_;
  std::unique_ptr<tbb::global_control> control_;
};

// With `inputs`, the command takes any number of inputs there instead of one in o.input.
void addSceneOptions(CLI::App& cmd, SceneOptions& o, std::vector<std::string>* inputs = nullptr);

// Model files already imported, by path and import options (normals, crease angle), so that many
// scenes of one model (a comparison sheet's panels) read it once. An entry imported ahead of use
// (a batch reads the next input while it draws this one) has its warnings and -v statistics still
// to report.
struct CachedModel {
  std::shared_ptr<const ImportedModel> model;
  bool reported = true;
};
struct ModelCache {
  std::map<std::string, CachedModel> models;  // model files drawn as previews
  SceneModelCache sceneModels;                // model files that scene files name
};

// Whether `input` names a model file (rather than a scene file or the built-in scene).
bool isModelInput(const std::string& input);
// The cache key of the model file the options name.
std::string modelCacheKey(const SceneOptions& o);
// Starts importing the model file the options name, as prepareScene would import it;
// `wallClockAllowance` as in ImportOptions (more than 1 when the import runs beside a render).
PendingImport startModelImport(const SceneOptions& o, double wallClockAllowance);

// Loads or builds the scene the options describe, validated (exit-2 errors name the option);
// warnings go to stderr, and with --verbose the model's statistics. `loadMs` is the time it took.
// With a cache, a model file already in it is not read again (nor its warnings printed twice).
// With `warnings`, warnings are collected there instead of printed.
// A model preview's tone map where --tone-map does not choose one: ACES for the pictures that are
// physically based (path traced, or lit by an environment: the studio of glTF's materials, or
// --environment), as the path tracer's; none, GL's clamp, for classic materials under the rig.
ToneMap previewToneMap(const Scene& scene);

Scene prepareScene(SceneOptions o, double* loadMs = nullptr, ModelCache* cache = nullptr,
                   std::vector<std::string>* warnings = nullptr);

// Peak resident memory of this process, MiB.
double peakMemoryMiB();

}  // namespace illum::cli

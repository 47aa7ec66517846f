#include "scene_options.h"

#include <illum/error.h>
#include <illum/framing.h>
#include <illum/captions.h>
#include <illum/import.h>
#include <illum/file_names.h>

#include "cli_values.h"
#include "stdin_input.h"

#include <nlohmann/json.hpp>
#include <sys/resource.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace illum::cli {
namespace {

namespace fs = std::filesystem;

// A warning goes into `warnings` when the caller collects them (a batch's JSON, the library), or to stderr.
void warn(std::vector<std::string>* warnings, const std::string& text) {
  if (warnings) warnings->push_back(text);
  else std::fprintf(stderr, "illum: warning: %s\n", text.c_str());
}

bool isSceneFile(const std::string& path) {
  return isSceneFileName(path);
}

Vec3 parseUp(const std::string& text) {
  if (text.size() == 2 && (text[0] == '+' || text[0] == '-')) {
    const Real s = text[0] == '+' ? 1 : -1;
    switch (std::toupper(static_cast<unsigned char>(text[1]))) {
      case 'X': return {s, 0, 0};
      case 'Y': return {0, s, 0};
      case 'Z': return {0, 0, s};
      default: break;
    }
  }
  badChoice("--up", text, {"+X", "-X", "+Y", "-Y", "+Z", "-Z"});
}

void parseResolution(const std::string& text, SceneOptions& o) {
  const auto comma = text.find(',');
  const auto dimension = [&](const std::string& part) {
    const Real v = parseNumber("--resolution", part, 1, 16384);
    if (v != std::floor(v)) throw InputError("--resolution: expected whole pixels W,H, got \"" + text + "\"");
    return int(v);
  };
  if (comma == std::string::npos) throw InputError("--resolution: expected W,H, got \"" + text + "\"");
  o.width = dimension(text.substr(0, comma));
  o.height = dimension(text.substr(comma + 1));
}

Real finitePositive(const char* option, double v) {
  if (!std::isfinite(Real(v)) || !(Real(v) > 0))
  {
    std::ostringstream text;
    text << option << ": expected a positive number, finite in the renderer's precision, got " << v;
    throw InputError(text.str());
  }
  return Real(v);
}

ImportOptions importOptions(const SceneOptions& o) {
  ImportOptions io;
  io.limits = o.limits;
  if (!o.normals.empty()) {
    if (o.normals == "auto") io.normals = NormalMode::Auto;
    else if (o.normals == "flat") io.normals = NormalMode::Flat;
    else if (o.normals == "smooth") io.normals = NormalMode::Smooth;
    else if (o.normals == "file") io.normals = NormalMode::File;
    else badChoice("--normals", o.normals, {"auto", "flat", "smooth", "file"});
  }
  if (o.creaseAngle) {
    if (!std::isfinite(*o.creaseAngle) || *o.creaseAngle < 0 || *o.creaseAngle > 180)
      throw InputError("--crease-angle: expected degrees in [0, 180]");
    io.creaseAngle = Real(*o.creaseAngle);
  }
  return io;
}

ViewOptions viewOptions(const SceneOptions& o) {
  ViewOptions v;
  if (!o.up.empty()) v.up = parseUp(o.up);
  const auto angle = [](const char* option, double degrees) {
    if (!std::isfinite(Real(degrees))) throw InputError(std::string(option) + ": expected a finite angle in degrees");
    return Real(degrees);
  };
  if (o.azimuth) v.azimuth = angle("--camera-azimuth-angle", *o.azimuth);
  if (o.elevation) v.elevation = angle("--camera-elevation-angle", *o.elevation);
  if (o.zoom) v.zoom = finitePositive("--camera-zoom-factor", *o.zoom);
  if (o.viewAngle) {
    v.viewAngle = Real(*o.viewAngle);
    if (!(v.viewAngle >= Real(0.01) && v.viewAngle <= Real(179.99)))
      throw InputError("--camera-view-angle: " + describe(CameraFault::ViewAngle));
  }
  v.orthographic = o.orthographic;
  return v;
}

// Options that place the camera explicitly apply to scene files too.
void applyExplicitCamera(const SceneOptions& o, Camera& cam) {
  if (!o.cameraPosition.empty()) cam.eye = parseVec3("--camera-position", o.cameraPosition);
  if (!o.cameraFocalPoint.empty()) cam.center = parseVec3("--camera-focal-point", o.cameraFocalPoint);
  if (!o.cameraViewUp.empty()) cam.up = parseVec3("--camera-view-up", o.cameraViewUp);
  if (o.viewAngle) cam.fovy = viewOptions(o).viewAngle;
  if (o.orthographic && cam.projection != Projection::Orthographic) {
    // Keep the picture's scale at the focal point: the height the perspective view shows there.
    cam.viewHeight = 2 * glm::length(cam.center - cam.eye) * std::tan(glm::radians(cam.fovy) / 2);
    cam.projection = Projection::Orthographic;
  }
}

// The camera the options made, checked by the rules scene cameras meet; the message names the
// options that set the faulty part (or says the file's framing did).
void validateCamera(const SceneOptions& o, const Camera& cam, Real aspect) {
  const CameraFault fault = cameraFault(cam, aspect);
  if (fault == CameraFault::None) return;
  std::vector<std::string> named;
  const auto name = [&](bool given, const char* option) {
    if (given) named.push_back(option);
  };
  switch (fault) {
    case CameraFault::ZeroUp:
    case CameraFault::UpParallel:
      name(!o.cameraViewUp.empty(), "--camera-view-up");
      if (named.empty()) name(!o.cameraPosition.empty(), "--camera-position");
      if (named.empty()) name(!o.cameraFocalPoint.empty(), "--camera-focal-point");
      break;
    case CameraFault::ViewAngle: name(o.viewAngle.has_value(), "--camera-view-angle"); break;
    default:
      name(!o.cameraPosition.empty(), "--camera-position");
      name(!o.cameraFocalPoint.empty(), "--camera-focal-point");
      name(o.zoom.has_value(), "--camera-zoom-factor");
      break;
  }
  std::string who;
  for (const std::string& n : named) who += (who.empty() ? "" : " with ") + n;
  throw InputError((who.empty() ? std::string("the camera") : who) + ": " + describe(fault));
}

// Options that cannot both be meant.
void rejectConflicts(const SceneOptions& o) {
  if (!o.resolution.empty() && (o.width || o.height))
    throw InputError("--resolution: give the size either as --resolution W,H or as --width and --height, not both");
  if (o.noBackground && !o.background.empty())
    throw InputError("--no-background: a transparent background has no colour; drop --background-color or --no-background");
  if (o.orthographic && o.viewAngle)
    throw InputError("--camera-view-angle: an orthographic camera has no view angle; drop it or --orthographic");
}

// --geometry-only, --color, --opacity: for files whose materials are black, invisible or beside the
// point. A colour replaces the file's colours (and the textures and vertex colours that carry them).
void overrideMaterials(const SceneOptions& o, std::vector<Object>& objects) {
  if (!o.geometryOnly && o.color.empty() && !o.opacity) return;
  std::optional<Color3> colour;
  if (!o.color.empty()) colour = parseColor("--color", o.color, true);
  if (o.opacity && !(*o.opacity >= 0 && *o.opacity <= 1)) throw InputError("--opacity: expected a number in [0, 1]");
  if (o.geometryOnly || colour) dropFileColours(objects);
  for (Object& obj : objects) {
    if (o.geometryOnly) obj.material = defaultModelMaterial();
    if (colour) {
      if (obj.material.physicallyBased) {
        PhysicalMaterial p = obj.material.physical;
        p.baseColor = *colour;
        glFromPhysical(obj.material, p);
      } else {
        obj.material.ambient = obj.material.diffuse = Color4(*colour, obj.material.diffuse.a);
      }
    }
    if (o.opacity) obj.material.diffuse.a = Real(*o.opacity);
  }
}

// The model the options name; one on standard input is read as --format says, its textures
// looked for in the working folder, and its messages name it "standard input".
// While the child reads the file, this process's worker threads are started (the render needs
// them next; the child, forked before, never runs them).
// So is the studio's image-based light, which a preview of physically based materials will ask
// for (made here, it costs no time: the child is still reading).
ImportedModel finishWhileWarming(PendingImport pending, bool mayUseStudio) {
  tbb::parallel_for(0, tbb::this_task_arena::max_concurrency(), [](int) {});
  if (mayUseStudio) prepareImageLight(studioEnvironment());
  return pending.finish();
}

ImportedModel importModelFor(const SceneOptions& o) {
  ImportOptions options = importOptions(o);
  const bool mayUseStudio = o.environment == "studio" || (o.environment.empty() && o.studioForPhysicallyBased);
  if (o.input != "-") return finishWhileWarming(startImport(o.input, options), mayUseStudio);
  options.format = o.stdinInput->format();
  options.companionDir = std::filesystem::current_path();
  try {
    ImportedModel model = importModel(o.stdinInput->path(), options);
    for (std::string& w : model.warnings) w = sayStandardInput(w, o.stdinInput->path());
    return model;
  } catch (const InputError& e) {
    throw InputError(sayStandardInput(e.what(), o.stdinInput->path()));
  }
}

// What a scene file says to bring a preview's objects (Object::source, for sceneJson): the model
// file by absolute path, its normals as the options make them, its colour textures as the preview
// reads them, and its own colours dropped where --color or --geometry-only drop them.
void setModelSources(const SceneOptions& o, bool srgbTextures, std::vector<Object>& objects) {
  if (o.input == "-") return;  // standard input is gone once read: no scene file can name it
  nlohmann::json mesh = {{"type", "file"}, {"path", std::filesystem::absolute(o.input).lexically_normal().string()}};
  if (!o.normals.empty()) mesh["normals"] = o.normals;
  if (o.creaseAngle) mesh["crease_angle"] = *o.creaseAngle;
  if (srgbTextures) mesh["colour_textures"] = "srgb";
  if (o.geometryOnly || !o.color.empty()) mesh["file_colours"] = false;
  const auto text = std::make_shared<const std::string>(mesh.dump());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    auto source = std::make_shared<ObjectSource>();
    source->mesh = text;
    source->part = int(i), source->parts = int(objects.size());
    source->fileMaterial = objects[i].material;
    objects[i].source = std::move(source);
  }
}

Scene modelScene(const SceneOptions& o, ImportedModel& model, bool srgbTextures) {
  Scene s;
  s.width = o.width.value_or(1000);
  s.height = o.height.value_or(600);
  s.background = {0.18, 0.19, 0.21, 1};
  ViewOptions view = viewOptions(o);
  if (o.up.empty() && model.upAxis) view.up = *model.upAxis;  // the file's (or its format's) up axis
  if (!o.cameraPosition.empty()) view.position = parseVec3("--camera-position", o.cameraPosition);
  if (!o.cameraFocalPoint.empty()) view.focalPoint = parseVec3("--camera-focal-point", o.cameraFocalPoint);
  if (!o.cameraViewUp.empty()) view.viewUp = parseVec3("--camera-view-up", o.cameraViewUp);
  if (view.viewUp && glm::length(*view.viewUp) == 0)
    throw InputError("--camera-view-up: " + describe(CameraFault::ZeroUp));
  s.camera = framePoints(worldPoints(model.objects), view, Real(s.width) / Real(s.height));
  if (view.viewUp && glm::length(glm::cross(s.camera.center - s.camera.eye, *view.viewUp)) <=
                         Real(1e-6) * glm::length(s.camera.center - s.camera.eye) * glm::length(*view.viewUp))
    throw InputError("--camera-view-up: " + describe(CameraFault::UpParallel));
  validateCamera(o, s.camera, Real(s.width) / Real(s.height));
  const Real intensity = o.lightIntensity ? Real(*o.lightIntensity) : Real(1);
  if (!std::isfinite(intensity) || intensity < 0) throw InputError("--light-intensity: expected a number ≥ 0");
  s.lights = cameraLightRig(s.camera, intensity);
  s.lightModel.ambient = cameraRigAmbient(intensity);
  // Flipped faces are common in the wild; light both sides so they are never black.
  s.lightModel.twoSided = true;
  // Glass and other translucent materials (MTL d, glTF alpha) show what is behind them.
  s.blend = true;
  s.objects = std::move(model.objects);
  setModelSources(o, srgbTextures, s.objects);
  if (o.input != "-") s.files.push_back(o.input);
  s.files.insert(s.files.end(), model.files.begin(), model.files.end());
  overrideMaterials(o, s.objects);
  return s;
}

void rejectModelOnlyOptions(const SceneOptions& o) {
  const auto reject = [](bool given, const char* name) {
    if (given) throw InputError(std::string(name) + ": applies to model files, not scene files (the scene sets it)");
  };
  reject(!o.up.empty(), "--up");
  reject(!o.color.empty(), "--color");
  reject(o.opacity.has_value(), "--opacity");
  reject(o.geometryOnly, "--geometry-only");
  reject(o.azimuth.has_value(), "--camera-azimuth-angle");
  reject(o.elevation.has_value(), "--camera-elevation-angle");
  reject(o.zoom.has_value(), "--camera-zoom-factor");
  reject(o.lightIntensity.has_value(), "--light-intensity");
  reject(!o.normals.empty(), "--normals");
  reject(o.creaseAngle.has_value(), "--crease-angle");
}

// The ray tracers trace surfaces: points and lines, which have none, are the rasterizer's. A scene
// of nothing else is refused; one that has surfaces too is drawn without them, with a warning.
void rejectTracedPointsAndLines(const Scene& scene, std::vector<std::string>* warnings) {
  if (scene.renderer == RendererKind::Raster) return;
  const auto hasPrimitives = [](const Object& o) { return o.mesh->hasPointsOrLines(); };
  if (std::none_of(scene.objects.begin(), scene.objects.end(), hasPrimitives)) return;
  const std::string renderer(toString(scene.renderer));
  if (std::all_of(scene.objects.begin(), scene.objects.end(), [](const Object& o) { return o.mesh->triangleCount() == 0; }))
    throw InputError("the " + renderer + " renderer: the scene holds only points and lines, which the rasterizer draws; " +
                     "the ray tracers trace surfaces (use --renderer raster)");
  const std::string w = "the ray tracers trace surfaces: the scene's points and lines are left out (the rasterizer draws them)";
  warn(warnings, w);
}

}  // namespace

bool isModelInput(const std::string& input) { return !input.empty() && input != "-" && !isSceneFile(input); }

std::string modelCacheKey(const SceneOptions& o) {
  return o.input + "\n" + o.normals + "\n" + (o.creaseAngle ? std::to_string(*o.creaseAngle) : "");
}

PendingImport startModelImport(const SceneOptions& o, double wallClockAllowance) {
  ImportOptions options = importOptions(o);
  options.wallClockAllowance = wallClockAllowance;
  return startImport(o.input, options);
}

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

ThreadLimit::ThreadLimit(const SceneOptions& o)
    : threads_(o.threads > 0 ? o.threads : tbb::info::default_concurrency()),
      control_(std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                     std::size_t(threads_))) {}

void addSceneOptions(CLI::App& cmd, SceneOptions& o, std::vector<std::string>* inputs) {
  if (inputs)
    cmd.add_option("inputs", *inputs,
                   "Scene (.json) or model files (or file:// URIs), folders, patterns ('scans/**/*.ply'), - for "
                   "standard input; none renders the built-in scene")
        ->transform(fileUriInput());
  else
    cmd.add_option("input", o.input, "Scene (.json) or model file (or file:// URI); none renders the built-in scene")
        ->transform(fileUriInput());
  cmd.add_option("--width", o.width, "Image width in pixels")->check(wholeRange(1, 16384));
  cmd.add_option("--height", o.height, "Image height in pixels")->check(wholeRange(1, 16384));
  cmd.add_option("--resolution", o.resolution, "Image size W,H (models: 1000,600)");
  cmd.add_option("--model", o.model, "Lighting model: " + lightingModelNames());
  cmd.add_option("--shading", o.shading, "Shading frequency: flat, gouraud or phong");
  cmd.add_option("--convention", o.convention,
                 "Compute the equation as GL does (gl) or as a lecture note does: note-shader (seed 001's shader: "
                 "ambient + (diffuse + specular) x Ld·max(N·L,0)), note-half-sum (H = (L+V)/2, not normalised) or "
                 "note-world-space (seed 004: V towards the camera's position)");
  cmd.add_option("--renderer", o.renderer, "raster (default), whitted (ray tracing, 1980), hall (1983) or path (path tracing, 1986)");
  cmd.add_flag("--no-shadows", o.noShadows, "Ray tracers: no shadow rays");
  cmd.add_option("--samples", o.samples,
                 "Rasterizer: multisamples per pixel, 1, 4, 8 or 16 [scenes 1, models 8]; ray tracers: rays per pixel [1; path: 64]")
      ->check(wholeRange(1, kMaxSamples));
  cmd.add_option("--max-depth", o.maxDepth, "Ray tracers: reflected and refracted bounces followed [5]")
      ->check(wholeRange(0, kMaxRayDepth));
  cmd.add_option("--seed", o.seed,
                 "Ray tracers: which of the equally good pictures their samples give (the same seed, the same bytes) "
                 "[scenes: their \"seed\"; 0]")
      ->check(wholeRange(0, std::numeric_limits<int>::max()));
  cmd.add_option("--tone-map", o.toneMap, "Radiance above 1: none (clamp; default), reinhard or aces");
  cmd.add_option("--encoding", o.encoding, "Bytes of the picture: linear (GL's; default) or srgb");
  cmd.add_option("--background-color,--background", o.background, "Background colour R,G,B or #rrggbb");
  cmd.add_flag("--no-background", o.noBackground, "Transparent background (alpha 0)");
  cmd.add_flag("--edges", o.edges, "Draw every triangle's edges over the surfaces (rasterizer)");
  cmd.add_flag("--grid", o.grid, "Draw a ground grid under the scene (rasterizer)");
  cmd.add_flag("--axes", o.axes, "Draw the world's axes in the lower left corner");
  cmd.add_option("--point-size", o.pointSize, "Pixel size of the points of point clouds [scenes 1 (GL's), models 3]")
      ->check(finiteRange(double(kMinPrimitiveSize), double(kMaxPrimitiveSize)));
  cmd.add_option("--line-width", o.lineWidth, "Pixel width of the lines of line sets [1]")
      ->check(finiteRange(double(kMinPrimitiveSize), double(kMaxPrimitiveSize)));
  cmd.add_flag("--ambient-occlusion", o.ambientOcclusion, "Scale the ambient term by ray-traced occlusion (rasterizer)");
  cmd.add_flag("--no-ambient-occlusion", o.noAmbientOcclusion, "No ambient occlusion, even where the scene file asks for it");
  cmd.add_flag("--denoise", o.denoise,
               "Path tracer: filter the picture with the feature-guided denoiser [models: on; scenes: their \"denoise\"]");
  cmd.add_flag("--no-denoise", o.noDenoise, "Path tracer: no denoiser, even where the scene file or a preview would use it");
  cmd.add_option("--environment", o.environment,
                 "Light every renderer by an environment: a latitude-longitude Radiance .hdr or OpenEXR .exr map, "
                 "studio (illum's built-in), or none [models with physically based materials: studio, for those materials alone]");
  cmd.add_option("--environment-rotation", o.environmentRotation, "Turn the environment about the up axis, degrees [0]")
      ->check(finiteRange(-360, 360));
  cmd.add_option("--environment-intensity", o.environmentIntensity, "Scale the environment's radiance [1]")
      ->check(finiteRange(0, 1e6));
  cmd.add_option("--environment-background", o.environmentBackground,
                 "Show the environment behind the scene: sharp, blurred or none [--environment FILE: sharp; else none]");
  cmd.add_option("--up", o.up, "Model files: the up axis, +Y, -Y, +Z, -Z, +X or -X [the file's: +Z for STL and 3DS, FBX's metadata, else +Y]");
  cmd.add_option("--color", o.color, "Model files: draw every surface in this colour R,G,B or #rrggbb");
  cmd.add_option("--opacity", o.opacity, "Model files: every surface's opacity, 0 to 1");
  cmd.add_flag("--geometry-only", o.geometryOnly, "Model files: ignore the file's materials, textures and vertex colours");
  cmd.add_option("--camera-position", o.cameraPosition, "Camera position x,y,z");
  cmd.add_option("--camera-focal-point", o.cameraFocalPoint, "Point the camera looks at x,y,z (models: the bounds' centre)");
  cmd.add_option("--camera-view-up", o.cameraViewUp, "Camera up direction x,y,z (models: the up axis)");
  cmd.add_option("--camera-view-angle", o.viewAngle, "Vertical view angle in degrees (models: 30)");
  cmd.add_option("--camera-azimuth-angle", o.azimuth, "Model files: turn the view about the up axis, degrees [35]");
  cmd.add_option("--camera-elevation-angle", o.elevation, "Model files: raise the view towards the up axis, degrees [25]");
  cmd.add_option("--camera-zoom-factor", o.zoom, "Model files: zoom in (> 1) or out (< 1) from the framing [1]");
  cmd.add_flag("--orthographic", o.orthographic, "Orthographic projection");
  cmd.add_option("--light-intensity", o.lightIntensity, "Model files: scale the default light rig [1]");
  cmd.add_option("--normals", o.normals, "Model files: auto (default), flat, smooth or file");
  cmd.add_option("--crease-angle", o.creaseAngle, "Model files: generated normals stay sharp above this angle [40]");
  cmd.add_option("--max-triangles", o.limits.maxTriangles, "Refuse scenes and models of more triangles [20000000]")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--max-pixels", o.limits.maxPixels, "Refuse images and textures of more pixels [67108864]")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--max-memory", o.limits.maxMemoryMiB,
                  "MiB the model importer may use [512 + 32 × the file's size]")->check(CLI::PositiveNumber);
  cmd.add_option("--max-time", o.limits.maxSeconds, "Seconds the model importer may take [1.5 + 0.5 per MiB]")
      ->check(finiteRange(0.001, 1e6));
  cmd.add_option_function<std::uint64_t>(
         "--max-scene-size", [&o](std::uint64_t mib) { o.limits.maxSceneBytes = mib << 20; },
         "Refuse scene files (and scenes on standard input) of more MiB [64]; their JSON values are limited in proportion")
      ->check(wholeRange(1, 1 << 20));
  cmd.add_option_function<std::uint64_t>(
         "--max-stdin-size", [&o](std::uint64_t mib) { o.limits.maxStdinBytes = mib << 20; },
         "Refuse a model on standard input of more MiB (it is held in memory) [256]")
      ->check(wholeRange(1, 1 << 20));
  cmd.add_option("--max-fill", o.limits.maxFill,
                 "Refuse pictures whose points and lines would cover more pixels, summed over samples [1000000000]")
      ->check(wholeRange(1, 1'000'000'000'000'000));
  cmd.add_option("--max-json-depth", o.limits.maxJsonDepth, "Refuse scene files whose arrays and objects nest deeper [64]")
      ->check(wholeRange(1, 10000));
  cmd.add_option("--threads", o.threads, "Worker threads (default: every core); the picture is the same for any count")
      ->check(wholeRange(1, 1024));
  cmd.add_flag("-v,--verbose", o.verbose, "Print model statistics, bounds, times and peak memory on stderr");
}

// The environment the options ask for, and a model preview's default: illum's studio lights its
// physically based materials (metals need surroundings to reflect), classic ones keep their look.
void applyEnvironmentOptions(const SceneOptions& o, Scene& scene, bool preview) {
  EnvironmentUse& use = scene.environment;
  const auto usePhysical = [&] {
    return std::any_of(scene.objects.begin(), scene.objects.end(),
                       [&](const Object& object) { return modelOf(object.material, scene.model) == LightingModel::CookTorrance; });
  };
  if (o.environment == "none") {
    scene.rayTracing.environmentMap.reset();
    scene.rayTracing.environment = Color3(0);
    use = {};
  } else if (o.environment == "studio") {
    scene.rayTracing.environmentMap = studioEnvironment();
    scene.rayTracing.environment = Color3(1);
    use.studio = true;
    use.lighting = EnvironmentLighting::All;
  } else if (!o.environment.empty()) {
    try {
      scene.rayTracing.environmentMap = EnvironmentMapFile::open(o.environment, o.limits);
    } catch (const InputError& e) {
      throw InputError(std::string("--environment: expected a readable Radiance .hdr or OpenEXR .exr image, \"studio\" or \"none\"; ") +
                       e.what());
    }
    scene.files.push_back(o.environment);
    scene.rayTracing.environment = Color3(1);
    use.studio = false;
    use.lighting = EnvironmentLighting::All;
    use.background = EnvironmentBackground::Sharp;
  } else if (preview && o.studioForPhysicallyBased && usePhysical()) {
    scene.rayTracing.environmentMap = studioEnvironment();
    scene.rayTracing.environment = Color3(1);
    use.studio = true;
    use.lighting = EnvironmentLighting::PhysicallyBased;
  }
  if (o.environmentRotation) use.rotation = Real(*o.environmentRotation);
  if (o.environmentIntensity) scene.rayTracing.environment = Color3(Real(*o.environmentIntensity));
  if (!o.environmentBackground.empty()) {
    const auto background = parseEnvironmentBackground(o.environmentBackground);
    if (!background) badChoice("--environment-background", o.environmentBackground, {"sharp", "blurred", "none"});
    use.background = *background;
  }
}

ToneMap previewToneMap(const Scene& scene) {
  // The path tracer's radiance has no upper bound; an environment's sky and sun reflect above 1 in
  // the rasterizer's too: both through ACES, so that the renderers show one look.
  const bool physical = scene.renderer == RendererKind::Path || scene.environment.lighting != EnvironmentLighting::None;
  return physical ? ToneMap::Aces : ToneMap::None;
}

Scene prepareScene(SceneOptions o, double* loadMs, ModelCache* cache, std::vector<std::string>* warnings) {
  const auto start = std::chrono::steady_clock::now();
  rejectConflicts(o);
  if (!o.resolution.empty()) parseResolution(o.resolution, o);
  std::optional<LightingModel> lightingModel;
  std::optional<Shading> shading;
  if (!o.model.empty()) {
    lightingModel = parseLightingModel(o.model);
    if (!lightingModel) badChoice("--model", o.model, lightingModelChoices());
  }
  std::optional<RendererKind> renderer;
  if (!o.renderer.empty()) {
    renderer = parseRendererKind(o.renderer);
    if (!renderer) badChoice("--renderer", o.renderer, {"raster", "whitted", "hall", "path"});
  }
  std::optional<ToneMap> toneMap;
  std::optional<Encoding> encoding;
  if (!o.toneMap.empty() && !(toneMap = parseToneMap(o.toneMap)))
    badChoice("--tone-map", o.toneMap, {"none", "reinhard", "aces"});
  if (!o.encoding.empty() && !(encoding = parseEncoding(o.encoding)))
    badChoice("--encoding", o.encoding, {"linear", "srgb"});
  if (!o.shading.empty()) {
    shading = parseShading(o.shading);
    if (!shading) badChoice("--shading", o.shading, {"flat", "gouraud", "phong"});
  }
  std::optional<Convention> convention;
  if (!o.convention.empty() && !(convention = parseConvention(o.convention)))
    badChoice("--convention", o.convention, conventionChoices());
  Scene scene;
  std::optional<ImportedModel> model;
  const StdinInput* piped = o.input == "-" ? o.stdinInput.get() : nullptr;
  if (o.input == "-" && !piped) throw Error("standard input was not read");
  if (o.input.empty() || (piped ? piped->isScene() : isSceneFile(o.input))) {
    rejectModelOnlyOptions(o);
    // The built-in scene's captions name the model and shading it is drawn with.
    scene = o.memoryScene ? parseScene(o.memoryScene->text, "the scene given", o.memoryScene->baseDir, o.limits,
                                       cache ? &cache->sceneModels : nullptr)
            : o.input.empty() ? defaultScene(lightingModel.value_or(LightingModel::BlinnPhong),
                                           shading.value_or(Shading::Phong), renderer.value_or(RendererKind::Raster))
            : piped ? parseScene(piped->text(), "standard input", std::filesystem::current_path(), o.limits,
                                 cache ? &cache->sceneModels : nullptr)
                    : loadSceneFile(o.input, o.limits, cache ? &cache->sceneModels : nullptr);
    const int designedWidth = scene.width, designedHeight = scene.height;
    if (o.width) scene.width = *o.width;
    if (o.height) scene.height = *o.height;
    // Captions are made for the scene's own size: they move and scale with the picture, and a
    // picture too small to read them (a thumbnail, a comparison sheet's panel) goes without.
    if (scene.width != designedWidth || scene.height != designedHeight) {
      const Vec2 scale(Real(scene.width) / Real(designedWidth), Real(scene.height) / Real(designedHeight));
      for (Label& label : scene.labels) {
        if (label.pixel) *label.pixel *= scale;
        label.size *= std::min(scale.x, scale.y);
      }
      std::erase_if(scene.labels, [](const Label& label) { return label.size < kReadableCaption; });
    }
    applyExplicitCamera(o, scene.camera);
    validateCamera(o, scene.camera, Real(scene.width) / Real(scene.height));
  } else {
    const std::string key = modelCacheKey(o);
    CachedModel entry;
    if (cache && cache->models.count(key)) entry = cache->models.at(key);
    else entry = {std::make_shared<const ImportedModel>(importModelFor(o)), false};
    const bool report = !entry.reported;
    entry.reported = true;
    if (cache) cache->models[key] = entry;
    model = *entry.model;
    if (report)
      for (const std::string& w : model->warnings) {
        warn(warnings, w);
      }
    if (o.verbose && report) {
      std::string primitives = withThousands(model->triangleCount) + " triangles";
      if (model->lineCount) primitives += ", " + withThousands(model->lineCount) + " lines";
      if (model->pointCount) primitives += ", " + withThousands(model->pointCount) + " points";
      std::fprintf(stderr, "illum: %s: %s vertices, %s, %zu materials, %zu textures\n",
                   o.input == "-" ? "standard input" : o.input.c_str(),
                   withThousands(model->vertexCount).c_str(), primitives.c_str(), model->materialCount, model->textureCount);
      const Vec3 &lo = model->boundsMin, &hi = model->boundsMax;
      std::fprintf(stderr, "illum: bounds [%g, %g, %g] .. [%g, %g, %g]\n", double(lo.x), double(lo.y), double(lo.z),
                   double(hi.x), double(hi.y), double(hi.z));
    }
    scene = modelScene(o, *model, encoding.value_or(Encoding::Srgb) == Encoding::Srgb);
  }
  scene.maxFill = o.limits.maxFill;
  if (std::uint64_t(scene.width) * std::uint64_t(scene.height) > o.limits.maxPixels)
    throw InputError("the image would be " + std::to_string(scene.width) + "×" + std::to_string(scene.height) + " = " +
                     withThousands(std::uint64_t(scene.width) * std::uint64_t(scene.height)) +
                     " pixels, more than the limit of " + withThousands(o.limits.maxPixels) + " (raise it with --max-pixels)");
  if (lightingModel) {
    // --model overrides every material's own model too.
    scene.model = *lightingModel;
    for (Object& object : scene.objects) object.material.model.reset();
  }
  if (shading) scene.shading = *shading;
  // Triangles smaller than pixels: Gouraud's interpolated colours and Phong's per-pixel lighting
  // agree to within what the eye sees (2CylinderEngine's 121k triangles at 256²: PSNR 56 dB, the
  // largest difference 29 of 255 at a few silhouette pixels), and a record of lit colours is
  // smaller and needs no shading per pixel.
  if (model && !shading && o.denseMeshesPerVertex &&
      model->triangleCount > std::uint64_t(scene.width) * std::uint64_t(scene.height))
    scene.shading = Shading::Gouraud;
  if (renderer) scene.renderer = *renderer;
  if (convention) scene.lightModel.convention = *convention;
  if (scene.lightModel.convention != Convention::GL && scene.renderer == RendererKind::Path)
    warn(warnings, "convention " + std::string(toString(scene.lightModel.convention)) +
                       ": the path tracer's light has no lecture note's convention; it is drawn as it is");
  if (model) {
    // Previews of model files are for screens: sRGB, unless --encoding says otherwise (their tone
    // map: previewToneMap, once the environment is known). Scene files stay as GL writes.
    scene.display.encoding = encoding.value_or(Encoding::Srgb);
    if (scene.display.encoding == Encoding::Srgb) {
      // The rig in linear light, and the grey of the background as it should appear.
      const Real intensity = o.lightIntensity ? Real(*o.lightIntensity) : Real(1);
      scene.lights = cameraLightRig(scene.camera, intensity, Encoding::Srgb);
      scene.lightModel.ambient = cameraRigAmbient(intensity, Encoding::Srgb);
      for (int c = 0; c < 3; ++c) scene.background[c] = srgbDecoded(scene.background[c]);
    }
  }
  if (toneMap) scene.display.toneMap = *toneMap;
  if (encoding) scene.display.encoding = *encoding;
  // Colour textures are stored sRGB-encoded (glTF says so of base colour and emissive textures;
  // image files in general are): an sRGB picture decodes them to the linear values it lights.
  if (model && scene.display.encoding == Encoding::Srgb) decodeColourTextures(scene.objects);
  if (o.noShadows) scene.rayTracing.shadows = false;
  if (o.samples) {
    // Rays per pixel for the ray tracers; the rasterizer's multisample count.
    scene.rayTracing.samples = *o.samples;
    int count = 16;
    while (count > *o.samples) count /= count == 4 ? 4 : 2;  // the largest of 16, 8, 4, 1 at most asked
    scene.multisample = count;
    if (count != *o.samples && scene.renderer == RendererKind::Raster)
      warn(warnings, "--samples: the rasterizer takes 1, 4, 8 or 16 samples per pixel; using " + std::to_string(count));
  } else if (model && scene.renderer == RendererKind::Raster) {
    scene.multisample = 8;  // previews are anti-aliased
  }
  if (o.maxDepth) scene.rayTracing.maxDepth = *o.maxDepth;
  if (o.seed) scene.rayTracing.seed = std::uint32_t(*o.seed);
  if (!o.background.empty()) {
    // The background is the colour the picture shows: in an sRGB picture, the linear value that
    // encodes to it.
    scene.background = Color4(parseColor("--background-color", o.background, true), 1);
    if (scene.display.encoding == Encoding::Srgb)
      for (int c = 0; c < 3; ++c) scene.background[c] = srgbDecoded(scene.background[c]);
  }
  if (o.noBackground) scene.background.a = 0;
  scene.overlays.edges = scene.overlays.edges || o.edges;
  scene.overlays.grid = scene.overlays.grid || o.grid;
  scene.overlays.axes = scene.overlays.axes || o.axes;
  if (o.ambientOcclusion && o.noAmbientOcclusion)
    throw InputError("--ambient-occlusion and --no-ambient-occlusion: expected one of them, not both");
  // Not on by default, even for previews: 8 rays a pixel cost more than an 8-sample preview's whole time
  // (docs/models.md), more than the third that would make it free enough.
  if (o.ambientOcclusion || o.noAmbientOcclusion) scene.ambientOcclusion.enabled = o.ambientOcclusion;
  if (o.ambientOcclusion && scene.renderer != RendererKind::Raster)
    throw InputError(scene.renderer == RendererKind::Path
                         ? "--ambient-occlusion: the path tracer computes the light that ambient occlusion approximates"
                         : "--ambient-occlusion: the rasterizer's; the ray tracers keep the classic ambient term");
  if (model && scene.ambientOcclusion.enabled) {
    // A preview's ambient is faint: occlusion shades the rig's fill light instead, made light
    // from everywhere (framing.h), so that crevices darken.
    const Real intensity = o.lightIntensity ? Real(*o.lightIntensity) : Real(1);
    const Encoding rig = scene.display.encoding == Encoding::Srgb ? Encoding::Srgb : Encoding::Linear;
    scene.lights = cameraLightRig(scene.camera, intensity, rig, true);
    scene.lightModel.ambient = cameraRigAmbient(intensity, rig, true);
  }
  applyEnvironmentOptions(o, scene, model.has_value());
  if (model && !toneMap) scene.display.toneMap = previewToneMap(scene);
  if (o.denoise && o.noDenoise) throw InputError("--denoise and --no-denoise: expected one of them, not both");
  if (model && scene.renderer == RendererKind::Path) scene.rayTracing.denoise = true;  // previews look clean
  if (o.denoise || o.noDenoise) scene.rayTracing.denoise = o.denoise;
  if (o.denoise && scene.renderer != RendererKind::Path)
    throw InputError("--denoise: the path tracer's; the rasterizer and the Whitted and Hall tracers draw no noise "
                     "to remove (use --renderer path)");
  if (o.seed && scene.renderer == RendererKind::Raster)
    throw InputError("--seed: the ray tracers'; the rasterizer takes no random samples (use --renderer whitted, hall "
                     "or path)");
  if (model) scene.pointSize = 3;  // a point cloud's 1-pixel points are hard to see in a preview
  if (o.pointSize) scene.pointSize = Real(*o.pointSize);
  if (o.lineWidth) scene.lineWidth = Real(*o.lineWidth);
  rejectTracedPointsAndLines(scene, warnings);
  if ((scene.overlays.edges || scene.overlays.grid) && scene.renderer != RendererKind::Raster)
    throw InputError(std::string(scene.overlays.edges ? "--edges" : "--grid") +
                     ": the rasterizer draws edges and grids; the ray tracers have no depth buffer to hide them with");

  if (o.verbose && !scene.objects.empty()) {
    // Which model lights what: a material's own model (glTF's physically based ones) or the scene's.
    std::map<std::string, std::size_t> objectsByModel;
    for (const Object& object : scene.objects) {
      const Material& m = object.material;
      ++objectsByModel[std::string(toString(modelOf(m, scene.model))) + (m.physicallyBased ? ", physically based" : "")];
    }
    std::string list;
    for (const auto& [name, count] : objectsByModel)
      list += (list.empty() ? "" : "; ") + std::to_string(count) + (count == 1 ? " object " : " objects ") + name;
    std::fprintf(stderr, "illum: lighting models: %s\n", list.c_str());
  }
  if (loadMs) *loadMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return scene;
}

}  // namespace illum::cli

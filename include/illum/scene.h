// A scene as the renderers see it: image settings, camera, lights and objects in world space.
// Its JSON form, version 1, is documented in docs/scene-format.md.
#pragma once

#include <illum/display.h>
#include <illum/lighting.h>
#include <illum/environment.h>
#include <illum/limits.h>
#include <illum/mesh.h>
#include <illum/texture.h>

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace illum {

enum class Projection { Perspective, Orthographic };

// gluLookAt + gluPerspective (or glOrtho with a given view height); aspect = width / height.
struct Camera {
  Vec3 eye{0, 0, 5};
  Vec3 center{0, 0, 0};
  Vec3 up{0, 1, 0};
  Real fovy = 45;  // degrees
  Real near = Real(0.1);
  Real far = 100;
  Projection projection = Projection::Perspective;
  Real viewHeight = 2;  // world units, orthographic only

  Mat4 viewFromWorld() const;
  Mat4 clipFromView(Real aspect) const;
};

// What makes a camera unusable, if anything: which part is wrong and what was expected. Eye and
// centre apart, a non-zero up not parallel to the view, a view angle a float can project with
// (at least 0.01°), and transforms that stay finite in the renderer's precision.
enum class CameraFault { None, SamePoint, ZeroUp, UpParallel, ViewAngle, TooLarge };
CameraFault cameraFault(const Camera& camera, Real aspect);
// The fault in words ("expected ..."), to follow the name of whatever set the camera.
std::string describe(CameraFault fault);

// What a surface does with rays beyond the local equation: the ray tracers' material keys
// (docs/scene-format.md). The rasterizer ignores them.
struct SurfaceOptics {
  Color3 reflective{0};    // k_r: the mirror-reflected ray's weight (Hall: times F_r)
  Color3 transmissive{0};  // k_t: the refracted ray's weight (Hall: times F_t = 1 − F_r)
  Real ior = Real(1.5);    // index of refraction of the inside of a closed mesh (outside: 1)
  std::optional<Real> transmissionShininess;  // Hall's n' of transmitted highlights; unset: shininess
  Color3 filter{1};        // Hall: fraction of light kept per unit distance travelled inside

  bool reflects() const { return reflective != Color3(0); }
  bool transmits() const { return transmissive != Color3(0); }
};

// glTF's other texture maps (§3.9 of the glTF 2.0 spec), read where the mesh has uvs, by per-pixel
// shading and the ray tracers (flat and Gouraud shading light vertices, which have no texels).
struct MaterialMaps {
  // Roughness × G, metallic × B (linear values), for the cook-torrance model.
  std::shared_ptr<const Texture> metallicRoughness;
  // A tangent-space normal (RGB = XYZ·0.5 + 0.5, +Y towards the image's top), for every model.
  std::shared_ptr<const Texture> normal;
  Real normalScale = 1;  // the map's X and Y are scaled by this (glTF's normalTexture.scale)
  // The emission colour × RGB, for every model.
  std::shared_ptr<const Texture> emissive;

  bool any() const { return metallicRoughness || normal || emissive; }
};

// Where an object came from, in a scene file's terms, so that a scene can be written back as one
// (sceneJson): the "mesh" value that made it (a model file's path absolute), the object's
// "transform", and for a model file, which of the file's mesh instances it is and the material
// the file gave that instance (an unchanged one is left for the file to give again).
struct ObjectSource {
  std::shared_ptr<const std::string> mesh;  // JSON
  Mat4 transform{1};
  int part = 0, parts = 1;
  std::optional<Material> fileMaterial;  // a model file's instance only
};

struct Object {
  std::shared_ptr<const Mesh> mesh;
  Mat4 worldFromObject{1};
  Material material;
  // Modulates the lit colour (GL_MODULATE) where the mesh has uvs.
  std::shared_ptr<const Texture> diffuseTexture;
  // Where the mesh has vertex colours they replace the material's ambient and diffuse colours
  // (GL_COLOR_MATERIAL with GL_AMBIENT_AND_DIFFUSE).
  SurfaceOptics optics;  // mirror and glass, for the ray tracers
  MaterialMaps maps;     // glTF's metallic-roughness, normal and emissive textures
  // What made it, when it came from a scene file, a model file or the built-in scene.
  std::shared_ptr<const ObjectSource> source;
};

// Text drawn over the finished picture, centred on a point of the world or of the image, so that a
// picture can say what it shows. Labels are not lit and not hidden by geometry.
struct Label {
  std::string text;
  std::optional<Vec3> position;  // world space: the text is centred just below its projection
  std::optional<Vec2> pixel;     // or image pixels from the top-left: the centre of the baseline
  Color3 color{1, 1, 1};
  Real size = 16;  // pixel height
};

// Drawings over the picture that viewers of CAD models and scans expect: every triangle's edges,
// a ground grid under the scene (both hidden where the surfaces hide them, rasterizer only), and
// a gizmo of the world's axes in the lower left corner (every renderer).
// Ambient occlusion: the ambient term scaled, pixel by pixel, by the fraction of the hemisphere
// (cosine-weighted) that `rays` rays find open within `distance` (unset: a fifth of the scene's
// diagonal). The rasterizer's; deterministic.
struct AmbientOcclusion {
  bool enabled = false;
  int rays = 8;
  std::optional<Real> distance;
};

struct Overlays {
  bool edges = false;
  bool grid = false;
  bool axes = false;
  bool any() const { return edges || grid || axes; }
};

// Which renderer draws the scene: the rasterizer (OpenGL's pipeline), a ray tracer, Whitted's
// (1980) or Hall and Greenberg's (1983), on the same scene, lights and local equation, or a path
// tracer solving Kajiya's rendering equation (1986) for the same lights and materials.
enum class RendererKind { Raster, Whitted, Hall, Path };
std::string_view toString(RendererKind renderer);
std::optional<RendererKind> parseRendererKind(std::string_view name);

// The ray tracers' settings (the rasterizer ignores them). Depth and samples are bounded so that
// no scene can ask for unbounded work.
constexpr int kMaxRayDepth = 16;
constexpr int kMaxSamples = 16384;  // a path-traced reference takes thousands
struct RayTracing {
  int maxDepth = 5;      // reflected and refracted rays followed this many bounces deep
  bool shadows = true;   // shadow rays towards every light
  std::optional<int> samples;  // rays per pixel: 1 through the centre, more jittered (as `seed` says)
  // Which of the equally good pictures the samples give: each seed scrambles every pixel's sample
  // points and paths another way (the same seed, the same bytes); 0 is the picture of every earlier
  // version. Renders of several seeds tell a picture's noise from its bias.
  std::uint32_t seed = 0;
  Color3 environment{0};       // the path tracer: radiance arriving from everywhere rays escape to
  // ... or from an equirectangular .hdr image, times `environment` (which is then 1 unless given)
  std::shared_ptr<const EnvironmentMapFile> environmentMap;
  // The path tracer: its picture filtered by the feature-guided À-trous denoiser (the first
  // non-specular hit's albedo and normal guide it). Off for scene files unless they say so.
  bool denoise = false;
};

// What the environment (RayTracing::environment and environmentMap) does besides lighting the
// path tracer's escaping paths: image-based lighting in the rasterizer and the Whitted and Hall
// tracers ("environment_lighting": physically based materials only, or classic ones too, where it
// takes the global ambient's place), turned about +Y ("environment_rotation", degrees, every
// renderer), and shown behind the scene ("environment_background"; the scene's background colour
// otherwise).
enum class EnvironmentLighting { None, PhysicallyBased, All };
enum class EnvironmentBackground { None, Sharp, Blurred };
std::string_view toString(EnvironmentLighting lighting);
std::string_view toString(EnvironmentBackground background);
std::optional<EnvironmentLighting> parseEnvironmentLighting(std::string_view name);
std::optional<EnvironmentBackground> parseEnvironmentBackground(std::string_view name);
// illum's studio: a neutral, procedural environment (a sky gradient over a darker floor, a soft
// key, a fill and a rim), made once per process. Model previews light physically based materials
// with it, so that metals have surroundings to reflect.
std::shared_ptr<const EnvironmentMapFile> studioEnvironment();
// Computes the image-based light of `map` ahead of the first frame that needs it (a process that
// waits for a model file to be read makes the studio's then), kept as every frame would keep it.
void prepareImageLight(const std::shared_ptr<const EnvironmentMapFile>& map);
struct EnvironmentUse {
  EnvironmentLighting lighting = EnvironmentLighting::None;
  Real rotation = 0;
  EnvironmentBackground background = EnvironmentBackground::None;
  // The environment map is illum's built-in studio ("studio_environment"), not a file.
  bool studio = false;
};

// The multisample counts the rasterizer takes.
constexpr bool isMultisampleCount(int n) { return n == 1 || n == 4 || n == 8 || n == 16; }

// glPointSize and glLineWidth bounds, in pixels.
constexpr Real kMinPrimitiveSize = Real(0.1);
constexpr Real kMaxPrimitiveSize = 256;

struct Scene;
// Rays per pixel: as the scene says, else 1 (64 for the path tracer, which needs many).
int samplesPerPixel(const Scene& scene);

struct Scene {
  RendererKind renderer = RendererKind::Raster;
  RayTracing rayTracing;
  EnvironmentUse environment;
  int width = 640;
  int height = 480;
  Color4 background{0, 0, 0, 1};
  LightingModel model = LightingModel::BlinnPhong;
  Shading shading = Shading::Phong;
  Camera camera;
  LightModel lightModel;
  std::vector<Light> lights = std::vector<Light>(1);  // one light with the defaults
  std::vector<Object> objects;
  std::vector<Label> labels;
  // GL_BLEND with glBlendFuncSeparate(SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ONE, ONE_MINUS_SRC_ALPHA):
  // translucent objects are drawn after the opaque ones, farthest first. Off, like GL, by default.
  bool blend = false;
  // How linear values become bytes (display.h): linear and unmapped by default, as GL writes them.
  Display display;
  // The rasterizer's samples per pixel: 1 (GL's single sample), or 4, 8 or 16 for multisampling
  // (coverage and depth per sample, each pixel shaded once per triangle at its centre, resolved
  // with premultiplied alpha). The ray tracers take rayTracing.samples instead.
  int multisample = 1;
  // glPointSize and glLineWidth: the pixel sizes of the points and lines of point clouds and line
  // sets (Mesh::pointIndices, lineIndices), which the rasterizer draws and the ray tracers leave out.
  Real pointSize = 1;
  Real lineWidth = 1;
  // The most pixels the points and lines may cover, over every pass (Limits::maxFill): a scene
  // that would cover more is refused before it is drawn.
  std::uint64_t maxFill = Limits{}.maxFill;
  Overlays overlays;
  AmbientOcclusion ambientOcclusion;
  // The files the scene was read from: the scene file, the model files and textures it names, its
  // environment map. No output may replace one of them.
  std::vector<std::filesystem::path> files;
};

struct ImportedModel;
// The model files scene files name, by canonical path, kept from one scene to the next: a batch of
// scenes that share assets reads each file once. What the scene being read uses is kept, and what
// the scene before it used, until the next scene starts: never more than two scenes' models.
class SceneModelCache {
 public:
  std::shared_ptr<const ImportedModel> find(const std::string& key);
  void add(const std::string& key, std::shared_ptr<const ImportedModel> model);
  void nextScene();  // a scene starts: forgets what the scene two before it used (parseScene calls it)

 private:
  std::map<std::string, std::shared_ptr<const ImportedModel>> current_, earlier_;
};

// Reads a scene file; relative mesh paths are resolved against the file's folder.
// Throws InputError naming the file, the JSON path and what was expected.
// Tessellation, model files and the image size are held to `limits` before anything is built.
// With `models`, model files already in it are not read again.
Scene loadSceneFile(const std::filesystem::path& path, const Limits& limits = {}, SceneModelCache* models = nullptr);

// Parses scene JSON text. `name` is used in messages; `baseDir` resolves mesh file paths.
Scene parseScene(const std::string& text, const std::string& name, const std::filesystem::path& baseDir,
                 const Limits& limits = {}, SceneModelCache* models = nullptr);

// The scene as a scene file (version 1, docs/scene-format.md) that reads back to the same scene:
// `illum render` of it draws the same picture, byte for byte. Model files are named by absolute
// path, with the materials that differ from the file's own. Throws Error for an object that no
// scene file made (Object::source unset).
std::string sceneJson(const Scene& scene);

// The built-in scene `illum render` draws with no arguments: GLUT's solids in several materials
// under coloured lights, the seeds' story at a glance, labelled with what each part shows.
// Its second caption names the shading frequency, or the ray tracer when `renderer` is one.
Scene defaultScene(LightingModel model = LightingModel::BlinnPhong, Shading shading = Shading::Phong,
                   RendererKind renderer = RendererKind::Raster);

}  // namespace illum

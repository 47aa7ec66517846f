// The scene file contract, version 1 (docs/scene-format.md): every key, default and rejection.
#include <illum/error.h>
#include <illum/captions.h>
#include <illum/scene.h>

#include <map>

#include <illum/import.h>
#include "core/input_file.h"
#include "scene/environment_use.h"
#include "scene/json_reader.h"
#include "scene/mesh_json.h"

#include <glm/gtc/matrix_transform.hpp>

#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

namespace illum {
namespace {

constexpr int kMaxImageSize = 16384;
constexpr int kMaxTessellation = 4096;
const Real kBig = std::numeric_limits<Real>::max();

void readCamera(const JsonReader& j, Camera& cam) {
  j.expectObject({"eye", "center", "up", "fovy", "near", "far", "projection", "view_height"});
  if (j.has("eye")) cam.eye = j.at("eye").vec3();
  if (j.has("center")) cam.center = j.at("center").vec3();
  if (j.has("up")) cam.up = j.at("up").vec3();
  if (j.has("fovy")) {
    cam.fovy = j.at("fovy").number(0, 180);
    if (cam.fovy <= 0 || cam.fovy >= 180) j.at("fovy").fail("expected an angle strictly between 0 and 180 degrees");
  }
  if (j.has("near")) cam.near = j.at("near").positive();
  if (j.has("far")) cam.far = j.at("far").positive();
  if (j.has("projection")) {
    const std::string p = j.at("projection").string();
    if (p == "perspective") cam.projection = Projection::Perspective;
    else if (p == "orthographic") cam.projection = Projection::Orthographic;
    else j.at("projection").fail("expected \"perspective\" or \"orthographic\", got \"" + p + "\"");
  }
  if (j.has("view_height")) cam.viewHeight = j.at("view_height").positive();
  if (!(cam.far > cam.near)) j.fail("expected far > near");
}

// The camera once the image size is known: the same rules the command line's camera meets.
void checkCamera(const JsonReader& j, const Camera& cam, Real aspect) {
  const CameraFault fault = cameraFault(cam, aspect);
  if (fault == CameraFault::None) return;
  const char* key = fault == CameraFault::ViewAngle ? "fovy"
                    : fault == CameraFault::ZeroUp || fault == CameraFault::UpParallel ? "up" : nullptr;
  if (key && j.at("camera").has(key)) j.at("camera").at(key).fail(describe(fault));
  j.at("camera").fail(fault == CameraFault::SamePoint ? "expected eye and center to differ" : describe(fault));
}

void readLightModel(const JsonReader& j, LightModel& lm) {
  j.expectObject({"ambient", "local_viewer", "two_sided", "convention"});
  if (j.has("ambient")) lm.ambient = Color3(j.at("ambient").intensity34());
  if (j.has("local_viewer")) lm.localViewer = j.at("local_viewer").boolean();
  if (j.has("two_sided")) lm.twoSided = j.at("two_sided").boolean();
  if (j.has("convention")) {
    const std::string name = j.at("convention").string();
    const std::optional<Convention> c = parseConvention(name);
    if (!c) j.at("convention").fail("expected " + conventionNames(true) + ", got \"" + name + "\"");
    lm.convention = *c;
  }
}

Light readLight(const JsonReader& j) {
  j.expectObject({"position", "ambient", "diffuse", "specular", "attenuation", "spot_direction",
                  "spot_exponent", "spot_cutoff"});
  Light l;
  if (j.has("position")) l.position = j.at("position").vec4();
  if (j.has("ambient")) l.ambient = Color3(j.at("ambient").intensity34());
  if (j.has("diffuse")) l.diffuse = Color3(j.at("diffuse").intensity34());
  if (j.has("specular")) l.specular = Color3(j.at("specular").intensity34());
  if (j.has("attenuation")) {
    const JsonReader a = j.at("attenuation");
    a.numbers(3);
    l.attenuation = {a.item(0).nonNegative(), a.item(1).nonNegative(), a.item(2).nonNegative()};
    if (l.attenuation == Vec3(0)) a.fail("expected at least one positive coefficient (1/(0+0d+0d²) is infinite)");
  }
  if (j.has("spot_direction")) {
    l.spotDirection = j.at("spot_direction").vec3();
    if (glm::length(l.spotDirection) == 0) j.at("spot_direction").fail("expected a non-zero direction");
  }
  if (j.has("spot_exponent")) l.spotExponent = j.at("spot_exponent").number(0, 128);
  if (j.has("spot_cutoff")) {
    l.spotCutoff = j.at("spot_cutoff").number(0, 180);
    if (l.spotCutoff > 90 && l.spotCutoff != 180) j.at("spot_cutoff").fail("expected an angle in [0, 90] or 180, got " + j.at("spot_cutoff").value().dump());
  }
  return l;
}

// A material: GL's keys (glMaterial), or physically based ones (glTF's metallic-roughness), not
// both; emission, the lighting model and the ray tracers' keys go with either.
Material readMaterial(const JsonReader& j) {
  j.expectObject({"ambient", "diffuse", "specular", "emission", "shininess", "base_color", "metallic", "roughness",
                  "f0", "distribution", "model", "emission_strength", "reflective", "transmissive", "ior", "transmission_shininess",
                  "filter"});
  Material m;
  if (j.has("emission")) m.emission = j.at("emission").color34();
  // Emitters brighter than white (area lights for the path tracer), like glTF's emissive_strength.
  if (j.has("emission_strength"))
    m.emission = Color4(Color3(m.emission) * j.at("emission_strength").number(0, Real(1e6)), m.emission.a);
  if (j.has("model")) {
    const std::string name = j.at("model").string();
    m.model = parseLightingModel(name);
    if (!m.model)
      j.at("model").fail("expected " + lightingModelNames(true) + ", got \"" + name + "\"");
  }
  const bool physical = j.has("base_color") || j.has("metallic") || j.has("roughness") || j.has("f0") ||
                        j.has("distribution");
  if (!physical) {
    if (j.has("ambient")) m.ambient = j.at("ambient").color34();
    if (j.has("diffuse")) m.diffuse = j.at("diffuse").color34();
    if (j.has("specular")) m.specular = j.at("specular").color34();
    if (j.has("shininess")) m.shininess = j.at("shininess").nonNegative();
    return m;
  }
  for (const char* gl : {"ambient", "diffuse", "specular", "shininess"})
    if (j.has(gl))
      j.at(gl).fail("a physically based material (base_color, metallic, roughness, f0, distribution) or a GL one "
                    "(ambient, diffuse, specular, shininess), not both");
  PhysicalMaterial p;
  if (j.has("base_color")) {
    const Color4 base = j.at("base_color").color34();
    p.baseColor = Color3(base);
    m.diffuse.a = base.a;
  }
  if (j.has("metallic")) p.metallic = j.at("metallic").number(0, 1);
  if (j.has("roughness")) p.roughness = j.at("roughness").number(0, 1);
  if (j.has("f0")) {
    p.f0 = j.at("f0").color3();
  } else if (j.has("ior")) {
    const Real n = j.at("ior").number(Real(1), Real(10));
    p.f0 = Color3(((n - 1) / (n + 1)) * ((n - 1) / (n + 1)));
  }
  if (j.has("distribution")) {
    const std::string d = j.at("distribution").string();
    if (d == "ggx") p.distribution = Microfacet::GGX;
    else if (d == "beckmann") p.distribution = Microfacet::Beckmann;
    else j.at("distribution").fail("expected \"ggx\" or \"beckmann\", got \"" + d + "\"");
  }
  glFromPhysical(m, p);
  return m;
}

// The ray tracers' keys of a material (its GL keys are readMaterial's).
SurfaceOptics readOptics(const JsonReader& j) {
  SurfaceOptics o;
  if (j.has("reflective")) o.reflective = j.at("reflective").color3();
  if (j.has("transmissive")) o.transmissive = j.at("transmissive").color3();
  if (j.has("ior")) o.ior = j.at("ior").number(Real(1), Real(10));
  if (j.has("transmission_shininess")) o.transmissionShininess = j.at("transmission_shininess").nonNegative();
  if (j.has("filter")) o.filter = j.at("filter").color3();
  return o;
}

Mat4 readTransform(const JsonReader& j) {
  Mat4 m(1);
  const std::size_t n = j.arraySize();
  for (std::size_t i = 0; i < n; ++i) {
    const JsonReader step = j.item(i);
    step.expectObject({"translate", "rotate", "scale", "matrix"});
    if (step.value().size() != 1) step.fail("expected exactly one of translate, rotate, scale or matrix");
    // Each step multiplies on the right, like glTranslate/glRotate/glScale after the view matrix.
    if (step.has("matrix")) {
      // Row by row, as a matrix is written; a first step is the matrix itself (I·M = M, and
      // exactly so: a scene written back (sceneJson) draws the same bytes).
      const std::vector<Real> v = step.at("matrix").numbers(16);
      Mat4 given;
      for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) given[col][row] = v[std::size_t(row * 4 + col)];
      if (glm::determinant(Mat3(given)) == 0)
        step.at("matrix").fail("expected an invertible upper 3×3 (a flat object has no normals)");
      m = i == 0 ? given : m * given;
    } else if (step.has("translate")) {
      m = glm::translate(m, step.at("translate").vec3());
    } else if (step.has("rotate")) {
      const Vec4 r = step.at("rotate").vec4();
      const Vec3 axis(r.y, r.z, r.w);
      if (glm::length(axis) == 0) step.at("rotate").fail("expected a non-zero rotation axis");
      m = glm::rotate(m, glm::radians(r.x), glm::normalize(axis));
    } else {
      const Vec3 s = step.at("scale").vec3();
      if (s.x == 0 || s.y == 0 || s.z == 0) step.at("scale").fail("expected non-zero scale factors (a flat object has no normals)");
      m = glm::scale(m, s);
    }
  }
  return m;
}

Mesh readTriangles(const JsonReader& j) {
  j.expectObject({"type", "positions", "normals", "indices"});
  if (!j.has("positions")) j.fail("expected \"positions\": [x,y,z,...]");
  if (!j.has("indices")) j.fail("expected \"indices\": [i,j,k,...]");
  Mesh mesh;
  const JsonReader p = j.at("positions");
  const std::size_t np = p.arraySize();
  if (np % 3 != 0) p.fail("expected a multiple of 3 numbers, got " + std::to_string(np));
  for (std::size_t i = 0; i < np; i += 3)
    mesh.positions.push_back({p.item(i).number(-kBig, kBig), p.item(i + 1).number(-kBig, kBig), p.item(i + 2).number(-kBig, kBig)});
  const JsonReader idx = j.at("indices");
  const std::size_t ni = idx.arraySize();
  if (ni % 3 != 0) idx.fail("expected a multiple of 3 indices, got " + std::to_string(ni));
  const int maxIndex = int(std::min<std::size_t>(mesh.positions.size(), std::size_t(std::numeric_limits<int>::max()))) - 1;
  for (std::size_t i = 0; i < ni; ++i) {
    if (maxIndex < 0) idx.fail("expected no indices, since there are no positions");
    mesh.indices.push_back(std::uint32_t(idx.item(i).integer(0, maxIndex)));
  }
  if (j.has("normals")) {
    const JsonReader n = j.at("normals");
    if (n.arraySize() != np) n.fail("expected " + std::to_string(np) + " numbers (one normal per position), got " + std::to_string(n.arraySize()));
    for (std::size_t i = 0; i < np; i += 3) {
      const Vec3 v(n.item(i).number(-kBig, kBig), n.item(i + 1).number(-kBig, kBig), n.item(i + 2).number(-kBig, kBig));
      if (glm::length(v) == 0) n.item(i).fail("expected a non-zero normal");
      mesh.normals.push_back(glm::normalize(v));
    }
  } else {
    mesh.normals = generateSmoothNormals(mesh.positions, mesh.indices);
  }
  return mesh;
}

// What reading one scene file carries along: where its paths start, and the triangle budget
// (--max-triangles) that GLUT tessellation and model files draw from before anything is built.
struct ReadContext {
  std::filesystem::path baseDir;
  Limits limits;
  std::uint64_t triangles = 0;
  // Model files already read, by their path: a file several objects name is read once, and its
  // meshes and textures are shared between them.
  SceneModelCache* models = nullptr;
  std::vector<std::filesystem::path>* files = nullptr;  // what the scene reads (Scene::files)

  void charge(const JsonReader& j, std::uint64_t count) {
    triangles += count;
    if (triangles > limits.maxTriangles)
      j.fail("a mesh that brings the scene to " + withThousands(triangles) + " triangles, more than the limit of " +
             withThousands(limits.maxTriangles) + " (raise it with --max-triangles)");
  }
};

bool isModelFile(const JsonReader& j) {
  return j.value().is_object() && j.has("type") && j.value()["type"] == "file";
}

// A model file mesh: its path, how its normals are made, and what becomes of its colours.
struct ModelFileMesh {
  std::filesystem::path path;  // as the scene file's folder resolves it
  ImportOptions options;
  bool srgbTextures = false, fileColours = true;
};

ModelFileMesh readModelFileMesh(const JsonReader& j, const ReadContext& context) {
  j.expectObject({"type", "path", "normals", "crease_angle", "colour_textures", "file_colours"});
  if (!j.has("path")) j.fail("expected a \"path\" to a model file");
  ModelFileMesh m;
  const std::filesystem::path rel = j.at("path").string();
  m.path = rel.is_absolute() ? rel : context.baseDir / rel;
  m.options.limits = context.limits;
  if (j.has("normals")) {
    const std::string n = j.at("normals").string();
    if (n == "auto") m.options.normals = NormalMode::Auto;
    else if (n == "flat") m.options.normals = NormalMode::Flat;
    else if (n == "smooth") m.options.normals = NormalMode::Smooth;
    else if (n == "file") m.options.normals = NormalMode::File;
    else j.at("normals").fail("expected \"auto\", \"flat\", \"smooth\" or \"file\", got \"" + n + "\"");
  }
  if (j.has("crease_angle")) m.options.creaseAngle = j.at("crease_angle").number(0, 180);
  if (j.has("colour_textures")) {
    const std::string e = j.at("colour_textures").string();
    if (e != "linear" && e != "srgb") j.at("colour_textures").fail("expected \"linear\" or \"srgb\", got \"" + e + "\"");
    m.srgbTextures = e == "srgb";
  }
  if (j.has("file_colours")) m.fileColours = j.at("file_colours").boolean();
  return m;
}

// The model file's objects, with their colours as the mesh says.
std::vector<Object> readModelFile(const JsonReader& j, ReadContext& context) {
  const ModelFileMesh mesh = readModelFileMesh(j, context);
  try {
    std::error_code ec;
    const std::string canonical = std::filesystem::weakly_canonical(mesh.path, ec).string();
    // Imported once per file and normals options.
    const std::string name = (ec ? mesh.path.string() : canonical) + "\n" +
                             std::to_string(int(mesh.options.normals)) + " " + std::to_string(mesh.options.creaseAngle);
    std::shared_ptr<const ImportedModel> cached = context.models->find(name);
    if (!cached) {
      cached = std::make_shared<const ImportedModel>(importModel(mesh.path, mesh.options));
      context.models->add(name, cached);
    }
    context.charge(j.at("path"), cached->triangleCount);
    context.files->push_back(mesh.path);
    context.files->insert(context.files->end(), cached->files.begin(), cached->files.end());
    std::vector<Object> objects = cached->objects;
    if (mesh.srgbTextures) decodeColourTextures(objects);
    if (!mesh.fileColours) dropFileColours(objects);
    return objects;
  } catch (const InputError& e) {
    j.at("path").fail(e.what());
  }
}

// The "mesh" value as a scene file would give it from anywhere: a model file's path absolute.
std::shared_ptr<const std::string> meshSource(const JsonReader& j, const ReadContext& context) {
  Json mesh = j.value();
  if (isModelFile(j)) {
    const std::filesystem::path rel = j.at("path").string();
    mesh["path"] = std::filesystem::absolute(rel.is_absolute() ? rel : context.baseDir / rel).lexically_normal().string();
  }
  return std::make_shared<const std::string>(mesh.dump());
}


Mesh readMesh(const JsonReader& j, ReadContext& context) {
  if (!j.value().is_object()) j.fail("expected an object, got something else");
  if (!j.has("type")) j.fail("expected a \"type\": sphere, cube, torus, cone, teapot, triangles or file");
  const std::string type = j.at("type").string();
  if (type == "sphere") {
    j.expectObject({"type", "radius", "slices", "stacks"});
    const Real radius = j.has("radius") ? j.at("radius").positive() : Real(1);
    const int slices = j.has("slices") ? j.at("slices").integer(3, kMaxTessellation) : 20;
    const int stacks = j.has("stacks") ? j.at("stacks").integer(2, kMaxTessellation) : 16;
    context.charge(j, 2 * std::uint64_t(slices) * std::uint64_t(stacks));
    return makeSphere(radius, slices, stacks);
  }
  if (type == "cube") {
    j.expectObject({"type", "size"});
    return makeCube(j.has("size") ? j.at("size").positive() : Real(1));
  }
  if (type == "torus") {
    j.expectObject({"type", "inner_radius", "outer_radius", "sides", "rings"});
    const Real inner = j.has("inner_radius") ? j.at("inner_radius").positive() : Real(0.3);
    const Real outer = j.has("outer_radius") ? j.at("outer_radius").positive() : Real(1);
    const int sides = j.has("sides") ? j.at("sides").integer(3, kMaxTessellation) : 16;
    const int rings = j.has("rings") ? j.at("rings").integer(3, kMaxTessellation) : 32;
    context.charge(j, 2 * std::uint64_t(sides) * std::uint64_t(rings));
    return makeTorus(inner, outer, sides, rings);
  }
  if (type == "cone") {
    j.expectObject({"type", "base", "height", "slices", "stacks"});
    const Real base = j.has("base") ? j.at("base").positive() : Real(1);
    const Real height = j.has("height") ? j.at("height").positive() : Real(2);
    const int slices = j.has("slices") ? j.at("slices").integer(3, kMaxTessellation) : 20;
    const int stacks = j.has("stacks") ? j.at("stacks").integer(1, kMaxTessellation) : 8;
    context.charge(j, 2 * std::uint64_t(slices) * (std::uint64_t(stacks) + 1));
    return makeCone(base, height, slices, stacks);
  }
  if (type == "teapot") {
    j.expectObject({"type", "size"});
    return makeTeapot(j.has("size") ? j.at("size").positive() : Real(1));
  }
  if (type == "triangles") {
    Mesh mesh = readTriangles(j);
    context.charge(j, mesh.triangleCount());
    return mesh;
  }
  j.at("type").fail("expected one of sphere, cube, torus, cone, teapot, triangles, file; got \"" + type + "\"");
}

// One object of the scene; a model file brings one object per mesh instance, each placed by its
// node transforms after the object's transform, in the file's materials unless one is given.
void readObject(const JsonReader& j, ReadContext& context, std::vector<Object>& out) {
  j.expectObject({"mesh", "transform", "material", "materials"});
  const Mat4 worldFromObject = j.has("transform") ? readTransform(j.at("transform")) : Mat4(1);
  std::optional<Material> material;
  SurfaceOptics optics;
  if (j.has("material")) material = readMaterial(j.at("material")), optics = readOptics(j.at("material"));
  const bool modelFile = j.has("mesh") && isModelFile(j.at("mesh"));
  if (j.has("materials") && (!modelFile || material))
    j.at("materials").fail(modelFile ? "expected \"material\" or \"materials\", not both"
                                     : "expected \"materials\" only for a model file mesh (one material per mesh of the file)");
  auto source = std::make_shared<ObjectSource>();
  source->mesh = j.has("mesh") ? meshSource(j.at("mesh"), context) : std::make_shared<const std::string>("{\"type\":\"sphere\"}");
  source->transform = worldFromObject;
  if (modelFile) {
    std::vector<Object> parts = readModelFile(j.at("mesh"), context);
    if (j.has("materials") && j.at("materials").arraySize() != parts.size())
      j.at("materials").fail("expected " + std::to_string(parts.size()) + " materials or nulls, one per mesh of the file, got " +
                             std::to_string(j.at("materials").arraySize()));
    for (std::size_t i = 0; i < parts.size(); ++i) {
      Object& o = parts[i];
      auto part = std::make_shared<ObjectSource>(*source);
      part->part = int(i), part->parts = int(parts.size()), part->fileMaterial = o.material;
      // Placed by the object's transform after the file's node transforms (none given: as the file places it).
      if (j.has("transform")) o.worldFromObject = worldFromObject * o.worldFromObject;
      o.optics = optics;
      if (material) o.material = *material;
      if (j.has("materials") && !j.at("materials").item(i).value().is_null()) {
        const JsonReader m = j.at("materials").item(i);
        o.material = readMaterial(m), o.optics = readOptics(m);
      }
      o.source = std::move(part);
      out.push_back(std::move(o));
    }
    return;
  }
  Object o;
  o.mesh = std::make_shared<Mesh>(j.has("mesh") ? readMesh(j.at("mesh"), context) : makeSphere(1, 20, 16));
  o.worldFromObject = worldFromObject;
  o.optics = optics;
  if (material) o.material = *material;
  o.source = std::move(source);
  out.push_back(std::move(o));
}

Label readLabel(const JsonReader& j) {
  j.expectObject({"text", "position", "pixel", "color", "size"});
  Label l;
  if (!j.has("text")) j.fail("expected a \"text\"");
  l.text = j.at("text").string();
  if (j.has("position") == j.has("pixel")) j.fail("expected either \"position\" (world) or \"pixel\" (image), not both or neither");
  if (j.has("position")) l.position = j.at("position").vec3();
  if (j.has("pixel")) {
    const auto v = j.at("pixel").numbers(2);
    l.pixel = Vec2(v[0], v[1]);
  }
  if (j.has("color")) l.color = j.at("color").color3();
  if (j.has("size")) l.size = j.at("size").number(4, 512);
  return l;
}

std::string describeParseError(const Json::parse_error& e, const std::string& text) {
  // Turn the byte offset into a line and column a text editor shows.
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
    if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
  }
  std::string why = e.what();
  if (auto p = why.find("error while parsing"); p != std::string::npos) why = why.substr(p);
  else if (auto q = why.find(": "); q != std::string::npos) why = why.substr(q + 2);
  return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": invalid JSON: " + why;
}

}  // namespace

std::shared_ptr<const ImportedModel> SceneModelCache::find(const std::string& key) {
  if (auto it = current_.find(key); it != current_.end()) return it->second;
  auto it = earlier_.find(key);
  if (it == earlier_.end()) return nullptr;
  return current_[key] = it->second;  // used again: kept for the next scene too
}

void SceneModelCache::add(const std::string& key, std::shared_ptr<const ImportedModel> model) {
  current_[key] = std::move(model);
}

void SceneModelCache::nextScene() {
  earlier_ = std::move(current_);
  current_.clear();
}

Scene parseScene(const std::string& text, const std::string& name, const std::filesystem::path& baseDir,
                 const Limits& limits, SceneModelCache* models) {
  if (models) models->nextScene();
  Json root;
  try {
    JsonBudget budget;
    budget.maxDepth = limits.maxJsonDepth;
    budget.maxValues = limits.maxSceneBytes / 4;
    root = parseJsonStrict(text, name, budget);
  } catch (const Json::parse_error& e) {
    throw InputError(name + ": " + describeParseError(e, text));
  } catch (const Json::out_of_range& e) {
    // nlohmann reports a number too large for a double (1e999) this way.
    std::string why = e.what();
    if (auto p = why.find("] "); p != std::string::npos) why = why.substr(p + 2);
    throw InputError(name + ": invalid JSON: " + why + " (expected a finite number)");
  }
  const JsonReader j(root, name);
  j.expectObject({"version", "width", "height", "background", "model", "shading", "camera",
                  "light_model", "lights", "objects", "labels", "blend", "renderer", "max_depth", "shadows",
                  "samples", "environment", "environment_map", "tone_map", "encoding", "multisample", "overlays", "ambient_occlusion",
                  "point_size", "line_width", "denoise", "environment_lighting", "environment_rotation",
                  "environment_background", "studio_environment", "seed"});
  Scene s;
  if (j.has("version") && j.at("version").integer(0, std::numeric_limits<int>::max()) != 1)
    j.at("version").fail("expected version 1");
  if (j.has("width")) s.width = j.at("width").integer(1, kMaxImageSize);
  if (j.has("height")) s.height = j.at("height").integer(1, kMaxImageSize);
  if (std::uint64_t(s.width) * std::uint64_t(s.height) > limits.maxPixels)
    (j.has("height") ? j.at("height") : j.has("width") ? j.at("width") : j)
        .fail("an image of at most " + withThousands(limits.maxPixels) + " pixels (raise it with --max-pixels), got " +
              std::to_string(s.width) + "×" + std::to_string(s.height));
  if (j.has("background")) s.background = j.at("background").color34();
  if (j.has("model")) {
    const std::string m = j.at("model").string();
    const auto model = parseLightingModel(m);
    if (!model) j.at("model").fail("expected " + lightingModelNames(true) + ", got \"" + m + "\"");
    s.model = *model;
  }
  if (j.has("shading")) {
    const std::string m = j.at("shading").string();
    const auto shading = parseShading(m);
    if (!shading) j.at("shading").fail("expected \"flat\", \"gouraud\" or \"phong\", got \"" + m + "\"");
    s.shading = *shading;
  }
  if (j.has("renderer")) {
    const std::string r = j.at("renderer").string();
    const auto renderer = parseRendererKind(r);
    if (!renderer) j.at("renderer").fail("expected \"raster\", \"whitted\", \"hall\" or \"path\", got \"" + r + "\"");
    s.renderer = *renderer;
  }
  if (j.has("tone_map")) {
    const std::string t = j.at("tone_map").string();
    const auto toneMap = parseToneMap(t);
    if (!toneMap) j.at("tone_map").fail("expected \"none\", \"reinhard\" or \"aces\", got \"" + t + "\"");
    s.display.toneMap = *toneMap;
  }
  if (j.has("encoding")) {
    const std::string e = j.at("encoding").string();
    const auto encoding = parseEncoding(e);
    if (!encoding) j.at("encoding").fail("expected \"linear\" or \"srgb\", got \"" + e + "\"");
    s.display.encoding = *encoding;
  }
  if (j.has("ambient_occlusion")) {
    const JsonReader ao = j.at("ambient_occlusion");
    if (ao.value().is_boolean()) {
      s.ambientOcclusion.enabled = ao.boolean();
    } else {
      ao.expectObject({"rays", "distance"});
      s.ambientOcclusion.enabled = true;
      if (ao.has("rays")) s.ambientOcclusion.rays = ao.at("rays").integer(1, 256);
      if (ao.has("distance")) s.ambientOcclusion.distance = ao.at("distance").number(Real(1e-6), Real(1e9));
    }
  }
  if (j.has("overlays")) {
    const JsonReader o = j.at("overlays");
    o.expectObject({"edges", "grid", "axes"});
    if (o.has("edges")) s.overlays.edges = o.at("edges").boolean();
    if (o.has("grid")) s.overlays.grid = o.at("grid").boolean();
    if (o.has("axes")) s.overlays.axes = o.at("axes").boolean();
  }
  if (j.has("multisample")) {
    s.multisample = j.at("multisample").integer(1, 16);
    if (!isMultisampleCount(s.multisample))
      j.at("multisample").fail("expected 1, 4, 8 or 16 samples per pixel, got " + std::to_string(s.multisample));
  }
  if (j.has("point_size")) s.pointSize = j.at("point_size").number(kMinPrimitiveSize, kMaxPrimitiveSize);
  if (j.has("line_width")) s.lineWidth = j.at("line_width").number(kMinPrimitiveSize, kMaxPrimitiveSize);
  if (j.has("max_depth")) s.rayTracing.maxDepth = j.at("max_depth").integer(0, kMaxRayDepth);
  if (j.has("shadows")) s.rayTracing.shadows = j.at("shadows").boolean();
  if (j.has("denoise")) s.rayTracing.denoise = j.at("denoise").boolean();
  if (j.has("samples")) s.rayTracing.samples = j.at("samples").integer(1, kMaxSamples);
  if (j.has("seed")) s.rayTracing.seed = std::uint32_t(j.at("seed").integer(0, std::numeric_limits<int>::max()));
  if (j.has("studio_environment") && j.has("environment_map") && j.at("studio_environment").boolean())
    j.at("studio_environment").fail("expected either an \"environment_map\" file or the studio, not both");
  if (j.has("environment_map")) {
    const std::filesystem::path file = baseDir / j.at("environment_map").string();
    try {
      s.rayTracing.environmentMap = EnvironmentMapFile::open(file, limits);
      s.files.push_back(file);
    } catch (const InputError& e) {
      j.at("environment_map").fail(std::string("expected a readable Radiance .hdr or OpenEXR .exr image; ") + e.what());
    }
    s.rayTracing.environment = Color3(1);
  }
  if (j.has("studio_environment") && j.at("studio_environment").boolean()) {
    s.rayTracing.environmentMap = studioEnvironment();
    s.rayTracing.environment = Color3(1);
    s.environment.studio = true;
  }
  if (j.has("environment")) s.rayTracing.environment = Color3(j.at("environment").intensity34());
  if (j.has("environment_lighting")) {
    const std::string l = j.at("environment_lighting").string();
    const auto lighting = parseEnvironmentLighting(l);
    if (!lighting) j.at("environment_lighting").fail("expected \"none\", \"physically_based\" or \"all\", got \"" + l + "\"");
    s.environment.lighting = *lighting;
  }
  if (j.has("environment_rotation")) s.environment.rotation = j.at("environment_rotation").number(Real(-360), Real(360));
  if (j.has("environment_background")) {
    const std::string b = j.at("environment_background").string();
    const auto background = parseEnvironmentBackground(b);
    if (!background) j.at("environment_background").fail("expected \"none\", \"sharp\" or \"blurred\", got \"" + b + "\"");
    s.environment.background = *background;
  }
  if (j.has("camera")) {
    readCamera(j.at("camera"), s.camera);
    checkCamera(j, s.camera, Real(s.width) / Real(s.height));
  }
  if (j.has("light_model")) readLightModel(j.at("light_model"), s.lightModel);
  if (j.has("lights")) {
    const JsonReader lights = j.at("lights");
    s.lights.clear();
    for (std::size_t i = 0, n = lights.arraySize(); i < n; ++i) s.lights.push_back(readLight(lights.item(i)));
  }
  if (j.has("objects")) {
    const JsonReader objects = j.at("objects");
    SceneModelCache ownModels;
    ReadContext context{baseDir, limits, 0, models ? models : &ownModels, &s.files};
    for (std::size_t i = 0, n = objects.arraySize(); i < n; ++i) readObject(objects.item(i), context, s.objects);
  }
  if (j.has("blend")) s.blend = j.at("blend").boolean();
  if (j.has("labels")) {
    const JsonReader labels = j.at("labels");
    for (std::size_t i = 0, n = labels.arraySize(); i < n; ++i) s.labels.push_back(readLabel(labels.item(i)));
    // A caption's placeholders name what the scene has (captions.h).
    for (std::size_t i = 0; i < s.labels.size(); ++i) try {
        expandCaption(s.labels[i].text, s);
      } catch (const InputError& e) {
        labels.item(i).at("text").fail(e.what());
      }
  }
  return s;
}

Mesh meshFromJson(const std::string& json) {
  const Json value = Json::parse(json);
  const JsonReader j(value, "mesh");
  if (isModelFile(j)) j.fail("expected a mesh made in place, not a model file");
  ReadContext context{".", Limits{}, 0, nullptr, nullptr};
  return readMesh(j, context);
}

Scene loadSceneFile(const std::filesystem::path& path, const Limits& limits, SceneModelCache* models) {
  const std::string text = readInputFile(path, limits.maxSceneBytes, {"scene file", "--max-scene-size"});
  Scene scene = parseScene(text, path.string(), path.parent_path(), limits, models);
  scene.files.insert(scene.files.begin(), path);
  return scene;
}

}  // namespace illum

// The library's API over the command line's own code: options go through the commands' parsers,
// scenes are made by prepareScene, pictures drawn by the Renderer, so that a picture from the
// library is byte for byte the one `illum render` writes with the same options.
#include <illum/illum.h>

#include <illum/image.h>
#include <illum/import.h>
#include <illum/render.h>
#include <illum/scene.h>
#include <illum/sheet.h>

#include "compare.h"
#include "eval.h"
#include "history.h"
#include "named_options.h"
#include "scene_options.h"

#include <nlohmann/json.hpp>

namespace illum {

struct Model::Impl {
  std::string path;
  cli::SceneOptions options;  // as it was read (normals, crease angle, limits)
  std::shared_ptr<const ImportedModel> model;
};

namespace {

// The standard input of the command line has no place here.
void refuseStandardInput(const std::string& path) {
  if (path == "-") throw InputError("-: standard input is the command line's; give a path, or Source::sceneJson(text)");
}

// `options` through the parser of `command` (made by `add`), with the source's path as its input.
template <typename Add>
void parse(const char* command, const Options& options, const Source& source, Add add) {
  CLI::App app;
  add(app);
  refuseStandardInput(source.path());
  const bool byPath = !source.isJson() && !source.model() && !source.path().empty();
  cli::parseNamedOptions(app, command, options, byPath ? std::vector<std::string>{source.path()} : std::vector<std::string>{});
}

// Points the scene options at the source; a model already read goes into `cache` under the key
// prepareScene looks for, unless the options read it otherwise (other normals, another crease angle).
void useSource(const Source& source, cli::SceneOptions& o, cli::ModelCache& cache) {
  if (source.isJson()) o.memoryScene = std::make_shared<const cli::MemoryScene>(cli::MemoryScene{source.json(), source.baseDir()});
  if (const auto& model = source.model()) {
    o.input = model->path;
    if (cli::modelCacheKey(o) == cli::modelCacheKey(model->options)) cache.models[cli::modelCacheKey(o)] = {model->model, true};
  }
}

Picture pictureOf(Image&& image) {
  Picture p;
  p.width = image.width;
  p.height = image.height;
  p.rgba = std::move(image.rgba);
  return p;
}

std::array<double, 3> triple(const nlohmann::json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }

}  // namespace

const char* version() { return "0.1.0"; }

std::vector<std::uint8_t> Picture::png() const {
  Image image(width, height);
  image.rgba = rgba;
  return encodePng(image);
}

const std::string& Model::path() const { return impl_->path; }
std::size_t Model::vertexCount() const { return impl_->model->vertexCount; }
std::size_t Model::triangleCount() const { return impl_->model->triangleCount; }
std::size_t Model::materialCount() const { return impl_->model->materialCount; }
std::size_t Model::textureCount() const { return impl_->model->textureCount; }
std::array<double, 3> Model::boundsMin() const {
  const Vec3 b = impl_->model->boundsMin;
  return {double(b.x), double(b.y), double(b.z)};
}
std::array<double, 3> Model::boundsMax() const {
  const Vec3 b = impl_->model->boundsMax;
  return {double(b.x), double(b.y), double(b.z)};
}
const std::vector<std::string>& Model::warnings() const { return impl_->model->warnings; }

std::vector<float> Model::positions() const {
  std::vector<float> out;
  for (const Object& object : impl_->model->objects)
    for (const Vec3& p : object.mesh->positions) {
      const Vec4 world = object.worldFromObject * Vec4(p, 1);
      out.insert(out.end(), {float(world.x), float(world.y), float(world.z)});
    }
  return out;
}

std::vector<std::uint32_t> Model::triangles() const {
  std::vector<std::uint32_t> out;
  std::uint32_t base = 0;
  for (const Object& object : impl_->model->objects) {
    for (const std::uint32_t i : object.mesh->indices) out.push_back(base + i);
    base += std::uint32_t(object.mesh->positions.size());
  }
  return out;
}

Model loadModel(const std::string& path, const Options& options) {
  auto impl = std::make_shared<Model::Impl>();
  parse("render", options, Source(path), [&](CLI::App& app) { cli::addSceneOptions(app, impl->options); });
  if (impl->options.input.empty()) throw InputError("load_model: expected the path of a model file");
  if (!cli::isModelInput(impl->options.input))
    throw InputError(impl->options.input + ": a scene file, not a model file (render it, or give a model file)");
  impl->path = impl->options.input;
  impl->model = std::make_shared<const ImportedModel>(cli::startModelImport(impl->options, 1).finish());
  return Model(std::move(impl));
}

Picture render(const Source& input, const Options& options, const RenderSettings& settings) {
  cli::SceneOptions o;
  parse("render", options, input, [&](CLI::App& app) { cli::addSceneOptions(app, o); });
  cli::ModelCache cache;
  useSource(input, o, cache);
  const cli::ThreadLimit limit(o);
  std::vector<std::string> warnings;
  const Scene scene = cli::prepareScene(o, nullptr, &cache, &warnings);
  Renderer renderer;
  if (settings.progress) renderer.onProgress(settings.progress);
  renderer.setCancel(settings.cancel);
  Image image;
  FloatImage linear;
  renderer.render(scene, image, nullptr, nullptr, settings.linear ? &linear : nullptr);
  if (settings.cancel && settings.cancel->load()) throw Error("cancelled");
  Picture p = pictureOf(std::move(image));
  p.linear = std::move(linear.rgba);
  p.warnings = std::move(warnings);
  return p;
}

Picture compare(const Source& input, const Options& options) {
  cli::CompareOptions o;
  parse("compare", options, input, [&](CLI::App& app) { cli::addCompareOptions(app, o); });
  cli::ModelCache cache;
  useSource(input, o.scene, cache);
  return pictureOf(composeSheet(cli::compareSheet(o, &cache)));
}

Picture history(const Source& input, const Options& options) {
  cli::SceneOptions o;
  parse("history", options, input, [&](CLI::App& app) { cli::addSceneOptions(app, o); });
  cli::ModelCache cache;
  useSource(input, o, cache);
  return pictureOf(composeSheet(cli::historySheet(o, &cache)));
}

std::string evaluateJson(const Options& options) {
  cli::EvalOptions o;
  CLI::App app;
  cli::addEvalOptions(app, o);
  cli::parseNamedOptions(app, "eval", options);
  return cli::evalJson(o);
}

Terms evaluate(const Options& options) {
  Terms t;
  t.json = evaluateJson(options);
  const nlohmann::json j = nlohmann::json::parse(t.json);
  if (j.is_array()) throw InputError("evaluate: a sweep gives many points: use evaluateJson");
  t.emission = triple(j.at("emission"));
  t.ambient = triple(j.at("ambient"));
  t.diffuse = triple(j.at("diffuse"));
  t.specular = triple(j.at("specular"));
  t.total = triple(j.at("total"));
  t.attenuation = j.at("attenuation").get<double>();
  t.spot = j.at("spot").get<double>();
  return t;
}

}  // namespace illum

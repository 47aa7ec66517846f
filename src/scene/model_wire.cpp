#include "scene/model_wire.h"

#include <illum/error.h>

#include <cstring>
#include <map>
#include <type_traits>

namespace illum {
namespace {

constexpr std::uint64_t kMagic = 0x316c65646f6d6c69;  // "ilmodel1"

class Writer {
 public:
  explicit Writer(IsolatedWriter& out) : out_(out) {}
  template <typename T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.write(&v, sizeof v);
  }
  template <typename T>
  void vector(const std::vector<T>& v) {
    value(std::uint64_t(v.size()));
    if (!v.empty()) out_.write(v.data(), v.size() * sizeof(T));
  }
  void string(const std::string& s) {
    value(std::uint64_t(s.size()));
    out_.write(s.data(), s.size());
  }

 private:
  IsolatedWriter& out_;
};

class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  template <typename T>
  T value() {
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  template <typename T>
  std::vector<T> vector() {
    const auto n = value<std::uint64_t>();
    if (n > bytes_.size() / sizeof(T)) broken();
    std::vector<T> v(n);
    if (n) std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
    return v;
  }
  std::string string() {
    const auto n = value<std::uint64_t>();
    if (n > bytes_.size()) broken();
    const auto* p = take(n);
    return {reinterpret_cast<const char*>(p), n};
  }
  std::size_t count(std::size_t bound) {
    const auto n = value<std::uint64_t>();
    if (n > bound) broken();
    return std::size_t(n);
  }
  bool atEnd() const { return offset_ == bytes_.size(); }
  [[noreturn]] static void broken() { throw Error("the isolated importer handed back an incomplete model"); }

 private:
  const std::uint8_t* take(std::size_t n) {
    if (n > bytes_.size() - offset_) broken();
    const auto* p = bytes_.data() + offset_;
    offset_ += n;
    return p;
  }
  std::span<const std::uint8_t> bytes_;
  std::size_t offset_ = 0;
};

}  // namespace

void writeModel(const ImportedModel& model, IsolatedWriter& out) {
  Writer w(out);
  w.value(kMagic);
  // Shared meshes and textures once each, then objects by index.
  std::map<const Mesh*, std::uint64_t> meshIndex;
  std::map<const Texture*, std::uint64_t> textureIndex;
  std::vector<const Mesh*> meshes;
  std::vector<const Texture*> textures;
  for (const Object& o : model.objects) {
    if (meshIndex.try_emplace(o.mesh.get(), meshes.size()).second) meshes.push_back(o.mesh.get());
    for (const Texture* t : {o.diffuseTexture.get(), o.maps.metallicRoughness.get(), o.maps.normal.get(),
                             o.maps.emissive.get()})
      if (t && textureIndex.try_emplace(t, textures.size()).second) textures.push_back(t);
  }
  const auto textureRef = [&](const std::shared_ptr<const Texture>& t) {
    return t ? textureIndex.at(t.get()) + 1 : std::uint64_t(0);
  };
  w.value(std::uint64_t(meshes.size()));
  for (const Mesh* m : meshes) {
    w.vector(m->positions);
    w.vector(m->normals);
    w.vector(m->indices);
    w.vector(m->pointIndices);
    w.vector(m->lineIndices);
    w.vector(m->uvs);
    w.vector(m->colors);
  }
  w.value(std::uint64_t(textures.size()));
  for (const Texture* t : textures) {
    const Image& image = t->baseImage();
    w.value(image.width);
    w.value(image.height);
    w.vector(image.rgba);
    w.value(std::uint8_t(t->wraps().s));
    w.value(std::uint8_t(t->wraps().t));
  }
  w.value(std::uint64_t(model.objects.size()));
  for (const Object& o : model.objects) {
    w.value(meshIndex.at(o.mesh.get()));
    for (const auto* t : {&o.diffuseTexture, &o.maps.metallicRoughness, &o.maps.normal, &o.maps.emissive})
      w.value(textureRef(*t));
    w.value(o.maps.normalScale);
    w.value(o.worldFromObject);
    w.value(o.material);
  }
  w.value(model.boundsMin);
  w.value(model.boundsMax);
  for (std::size_t n : {model.vertexCount, model.triangleCount, model.materialCount, model.textureCount,
                        model.pointCount, model.lineCount})
    w.value(std::uint64_t(n));
  w.value(model.transparencyIgnored);
  w.value(model.upAxis.has_value());
  w.value(model.upAxis.value_or(Vec3(0)));
  w.value(std::uint64_t(model.warnings.size()));
  for (const std::string& s : model.warnings) w.string(s);
  w.value(std::uint64_t(model.files.size()));
  for (const std::string& s : model.files) w.string(s);
  w.value(kMagic);
}

ImportedModel readModel(std::span<const std::uint8_t> bytes) {
  Reader r(bytes);
  if (r.value<std::uint64_t>() != kMagic) Reader::broken();
  ImportedModel model;
  std::vector<std::shared_ptr<const Mesh>> meshes(r.count(bytes.size()));
  for (auto& slot : meshes) {
    auto m = std::make_shared<Mesh>();
    m->positions = r.vector<Vec3>();
    m->normals = r.vector<Vec3>();
    m->indices = r.vector<std::uint32_t>();
    m->pointIndices = r.vector<std::uint32_t>();
    m->lineIndices = r.vector<std::uint32_t>();
    m->uvs = r.vector<Vec2>();
    m->colors = r.vector<Vec4>();
    for (const auto* list : {&m->indices, &m->pointIndices, &m->lineIndices})
      for (std::uint32_t i : *list)
        if (i >= m->positions.size()) Reader::broken();
    const std::size_t n = m->positions.size();
    if (m->indices.size() % 3 || m->lineIndices.size() % 2 || (m->normals.size() != n && !m->indices.empty()) ||
        (!m->normals.empty() && m->normals.size() != n) || (!m->uvs.empty() && m->uvs.size() != n) ||
        (!m->colors.empty() && m->colors.size() != n))
      Reader::broken();
    slot = std::move(m);
  }
  std::vector<std::shared_ptr<const Texture>> textures(r.count(bytes.size()));
  for (auto& slot : textures) {
    Image image;
    image.width = r.value<int>();
    image.height = r.value<int>();
    image.rgba = r.vector<std::uint8_t>();
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
      Reader::broken();
    TextureWraps wraps;
    for (TextureWrap* wrap : {&wraps.s, &wraps.t}) {
      const auto mode = r.value<std::uint8_t>();
      if (mode > std::uint8_t(TextureWrap::ClampToEdge)) Reader::broken();
      *wrap = TextureWrap(mode);
    }
    slot = std::make_shared<const Texture>(std::move(image), TexelEncoding::Linear, wraps);
  }
  model.objects.resize(r.count(bytes.size()));
  for (Object& o : model.objects) {
    const auto mesh = r.value<std::uint64_t>();
    if (mesh >= meshes.size()) Reader::broken();
    o.mesh = meshes[mesh];
    for (auto* t : {&o.diffuseTexture, &o.maps.metallicRoughness, &o.maps.normal, &o.maps.emissive}) {
      const auto texture = r.value<std::uint64_t>();
      if (texture > textures.size()) Reader::broken();
      if (texture) *t = textures[texture - 1];
    }
    o.maps.normalScale = r.value<Real>();
    o.worldFromObject = r.value<Mat4>();
    o.material = r.value<Material>();
  }
  model.boundsMin = r.value<Vec3>();
  model.boundsMax = r.value<Vec3>();
  for (std::size_t* n : {&model.vertexCount, &model.triangleCount, &model.materialCount, &model.textureCount,
                         &model.pointCount, &model.lineCount})
    *n = std::size_t(r.value<std::uint64_t>());
  model.transparencyIgnored = r.value<bool>();
  const bool hasUp = r.value<bool>();
  const Vec3 up = r.value<Vec3>();
  if (hasUp) model.upAxis = up;
  model.warnings.resize(r.count(bytes.size()));
  for (std::string& s : model.warnings) s = r.string();
  model.files.resize(r.count(bytes.size()));
  for (std::string& s : model.files) s = r.string();
  if (r.value<std::uint64_t>() != kMagic || !r.atEnd()) Reader::broken();
  return model;
}

}  // namespace illum

#include <illum/import.h>

#include <illum/error.h>
#include <illum/file_names.h>

#include "core/input_file.h"
#include "scene/model_format.h"
#include "scene/model_precheck.h"
#include "scene/texture_lookup.h"
#include "scene/texture_transform.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/GltfMaterial.h>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <stb_image.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <utility>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <optional>
#include <system_error>

namespace illum {
namespace {

namespace fs = std::filesystem;

Mat4 toMat4(const aiMatrix4x4& a) {
  Mat4 m;  // assimp is row-major, glm column-major
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = Real(a[r][c]);
  return m;
}

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Vertices no triangle, line or point uses (left over from an exporter) are dropped, so that they
// neither frame the picture nor cost memory; assimp's JoinIdenticalVertices used to do this.
void dropUnusedVertices(Mesh& mesh) {
  constexpr std::uint32_t kUnused = ~std::uint32_t(0);
  std::vector<std::uint32_t> remap(mesh.positions.size(), kUnused);
  for (const auto* list : {&mesh.indices, &mesh.lineIndices, &mesh.pointIndices})
    for (std::uint32_t i : *list) remap[i] = 0;
  std::uint32_t kept = 0;
  for (std::uint32_t& r : remap)
    if (r != kUnused) r = kept++;
  if (kept == mesh.positions.size()) return;
  const auto compact = [&](auto& attribute) {
    if (attribute.empty()) return;
    for (std::size_t i = 0; i < remap.size(); ++i)
      if (remap[i] != kUnused) attribute[remap[i]] = attribute[i];
    attribute.resize(kept);
  };
  compact(mesh.positions);
  compact(mesh.normals);
  compact(mesh.uvs);
  compact(mesh.colors);
  for (auto* list : {&mesh.indices, &mesh.lineIndices, &mesh.pointIndices})
    for (std::uint32_t& i : *list) i = remap[i];
}

// Hands an assimp mesh's per-vertex and per-face arrays back once they are copied: a big mesh's
// peak memory is then illum's copy, not both (the mesh keeps its name and material).
void releaseMeshArrays(aiMesh& m) {
  delete[] std::exchange(m.mVertices, nullptr);
  delete[] std::exchange(m.mNormals, nullptr);
  delete[] std::exchange(m.mTangents, nullptr);
  delete[] std::exchange(m.mBitangents, nullptr);
  for (auto& uv : m.mTextureCoords) delete[] std::exchange(uv, nullptr);
  for (auto& c : m.mColors) delete[] std::exchange(c, nullptr);
  delete[] std::exchange(m.mFaces, nullptr);
  m.mNumVertices = 0;
  m.mNumFaces = 0;
}

// One assimp mesh as an illum mesh, with normals chosen by `options`; the assimp mesh's arrays
// are released (releaseMeshArrays) once copied.
// `uvChannel`: the texture coordinates its material's textures read (materialUv).
Mesh convertMesh(aiMesh& m, const fs::path& path, const ImportOptions& options, bool normalsArePerFace,
                 unsigned uvChannel) {
  const std::string where = path.string() + ": mesh \"" + m.mName.C_Str() + "\"";
  Mesh mesh;
  mesh.positions.reserve(m.mNumVertices);
  // Per-face normals (STL's) are replaced by generated ones unless the file's are asked for: not
  // even copied then.
  const aiVector3D* fileNormals = normalsArePerFace && options.normals == NormalMode::Auto ? nullptr : m.mNormals;
  if (fileNormals) mesh.normals.reserve(m.mNumVertices);
  bool fileNormalsUsable = fileNormals != nullptr;  // present, finite and non-zero everywhere
  for (unsigned v = 0; v < m.mNumVertices; ++v) {
    if (!finite(m.mVertices[v]))
      throw InputError(where + " vertex " + std::to_string(v) + ": expected a finite position");
    mesh.positions.push_back({m.mVertices[v].x, m.mVertices[v].y, m.mVertices[v].z});
    if (fileNormals) {
      const aiVector3D& n = fileNormals[v];
      const Vec3 nv(n.x, n.y, n.z);
      const Real len = finite(n) ? glm::length(nv) : Real(0);
      fileNormalsUsable = fileNormalsUsable && len > Real(1e-12) && std::isfinite(len);
      mesh.normals.push_back(len > Real(1e-12) && std::isfinite(len) ? nv / len : Vec3(0));
    }
  }
  if (uvChannel >= AI_MAX_NUMBER_OF_TEXTURECOORDS || !m.mTextureCoords[uvChannel]) uvChannel = 0;
  if (const aiVector3D* uvs = m.mTextureCoords[uvChannel]) {
    mesh.uvs.reserve(m.mNumVertices);
    for (unsigned v = 0; v < m.mNumVertices; ++v) mesh.uvs.push_back({uvs[v].x, uvs[v].y});
  }
  if (m.mColors[0]) {
    mesh.colors.reserve(m.mNumVertices);
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      const aiColor4D& c = m.mColors[0][v];
      mesh.colors.push_back(glm::clamp(Vec4(c.r, c.g, c.b, c.a), Vec4(0), Vec4(1)));
    }
    // Every vertex transparent black is a reader's placeholder for "no colours" (assimp's AMF
    // reader fills the array so when the file gives none), not colours meant to hide the model.
    if (std::all_of(mesh.colors.begin(), mesh.colors.end(), [](const Vec4& c) { return c == Vec4(0); }))
      mesh.colors.clear();
  }
  // Triangles, line segments and points (SortByPType gives each kind a mesh of its own).
  if (m.mPrimitiveTypes == aiPrimitiveType_TRIANGLE) mesh.indices.reserve(3 * std::size_t(m.mNumFaces));
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    std::vector<std::uint32_t>& list =
        face.mNumIndices == 3 ? mesh.indices : face.mNumIndices == 2 ? mesh.lineIndices : mesh.pointIndices;
    if (face.mNumIndices > 3) continue;  // Triangulate left none; a polygon is not drawn whole
    for (unsigned c = 0; c < face.mNumIndices; ++c) {
      if (face.mIndices[c] >= m.mNumVertices)
        throw InputError(where + " face " + std::to_string(f) + ": index " + std::to_string(face.mIndices[c]) +
                         " is out of range (" + std::to_string(m.mNumVertices) + " vertices)");
      list.push_back(face.mIndices[c]);
    }
  }

  const bool hadNormals = m.mNormals != nullptr;
  releaseMeshArrays(m);
  dropUnusedVertices(mesh);
  // Usable means every vertex used has a finite, non-zero normal (stored as 0 if not).
  if (fileNormals)
    fileNormalsUsable = std::none_of(mesh.normals.begin(), mesh.normals.end(), [](const Vec3& n) { return n == Vec3(0); });
  if (mesh.indices.empty()) {
    // Points and lines alone: lit with the file's normals (as GL lights GL_POINTS), else unlit;
    // there are no faces to make normals from.
    if (!fileNormalsUsable) mesh.normals.clear();
    return mesh;
  }
  switch (options.normals) {
    case NormalMode::Flat: generateFlatNormals(mesh); break;
    case NormalMode::Smooth: generateCreaseNormals(mesh, 180); break;
    case NormalMode::File:
      if (!hadNormals) {
        generateCreaseNormals(mesh, options.creaseAngle);  // none to keep
      } else if (!fileNormalsUsable) {
        // Keep every usable normal; a zero one takes the mean of the faces at its vertex.
        const std::vector<Vec3> generated = generateSmoothNormals(mesh.positions, mesh.indices);
        for (std::size_t i = 0; i < mesh.normals.size(); ++i)
          if (mesh.normals[i] == Vec3(0)) mesh.normals[i] = generated[i];
      }
      break;
    case NormalMode::Auto:
      if (!fileNormalsUsable || normalsArePerFace) generateCreaseNormals(mesh, options.creaseAngle);
      break;
  }
  return mesh;
}

FileMaterialValues readMaterial(const aiMaterial& m) {
  FileMaterialValues v;
  aiColor4D c;
  if (m.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)
    v.diffuse = {c.r, c.g, c.b, c.a};
  if (m.Get(AI_MATKEY_COLOR_AMBIENT, c) == AI_SUCCESS) {
    v.hasAmbient = true;
    v.ambient = {c.r, c.g, c.b};
  }
  if (m.Get(AI_MATKEY_COLOR_SPECULAR, c) == AI_SUCCESS) {
    v.hasSpecular = true;
    v.specular = {c.r, c.g, c.b};
  }
  if (m.Get(AI_MATKEY_COLOR_EMISSIVE, c) == AI_SUCCESS) v.emission = {c.r, c.g, c.b};
  float f = 0;
  if (m.Get(AI_MATKEY_SHININESS, f) == AI_SUCCESS) v.shininess = f;
  // A specular colour with no exponent at all (assimp leaves it out for 3DS's Gouraud materials and
  // some ASE ones) would be GL's exponent 0: the colour added over the whole lit side, washing it
  // out, which no modeller draws. No exponent, no highlight.
  else v.hasSpecular = false;
  // The highlight's strength, kept apart from its colour by 3ds Max (3DS, ASE) and FBX
  // (SpecularFactor): it scales the colour, as those programs draw it.
  if (v.hasSpecular && m.Get(AI_MATKEY_SHININESS_STRENGTH, f) == AI_SUCCESS && std::isfinite(f) && f >= 0)
    v.specular *= f;
  if (m.Get(AI_MATKEY_OPACITY, f) == AI_SUCCESS) v.opacity = f;
  if (m.Get(AI_MATKEY_METALLIC_FACTOR, f) == AI_SUCCESS) {
    v.isMetallicRoughness = true;
    v.metallic = f;
    v.roughness = m.Get(AI_MATKEY_ROUGHNESS_FACTOR, f) == AI_SUCCESS ? f : 1.0f;
  }
  return v;
}

// A texture named by a material: embedded ("*0" or by file name) or a file found beside the model
// (texture_lookup.h). Its header is read first: an image larger than --max-pixels is not decoded.
std::shared_ptr<const Texture> loadTexture(const aiScene& scene, const std::string& name, TextureWraps wraps,
                                           const fs::path& modelDir, std::vector<std::string>& warnings,
                                           std::vector<std::string>& files, const fs::path& path, const Limits& limits) {
  const auto warn = [&](const std::string& why) {
    warnings.push_back(path.string() + ": texture \"" + name + "\" " + why + "; rendering untextured");
    return nullptr;
  };
  const auto tooLarge = [&](int w, int h) {
    return std::uint64_t(w) * std::uint64_t(h) > limits.maxPixels;
  };
  const auto sizeText = [](int w, int h) { return std::to_string(w) + "×" + std::to_string(h); };
  const std::string limitText = "more than the limit of " + withThousands(limits.maxPixels) + " pixels (raise it with --max-pixels)";
  int w = 0, h = 0, n = 0;
  stbi_uc* data = nullptr;
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(name.c_str())) {
    if (embedded->mHeight == 0) {
      const auto* bytes = reinterpret_cast<const stbi_uc*>(embedded->pcData);
      if (embedded->mWidth > unsigned(std::numeric_limits<int>::max())) return warn("is too large");
      if (stbi_info_from_memory(bytes, int(embedded->mWidth), &w, &h, &n) && tooLarge(w, h))
        return warn("is " + sizeText(w, h) + " pixels, " + limitText);
      data = stbi_load_from_memory(bytes, int(embedded->mWidth), &w, &h, &n, 4);
    } else {
      if (tooLarge(int(embedded->mWidth), int(embedded->mHeight)))
        return warn("is " + sizeText(int(embedded->mWidth), int(embedded->mHeight)) + " pixels, " + limitText);
      Image img(int(embedded->mWidth), int(embedded->mHeight));
      for (std::size_t i = 0; i < std::size_t(embedded->mWidth) * embedded->mHeight; ++i) {
        const aiTexel& t = embedded->pcData[i];
        img.rgba[i * 4] = t.r, img.rgba[i * 4 + 1] = t.g, img.rgba[i * 4 + 2] = t.b, img.rgba[i * 4 + 3] = t.a;
      }
      return std::make_shared<const Texture>(std::move(img), TexelEncoding::Linear, wraps);
    }
  } else {
    const TextureLookup lookup = findTextureFile(name, modelDir);
    if (lookup.found) files.push_back(lookup.found->string());
    if (!lookup.found) {
      std::string tried;
      for (const std::string& t : lookup.tried) tried += (tried.empty() ? "" : "; ") + t;
      return warn("was not found (tried " + tried + ")");
    }
    if (!stbi_info(lookup.found->c_str(), &w, &h, &n))
      return warn("(" + lookup.found->string() + ") cannot be decoded (" +
                  (stbi_failure_reason() ? stbi_failure_reason() : "unknown reason") + ")");
    if (tooLarge(w, h)) return warn("(" + lookup.found->string() + ") is " + sizeText(w, h) + " pixels, " + limitText);
    data = stbi_load(lookup.found->c_str(), &w, &h, &n, 4);
    if (!data) return warn("(" + lookup.found->string() + ") cannot be decoded (" +
                           (stbi_failure_reason() ? stbi_failure_reason() : "unknown reason") + ")");
  }
  if (!data) return warn(std::string("cannot be decoded (") + (stbi_failure_reason() ? stbi_failure_reason() : "unknown reason") + ")");
  Image img(w, h);
  std::copy(data, data + img.rgba.size(), img.rgba.begin());
  stbi_image_free(data);
  return std::make_shared<const Texture>(std::move(img), TexelEncoding::Linear, wraps);
}

// Whether the material has a texture of `type` (its first), and its name: one with an empty name
// (MD5's, where the file names no shader image) is none.
bool hasTexture(const aiMaterial& material, aiTextureType type, aiString& name) {
  return material.GetTexture(type, 0, &name) == AI_SUCCESS && name.length > 0;
}

// The texture kinds illum draws, in the order it looks them up: the base colour first.
constexpr aiTextureType kDrawnTextures[] = {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE,   aiTextureType_UNKNOWN,
                                            aiTextureType_METALNESS,  aiTextureType_DIFFUSE_ROUGHNESS,
                                            aiTextureType_NORMALS,    aiTextureType_EMISSIVE};

// The texture coordinates (assimp's UV channel) that a material's textures read, as one set: its
// first drawn texture's (glTF's texCoord), with that texture's KHR_texture_transform (`gltf`). A
// mesh keeps one set of coordinates, so a texture of the material that reads another set, or
// transforms it otherwise, is sampled with these: a warning says so.
struct MaterialUv {
  unsigned channel = 0;
  std::optional<UvTransform> transform;
};
MaterialUv materialUv(const aiMaterial& material, bool gltf, const fs::path& path, std::vector<std::string>& warnings) {
  std::optional<MaterialUv> first;
  bool mixed = false;
  for (aiTextureType type : kDrawnTextures) {
    aiString name;
    if (!hasTexture(material, type, name)) continue;
    MaterialUv uv;
    int channel = 0;
    if (material.Get(AI_MATKEY_UVWSRC(type, 0), channel) == AI_SUCCESS && channel >= 0 &&
        channel < AI_MAX_NUMBER_OF_TEXTURECOORDS)
      uv.channel = unsigned(channel);
    aiUVTransform t;
    if (gltf && material.Get(AI_MATKEY_UVTRANSFORM(type, 0), t) == AI_SUCCESS) uv.transform = fromAssimpGltf(t);
    if (!first) first = uv;
    else mixed = mixed || first->channel != uv.channel || first->transform != uv.transform;
  }
  if (mixed)
    warnings.push_back(path.string() + ": material \"" + material.GetName().C_Str() +
                       "\": its textures read different texture coordinates (or transform them differently); all "
                       "are sampled with its first texture's");
  return first.value_or(MaterialUv{});
}

// A mirroring transform (a negative scale: FBX's mirrored instances, the X reader's change of
// handedness at the root) turns the triangles' winding round on screen, so that GL would light
// their outsides as back faces. Modelling programs and three.js keep them front faces; so does a
// preview: a mirrored object draws its mesh wound the other way (the mesh itself where every
// object that draws it is mirrored, else a copy). `mesh[i]`: objects[i]'s index into `meshes`.
void mirrorInstances(std::vector<Object>& objects, const std::vector<unsigned>& mesh,
                     const std::vector<std::shared_ptr<Mesh>>& meshes) {
  const auto mirrored = [](const Object& o) { return glm::determinant(Mat3(o.worldFromObject)) < 0; };
  std::vector<std::uint8_t> drawnPlain(meshes.size(), 0);
  for (std::size_t i = 0; i < objects.size(); ++i) drawnPlain[mesh[i]] |= !mirrored(objects[i]);
  const auto reverse = [](Mesh& m) {
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
  };
  std::map<unsigned, std::shared_ptr<const Mesh>> reversed;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (!mirrored(objects[i])) continue;
    std::shared_ptr<const Mesh>& r = reversed[mesh[i]];
    if (!r) {
      if (drawnPlain[mesh[i]]) {
        auto copy = std::make_shared<Mesh>(*meshes[mesh[i]]);
        reverse(*copy);
        r = std::move(copy);
      } else {
        reverse(*meshes[mesh[i]]);
        r = meshes[mesh[i]];
      }
    }
    objects[i].mesh = r;
  }
}

// A material's texture's wrap modes (glTF's sampler, Collada's and FBX's wrap flags, as assimp
// files them): repeat unless the file says otherwise. assimp's "decal" (nothing outside [0, 1])
// is read as clamp to edge, which GL's modes come nearest to.
TextureWraps textureWraps(const aiMaterial& material, aiTextureType type) {
  const auto wrapOf = [&](const char* key) {
    int mode = aiTextureMapMode_Wrap;
    if (material.Get(key, unsigned(type), 0, mode) != AI_SUCCESS) return TextureWrap::Repeat;
    switch (mode) {
      case aiTextureMapMode_Mirror: return TextureWrap::MirroredRepeat;
      case aiTextureMapMode_Clamp:
      case aiTextureMapMode_Decal: return TextureWrap::ClampToEdge;
      default: return TextureWrap::Repeat;
    }
  };
  return {wrapOf(_AI_MATKEY_MAPPINGMODE_U_BASE), wrapOf(_AI_MATKEY_MAPPINGMODE_V_BASE)};
}

// Collects assimp's warnings while one file is read. Some importers repair broken input with no
// more than a warning (faces with out-of-range indices are dropped); illum refuses such files.
class AssimpWarnings : public Assimp::LogStream {
 public:
  AssimpWarnings() {
    Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(this, Assimp::Logger::Warn | Assimp::Logger::Err);
  }
  ~AssimpWarnings() override {
    Assimp::DefaultLogger::get()->detachStream(this, Assimp::Logger::Warn | Assimp::Logger::Err);
    Assimp::DefaultLogger::kill();
  }
  AssimpWarnings(const AssimpWarnings&) = delete;
  AssimpWarnings& operator=(const AssimpWarnings&) = delete;

  void write(const char* message) override { messages_.emplace_back(message); }
  // The first message that contains `text`, without assimp's "Warn,  T0: " prefix and newline.
  std::optional<std::string> find(const std::string& text) const {
    for (std::string m : messages_) {
      if (m.find(text) == std::string::npos) continue;
      if (auto p = m.find(": "); p != std::string::npos) m = m.substr(p + 2);
      while (!m.empty() && (m.back() == '\n' || m.back() == '\r')) m.pop_back();
      return m;
    }
    return std::nullopt;
  }

 private:
  std::vector<std::string> messages_;
};

// Faces as the file gave them: every face needs vertices, and every index a vertex.
void checkFaces(const aiScene& scene, const fs::path& path) {
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
    const aiMesh& m = *scene.mMeshes[i];
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      // (The message is made only for a face that fails: a model has a hundred thousand good ones.)
      const auto where = [&] { return path.string() + ": mesh \"" + m.mName.C_Str() + "\" face " + std::to_string(f); };
      if (face.mNumIndices == 0 || !face.mIndices)
        throw InputError(where() + " has no vertices (is the file truncated?)");
      for (unsigned c = 0; c < face.mNumIndices; ++c)
        if (face.mIndices[c] >= m.mNumVertices)
          throw InputError(where() + ": index " + std::to_string(face.mIndices[c]) + " is out of range (" +
                           std::to_string(m.mNumVertices) + " vertices)");
    }
  }
}

}  // namespace

Material defaultModelMaterial() {
  Material m;
  m.diffuse = {0.72, 0.72, 0.74, 1};
  m.ambient = m.diffuse;
  m.specular = {0.3, 0.3, 0.3, 1};
  m.shininess = 40;
  return m;
}

Material materialFromFile(const FileMaterialValues& v) {
  Material m;
  m.diffuse = Color4(Color3(v.diffuse), glm::clamp(v.diffuse.a * v.opacity, Real(0), Real(1)));
  m.emission = Color4(v.emission, 1);
  // Files without an ambient colour (glTF, most PLY/STL) reflect ambient light in their diffuse colour.
  m.ambient = Color4(v.hasAmbient ? v.ambient : Color3(v.diffuse), 1);
  if (v.isMetallicRoughness) {
    // glTF's metallic-roughness material is physically based: drawn with cook-torrance unless a
    // model is asked for, and seen by the classic models through its derived GL parameters.
    PhysicalMaterial p;
    p.baseColor = glm::clamp(Color3(v.diffuse), Color3(0), Color3(1));
    p.metallic = glm::clamp(v.metallic, Real(0), Real(1));
    p.roughness = glm::clamp(v.roughness, Real(0), Real(1));
    m.emission = glm::clamp(m.emission, Color4(0), Color4(1));
    m.diffuse.a = glm::clamp(m.diffuse.a, Real(0), Real(1));
    glFromPhysical(m, p);
    m.model = LightingModel::CookTorrance;
    return m;
  } else {
    m.specular = Color4(v.hasSpecular ? v.specular : Color3(0), 1);
    m.shininess = std::max(v.shininess, Real(0));  // MTL Ns is the exponent itself
  }
  for (Color4* c : {&m.ambient, &m.diffuse, &m.specular, &m.emission}) *c = glm::clamp(*c, Color4(0), Color4(1));
  return m;
}

namespace {

// assimp turns the allocation failures of its readers into an error string; under the isolated
// importer's memory limit that is the limit speaking.
[[noreturn]] void readFailed(const fs::path& path, const Assimp::Importer& importer) {
  const std::string why = importer.GetErrorString();
  if (why.find("bad_alloc") != std::string::npos) throw std::bad_alloc();
  throw InputError(path.string() + ": cannot read the model: " + why);
}

// A point cloud's vertices as GL_POINTS: assimp's PLY reader, among others, gives a mesh of
// vertices and no faces, which its validation step (and every later step) would refuse.
// The points count against the triangle limit, checked before any face is made.
void facesForPointClouds(aiScene& scene, const fs::path& path, const Limits& limits) {
  std::uint64_t points = 0;
  for (unsigned i = 0; i < scene.mNumMeshes; ++i)
    if (scene.mMeshes[i]->mNumFaces == 0 && !scene.mMeshes[i]->mFaces) points += scene.mMeshes[i]->mNumVertices;
  if (points > limits.maxTriangles)
    throw InputError(path.string() + ": the model has " + withThousands(points) + " points, more than the limit of " +
                     withThousands(limits.maxTriangles) + " primitives (raise it with --max-triangles)");
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
    aiMesh& m = *scene.mMeshes[i];
    if (m.mNumFaces != 0 || m.mNumVertices == 0 || m.mFaces) continue;
    m.mFaces = new aiFace[m.mNumVertices];
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      m.mFaces[v].mNumIndices = 1;
      m.mFaces[v].mIndices = new unsigned[1]{v};
    }
    m.mNumFaces = m.mNumVertices;
    m.mPrimitiveTypes = aiPrimitiveType_POINT;
  }
}

// Opacity as drawn: vertex colours' alpha replaces the material's (GL_COLOR_MATERIAL).
bool fullyTransparent(const Object& o) {
  if (!o.mesh->colors.empty())
    return std::all_of(o.mesh->colors.begin(), o.mesh->colors.end(), [](const Vec4& c) { return c.a <= 0; });
  return o.material.diffuse.a <= 0;
}

bool hasDrawableTriangle(const Mesh& mesh) {
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const Vec3 &a = mesh.positions[mesh.indices[t]], &b = mesh.positions[mesh.indices[t + 1]],
               &c = mesh.positions[mesh.indices[t + 2]];
    if (glm::length(glm::cross(b - a, c - a)) > 0) return true;
  }
  return false;
}

// assimp's file system with one file under another name: `alias` opens `real`.
class RenamingIOSystem final : public Assimp::DefaultIOSystem {
 public:
  RenamingIOSystem(fs::path alias, fs::path real) : alias_(std::move(alias)), real_(std::move(real)) {}
  bool Exists(const char* file) const override { return DefaultIOSystem::Exists(redirect(file).c_str()); }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    return DefaultIOSystem::Open(redirect(file).c_str(), mode);
  }

 private:
  std::string redirect(const char* file) const { return fs::path(file) == alias_ ? real_.string() : std::string(file); }
  fs::path alias_, real_;
};

}  // namespace

bool isModelFileName(const fs::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext.size() < 2) return false;
  static const Assimp::Importer importer;
  return importer.IsExtensionSupported(ext);
}

ImportedModel importModelInProcess(const fs::path& path, const ImportOptions& options) {
  std::error_code ec;
  checkRegularFile(path, {"model file", nullptr});
  if (fs::file_size(path, ec) == 0) throw InputError(path.string() + ": the model file is empty");
  // The format: the name's, unless the content says otherwise (or standard input's, as told).
  const std::string ext = options.format.empty() ? modelFormatOf(path) : options.format;
  const fs::path companionDir = options.format.empty() ? path.parent_path() : options.companionDir;
  precheckModelFile(path, options.limits, ext);

  AssimpWarnings assimpWarnings;
  Assimp::Importer importer;
  // Points and lines stay, each kind in meshes of its own (SortByPType removes none).
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, 0);
  // Read and validate before anything else: assimp's later steps assert (and abort) on some broken input.
  std::string bytes;  // a file without its format's name is read from memory, with the format as a hint
  if (!options.format.empty()) {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    // assimp's memory reader opens companion files (.mtl, .bin) by their bare names, from the
    // working folder: standard input's companion folder.
  }
  // A file whose name says another format than its content is read under a name that says the
  // content's, beside it, so that its companion files are still found where it is.
  fs::path readAs = path;
  if (bytes.empty() && ext != lowerExtension(path)) {
    readAs = path.parent_path() / (path.filename().string() + ext);
    importer.SetIOHandler(new RenamingIOSystem(readAs, path));
  }
  const aiScene* scene = bytes.empty() ? importer.ReadFile(readAs.string(), 0)
                                       : importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, ext.substr(1).c_str());
  if (!scene) readFailed(path, importer);
  // The importer owns the scene; its own post-processing steps change it in place as this does.
  facesForPointClouds(*const_cast<aiScene*>(scene), path, options.limits);
  scene = importer.ApplyPostProcessing(aiProcess_ValidateDataStructure);
  if (!scene) readFailed(path, importer);
  checkFaces(*scene, path);
  std::uint64_t faces = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) faces += scene->mMeshes[i]->mNumFaces;
  if (faces > options.limits.maxTriangles)
    throw InputError(path.string() + ": the model has " + withThousands(faces) + " faces, more than the limit of " +
                     withThousands(options.limits.maxTriangles) + " triangles (raise it with --max-triangles)");
  // GenUVCoords: a texture mapped spherically, cylindrically, onto a plane or a box (LightWave's,
  // 3DS's and others' projections) gets coordinates of its own, as a UV-mapped one has them.
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_GenUVCoords);
  if (!scene) readFailed(path, importer);
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode || scene->mNumMeshes == 0)
    throw InputError(path.string() + ": the model has no triangles, lines or points");
  if (auto w = assimpWarnings.find("out-of-range")) throw InputError(path.string() + ": indices out of range: " + *w);

  ImportedModel model;
  // Normals the file has that do not say how its faces are shaded: STL stores one per facet, and
  // assimp's Blender reader gives every vertex its smooth normal whether the face is smooth or
  // solid ("Shade Flat", Blender's default cube). Both get crease normals unless --normals file.
  const bool unshapedNormals = ext == ".stl" || ext == ".blend";
  std::vector<MaterialUv> uvs;
  for (unsigned i = 0; i < scene->mNumMaterials; ++i)
    uvs.push_back(materialUv(*scene->mMaterials[i], ext == ".gltf" || ext == ".glb", path, model.warnings));
  std::vector<std::shared_ptr<Mesh>> meshes(scene->mNumMeshes);  // (mirrorInstances may turn one round)
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    aiMesh& m = *scene->mMeshes[i];  // the importer's: released as it is converted
    const MaterialUv uv = m.mMaterialIndex < uvs.size() ? uvs[m.mMaterialIndex] : MaterialUv{};
    Mesh mesh = convertMesh(m, path, options, unshapedNormals, uv.channel);
    if (uv.transform) applyUvTransform(*uv.transform, mesh.uvs);
    meshes[i] = std::make_shared<Mesh>(std::move(mesh));
  }
  std::vector<Material> materials;
  struct MaterialTextures {
    std::shared_ptr<const Texture> diffuse;
    MaterialMaps maps;
  };
  std::vector<MaterialTextures> textures;
  std::map<std::tuple<std::string, TextureWrap, TextureWrap>, std::shared_ptr<const Texture>> textureByName;
  // PLY and STL carry no materials, and an OBJ without MTL neither: assimp fills in placeholders
  // (white diffuse, specular and ambient) that would wash the picture out; use illum's neutral one.
  const bool formatHasMaterials = ext != ".stl" && ext != ".ply";
  for (unsigned i = 0; i < scene->mNumMaterials; ++i) {
    const aiMaterial& am = *scene->mMaterials[i];
    const bool placeholder = !formatHasMaterials || am.GetName() == aiString(AI_DEFAULT_MATERIAL_NAME);
    materials.push_back(placeholder ? defaultModelMaterial() : materialFromFile(readMaterial(am)));
    // The first texture of the first of `types` the material has, with its sampler's wrap modes,
    // each file loaded once for each pair of modes it is used with.
    const auto texture = [&](std::initializer_list<aiTextureType> types) -> std::shared_ptr<const Texture> {
      aiString name;
      for (aiTextureType type : types) {
        if (!hasTexture(am, type, name)) continue;
        const TextureWraps wraps = textureWraps(am, type);
        auto [it, inserted] = textureByName.try_emplace({name.C_Str(), wraps.s, wraps.t}, nullptr);
        if (inserted) it->second = loadTexture(*scene, name.C_Str(), wraps, companionDir, model.warnings, model.files,
                                                 path, options.limits);
        return it->second;
      }
      return nullptr;
    };
    MaterialTextures t;
    t.diffuse = texture({aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE});
    if (!placeholder && materials.back().physicallyBased) {
      // glTF: assimp 5.2 files the metallic-roughness texture under UNKNOWN (GltfMaterial.h).
      t.maps.metallicRoughness = texture({aiTextureType_UNKNOWN, aiTextureType_METALNESS, aiTextureType_DIFFUSE_ROUGHNESS});
      t.maps.normal = texture({aiTextureType_NORMALS});
      float scale = 1;
      if (t.maps.normal && am.Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), scale) == AI_SUCCESS &&
          std::isfinite(scale))
        t.maps.normalScale = std::clamp(Real(scale), Real(-100), Real(100));
      t.maps.emissive = texture({aiTextureType_EMISSIVE});
    }
    textures.push_back(std::move(t));
  }
  model.materialCount = materials.size();
  model.textureCount = std::size_t(std::count_if(textureByName.begin(), textureByName.end(),
                                                 [](const auto& kv) { return kv.second != nullptr; }));

  // Walk the node tree; every (node, mesh) pair is an object with the node's world transform.
  Vec3 lo(std::numeric_limits<Real>::max()), hi(-std::numeric_limits<Real>::max());
  std::vector<std::pair<const aiNode*, Mat4>> stack = {{scene->mRootNode, Mat4(1)}};
  std::size_t visited = 0;
  bool drawable = false;
  std::set<unsigned> untexturedMeshes;  // warned of once, however many nodes draw them
  std::vector<unsigned> instanceMesh;     // each object's assimp mesh
  while (!stack.empty()) {
    auto [node, parent] = stack.back();
    stack.pop_back();
    if (++visited > 1000000) throw InputError(path.string() + ": the node hierarchy is too deep or cyclic");
    const Mat4 world = parent * toMat4(node->mTransformation);
    for (unsigned k = 0; k < node->mNumMeshes; ++k) {
      const unsigned mi = node->mMeshes[k];
      if (mi >= meshes.size() || !meshes[mi] || (meshes[mi]->indices.empty() && !meshes[mi]->hasPointsOrLines())) continue;
      Object o;
      o.mesh = meshes[mi];
      o.worldFromObject = world;
      instanceMesh.push_back(mi);
      const unsigned mat = scene->mMeshes[mi]->mMaterialIndex;
      if (mat < materials.size()) {
        o.material = materials[mat];
        o.diffuseTexture = textures[mat].diffuse;
        o.maps = textures[mat].maps;
        if ((o.diffuseTexture || o.maps.any()) && o.mesh->uvs.empty() && !o.mesh->indices.empty() &&
            untexturedMeshes.insert(mi).second)
          model.warnings.push_back(path.string() + ": mesh \"" + scene->mMeshes[mi]->mName.C_Str() +
                                   "\" has textures but no texture coordinates; rendering it untextured");
      }
      for (const Vec3& p : o.mesh->positions) {
        const Vec3 w = Vec3(world * Vec4(p, 1));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
      }
      drawable = drawable || o.mesh->hasPointsOrLines() || hasDrawableTriangle(*o.mesh);
      model.vertexCount += o.mesh->positions.size();
      model.triangleCount += o.mesh->triangleCount();
      model.pointCount += o.mesh->pointCount();
      model.lineCount += o.mesh->lineCount();
      if (model.triangleCount > options.limits.maxTriangles)
        throw InputError(path.string() + ": the model's instances make more than the limit of " +
                         withThousands(options.limits.maxTriangles) + " triangles (raise it with --max-triangles)");
      model.objects.push_back(std::move(o));
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) stack.push_back({node->mChildren[c], world});
  }
  if (model.objects.empty()) throw InputError(path.string() + ": the model has no triangles, lines or points");
  mirrorInstances(model.objects, instanceMesh, meshes);
  if (!std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z))
    throw InputError(path.string() + ": the node transforms place the model at infinity");
  if (!drawable || hi == lo)
    throw InputError(path.string() + (hi == lo ? ": the model has nothing to draw: all its vertices are at one point"
                                               : ": the model has no drawable triangle (every triangle has zero area)"));
  // Exporters that write <transparency>0</transparency> or an alpha-0 diffuse for opaque
  // surfaces would make the whole model invisible: that is their bug, not the author's intent.
  if (std::all_of(model.objects.begin(), model.objects.end(), fullyTransparent)) {
    model.transparencyIgnored = true;
    for (Object& o : model.objects) {
      o.material.diffuse.a = 1;
      if (!o.mesh->colors.empty()) {
        auto opaque = std::make_shared<Mesh>(*o.mesh);
        for (Vec4& c : opaque->colors) c.a = 1;
        o.mesh = std::move(opaque);
      }
    }
    model.warnings.push_back(path.string() + ": every surface of the model is fully transparent (an exporter's " +
                             "bug, such as Collada's <transparency>0</transparency>); rendering it opaque");
  }
  model.boundsMin = lo;
  model.boundsMax = hi;
  // The up axis: as the file's metadata says (assimp reads FBX's), else the format's habit.
  int axis = 1, sign = 1;
  if (scene->mMetaData && scene->mMetaData->Get("UpAxis", axis) && axis >= 0 && axis <= 2) {
    scene->mMetaData->Get("UpAxisSign", sign);
    Vec3 up(0);
    up[axis] = sign < 0 ? Real(-1) : Real(1);
    if (up != Vec3(0, 1, 0)) model.upAxis = up;
  } else if (ext == ".stl" || ext == ".3ds") {
    model.upAxis = Vec3(0, 0, 1);
  }
  return model;
}

}  // namespace illum

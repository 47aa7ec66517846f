#include "scene/import.h"

#include <illum/error.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cmath>
#include <system_error>

namespace illum {
namespace {

Mat4 toMat4(const aiMatrix4x4& a) {
  // assimp stores row-major; glm is column-major.
  Mat4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = Real(a[r][c]);
  return m;
}

void appendNode(const aiScene& scene, const aiNode& node, const Mat4& parent, Mesh& out,
                const std::filesystem::path& path) {
  const Mat4 worldFromNode = parent * toMat4(node.mTransformation);
  const Mat3 normalFromNode = glm::transpose(glm::inverse(Mat3(worldFromNode)));
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh& m = *scene.mMeshes[node.mMeshes[k]];
    if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    const auto base = std::uint32_t(out.positions.size());
    const bool hasNormals = m.mNormals != nullptr;
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      const aiVector3D& p = m.mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw InputError(path.string() + ": mesh \"" + m.mName.C_Str() + "\" vertex " + std::to_string(v) +
                         ": expected a finite position");
      out.positions.push_back(Vec3(worldFromNode * Vec4(p.x, p.y, p.z, 1)));
      Vec3 n(0);
      if (hasNormals) {
        const aiVector3D& a = m.mNormals[v];
        if (std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z)) n = normalFromNode * Vec3(a.x, a.y, a.z);
      }
      out.normals.push_back(n);
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines are not surfaces
      for (int c = 0; c < 3; ++c) {
        if (face.mIndices[c] >= m.mNumVertices)
          throw InputError(path.string() + ": mesh \"" + m.mName.C_Str() + "\" face " + std::to_string(f) +
                           ": index " + std::to_string(face.mIndices[c]) + " is out of range (" +
                           std::to_string(m.mNumVertices) + " vertices)");
        out.indices.push_back(base + face.mIndices[c]);
      }
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) appendNode(scene, *node.mChildren[c], worldFromNode, out, path);
}

}  // namespace

Mesh importMergedMesh(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string() + ": no such model file");
  if (std::filesystem::file_size(path, ec) == 0) throw InputError(path.string() + ": the model file is empty");

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(
      path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                         aiProcess_ValidateDataStructure);
  if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode)
    throw InputError(path.string() + ": cannot read the model: " + importer.GetErrorString());

  Mesh mesh;
  appendNode(*scene, *scene->mRootNode, Mat4(1), mesh, path);
  if (mesh.indices.empty()) throw InputError(path.string() + ": the model has no triangles");

  // Keep the file's normals where they are sane; fill in the rest from the geometry.
  bool missing = false;
  for (Vec3& n : mesh.normals) {
    const Real len = glm::length(n);
    if (len > Real(1e-20) && std::isfinite(len)) n /= len;
    else missing = true;
  }
  if (missing) {
    const std::vector<Vec3> generated = generateSmoothNormals(mesh.positions, mesh.indices);
    for (std::size_t i = 0; i < mesh.normals.size(); ++i)
      if (!(glm::length(mesh.normals[i]) > Real(0.5))) mesh.normals[i] = generated[i];
  }
  return mesh;
}

}  // namespace illum

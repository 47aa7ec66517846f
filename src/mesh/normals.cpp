// Vertex normals for meshes that come without them.
#include <illum/mesh.h>

#include <cmath>

namespace illum {

std::vector<Vec3> generateSmoothNormals(const std::vector<Vec3>& positions,
                                        const std::vector<std::uint32_t>& indices) {
  std::vector<Vec3> sum(positions.size(), Vec3(0));
  std::vector<Vec3> firstFace(positions.size(), Vec3(0));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t v[3] = {indices[t], indices[t + 1], indices[t + 2]};
    const Vec3 faceCross = glm::cross(positions[v[1]] - positions[v[0]], positions[v[2]] - positions[v[0]]);
    const Real area2 = glm::length(faceCross);
    if (!(area2 > 0)) continue;
    const Vec3 faceNormal = faceCross / area2;
    // Weight by the corner angle so that a vertex's normal does not depend on how the faces
    // around it were split into triangles.
    for (int c = 0; c < 3; ++c) {
      const Vec3 e1 = glm::normalize(positions[v[(c + 1) % 3]] - positions[v[c]]);
      const Vec3 e2 = glm::normalize(positions[v[(c + 2) % 3]] - positions[v[c]]);
      const Real angle = std::acos(glm::clamp(glm::dot(e1, e2), Real(-1), Real(1)));
      sum[v[c]] += angle * faceNormal;
      if (firstFace[v[c]] == Vec3(0)) firstFace[v[c]] = faceNormal;
    }
  }
  std::vector<Vec3> normals(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Real len = glm::length(sum[i]);
    if (len > Real(1e-12)) normals[i] = sum[i] / len;
    else if (firstFace[i] != Vec3(0)) normals[i] = firstFace[i];
    else normals[i] = Vec3(0, 0, 1);  // a vertex on no proper triangle is never lit
  }
  return normals;
}

}  // namespace illum

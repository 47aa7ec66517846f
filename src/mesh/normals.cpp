// Vertex normals for meshes that come without them.
#include <illum/mesh.h>

#include <cmath>
#include <cstring>
#include <algorithm>
#include <cstdint>

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

namespace illum {
namespace {

// An id per distinct position, numbered in order of first appearance: an open-addressing table
// (linear probing over a power-of-two array) keyed by the coordinates' bits, so that equal
// positions, and only they, share an id (−0 counts as +0).
std::vector<std::uint32_t> weldByPosition(const std::vector<Vec3>& positions) {
  constexpr std::uint32_t kEmpty = ~std::uint32_t(0);
  std::size_t capacity = 16;
  while (capacity < positions.size() * 2) capacity *= 2;
  std::vector<std::uint32_t> slots(capacity, kEmpty);  // the first vertex seen at each position
  std::vector<std::uint32_t> ids(positions.size());
  std::vector<std::uint32_t> idOfFirst(positions.size(), 0);
  std::uint32_t next = 0;
  const auto bits = [](Real r) {
    if (r == 0) r = 0;  // −0 is the same place as +0
    std::uint64_t u = 0;
    std::memcpy(&u, &r, sizeof r);
    return u;
  };
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3& p = positions[i];
    std::uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull ^ bits(p.y) * 0xC2B2AE3D27D4EB4Full ^ bits(p.z) * 0x165667B19E3779F9ull;
    h ^= h >> 29;
    for (std::size_t s = std::size_t(h) & (capacity - 1);; s = (s + 1) & (capacity - 1)) {
      const std::uint32_t v = slots[s];
      if (v == kEmpty) {
        slots[s] = std::uint32_t(i);
        idOfFirst[i] = ids[i] = next++;
        break;
      }
      const Vec3& q = positions[v];
      if (bits(q.x) == bits(p.x) && bits(q.y) == bits(p.y) && bits(q.z) == bits(p.z)) {
        ids[i] = idOfFirst[v];
        break;
      }
    }
  }
  return ids;
}

// Copies vertex `from` of `src` (position, uv, colour) to the end of `dst` with normal `n`.
std::uint32_t appendVertex(const Mesh& src, std::uint32_t from, const Vec3& n, Mesh& dst) {
  dst.positions.push_back(src.positions[from]);
  dst.normals.push_back(n);
  if (!src.uvs.empty()) dst.uvs.push_back(src.uvs[from]);
  if (!src.colors.empty()) dst.colors.push_back(src.colors[from]);
  return std::uint32_t(dst.positions.size() - 1);
}

Vec3 faceNormal(const Mesh& m, std::size_t t) {
  const Vec3& a = m.positions[m.indices[t]];
  const Vec3 n = glm::cross(m.positions[m.indices[t + 1]] - a, m.positions[m.indices[t + 2]] - a);
  const Real len = glm::length(n);
  return len > 0 && std::isfinite(len) ? n / len : Vec3(0);
}

}  // namespace

void generateFlatNormals(Mesh& mesh) {
  Mesh out;
  out.positions.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Vec3 n = faceNormal(mesh, t);
    if (n == Vec3(0)) n = Vec3(0, 0, 1);
    for (int c = 0; c < 3; ++c) out.indices.push_back(appendVertex(mesh, mesh.indices[t + std::size_t(c)], n, out));
  }
  mesh = std::move(out);
}

void generateCreaseNormals(Mesh& mesh, Real creaseAngleDegrees) {
  const std::size_t triangles = mesh.indices.size() / 3;
  // Weld by position so that faces meeting at split vertices (uv seams, STL soups) still share.
  const std::vector<std::uint32_t> positionId = weldByPosition(mesh.positions);
  const std::size_t welded = positionId.empty() ? 0 : *std::max_element(positionId.begin(), positionId.end()) + 1;
  // Face normals and corner angles.
  std::vector<Vec3> faceN(triangles);
  std::vector<Real> cornerAngle(triangles * 3);
  for (std::size_t f = 0; f < triangles; ++f) {
    faceN[f] = faceNormal(mesh, f * 3);
    for (int c = 0; c < 3; ++c) {
      const Vec3& p = mesh.positions[mesh.indices[f * 3 + std::size_t(c)]];
      const Vec3 e1 = mesh.positions[mesh.indices[f * 3 + std::size_t((c + 1) % 3)]] - p;
      const Vec3 e2 = mesh.positions[mesh.indices[f * 3 + std::size_t((c + 2) % 3)]] - p;
      const Real l = glm::length(e1) * glm::length(e2);
      cornerAngle[f * 3 + std::size_t(c)] = l > 0 ? std::acos(glm::clamp(glm::dot(e1, e2) / l, Real(-1), Real(1))) : Real(0);
    }
  }
  // Faces around each welded position (compressed rows).
  std::vector<std::uint32_t> start(welded + 1, 0), faces(triangles * 3);
  for (std::uint32_t v : mesh.indices) ++start[positionId[v] + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < mesh.indices.size(); ++k) faces[fill[positionId[mesh.indices[k]]]++] = std::uint32_t(k);

  const Real cosCrease = std::cos(glm::radians(glm::clamp(creaseAngleDegrees, Real(0), Real(180))));
  Mesh out;
  out.positions.reserve(mesh.positions.size());
  out.normals.reserve(mesh.positions.size());
  out.indices.reserve(mesh.indices.size());
  // Corners at one position with the same normal, uv and colour share one new vertex. The new
  // vertices of each welded position form a short list (head per position, next per vertex),
  // searched by comparing the three attributes exactly.
  constexpr std::uint32_t kNone = ~std::uint32_t(0);
  std::vector<std::uint32_t> head(welded, kNone), next;
  next.reserve(mesh.positions.size());
  for (std::size_t k = 0; k < mesh.indices.size(); ++k) {
    const std::size_t f = k / 3;
    const std::uint32_t v = mesh.indices[k];
    Vec3 sum(0);
    const std::uint32_t pid = positionId[v];
    for (std::uint32_t r = start[pid]; r < start[pid + 1]; ++r) {
      const std::size_t g = faces[r] / 3;
      if (faceN[f] == Vec3(0) || glm::dot(faceN[f], faceN[g]) >= cosCrease - Real(1e-6)) sum += cornerAngle[faces[r]] * faceN[g];
    }
    const Real len = glm::length(sum);
    const Vec3 n = len > Real(1e-20) ? sum / len : (faceN[f] != Vec3(0) ? faceN[f] : Vec3(0, 0, 1));
    const Vec2 uv = mesh.uvs.empty() ? Vec2(0) : mesh.uvs[v];
    const Vec4 color = mesh.colors.empty() ? Vec4(0) : mesh.colors[v];
    std::uint32_t found = head[pid];
    while (found != kNone && !(out.normals[found] == n && (mesh.uvs.empty() || out.uvs[found] == uv) &&
                               (mesh.colors.empty() || out.colors[found] == color)))
      found = next[found];
    if (found == kNone) {
      found = appendVertex(mesh, v, n, out);
      next.push_back(head[pid]);
      head[pid] = found;
    }
    out.indices.push_back(found);
  }
  mesh = std::move(out);
}

}  // namespace illum

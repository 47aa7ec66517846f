#include "raster/vertex.h"

#include "math/transform.h"
#include "raster/clip.h"
#include "raster/setup.h"
#include "shading/shade_points.h"

#include <algorithm>

namespace illum {

namespace {

constexpr std::size_t kLightingBatch = 256;  // vertices lit together, as structure of arrays

// Lights vertices [first, last) of `out` (eye position, normal and colour already set) in
// batches: front colours with N, and under two-sided lighting back colours with −N.
void lightVertices(const FrameContext& frame, const Object& object, std::vector<ShadedVertex>& out, std::size_t first,
                   std::size_t last) {
  const ShadeSetup setup{frame.lights, frame.lightModel, modelOf(object.material, frame.model), object.material};
  const bool hasColors = !object.mesh->colors.empty();
  Real soa[14][kLightingBatch];  // position xyz, normal xyz, colour rgba, result rgba
  for (std::size_t b = first; b < last; b += kLightingBatch) {
    const std::size_t n = std::min(kLightingBatch, last - b);
    for (std::size_t k = 0; k < n; ++k) {
      const ShadedVertex& v = out[b + k];
      for (int c = 0; c < 3; ++c) soa[c][k] = v.eyePosition[c], soa[3 + c][k] = v.eyeNormal[c];
      if (hasColors)
        for (int c = 0; c < 4; ++c) soa[6 + c][k] = v.color[c];
    }
    SurfacePoints points;
    points.count = n;
    for (int c = 0; c < 3; ++c) points.position[c] = soa[c], points.normal[c] = soa[3 + c];
    if (hasColors)
      for (int c = 0; c < 4; ++c) points.color[c] = soa[6 + c];
    Real* const result[4] = {soa[10], soa[11], soa[12], soa[13]};
    shadePoints(setup, points, result);
    for (std::size_t k = 0; k < n; ++k) out[b + k].front = {soa[10][k], soa[11][k], soa[12][k], soa[13][k]};
    if (!frame.lightModel.twoSided) continue;
    for (int c = 3; c < 6; ++c)
      for (std::size_t k = 0; k < n; ++k) soa[c][k] = -soa[c][k];
    shadePoints(setup, points, result);
    for (std::size_t k = 0; k < n; ++k) out[b + k].back = {soa[10][k], soa[11][k], soa[12][k], soa[13][k]};
  }
}

}  // namespace

void runVertexStage(const FrameContext& frame, const Object& object, std::vector<ShadedVertex>& out,
                    std::size_t first, std::size_t last) {
  const Mesh& mesh = *object.mesh;
  const Mat4 viewFromObject = frame.viewFromWorld * object.worldFromObject;  // GL_MODELVIEW
  const Mat4 clipFromObject = frame.clipFromView * viewFromObject;
  const Mat3 normalFromObject = normalMatrix(viewFromObject);
  const bool hasUvs = !mesh.uvs.empty(), hasColors = !mesh.colors.empty();
  for (std::size_t i = first; i < last; ++i) {
    ShadedVertex& v = out[i];
    const Vec4 p(mesh.positions[i], 1);
    v.clip = clipFromObject * p;
    v.outcode = clipOutcode(v.clip, frame.width, frame.height);
    v.hasWindow = v.outcode == 0;
    if (v.hasWindow) v.window = toWindow(v.clip, frame.width, frame.height);
    v.eyePosition = Vec3(viewFromObject * p);
    const Vec3 n = normalFromObject * mesh.normals[i];
    const Real len = glm::length(n);
    v.eyeNormal = len > 0 ? n / len : n;
    if (hasUvs) v.uv = mesh.uvs[i];
    if (hasColors) v.color = mesh.colors[i];
  }
  if (frame.shading != Shading::Phong) lightVertices(frame, object, out, first, last);
}

ShadedVertex lerp(const ShadedVertex& a, const ShadedVertex& b, Real t) {
  ShadedVertex v;
  v.clip = a.clip + t * (b.clip - a.clip);
  v.eyePosition = a.eyePosition + t * (b.eyePosition - a.eyePosition);
  v.eyeNormal = a.eyeNormal + t * (b.eyeNormal - a.eyeNormal);
  v.front = a.front + t * (b.front - a.front);
  v.back = a.back + t * (b.back - a.back);
  v.uv = a.uv + t * (b.uv - a.uv);
  v.color = a.color + t * (b.color - a.color);
  return v;
}

}  // namespace illum

#include "raster/setup/vertex.h"

#include "math/transform.h"
#include "raster/setup/clip.h"
#include "raster/setup/setup.h"
#include "raster/setup/vertex_transform.h"
#include "shading/shade_points.h"

#include <algorithm>

namespace illum {

namespace {

// Lights a batch of transformed vertices (the object's from `first` on): front colours with N, and
// under two-sided lighting back colours with −N, into out[0, n); each side's ambient occluded as
// seen along its normal when the frame traces occlusion.
void lightBatch(const FrameContext& frame, const Object& object, std::uint32_t objectIndex, std::size_t first,
                TransformedVertices& batch, const Color4* colors, std::size_t n, ShadedVertex* out) {
  const ShadeSetup setup{frame.lights, frame.lightModel, modelOf(object.material, frame.model), object.material};
  Real color[4][kVertexBatch], result[4][kVertexBatch];
  SurfacePoints points;
  points.count = n;
  for (int c = 0; c < 3; ++c) points.position[c] = batch.eye[c], points.normal[c] = batch.normal[c];
  if (colors) {
    for (std::size_t k = 0; k < n; ++k)
      for (int c = 0; c < 4; ++c) color[c][k] = colors[k][c];
    for (int c = 0; c < 4; ++c) points.color[c] = color[c];
  }
  Real* const lit[4] = {result[0], result[1], result[2], result[3]};
  Real open[kVertexBatch];
  std::uint64_t seed[kVertexBatch];
  const auto occlude = [&](bool back) {
    if (!frame.occlusion) return;
    for (std::size_t k = 0; k < n; ++k) seed[k] = OcclusionQuery::vertexSeed(objectIndex, first + k, back);
    frame.occlusion->open(n, points.position, points.normal, seed, open);
    points.ambientOpen = open;
  };
  occlude(false);
  shadePoints(setup, points, lit);
  for (std::size_t k = 0; k < n; ++k) out[k].front = {result[0][k], result[1][k], result[2][k], result[3][k]};
  if (!frame.lightModel.twoSided) return;
  for (int c = 0; c < 3; ++c)
    for (std::size_t k = 0; k < n; ++k) batch.normal[c][k] = -batch.normal[c][k];
  occlude(true);
  shadePoints(setup, points, lit);
  for (std::size_t k = 0; k < n; ++k) out[k].back = {result[0][k], result[1][k], result[2][k], result[3][k]};
}

}  // namespace

void runVertexStage(const FrameContext& frame, const Object& object, std::uint32_t objectIndex,
                    std::span<ShadedVertex> out, std::size_t first, std::size_t last) {
  const Mesh& mesh = *object.mesh;
  VertexTransform transform;
  transform.viewFromObject = frame.viewFromWorld * object.worldFromObject;  // GL_MODELVIEW
  transform.clipFromObject = frame.clipFromView * transform.viewFromObject;
  transform.normalFromObject = normalMatrix(transform.viewFromObject);
  transform.width = frame.width, transform.height = frame.height;
  const bool hasUvs = !mesh.uvs.empty(), hasColors = !mesh.colors.empty();
  TransformedVertices batch;
  for (std::size_t b = first; b < last; b += kVertexBatch) {
    const std::size_t n = std::min(kVertexBatch, last - b);
    transformVertices(transform, &mesh.positions[b], &mesh.normals[b], n, batch);
    for (std::size_t k = 0; k < n; ++k) {
      ShadedVertex& v = out[b + k];
      v.clip = {batch.clip[0][k], batch.clip[1][k], batch.clip[2][k], batch.clip[3][k]};
      v.outcode = batch.outcode[k];
      v.hasWindow = v.outcode == 0;
      if (v.hasWindow) v.window = {batch.windowX[k], batch.windowY[k], batch.windowZ[k], batch.invW[k]};
      v.eyePosition = {batch.eye[0][k], batch.eye[1][k], batch.eye[2][k]};
      v.eyeNormal = {batch.normal[0][k], batch.normal[1][k], batch.normal[2][k]};
      if (hasUvs) v.uv = mesh.uvs[b + k];
      if (hasColors) v.color = mesh.colors[b + k];
    }
    if (frame.shading != Shading::Phong)
      lightBatch(frame, object, objectIndex, b, batch, hasColors ? &mesh.colors[b] : nullptr, n, &out[b]);
  }
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

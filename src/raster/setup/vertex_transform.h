// The vertex stage's arithmetic for a batch of vertices at once (SIMD, Highway, dispatched at run
// time): object → clip and eye space, normals by the normal matrix and renormalized, clip
// outcodes and window positions. Bit for bit what the one-vertex formulas compute: glm's matrix
// products in glm's order, clipOutcode and toWindow (tested against them on every target).
#pragma once

#include "raster/frame_context.h"

#include <cstddef>
#include <cstdint>

namespace illum {

constexpr std::size_t kVertexBatch = 256;

struct VertexTransform {
  Mat4 clipFromObject;    // GL_PROJECTION · GL_MODELVIEW
  Mat4 viewFromObject;    // GL_MODELVIEW
  Mat3 normalFromObject;  // its inverse transpose
  int width = 0, height = 0;
};

// Up to kVertexBatch vertices, structure of arrays.
struct TransformedVertices {
  Real clip[4][kVertexBatch];
  Real eye[3][kVertexBatch];
  Real normal[3][kVertexBatch];  // unit length, or as transformed when that is zero
  std::uint32_t outcode[kVertexBatch];
  // toWindow(clip), only where the outcode is 0 (inside the clip volume).
  std::int64_t windowX[kVertexBatch], windowY[kVertexBatch];
  Real windowZ[kVertexBatch], invW[kVertexBatch];
};

// Vertices [0, n) of `positions` and `normals` (n ≤ kVertexBatch).
void transformVertices(const VertexTransform& t, const Vec3* positions, const Vec3* normals, std::size_t n,
                       TransformedVertices& out);

}  // namespace illum

// What glTF's texture maps do to a surface point once their texels are sampled (glTF 2.0 §3.9):
// the same lines for the rasterizer's per-pixel shading and for the ray tracers, which differ only
// in how they find a texel's footprint.
#pragma once

#include <illum/lighting.h>
#include <illum/real.h>

#include <array>
#include <optional>

namespace illum {

// The texels of an object's maps at one point; each is present when the object has that map.
struct MapTexels {
  std::optional<Vec4> metallicRoughness;
  std::optional<Vec4> normal;
  std::optional<Vec4> emissive;
};

// The material with the texels applied: roughness × G and metallic × B of a physically based
// material (the classic models keep the GL parameters derived from the factors), and the emission
// colour × the emissive texel's RGB.
Material withMapTexels(Material m, const MapTexels& texels);

// A triangle's tangent frame: how the position moves per unit of u (∂P/∂u) and of v (∂P/∂v),
// from its three positions and texture coordinates, in whatever space the positions are given.
// Zero vectors when the uvs are degenerate (all on a line).
struct TangentFrame {
  Vec3 dPdu{0}, dPdv{0};
};
TangentFrame triangleTangents(const std::array<Vec3, 3>& p, const std::array<Vec2, 3>& uv);

// The normal a tangent-space normal map gives: n = (2·rgb − 1) with X and Y × `scale`, in the frame
// of the unit normal N, the tangent ∂P/∂u made orthogonal to N, and the bitangent N × T on the
// side ∂P/∂v points to. Returns N itself where the frame is degenerate or the map's normal is zero.
Vec3 normalFromMap(const Vec3& N, const TangentFrame& frame, const Vec4& texel, Real scale);

}  // namespace illum

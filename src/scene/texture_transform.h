// glTF's KHR_texture_transform: a texture's coordinates offset, rotated and scaled before it is
// sampled (uv' = T·R·S·uv in glTF's texture space, whose v runs down). illum keeps one set of
// coordinates per mesh, so the transform of a material's textures is baked into the coordinates
// of the meshes that use it.
#pragma once

#include <illum/mesh.h>

#include <assimp/material.h>

namespace illum {

struct UvTransform {
  Vec2 offset{0, 0};
  Real rotation = 0;  // radians, counter-clockwise in the picture
  Vec2 scale{1, 1};
  bool operator==(const UvTransform&) const = default;
};

// The extension's own values from what assimp 5.2's glTF 2 reader files under
// AI_MATKEY_UVTRANSFORM: the scale as it is, the rotation negated, and the offset moved to a
// translation about assimp's centre of rotation, which assimp's own TransformUVCoords step then
// undoes wrongly for rotations and scales (assimp issues 6035, pull request 6804): its change of
// coordinates, inverted.
UvTransform fromAssimpGltf(const aiUVTransform& t);

// Applies `t` to texture coordinates in GL's convention (v up, as illum's meshes keep them).
void applyUvTransform(const UvTransform& t, std::vector<Vec2>& uvs);

}  // namespace illum

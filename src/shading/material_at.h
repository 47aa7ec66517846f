// The material at a surface point, asked for once (as pbrt-v4's GetBSDF and Filament's
// PixelParams): the object's material with its vertex colour, its texture (as the base colour or as
// GL_MODULATE's factor) and glTF's metallic-roughness, emissive and normal maps applied. The
// rasterizer, both ray tracers, ambient occlusion and the path tracer all come here; they differ
// only in how they find a texel's footprint (the `sample` callable).
#pragma once

#include <illum/lighting.h>
#include <illum/scene.h>

#include "shading/material_maps.h"

#include <optional>

namespace illum {

// The texture that colours an object's points: its diffuse texture, when its mesh has the
// coordinates to look it up; otherwise null.
inline const Texture* drawnTexture(const Object& object) {
  return object.diffuseTexture && !object.mesh->uvs.empty() ? object.diffuseTexture.get() : nullptr;
}

// Whether glTF's other maps (metallic-roughness, normal, emissive) shape an object's points: where
// the point is lit on its own (per-pixel shading or a ray) and its mesh has uvs.
inline bool mapsDrawn(const Object& object, bool litPerPoint) {
  return litPerPoint && object.maps.any() && !object.mesh->uvs.empty();
}

// Whether an object's texel is its base colour, multiplied in before lighting: a physically based
// model lit at the point itself (glTF's baseColorTexture, under Phong shading or a ray).
// Otherwise GL_MODULATE multiplies the lit colour by the texel, as GL does (and as the per-vertex
// frequencies must).
inline bool texelIsBaseColor(const Object& object, LightingModel sceneModel, bool litPerPoint) {
  return drawnTexture(object) && litPerPoint && modelOf(object.material, sceneModel) == LightingModel::CookTorrance;
}

// The material with its base colour (or vertex colour) multiplied by a texel.
inline Material withBaseTexel(const Material& m, const Vec4& texel) {
  return withVertexColor(m, Color4(physicalOf(m).baseColor, m.diffuse.a) * texel);
}

struct PointMaterial {
  Material material;              // vertex colour, base texel and map texels applied
  LightingModel model{};          // the lighting model that draws it
  bool textured = false;          // the object's texture was looked up here
  Vec4 texel{1};                  // its texel
  bool texelIsBaseColor = false;  // it tinted the base colour (else it modulates the lit colour)
  std::optional<Vec4> normalTexel;  // the normal map's texel, for normalFromMap in the caller's frame

  // What GL_MODULATE multiplies the lit colour by (1 when the texel was the base colour).
  Vec4 modulation() const { return textured && !texelIsBaseColor ? texel : Vec4(1); }
};

// The material at a point of `object`, lit per point or not (`litPerPoint`), with its interpolated
// vertex colour (null when the mesh has none). `sample(texture)` gives a texture's filtered texel
// at the point.
template <class Sample>
PointMaterial materialAt(const Object& object, LightingModel sceneModel, bool litPerPoint, const Color4* vertexColor,
                         Sample&& sample) {
  PointMaterial p;
  p.material = vertexColor ? withVertexColor(object.material, *vertexColor) : object.material;
  p.model = modelOf(p.material, sceneModel);
  if (const Texture* texture = drawnTexture(object)) {
    p.textured = true;
    p.texel = sample(*texture);
    p.texelIsBaseColor = texelIsBaseColor(object, sceneModel, litPerPoint);
    if (p.texelIsBaseColor) p.material = withBaseTexel(p.material, p.texel);
  }
  if (mapsDrawn(object, litPerPoint)) {
    const MaterialMaps& maps = object.maps;
    MapTexels texels;
    if (maps.metallicRoughness) texels.metallicRoughness = sample(*maps.metallicRoughness);
    if (maps.emissive) texels.emissive = sample(*maps.emissive);
    p.material = withMapTexels(p.material, texels);
    if (maps.normal) p.normalTexel = sample(*maps.normal);
  }
  return p;
}

}  // namespace illum

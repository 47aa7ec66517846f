// Ambient occlusion for the rasterizer's picture: at each pixel's centre, a camera ray finds the
// surface, rays over its hemisphere (cosine-weighted, stratified, seeded by the pixel alone) find
// how much of it is open within a distance, and the pixel loses that share of its ambient term.
// Ray-traced on Embree, so it has none of screen-space AO's halos or missing occluders.
#pragma once

#include <illum/image.h>
#include <illum/scene.h>

namespace illum {

// Darkens `image` (the rasterizer's linear bytes, rows top to bottom, before display encoding):
// each pixel's lit colour c = clamp(e + a + d + s)·t becomes clamp(e + k·a + d + s)·t, with the
// terms evaluated at the pixel centre's surface point and t GL_MODULATE's texel.
void applyAmbientOcclusion(const Scene& scene, Image& image);

// The distance occlusion rays travel in a scene: as set, else a fifth of its bounds' diagonal.
Real occlusionDistance(const Scene& scene);

}  // namespace illum

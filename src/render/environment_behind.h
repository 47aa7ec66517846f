// The environment shown behind the scene ("environment_background"): every renderer draws the
// scene over a transparent background, and each pixel's colour is laid over the environment's
// displayed radiance by its alpha (the coverage an edge or a translucent surface leaves).
#pragma once

#include <illum/image.h>
#include <illum/scene.h>

namespace illum {

// Whether the picture shows the environment behind the scene: asked for, and the background not
// made transparent (--no-background keeps the environment's light and drops its picture).
bool showsEnvironmentBehind(const Scene& scene);

// `image` (display-encoded bytes, drawn over a transparent background) laid over the environment
// seen through each pixel's centre, tone-mapped and encoded as the scene's display says; opaque.
void layEnvironmentBehind(const Scene& scene, Image& image);

}  // namespace illum

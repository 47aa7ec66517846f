// Captions that stay true: a label's text is a template over what it describes, filled in from
// the scene as it is drawn, so that an override or a sheet's axis that changes a light, a material
// or the model changes the caption with it (docs/scene-format.md, "labels").
//
//   {model}, {model.description}       the scene's lighting model: "phong", "Phong: ambient + ..."
//   {convention}, {convention.description}  gl or a lecture note's (light_model's convention)
//   {shading}, {shading.description}   its shading frequency (or ray tracer): "gouraud", "Gouraud shading: ..."
//   {renderer}                         raster, whitted, hall or path
//   {light.N.KEY}                      position, ambient, diffuse, specular, attenuation,
//                                      spot_direction, spot_cutoff, spot_exponent (N from 0)
//   {object.N.material.KEY}            ambient, diffuse, specular, emission, shininess, base_color,
//                                      metallic, roughness
//   {object.N.model}                   the model that object is lit by
//   {object.N.highlight}               its highlight as that model sees it: "n = 60", "no specular",
//                                      "roughness 0.25"
#pragma once

#include <illum/scene.h>

#include <string>

namespace illum {

// The smallest caption a picture keeps when it is drawn smaller than its scene was made for (a
// sheet's panel, a thumbnail): below it, text is guessed at rather than read.
constexpr Real kReadableCaption = 10;

// The text with every {placeholder} filled in from `scene`. Throws InputError naming a
// placeholder it does not know or a light or object the scene lacks.
std::string expandCaption(const std::string& text, const Scene& scene);

// What the lighting model (as the convention computes it), the convention and the shading (or ray
// tracer) are, in a line each, as the built-in scene's titles say them.
std::string describeModel(LightingModel model, Convention convention = Convention::GL);
std::string describeConvention(Convention convention);
std::string describeShading(Shading shading, RendererKind renderer);

// Why a picture of the scene comes out black where its objects are, when the lights reach none of
// the points the scene is lit at (its vertices under flat and Gouraud shading): "no light", "every
// light is behind the surfaces", "no vertex lies inside a spot's cone (flat and Gouraud shading
// light the vertices only)"; empty when some light reaches some point.
std::string whyUnlit(const Scene& scene);

}  // namespace illum

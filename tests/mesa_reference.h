// The reference renderer: Mesa's llvmpipe through OSMesa, drawing a scene with OpenGL's
// fixed-function lighting (blinn-phong with flat or Gouraud shading) or with a small GLSL
// program that evaluates the same OpenGL 2.1 §2.14.1 equation per vertex or per pixel.
#pragma once

#include <illum/image.h>
#include <illum/scene.h>

namespace illum::test {

enum class MesaPath { FixedFunction, GlslPerVertex, GlslPerPixel };

// The path that renders `scene` as GL would: fixed function where GL has it.
MesaPath mesaPathFor(const Scene& scene);

// Renders with Mesa; row 0 at the top, like illum's images. Throws std::runtime_error when
// OSMesa cannot make a context or a shader does not compile.
Image renderWithMesa(const Scene& scene, MesaPath path);

}  // namespace illum::test

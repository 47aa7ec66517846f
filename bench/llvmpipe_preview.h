// The llvmpipe peer of a model preview: Mesa's llvmpipe (through OSMesa) drawing the scene illum
// prepares for a model file (the same imported meshes, materials, textures, camera and light rig)
// the way a viewer application would: every mesh, colour and uv in buffer objects and every texture
// (sRGB colour textures as GL_SRGB8_ALPHA8, mipmapped) uploaded once; per frame, clear, the opaque
// objects and then the translucent ones back to front with blending, one per-pixel GLSL program
// that evaluates each material's model (GL's equation for the classic models, Cook-Torrance with
// GGX, Smith-GGX visibility and Schlick's Fresnel for physically based ones) with the texel as
// GL_MODULATE's factor or the base colour, two-sided lighting, and the display's sRGB encoding;
// multisampled through a multisampled framebuffer object resolved by glBlitFramebuffer.
#pragma once

#include <illum/image.h>
#include <illum/scene.h>

#include <cstdint>
#include <vector>

namespace illum::bench {

class PreviewSession {
 public:
  // `samples` per pixel: 1, or what a multisampled renderbuffer takes (llvmpipe: up to 4).
  PreviewSession(const Scene& scene, int samples);
  ~PreviewSession();
  PreviewSession(const PreviewSession&) = delete;
  PreviewSession& operator=(const PreviewSession&) = delete;

  void draw();  // one frame, finished (glFinish)
  Image image() const;

 private:
  struct Draw {
    std::size_t object;
    unsigned buffer = 0, indices = 0, texture = 0;
    bool colors = false, uvs = false;
  };
  const Scene& scene_;
  int samples_;
  std::vector<std::uint8_t> pixels_;
  void* context_ = nullptr;
  unsigned program_ = 0, framebuffer_ = 0, colorBuffer_ = 0, depthBuffer_ = 0;
  std::vector<Draw> draws_;  // in drawing order: opaque first, then translucent back to front
};

}  // namespace illum::bench

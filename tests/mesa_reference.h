// The reference renderer: Mesa's llvmpipe through OSMesa, drawing a scene with OpenGL's
// fixed-function lighting (blinn-phong with flat or Gouraud shading) or with a small GLSL
// program that evaluates the same OpenGL 2.1 §2.14.1 equation per vertex or per pixel.
#pragma once

#include <illum/image.h>
#include <illum/scene.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace illum::test {

enum class MesaPath { FixedFunction, GlslPerVertex, GlslPerPixel };

// The path that renders `scene` as GL would: fixed function where GL has it.
MesaPath mesaPathFor(const Scene& scene);

// One OSMesa context set up for a scene: GL state, lights, program, and every mesh in buffer
// objects, so that draw() is one frame as an application would draw it (clear, the draws,
// glFinish): what the bench times. Throws std::runtime_error when OSMesa cannot make a context or
// a shader does not compile.
class MesaSession {
 public:
  MesaSession(const Scene& scene, MesaPath path);
  ~MesaSession();
  MesaSession(const MesaSession&) = delete;
  MesaSession& operator=(const MesaSession&) = delete;

  void draw();
  Image image() const;  // the last frame, row 0 at the top like illum's images

 private:
  const Scene& scene_;
  std::vector<std::uint8_t> buffer_;
  void* context_ = nullptr;
  unsigned program_ = 0;
  std::vector<std::pair<unsigned, unsigned>> meshBuffers_;  // vertex and index buffer per object
  std::vector<std::vector<float>> colors_, uvs_;             // per object, from client memory
  std::vector<unsigned> textures_;                          // per object, 0 for none
};

// Renders with Mesa; row 0 at the top, like illum's images.
Image renderWithMesa(const Scene& scene, MesaPath path);

// What the GL peers share (the parity reference, and the benchmarks' preview peer), in the current
// context: a shader compiled (GLenum type; throws std::runtime_error with GL's log), a matrix
// loaded as glLoadMatrixf, and one light set as glLight (`id` is GL_LIGHT0 + i).
unsigned compileShader(unsigned type, const std::string& source);
void loadMatrix(const Mat4& m);
void setLight(unsigned id, const Light& light);

}  // namespace illum::test

// Ambient occlusion as the equation takes it: how open the hemisphere over each point of a batch
// is (1: nothing in the way within the scene's occlusion distance), which scales the point's
// ambient term (SurfacePoints::ambientOpen) before its colour is quantised. The rasterizer asks for
// it at the points it lights, pixels or vertices; it is answered from above (render/ hands over a
// ray-traced one, trace/ambient_occlusion.h), so that the rasterizer needs no ray tracer.
#pragma once

#include <illum/real.h>

#include <cstddef>
#include <cstdint>

namespace illum {

class OcclusionQuery {
 public:
  virtual ~OcclusionQuery() = default;
  // open[i] for the points i < count: their eye-space positions and the unit normals of the sides
  // lit; seed[i] is the point's own number (a pixel's, a vertex's), which picks its rays, so that
  // every run and every thread count traces the same ones. Safe to call from many threads at once.
  virtual void open(std::size_t count, const Real* const position[3], const Real* const normal[3],
                    const std::uint64_t* seed, Real* open) const = 0;

  // Seeds: a pixel of a width-wide frame (x, GL row y), and a vertex's side (N or −N).
  static std::uint64_t pixelSeed(int x, int y, int width) {
    return std::uint64_t(std::uint32_t(y)) * std::uint64_t(std::uint32_t(width)) + std::uint64_t(std::uint32_t(x));
  }
  static std::uint64_t vertexSeed(std::uint32_t object, std::size_t vertex, bool back) {
    return std::uint64_t(1) << 63 | std::uint64_t(back) << 62 | std::uint64_t(object) << 32 | std::uint64_t(vertex);
  }
};

}  // namespace illum

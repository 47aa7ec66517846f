// Ambient occlusion for the rasterizer, ray-traced on Embree: at each point it lights (a pixel's
// visible surface, or a vertex for flat and Gouraud shading), rays over the hemisphere of the side
// it lights (cosine-weighted, stratified, seeded by the point's own number) find how much of it is
// open within a distance, and that share scales the point's ambient term (shading/occlusion.h)
// before its colour is quantised. None of screen-space AO's halos or missing occluders.
#pragma once

#include <illum/scene.h>

#include "shading/occlusion.h"

#include <memory>

namespace illum {

class RayScene;

class TracedOcclusion final : public OcclusionQuery {
 public:
  // The scene's triangles in one BVH, and its occlusion settings (rays, distance).
  explicit TracedOcclusion(const Scene& scene);
  ~TracedOcclusion() override;
  void open(std::size_t count, const Real* const position[3], const Real* const normal[3], const std::uint64_t* seed,
            Real* open) const override;

 private:
  std::unique_ptr<RayScene> rays_;
  Real distance_;
  int count_;
};

// The distance occlusion rays travel in a scene: as set, else a fifth of its bounds' diagonal.
Real occlusionDistance(const Scene& scene);

}  // namespace illum

// The scene as the ray tracers see it: every object's triangles in eye space (the space the
// rasterizer lights in), in one Embree 3 BVH, with what shading a hit needs beside them.
#pragma once

#include <illum/scene.h>

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

namespace illum {

// A ray in eye space: points o + t·d for t in (tNear, tFar).
struct Ray {
  Vec3 origin{0};
  Vec3 direction{0, 0, -1};
  Real tNear = 0;
  Real tFar = std::numeric_limits<Real>::infinity();
};

// Where a ray first meets the scene.
struct RayHit {
  Real t = 0;
  std::uint32_t object = 0;    // index into Scene::objects
  std::uint32_t triangle = 0;  // of that object's mesh
  Real u = 0, v = 0;           // Embree's barycentrics: P = (1−u−v)·p0 + u·p1 + v·p2
};

// One object's vertices in eye space, as the vertex stage computes them.
struct EyeMesh {
  const Object* object = nullptr;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // unit (or zero, where the model-view squashed them)
};

class RayScene {
 public:
  // Builds the BVH of `scene`'s objects seen from its camera (eye space = GL's, view matrix applied).
  explicit RayScene(const Scene& scene);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // The closest hit in (tNear, tFar), if any.
  bool intersect(const Ray& ray, RayHit& hit) const;
  // Whether anything lies in (tNear, tFar).
  bool occluded(const Ray& ray) const;
  // Sixteen rays at once (a 4×4 block of primary rays): hit[i].t < 0 where ray i misses; rays with
  // active[i] false are not traced.
  void intersect16(const Ray* rays, const bool* active, RayHit* hits) const;

  const EyeMesh& mesh(std::uint32_t object) const { return meshes_[object]; }
  std::size_t triangleCount() const { return triangles_; }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<EyeMesh> meshes_;
  std::size_t triangles_ = 0;
};

}  // namespace illum

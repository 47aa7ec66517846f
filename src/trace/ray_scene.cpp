#include "trace/ray_scene.h"

#include <illum/error.h>

#include "math/transform.h"

#include <cmath>
#include <limits>
#include <string>

namespace illum {
namespace {

[[noreturn]] void embreeFailed(RTCDevice device, const char* what) {
  const RTCError code = device ? rtcGetDeviceError(device) : rtcGetDeviceError(nullptr);
  throw Error(std::string("Embree: ") + what + " failed (error " + std::to_string(int(code)) + ")");
}

RTCRay toRtc(const Ray& r) {
  RTCRay out;
  out.org_x = float(r.origin.x), out.org_y = float(r.origin.y), out.org_z = float(r.origin.z);
  out.dir_x = float(r.direction.x), out.dir_y = float(r.direction.y), out.dir_z = float(r.direction.z);
  out.tnear = float(r.tNear);
  out.tfar = std::isinf(r.tFar) ? std::numeric_limits<float>::infinity() : float(r.tFar);
  out.time = 0;
  out.mask = 0xFFFFFFFFu;
  out.id = 0;
  out.flags = 0;
  return out;
}

}  // namespace

RayScene::RayScene(const Scene& scene) {
  // Embree's own threads follow oneTBB's limit (--threads), as the rasterizer's do.
  device_ = rtcNewDevice(nullptr);
  if (!device_) embreeFailed(nullptr, "creating a device");
  scene_ = rtcNewScene(device_);
  // Robust: watertight enough that rays do not slip between two triangles sharing an edge.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  const Mat4 viewFromWorld = scene.camera.viewFromWorld();
  meshes_.resize(scene.objects.size());
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    const Mesh& mesh = *object.mesh;
    EyeMesh& eye = meshes_[i];
    eye.object = &object;
    if (mesh.triangleCount() == 0) continue;  // points and lines are the rasterizer's
    // GL_MODELVIEW and its normal matrix, as the vertex stage applies them (raster/vertex.cpp).
    const Mat4 viewFromObject = viewFromWorld * object.worldFromObject;
    const Mat3 normalFromObject = normalMatrix(viewFromObject);
    eye.positions.resize(mesh.positions.size());
    eye.normals.resize(mesh.positions.size());
    for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
      eye.positions[k] = Vec3(viewFromObject * Vec4(mesh.positions[k], 1));
      const Vec3 n = normalFromObject * mesh.normals[k];
      const Real len = glm::length(n);
      eye.normals[k] = len > 0 ? n / len : n;
    }
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry) embreeFailed(device_, "creating a triangle geometry");
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), eye.positions.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh.triangleCount()));
    if (!vertices || !indices) embreeFailed(device_, "allocating a geometry's buffers");
    for (std::size_t k = 0; k < eye.positions.size(); ++k)
      for (int c = 0; c < 3; ++c) vertices[3 * k + std::size_t(c)] = float(eye.positions[k][c]);
    for (std::size_t k = 0; k < mesh.indices.size(); ++k) indices[k] = mesh.indices[k];
    rtcCommitGeometry(geometry);
    // Geometry IDs are given in order from 0, so an ID is the object's index.
    rtcAttachGeometryByID(scene_, geometry, unsigned(i));
    rtcReleaseGeometry(geometry);
    triangles_ += mesh.triangleCount();
  }
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) embreeFailed(device_, "building the BVH");
}

RayScene::~RayScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

bool RayScene::intersect(const Ray& ray, RayHit& hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray = toRtc(ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit = {Real(rh.ray.tfar), rh.hit.geomID, rh.hit.primID, Real(rh.hit.u), Real(rh.hit.v)};
  return true;
}

bool RayScene::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = toRtc(ray);
  rtcOccluded1(scene_, &context, &r);
  return r.tfar < 0;  // Embree marks an occluded ray with tfar = −∞
}

void RayScene::intersect16(const Ray* rays, const bool* active, RayHit* hits) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(64) RTCRayHit16 rh;
  alignas(64) int valid[16];
  for (int i = 0; i < 16; ++i) {
    valid[i] = active[i] ? -1 : 0;
    const RTCRay r = toRtc(rays[i]);
    rh.ray.org_x[i] = r.org_x, rh.ray.org_y[i] = r.org_y, rh.ray.org_z[i] = r.org_z;
    rh.ray.dir_x[i] = r.dir_x, rh.ray.dir_y[i] = r.dir_y, rh.ray.dir_z[i] = r.dir_z;
    rh.ray.tnear[i] = r.tnear, rh.ray.tfar[i] = r.tfar;
    rh.ray.time[i] = 0, rh.ray.mask[i] = 0xFFFFFFFFu, rh.ray.id[i] = unsigned(i), rh.ray.flags[i] = 0;
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect16(valid, scene_, &context, &rh);
  for (int i = 0; i < 16; ++i) {
    if (!active[i] || rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) {
      hits[i].t = -1;
      continue;
    }
    hits[i] = {Real(rh.ray.tfar[i]), rh.hit.geomID[i], rh.hit.primID[i], Real(rh.hit.u[i]), Real(rh.hit.v[i])};
  }
}

}  // namespace illum

#include "raster/vertex.h"

#include "math/transform.h"

namespace illum {

void runVertexStage(const FrameContext& frame, const Object& object, std::vector<ShadedVertex>& out,
                    std::size_t first, std::size_t last) {
  const Mesh& mesh = *object.mesh;
  const Mat4 viewFromObject = frame.viewFromWorld * object.worldFromObject;  // GL_MODELVIEW
  const Mat4 clipFromObject = frame.clipFromView * viewFromObject;
  const Mat3 normalFromObject = normalMatrix(viewFromObject);
  const bool lightVertices = frame.shading != Shading::Phong;
  const bool hasUvs = !mesh.uvs.empty(), hasColors = !mesh.colors.empty();
  for (std::size_t i = first; i < last; ++i) {
    ShadedVertex& v = out[i];
    const Vec4 p(mesh.positions[i], 1);
    v.clip = clipFromObject * p;
    v.eyePosition = Vec3(viewFromObject * p);
    const Vec3 n = normalFromObject * mesh.normals[i];
    const Real len = glm::length(n);
    v.eyeNormal = len > 0 ? n / len : n;
    if (hasUvs) v.uv = mesh.uvs[i];
    if (hasColors) v.color = mesh.colors[i];
    if (!lightVertices) continue;
    const Material material = hasColors ? withVertexColor(object.material, v.color) : object.material;
    SurfaceGeometry s{v.eyePosition, v.eyeNormal, viewerDirection(v.eyePosition, frame.lightModel.localViewer)};
    v.front = clampedColor(evaluateTerms(frame.lights, frame.lightModel, material, frame.model, s), material);
    if (frame.lightModel.twoSided) {
      s.normal = -s.normal;
      v.back = clampedColor(evaluateTerms(frame.lights, frame.lightModel, material, frame.model, s), material);
    }
  }
}

ShadedVertex lerp(const ShadedVertex& a, const ShadedVertex& b, Real t) {
  ShadedVertex v;
  v.clip = a.clip + t * (b.clip - a.clip);
  v.eyePosition = a.eyePosition + t * (b.eyePosition - a.eyePosition);
  v.eyeNormal = a.eyeNormal + t * (b.eyeNormal - a.eyeNormal);
  v.front = a.front + t * (b.front - a.front);
  v.back = a.back + t * (b.back - a.back);
  v.uv = a.uv + t * (b.uv - a.uv);
  v.color = a.color + t * (b.color - a.color);
  return v;
}

}  // namespace illum

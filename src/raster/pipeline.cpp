// The pipeline in order: vertex → clip → setup → rasterize → fragment → framebuffer.
#include <illum/render.h>

#include "raster/clip.h"
#include "raster/fragment.h"
#include "raster/frame_context.h"
#include "raster/framebuffer.h"
#include "raster/labels.h"
#include "raster/rasterize.h"
#include "raster/setup.h"
#include "raster/vertex.h"

#include <algorithm>
#include <limits>

namespace illum {
namespace {

struct TriangleColor {
  Color4 front, back;  // flat shading: the provoking vertex's colours
};

void drawTriangle(const FrameContext& frame, const Object& object, const TriangleSetup& t,
                  const TriangleColor& flat, Framebuffer& fb, RenderStats& stats) {
  const bool back = frame.lightModel.twoSided && !t.frontFacing;
  const bool vertexColors = !object.mesh->colors.empty();
  const Texture* texture = object.mesh->uvs.empty() ? nullptr : object.diffuseTexture.get();
  rasterizeTriangle(t, [&](int x, int y, Real l0, Real l1, Real l2) {
    const Real z = l0 * t.z[0] + l1 * t.z[1] + l2 * t.z[2];
    if (!fb.depthTest(x, y, z)) return;
    ++stats.fragmentsShaded;
    Color4 c;
    switch (frame.shading) {
      case Shading::Flat:
        c = back ? flat.back : flat.front;
        break;
      case Shading::Gouraud:
        c = shadeGouraudFragment(frame, t, perspectiveWeights(t, l0, l1, l2));
        break;
      case Shading::Phong:
        c = shadePhongFragment(frame, object.material, vertexColors, t, perspectiveWeights(t, l0, l1, l2));
        break;
    }
    // GL_MODULATE: the lit colour times the texel, alpha included.
    if (texture) c *= sampleDiffuseTexture(*texture, t, l0, l1, l2);
    if (frame.blend) fb.blendColor(x, y, c);
    else fb.writeColor(x, y, c);
  });
}

void drawObject(const FrameContext& frame, const Object& object, Framebuffer& fb, RenderStats& stats) {
  std::vector<ShadedVertex> vertices;
  runVertexStage(frame, object, vertices);
  std::vector<ShadedVertex> polygon;
  const auto& indices = object.mesh->indices;
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    ++stats.trianglesIn;
    const std::array<ShadedVertex, 3> tri = {vertices[indices[i]], vertices[indices[i + 1]], vertices[indices[i + 2]]};
    // GL's provoking vertex for flat shading is the triangle's last one.
    const TriangleColor flat{tri[2].front, tri[2].back};
    polygon.clear();
    if (clipTriangle(tri, frame.width, frame.height, polygon) == ClipResult::Outside) continue;
    // The clipped polygon is convex: draw it as a fan.
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      TriangleSetup setup;
      if (!setupTriangle(polygon[0], polygon[k], polygon[k + 1], frame.width, frame.height, setup)) continue;
      ++stats.trianglesDrawn;
      drawTriangle(frame, object, setup, flat, fb, stats);
    }
  }
}

bool isTranslucent(const Object& o) {
  return o.material.diffuse.a < 1 || (o.diffuseTexture && o.diffuseTexture->hasTransparency()) ||
         std::any_of(o.mesh->colors.begin(), o.mesh->colors.end(), [](const Color4& c) { return c.a < 1; });
}

// Scene order, or with blending the opaque objects first and then the translucent ones from the
// farthest to the nearest (by the eye-space depth of their bounds' centre). Ties keep scene order.
std::vector<const Object*> drawingOrder(const Scene& scene, const FrameContext& frame) {
  std::vector<const Object*> order;
  for (const Object& o : scene.objects) order.push_back(&o);
  if (!scene.blend) return order;
  const auto depth = [&](const Object* o) {
    Vec3 lo(std::numeric_limits<Real>::max()), hi(-std::numeric_limits<Real>::max());
    for (const Vec3& p : o->mesh->positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return (frame.viewFromWorld * o->worldFromObject * Vec4((lo + hi) * Real(0.5), 1)).z;
  };
  std::vector<std::pair<Real, const Object*>> translucent;
  std::vector<const Object*> opaque;
  for (const Object* o : order) {
    if (isTranslucent(*o)) translucent.push_back({depth(o), o});
    else opaque.push_back(o);
  }
  // Eye space looks down −Z: the most negative z is the farthest.
  std::stable_sort(translucent.begin(), translucent.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [unused, o] : translucent) opaque.push_back(o);
  return opaque;
}

}  // namespace

Image renderScene(const Scene& scene, RenderStats* statsOut) {
  const FrameContext frame = FrameContext::fromScene(scene);
  Framebuffer fb(scene.width, scene.height, scene.background);
  RenderStats stats;
  for (const Object* object : drawingOrder(scene, frame)) drawObject(frame, *object, fb, stats);
  Image image = fb.toImage();
  stats.labelsSkipped = !drawLabels(image, scene);
  if (statsOut) *statsOut = stats;
  return image;
}

}  // namespace illum

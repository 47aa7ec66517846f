#include "raster/shade/draw.h"

#include "raster/shade/fragment.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace illum {

namespace {
bool isTranslucent(const Object& o);
}  // namespace

Route chooseRoute(const FrameContext& frame, const Object& object, bool translucent) {
  if (translucent) return Route::Blended;
  // The colouring kernels write float channels (the SIMD conversion to RGBA8 takes floats).
  if (sizeof(Real) != 4) return Route::Deferred;
  const bool textured = drawnTexture(object) != nullptr;
  if (frame.shading != Shading::Phong) return textured ? Route::Deferred : Route::Colored;
  // The visible surface is one per pixel: a multisampled tile keeps what each sample shows.
  const bool oneSample = frame.samples.size() <= 1;
  return oneSample && litFromSurface(frame, object) ? Route::Surface : Route::Deferred;
}

bool litFromSurface(const FrameContext& frame, const Object& object) {
  // Pixels whose ambient is occluded are lit with their occlusion, which the Deferred route asks for.
  return sizeof(Real) == 4 && frame.shading == Shading::Phong && drawnTexture(object) == nullptr &&
         !mapsDrawn(object, frame.litPerPixel()) && !frame.occlusion;
}

DrawTarget::DrawTarget(const FrameContext& frame, const Scene& scene, Framebuffer& fb, PixelProbe* probe)
    : frame(frame), scene(scene), fb(fb), probe(probe) {
  for (const Object& o : scene.objects) {
    layouts.push_back(AttributeLayout::forObject(frame, o, probe != nullptr));
    setups.push_back({frame.lights, frame.lightModel, modelOf(o.material, frame.model), o.material});
    colored.push_back(!o.mesh->colors.empty());
    route.push_back(chooseRoute(frame, o, frame.blend && isTranslucent(o)));
    // Tiny triangles are worked out at setup as the tile would draw them: coloured (at every
    // sample, multisampled), or as visible surface (without vertex colours); multisampled, Phong's
    // are lit there, at every sample (without vertex colours).
    const bool litAtSetup = frame.samples.size() > 1 && route.back() == Route::Deferred && litFromSurface(frame, o);
    tiny.push_back(route.back() == Route::Colored ||
                   ((route.back() == Route::Surface || litAtSetup) && colored.back() == 0));
    tinyLit.push_back(tiny.back() && litAtSetup);
  }
  // Objects that share a material usually come together: each is compared with the last few
  // owners found, not with every object before it.
  constexpr std::size_t kOwnersCompared = 16;
  std::vector<std::uint32_t> owners;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto alike = [&](std::uint32_t j) {
      return setups[j].model == setups[i].model && colored[j] == colored[i] && setups[j].material == setups[i].material;
    };
    const auto recent = owners.size() > kOwnersCompared ? owners.end() - kOwnersCompared : owners.begin();
    const auto found = std::find_if(recent, owners.end(), alike);
    if (found != owners.end()) {
      shadeOwner.push_back(*found);
    } else {
      shadeOwner.push_back(std::uint32_t(i));
      owners.push_back(std::uint32_t(i));
    }
  }
}

void recordProbe(const DrawTarget& target, const DrawRecord& record, const std::array<Real, 3>& w, const Color4& lit,
                 const Vec4* texel, const Color4& c, bool texelIsBaseColor, const MappedSurface* mapped) {
  const Object& object = target.scene.objects[record.object];
  const std::size_t objectIndex = record.object, triangle = record.triangle;
  const TriangleSetup& t = record.setup;
  const AttributeLayout& l = target.layout(record);
  const VertexValues v[3] = {{record.vertex(0, l), l}, {record.vertex(1, l), l}, {record.vertex(2, l), l}};
  PixelProbe& p = *target.probe;
  const bool back = target.frame.lightModel.twoSided && !t.frontFacing;
  p.hit = true;
  p.object = objectIndex;
  p.triangle = triangle;
  p.frontFacing = t.frontFacing;
  p.written = c;
  p.lit = lit;
  p.textured = texel != nullptr;
  p.texel = texel ? *texel : Vec4(1);
  p.blended = target.blends(record) && c.a < 1;  // alpha 1 blends to the fragment itself
  p.weights = w;
  for (std::size_t i = 0; i < 3; ++i) {
    p.vertexColors[i] = v[i].lit();  // already the side shown
    p.vertexPositions[i] = v[i].position();
    p.vertexNormals[i] = back ? -v[i].normal() : v[i].normal();
    p.vertexMaterials[i] = object.mesh->colors.empty() ? object.material : withVertexColor(object.material, v[i].color());
  }
  // The material at the pixel, as its fragment was lit (the maps' texels came with `mapped`).
  p.texelIsBaseColor = texelIsBaseColor;
  if (mapped) {
    p.material = mapped->point.material;
  } else {
    const bool colored = !object.mesh->colors.empty();
    const Color4 color = colored ? w[0] * v[0].color() + w[1] * v[1].color() + w[2] * v[2].color() : Color4(1);
    p.material = materialAt(object, target.frame.model, target.frame.litPerPixel(), colored ? &color : nullptr,
                            [&](const Texture&) { return texel ? *texel : Vec4(1); })
                     .material;
  }
  if (target.frame.shading == Shading::Flat) {
    const Real* provoking = record.provoking(l);
    p.eyePosition = Vec3(provoking[0], provoking[1], provoking[2]);
    p.eyeNormal = Vec3(provoking[3], provoking[4], provoking[5]);
    if (back) p.eyeNormal = -p.eyeNormal;
  } else {
    // Where Phong shading lit this pixel (for Gouraud, the point between the vertices).
    const PhongSurface surface = phongSurface(target.frame, false, record, l, w);
    p.eyePosition = surface.position;
    p.eyeNormal = mapped ? mapped->normal : surface.normal;
  }
}

namespace {

// Where one record's pass draws: its triangle as set up for the pass's sample, that sample's
// framebuffer and offset, and whether the watched pixel is recorded in this pass.
struct SamplePass {
  const TriangleSetup& setup;
  int plane;  // of the framebuffer's samples
  SubpixelOffset sample;
  bool probe;
};

// One record's pixels with every per-draw choice fixed at compile time (the shading frequency,
// texturing, blending, a watched pixel), so the pixel loop never branches on them.
template <Shading kShading, bool kTextured, bool kBlend, bool kProbe>
void drawPixels(const DrawTarget& target, const DrawRecord& record, const SamplePass& pass, const PixelRect& rect,
                std::size_t& fragments) {
  const Object& object = target.scene.objects[record.object];
  const TriangleSetup& t = pass.setup;
  Framebuffer& fb = target.fb;
  const FrameContext& frame = target.frame;
  const AttributeLayout& l = target.layout(record);
  const Texture* texture = kTextured ? object.diffuseTexture.get() : nullptr;
  const bool baseTexture = kTextured && texelIsBaseColor(object, frame.model, frame.litPerPixel());
  const bool mapped = mapsDrawn(object, frame.litPerPixel());
  MappedSurface surface;
  const int probeRow = kProbe ? frame.height - 1 - target.probe->y : -1;  // GL rows run bottom up
  // A multisample pass tests coverage and depth at the sample, and shades at the pixel centre.
  rasterizeTriangle(t, rect, [&](int x, int y, Real l0, Real l1, Real l2) {
    const Real z = l0 * t.z[0] + l1 * t.z[1] + l2 * t.z[2];
    if (!fb.depthTest(x, y, z, pass.plane)) return;
    if (frame.multisampled) {
      const std::array<Real, 3> centre = centreBarycentrics(t, x, y, pass.sample);
      l0 = centre[0], l1 = centre[1], l2 = centre[2];
    }
    ++fragments;
    Color4 c;
    Vec4 texel(1);
    if constexpr (kShading == Shading::Flat) c = record.flat;
    else if constexpr (kShading == Shading::Gouraud) c = gouraudColor(record, l, perspectiveWeights(t, l0, l1, l2));
    if (kShading == Shading::Phong && mapped) {
      surface = mappedSurface(frame, object, record, l, l0, l1, l2);
      c = shadeMappedFragment(frame, surface, OcclusionQuery::pixelSeed(x, y, frame.width));
      texel = surface.point.texel;
    } else {
      if constexpr (kTextured) texel = sampleDiffuseTexture(*texture, record, l, l0, l1, l2);
      if constexpr (kShading == Shading::Phong)
        c = shadePhongFragment(frame, object, record, l, perspectiveWeights(t, l0, l1, l2), kTextured ? &texel : nullptr,
                               OcclusionQuery::pixelSeed(x, y, frame.width));
    }
    const Color4 lit = c;
    // GL_MODULATE: the lit colour times the texel, alpha included (unless it was the base colour).
    if constexpr (kTextured)
      if (!baseTexture) c *= texel;
    if constexpr (kBlend) fb.blendColor(x, y, c, pass.plane);
    else fb.writeColor(x, y, c, pass.plane);
    if constexpr (kProbe)
      if (y == probeRow && x == target.probe->x)
        recordProbe(target, record, perspectiveWeights(t, l0, l1, l2), lit, kTextured ? &texel : nullptr, c,
                    baseTexture, kShading == Shading::Phong && mapped ? &surface : nullptr);
  });
}

template <Shading kShading, bool kTextured, bool kBlend>
void drawPixels(const DrawTarget& target, const DrawRecord& record, const SamplePass& pass, const PixelRect& rect,
                std::size_t& fragments) {
  if (pass.probe) drawPixels<kShading, kTextured, kBlend, true>(target, record, pass, rect, fragments);
  else drawPixels<kShading, kTextured, kBlend, false>(target, record, pass, rect, fragments);
}

template <Shading kShading, bool kTextured>
void drawPixels(const DrawTarget& target, const DrawRecord& record, const SamplePass& pass, const PixelRect& rect,
                std::size_t& fragments) {
  if (target.blends(record)) drawPixels<kShading, kTextured, true>(target, record, pass, rect, fragments);
  else drawPixels<kShading, kTextured, false>(target, record, pass, rect, fragments);
}

template <Shading kShading>
void drawPixels(const DrawTarget& target, const DrawRecord& record, const SamplePass& pass, const PixelRect& rect,
                std::size_t& fragments) {
  const Object& object = target.scene.objects[record.object];
  if (drawnTexture(object)) drawPixels<kShading, true>(target, record, pass, rect, fragments);
  else drawPixels<kShading, false>(target, record, pass, rect, fragments);
}

}  // namespace

void drawRecord(const DrawTarget& target, const DrawRecord& record, const PixelRect& rect, std::size_t& fragments,
                int sample) {
  // One sample of a multisampled tile: the record's triangle moved as that sample's pass would
  // have set it up; the watched pixel is reported from the first sample, as the resolve's input.
  const TriangleSetup moved = sample >= 0 ? atSample(record.setup, target.frame.samples[std::size_t(sample)]) : record.setup;
  const SamplePass pass = sample >= 0 ? SamplePass{moved, sample, target.frame.samples[std::size_t(sample)],
                                                   target.probe && sample == 0}
                                      : SamplePass{record.setup, 0, target.frame.sample, target.probe != nullptr};
  switch (target.frame.shading) {
    case Shading::Flat: return drawPixels<Shading::Flat>(target, record, pass, rect, fragments);
    case Shading::Gouraud: return drawPixels<Shading::Gouraud>(target, record, pass, rect, fragments);
    case Shading::Phong: return drawPixels<Shading::Phong>(target, record, pass, rect, fragments);
  }
}

std::size_t pixelsUnlike(const Image& image, const Color4& background) {
  std::uint8_t bytes[4];
  for (int c = 0; c < 4; ++c) bytes[c] = toUnorm8(background[c]);
  std::size_t n = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) n += std::memcmp(&image.rgba[i], bytes, 4) != 0;
  return n;
}

namespace {

bool isTranslucent(const Object& o) {
  return o.material.diffuse.a < 1 || (o.diffuseTexture && o.diffuseTexture->hasTransparency()) ||
         std::any_of(o.mesh->colors.begin(), o.mesh->colors.end(), [](const Color4& c) { return c.a < 1; });
}

}  // namespace

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

}  // namespace illum

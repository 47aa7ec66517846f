// shade_visible.h: the lanes' part compiled once per SIMD target (Highway's foreach_target) and
// dispatched at run time; the batches gathered and written back (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/shade_visible.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "image/texture_lanes-inl.h"
#include "raster/interpolate-inl.h"
#include "raster/shade_visible.h"

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The layout's texel at each lane's pixel: its uv, and how uv changes one pixel right and one up
// (texturePoint), trilinearly filtered for that footprint (sampleAt).
template <class D, class V = hn::VFromD<D>>
HWY_INLINE void TexelLanes(D d, const VisibleLayout& layout, const VisibleBatch& b, std::size_t i, const V (&l)[3],
                           const V (&invW)[3], const V (&p)[3], V (&texel)[4]) {
  const auto load = [&](const Real* a) { return hn::Load(d, a + i); };
  V uv[2][3];  // channel, vertex
  for (int c = 0; c < 2; ++c)
    for (int k = 0; k < 3; ++k) uv[c][k] = load(b.vertex[k][layout.uv + c]);
  const auto uvAt = [&](const V (&w)[3], V (&out)[2]) {
    for (int c = 0; c < 2; ++c) out[c] = Blend(w, uv[c][0], uv[c][1], uv[c][2]);
  };
  V at[2];
  uvAt(p, at);
  V length[2];
  const Real size[2] = {Real(layout.texture->width()), Real(layout.texture->height())};
  for (int axis = 0; axis < 2; ++axis) {
    const Real(&step)[3][VisibleBatch::kSize] = axis == 0 ? b.stepX : b.stepY;
    V w[3], moved[2];
    PerspectiveWeights(l[0] + load(step[0]), l[1] + load(step[1]), l[2] + load(step[2]), invW[0], invW[1], invW[2], w);
    uvAt(w, moved);
    const V x = (moved[0] - at[0]) * hn::Set(d, size[0]), y = (moved[1] - at[1]) * hn::Set(d, size[1]);
    length[axis] = hn::Sqrt(x * x + y * y);
  }
  const V footprint = hn::IfThenElse(length[0] < length[1], length[1], length[0]);  // std::max's choice
#if !ILLUM_USE_DOUBLE
  SampleTextureLanes(d, *layout.texture, at[0], at[1], footprint, texel);
#else
  HWY_ALIGN Real u[hn::MaxLanes(d)], v[hn::MaxLanes(d)], f[hn::MaxLanes(d)], out[4][hn::MaxLanes(d)];
  hn::Store(at[0], d, u), hn::Store(at[1], d, v), hn::Store(footprint, d, f);
  for (std::size_t k = 0; k < hn::Lanes(d); ++k) {
    const Vec4 t = layout.texture->sample(Vec2(u[k], v[k]), f[k]);
    for (int c = 0; c < 4; ++c) out[c][k] = t[c];
  }
  for (int c = 0; c < 4; ++c) texel[c] = hn::Load(d, out[c]);
#endif
}

void InterpolateVisible(const VisibleLayout& layout, VisibleBatch& b) {
  const hn::ScalableTag<Real> d;
  using V = hn::VFromD<decltype(d)>;
  const hn::RebindToUnsigned<decltype(d)> du;
  const V one = hn::Set(d, Real(1));
  for (std::size_t i = 0; i < b.count; i += hn::Lanes(d)) {
    const auto load = [&](const Real* a) { return hn::Load(d, a + i); };
    const auto vertex = [&](int k, int value) { return load(b.vertex[k][value]); };
    const auto blend = [&](const V (&p)[3], int value) { return Blend(p, vertex(0, value), vertex(1, value), vertex(2, value)); };
    const V l[3] = {load(b.l[0]), load(b.l[1]), load(b.l[2])};
    const V invW[3] = {load(b.invW[0]), load(b.invW[1]), load(b.invW[2])};
    V p[3];
    PerspectiveWeights(l[0], l[1], l[2], invW[0], invW[1], invW[2], p);
    V color[4];
    for (int c = 0; c < 4; ++c) color[c] = load(b.color[c]);  // flat: the provoking vertex's, as gathered
    if (layout.shading == Shading::Gouraud) {
      for (int c = 0; c < 4; ++c) color[c] = blend(p, layout.lit + c);
    } else if (layout.shading == Shading::Phong) {
      V n[3], unit[3];
      for (int c = 0; c < 3; ++c) {
        hn::Store(blend(p, layout.position + c), d, b.position[c] + i);
        n[c] = blend(p, layout.normal + c);
      }
      UnitNormal(n, hn::RebindMask(d, hn::Ne(hn::Load(du, b.negate + i), hn::Zero(du))), unit);
      for (int c = 0; c < 3; ++c) hn::Store(unit[c], d, b.normal[c] + i);
      for (int c = 0; c < 4; ++c) color[c] = layout.color >= 0 ? blend(p, layout.color + c) : one;
    }
    if (layout.texture) {
      V texel[4];
      TexelLanes(d, layout, b, i, l, invW, p, texel);
      for (int c = 0; c < 4; ++c) hn::Store(texel[c], d, b.texel[c] + i);
      // A base colour texture tints the material's (or the vertex's) colour before lighting.
      if (layout.baseTexel)
        for (int c = 0; c < 4; ++c)
          color[c] = (layout.color >= 0 ? color[c] : hn::Set(d, layout.baseColor[c])) * texel[c];
    }
    for (int c = 0; c < 4; ++c) hn::Store(color[c], d, b.color[c] + i);
  }
}

void FinishVisible(const VisibleLayout& layout, VisibleBatch& b) {
  const hn::ScalableTag<Real> d;
  using V = hn::VFromD<decltype(d)>;
  const bool modulate = layout.texture && !layout.baseTexel;
  for (std::size_t i = 0; i < b.count; i += hn::Lanes(d)) {
    V c[4];
    for (int k = 0; k < 4; ++k) {
      c[k] = hn::Load(d, b.lit[k] + i);
      if (modulate) c[k] = c[k] * hn::Load(d, b.texel[k] + i);  // GL_MODULATE
    }
#if !ILLUM_USE_DOUBLE
    hn::Store(PackUnorm8(d, c[0], c[1], c[2], c[3]), hn::Rebind<std::uint32_t, decltype(d)>(), b.rgba + i);
#else
    HWY_ALIGN Real out[4][hn::MaxLanes(d)];
    for (int k = 0; k < 4; ++k) hn::Store(c[k], d, out[k]);
    for (std::size_t k = 0; k < hn::Lanes(d) && i + k < VisibleBatch::kSize; ++k)
      b.rgba[i + k] = packUnorm8(Color4(out[0][k], out[1][k], out[2][k], out[3][k]));
#endif
  }
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "raster/fragment.h"
#include "shading/shade_points.h"

#include <algorithm>

namespace illum {

HWY_EXPORT(InterpolateVisible);
HWY_EXPORT(FinishVisible);

void interpolateVisible(const VisibleLayout& layout, VisibleBatch& batch) {
  HWY_DYNAMIC_DISPATCH(InterpolateVisible)(layout, batch);
}

void finishVisible(const VisibleLayout& layout, VisibleBatch& batch) {
  HWY_DYNAMIC_DISPATCH(FinishVisible)(layout, batch);
}

namespace {

// Where an object's per-vertex values go in a batch, for the frame's shading.
VisibleLayout layoutOf(const FrameContext& frame, const Object& object) {
  VisibleLayout v;
  v.shading = frame.shading;
  int next = 0;
  const auto take = [&](int n) {
    const int at = next;
    next += n;
    return at;
  };
  if (frame.shading == Shading::Gouraud) v.lit = take(4);
  if (frame.shading == Shading::Phong) {
    v.position = take(3), v.normal = take(3);
    if (!object.mesh->colors.empty()) v.color = take(4);
  }
  v.texture = drawnTexture(object);
  if (v.texture) v.uv = take(2);
  v.baseTexel = texelIsBaseColor(object, frame.model, frame.litPerPixel());
  const Material& m = object.material;
  v.baseColor = Color4(physicalOf(m).baseColor, m.diffuse.a);
  return v;
}

}  // namespace

void VisibleShader::add(int index, std::uint32_t slot) {
  const DrawRecord& r = *records_[slot];
  const Object& object = target_.scene.objects[r.object];
  if (mapsDrawn(object, target_.frame.litPerPixel())) return shadeMapped(object, index, slot, r);
  if (b_.count == VisibleBatch::kSize || (b_.count > 0 && r.object != object_)) flush();
  if (b_.count == 0) {
    object_ = r.object;
    layout_ = layoutOf(target_.frame, object);
  }
  const std::size_t k = b_.count++;
  const TriangleSetup& t = r.setup;
  const int x = rect_.minX + index % kTileSize, y = rect_.minY + index / kTileSize;
  const std::array<Real, 3> l = centreBarycentrics(t, x, y, target_.frame.sample);
  for (int i = 0; i < 3; ++i) b_.l[i][k] = l[std::size_t(i)], b_.invW[i][k] = t.invW[std::size_t(i)];
  const AttributeLayout& a = target_.layout(r);
  for (int i = 0; i < 3; ++i) {
    const VertexValues v{r.vertex(i, a), a};
    const auto put = [&](int at, const auto& value, int n) {
      if (at >= 0)
        for (int c = 0; c < n; ++c) b_.vertex[i][at + c][k] = value[c];
    };
    if (layout_.lit >= 0) put(layout_.lit, v.lit(), 4);
    if (layout_.position >= 0) put(layout_.position, v.position(), 3), put(layout_.normal, v.normal(), 3);
    if (layout_.color >= 0) put(layout_.color, v.color(), 4);
    if (layout_.uv >= 0) put(layout_.uv, v.uv(), 2);
  }
  if (layout_.shading == Shading::Flat)
    for (int c = 0; c < 4; ++c) b_.color[c][k] = r.flat[c];
  if (layout_.texture) {
    // Screen-space barycentrics are linear: one pixel right adds a·256/area, one up adds b·256/area.
    const Real step = Real(kSubpixelOne) / Real(t.area2);
    for (int i = 0; i < 3; ++i)
      b_.stepX[i][k] = Real(t.edge[std::size_t(i)].a) * step, b_.stepY[i][k] = Real(t.edge[std::size_t(i)].b) * step;
  }
  b_.negate[k] = target_.frame.lightModel.twoSided && !t.frontFacing ? ~0u : 0u;
  b_.pixel[k] = std::uint16_t(index);
  b_.slot[k] = slot;
}

void VisibleShader::flush() {
  if (b_.count == 0) return;
  // The lanes read whole vectors: the spare ones repeat pair 0 (finite values).
  const std::size_t padded = std::min(VisibleBatch::kSize, (b_.count + 15) / 16 * 16);
  for (std::size_t k = b_.count; k < padded; ++k) {
    for (int i = 0; i < 3; ++i) {
      b_.l[i][k] = b_.l[i][0], b_.invW[i][k] = b_.invW[i][0], b_.stepX[i][k] = b_.stepX[i][0], b_.stepY[i][k] = b_.stepY[i][0];
      for (int v = 0; v < VisibleBatch::kValues; ++v) b_.vertex[i][v][k] = b_.vertex[i][v][0];
    }
    for (int c = 0; c < 4; ++c) b_.color[c][k] = b_.color[c][0];
    b_.negate[k] = b_.negate[0];
  }
  interpolateVisible(layout_, b_);
  const Object& object = target_.scene.objects[object_];
  if (layout_.shading == Shading::Phong) {
    const ShadeSetup setup{target_.frame.lights, target_.frame.lightModel, modelOf(object.material, target_.frame.model),
                           object.material};
    SurfacePoints points;
    points.count = b_.count;
    for (int c = 0; c < 3; ++c) points.position[c] = b_.position[c], points.normal[c] = b_.normal[c];
    if (layout_.color >= 0 || layout_.baseTexel)
      for (int c = 0; c < 4; ++c) points.color[c] = b_.color[c];
    Real* const lit[4] = {b_.lit[0], b_.lit[1], b_.lit[2], b_.lit[3]};
    shadePoints(setup, points, lit);
  } else {
    for (int c = 0; c < 4; ++c) std::copy_n(b_.color[c], padded, b_.lit[c]);
  }
  finishVisible(layout_, b_);
  // The watched pixel's index in this tile, if it lies here (GL rows run bottom up).
  int probeIndex = -1;
  if (const PixelProbe* probe = target_.probe) {
    const int x = probe->x, y = target_.frame.height - 1 - probe->y;
    if (x >= rect_.minX && x <= rect_.maxX && y >= rect_.minY && y <= rect_.maxY)
      probeIndex = (y - rect_.minY) * kTileSize + (x - rect_.minX);
  }
  for (std::size_t k = 0; k < b_.count; ++k) {
    out_.write(b_.pixel[k], b_.slot[k], b_.rgba[k]);
    if (b_.pixel[k] != probeIndex || !out_.reported(b_.pixel[k], b_.slot[k])) continue;
    const DrawRecord& r = *records_[b_.slot[k]];
    const Color4 lit(b_.lit[0][k], b_.lit[1][k], b_.lit[2][k], b_.lit[3][k]);
    const Vec4 texel(b_.texel[0][k], b_.texel[1][k], b_.texel[2][k], b_.texel[3][k]);
    const Color4 c = layout_.texture && !layout_.baseTexel ? lit * texel : lit;
    recordProbe(target_, r, perspectiveWeights(r.setup, b_.l[0][k], b_.l[1][k], b_.l[2][k]), lit,
                layout_.texture ? &texel : nullptr, c, layout_.baseTexel);
  }
  b_.count = 0;
}

// A pixel whose material or normal comes from glTF's maps: lit on its own (fragment.h).
void VisibleShader::shadeMapped(const Object& object, int index, std::uint32_t slot, const DrawRecord& r) {
  const int x = rect_.minX + index % kTileSize, y = rect_.minY + index / kTileSize;
  const auto [l0, l1, l2] = centreBarycentrics(r.setup, x, y, target_.frame.sample);
  const MappedSurface surface = mappedSurface(target_.frame, object, r, target_.layout(r), l0, l1, l2);
  const Color4 lit = shadeMappedFragment(target_.frame, surface);
  const Vec4* texel = surface.point.textured ? &surface.point.texel : nullptr;
  const Color4 c = texel && !surface.point.texelIsBaseColor ? lit * *texel : lit;
  out_.write(index, slot, packUnorm8(c));
  if (target_.probe && x == target_.probe->x && y == target_.frame.height - 1 - target_.probe->y &&
      out_.reported(index, slot))
    recordProbe(target_, r, perspectiveWeights(r.setup, l0, l1, l2), lit, texel, c, surface.point.texelIsBaseColor,
                &surface);
}

}  // namespace illum
#endif  // HWY_ONCE

// shade_visible.h's sampleBatchTexels and finishVisible: the textures read at the batch's points,
// a texture at a time, and the colours finished after lighting. Compiled once per SIMD target
// (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/shade/visible_texels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "image/texture_lanes-inl.h"
#include "math/unorm8-inl.h"
#include "shading/lane_math-inl.h"
#include "raster/shade/shade_visible.h"
#include "raster/shade/visible_lanes.h"

#include <cstddef>
#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// How many base texels of `texture` a pixel spans at each lane's point (texturePoint's footprint):
// the longer of uv's steps one pixel right and one up, in texels.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE V FootprintLanes(D d, const Texture& texture, const UvLanes<V>& at) {
  const V width = hn::Set(d, Real(texture.width())), height = hn::Set(d, Real(texture.height()));
  const V x0 = at.dx[0] * width, y0 = at.dx[1] * height, x1 = at.dy[0] * width, y1 = at.dy[1] * height;
  // std::max of the two lengths (fragment.cpp) with one square root: it is monotonic and correctly
  // rounded, so the root of the larger square is the larger root, bit for bit, and a NaN square
  // is passed over or kept as std::max passes over or keeps its root.
  const V right2 = x0 * x0 + y0 * y0, up2 = x1 * x1 + y1 * y1;
  return hn::Sqrt(hn::IfThenElse(right2 < up2, up2, right2));
}

// A texture's texel at each lane's (u, v), trilinearly filtered for its footprint there (sampleAt).
// With `planes`, colour bytes are looked up in them (SampleTextureLanes).
template <class D, class V = hn::VFromD<D>, class Planes = std::nullptr_t>
HWY_INLINE void SampleLanes(D d, const Texture& texture, V u, V v, V footprint, V (&texel)[4],
                            [[maybe_unused]] const Planes* planes = nullptr) {
#if !ILLUM_USE_DOUBLE
  SampleTextureLanes(d, texture, u, v, footprint, texel, planes);
#else
  HWY_ALIGN Real us[hn::MaxLanes(d)], vs[hn::MaxLanes(d)], f[hn::MaxLanes(d)], out[4][hn::MaxLanes(d)];
  hn::Store(u, d, us), hn::Store(v, d, vs), hn::Store(footprint, d, f);
  for (std::size_t k = 0; k < hn::Lanes(d); ++k) {
    const Vec4 t = texture.sample(Vec2(us[k], vs[k]), f[k]);
    for (int c = 0; c < 4; ++c) out[c][k] = t[c];
  }
  for (int c = 0; c < 4; ++c) texel[c] = hn::Load(d, out[c]);
#endif
}

// normalFromMap over lanes: the tangent-space normal of the map's texel in the frame of the unit
// (front) normal N, the record's ∂P/∂u made orthogonal to it, and the bitangent N × T on the side
// ∂P/∂v points to; N where that frame or the normal is degenerate.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE Vec3L<V> NormalFromMapLanes(D d, const Vec3L<V>& N, const Vec3L<V>& dPdu, const Vec3L<V>& dPdv,
                                       const V (&texel)[4], Real scale) {
  const Vec3L<V> t = dPdu - Dot(dPdu, N) * N;
  const V tLen = Length(t);
  const auto framed = tLen > hn::Zero(d);
  const Vec3L<V> T = t / hn::IfThenElse(framed, tLen, hn::Set(d, Real(1)));
  const Vec3L<V> c{N.y * T.z - T.y * N.z, N.z * T.x - T.z * N.x, N.x * T.y - T.x * N.y};  // glm::cross(N, T)
  const Vec3L<V> B = Select(Dot(c, dPdv) < hn::Zero(d), -c, c);
  const V two = hn::Set(d, Real(2)), one = hn::Set(d, Real(1)), s = hn::Set(d, scale);
  const V nx = (two * texel[0] - one) * s, ny = (two * texel[1] - one) * s, nz = two * texel[2] - one;
  const Vec3L<V> perturbed = (nx * T + ny * B) + nz * N;
  const V len = Length(perturbed);
  const auto unit = len > hn::Zero(d);
  const Vec3L<V> mapped = perturbed / hn::IfThenElse(unit, len, one);
  return Select(hn::And(framed, unit), mapped, N);
}

// What a texture of the layout does with its texels at the batch's pixels (withMapTexels,
// normalFromMap): the base colour's tints the colour before lighting, or modulates it after
// (GL_MODULATE: kept); glTF's maps scale the material's metallic and roughness, and emission, and
// bend the front side's normal (two-sided lighting's back faces take its opposite).
enum class TexelUse { kBaseColor, kMetallicRoughness, kEmissive, kNormal };

// One texture's texels at the points GatherLanes kept, a texture at a time over the whole batch:
// apart from the gathering, whose many values would crowd the registers the sampler's texel reads
// and decode tables use.
template <TexelUse kUse, class Planes = std::nullptr_t>
HWY_INLINE void SampleBatchTexture(const VisibleLayout& layout, const Texture& texture, VisibleBatch& b,
                                   const Planes* planes = nullptr) {
  const hn::ScalableTag<Real> d;
  using V = hn::VFromD<decltype(d)>;
  const std::size_t lanes = hn::Lanes(d);
  for (std::size_t i = 0; i < b.count; i += lanes) {
    // Lanes past the last pixel sample (0, 0): the batch's room past it holds no points.
    const auto inside = hn::FirstN(d, b.count - i);
    UvLanes<V> at;
    for (int c = 0; c < 2; ++c) {
      at.uv[c] = hn::IfThenElseZero(inside, hn::Load(d, b.uv[c] + i));
      at.dx[c] = hn::IfThenElseZero(inside, hn::Load(d, b.uvDx[c] + i));
      at.dy[c] = hn::IfThenElseZero(inside, hn::Load(d, b.uvDy[c] + i));
    }
    V texel[4];
    SampleLanes(d, texture, at.uv[0], at.uv[1], FootprintLanes(d, texture, at), texel, planes);
    if constexpr (kUse == TexelUse::kBaseColor) {
      for (int c = 0; c < 4; ++c) hn::Store(texel[c], d, b.texel[c] + i);
      if (layout.baseTexel)
        for (int c = 0; c < 4; ++c) hn::Store(hn::Load(d, b.color[c] + i) * texel[c], d, b.color[c] + i);
    } else if constexpr (kUse == TexelUse::kMetallicRoughness) {
      hn::Store(hn::Set(d, layout.metallic) * texel[2], d, b.metallic + i);
      hn::Store(hn::Set(d, layout.roughness) * texel[1], d, b.roughness + i);
    } else if constexpr (kUse == TexelUse::kEmissive) {
      for (int c = 0; c < 3; ++c) hn::Store(hn::Set(d, layout.emission[c]) * texel[c], d, b.emission[c] + i);
    } else {
      const auto load3 = [&](const Real (&plane)[3][VisibleBatch::kRoom]) {
        return Vec3L<V>{hn::Load(d, plane[0] + i), hn::Load(d, plane[1] + i), hn::Load(d, plane[2] + i)};
      };
      const Vec3L<V> bent =
          NormalFromMapLanes(d, load3(b.normal), load3(b.dPdu), load3(b.dPdv), texel, layout.maps->normalScale);
      const V out[3] = {bent.x, bent.y, bent.z};
      const auto negate = hn::Load(d, b.flip + i) != hn::Zero(d);
      for (int c = 0; c < 3; ++c) hn::Store(hn::IfThenElse(negate, hn::Neg(out[c]), out[c]), d, b.normal[c] + i);
    }
  }
}

#if (HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL) && !ILLUM_USE_DOUBLE
// Compiled for VBMI, with the texture's decode byte planes loaded once for the batch and their
// lookups inlined (flatten: a function compiled for VBMI can be inlined only into another such).
template <TexelUse kUse>
__attribute__((target(HWY_TARGET_STR ",avx512vbmi"), flatten)) void SampleBatchTextureVbmi(
    const VisibleLayout& layout, const Texture& texture, VisibleBatch& b) {
  const ColorBytePlanes planes(texture.colorTableBytes());
  SampleBatchTexture<kUse>(layout, texture, b, &planes);
}
#endif

template <TexelUse kUse>
void SampleBatchTextureOnCpu(const VisibleLayout& layout, const Texture& texture, VisibleBatch& b) {
#if (HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL) && !ILLUM_USE_DOUBLE
  if (texelByteLookups()) return SampleBatchTextureVbmi<kUse>(layout, texture, b);
#endif
  SampleBatchTexture<kUse>(layout, texture, b);
}

void SampleBatchTexels(const VisibleLayout& layout, VisibleBatch& b) {
  if (layout.texture) SampleBatchTextureOnCpu<TexelUse::kBaseColor>(layout, *layout.texture, b);
  if (const MaterialMaps* maps = layout.maps) {
    if (maps->metallicRoughness && layout.physical)
      SampleBatchTextureOnCpu<TexelUse::kMetallicRoughness>(layout, *maps->metallicRoughness, b);
    if (maps->emissive) SampleBatchTextureOnCpu<TexelUse::kEmissive>(layout, *maps->emissive, b);
    if (maps->normal && layout.shading == Shading::Phong)  // (maps are drawn lit per pixel: Phong keeps normals)
      SampleBatchTextureOnCpu<TexelUse::kNormal>(layout, *maps->normal, b);
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
    for (std::size_t k = 0; k < hn::Lanes(d) && i + k < b.count; ++k)
      b.rgba[i + k] = packUnorm8(Color4(out[0][k], out[1][k], out[2][k], out[3][k]));
#endif
  }
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(SampleBatchTexels);
HWY_EXPORT(FinishVisible);

void sampleBatchTexels(const VisibleLayout& layout, VisibleBatch& batch) {
  HWY_DYNAMIC_DISPATCH(SampleBatchTexels)(layout, batch);
}

void finishVisible(const VisibleLayout& layout, VisibleBatch& batch) {
  HWY_DYNAMIC_DISPATCH(FinishVisible)(layout, batch);
}

}  // namespace illum
#endif  // HWY_ONCE

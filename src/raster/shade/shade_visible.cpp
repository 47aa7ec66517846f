// shade_visible.h: the lanes' part compiled once per SIMD target (Highway's foreach_target) and
// dispatched at run time; the records gathered, lit and written back (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/shade/shade_visible.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "image/texture_lanes-inl.h"
#include "raster/coverage/interpolate-inl.h"
#include "shading/lane_math-inl.h"
#include "raster/shade/shade_visible.h"

#include <algorithm>
#include <cstring>
#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Where each lane's pixel falls on the textures (texturePoint): its uv, and how uv changes one
// pixel right (dx) and one up (dy), from the barycentrics moved by the record's steps.
template <class V>
struct UvLanes {
  V uv[2], dx[2], dy[2];
};
template <class D, class V = hn::VFromD<D>>
HWY_INLINE UvLanes<V> UvAt(D d, const VisibleLayout& layout, const ShownRecord& rec, const V (&l)[3], const V (&invW)[3],
                           const V (&p)[3]) {
  const auto uvAt = [&](const V (&w)[3], V (&out)[2]) {
    for (int c = 0; c < 2; ++c)
      out[c] = Blend(w, hn::Set(d, rec.vertex[0][layout.uv + c]), hn::Set(d, rec.vertex[1][layout.uv + c]),
                     hn::Set(d, rec.vertex[2][layout.uv + c]));
  };
  UvLanes<V> u;
  uvAt(p, u.uv);
  for (int axis = 0; axis < 2; ++axis) {
    const Real(&step)[3] = axis == 0 ? rec.stepX : rec.stepY;
    V w[3], moved[2];
    PerspectiveWeights(l[0] + hn::Set(d, step[0]), l[1] + hn::Set(d, step[1]), l[2] + hn::Set(d, step[2]), invW[0],
                       invW[1], invW[2], w);
    uvAt(w, moved);
    V(&delta)[2] = axis == 0 ? u.dx : u.dy;
    for (int c = 0; c < 2; ++c) delta[c] = moved[c] - u.uv[c];
  }
  return u;
}

// A texture's texel at each lane's point, trilinearly filtered for its footprint there (sampleAt).
template <class D, class V = hn::VFromD<D>>
HWY_INLINE void TexelLanes(D d, const Texture& texture, const UvLanes<V>& at, V (&texel)[4]) {
  const V width = hn::Set(d, Real(texture.width())), height = hn::Set(d, Real(texture.height()));
  const V x0 = at.dx[0] * width, y0 = at.dx[1] * height, x1 = at.dy[0] * width, y1 = at.dy[1] * height;
  // std::max of the two lengths (fragment.cpp) with one square root: it is monotonic and correctly
  // rounded, so the root of the larger square is the larger root, bit for bit, and a NaN square
  // is passed over or kept as std::max passes over or keeps its root.
  const V right2 = x0 * x0 + y0 * y0, up2 = x1 * x1 + y1 * y1;
  const V footprint = hn::Sqrt(hn::IfThenElse(right2 < up2, up2, right2));
#if !ILLUM_USE_DOUBLE
  SampleTextureLanes(d, texture, at.uv[0], at.uv[1], footprint, texel);
#else
  HWY_ALIGN Real u[hn::MaxLanes(d)], v[hn::MaxLanes(d)], f[hn::MaxLanes(d)], out[4][hn::MaxLanes(d)];
  hn::Store(at.uv[0], d, u), hn::Store(at.uv[1], d, v), hn::Store(footprint, d, f);
  for (std::size_t k = 0; k < hn::Lanes(d); ++k) {
    const Vec4 t = texture.sample(Vec2(u[k], v[k]), f[k]);
    for (int c = 0; c < 4; ++c) out[c][k] = t[c];
  }
  for (int c = 0; c < 4; ++c) texel[c] = hn::Load(d, out[c]);
#endif
}

// normalFromMap over lanes: the tangent-space normal of the map's texel in the frame of the unit
// (front) normal N, the record's ∂P/∂u made orthogonal to it, and the bitangent N × T on the side
// ∂P/∂v points to; N where that frame or the normal is degenerate.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE Vec3L<V> NormalFromMapLanes(D d, const Vec3L<V>& N, const ShownRecord& rec, const V (&texel)[4], Real scale) {
  const Vec3L<V> dPdu = Broadcast(d, rec.dPdu), dPdv = Broadcast(d, rec.dPdv);
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

// gatherShown, its pixels in the widest Real lanes. Their edge values are exact integers, the
// first pixel's plus dx·256a + dy·256b: with kSplit in float lanes, a multiple of 256 plus the
// rest (exact while every part stays below 2^31, as SamplesPassIn keeps them), else in double
// lanes, half a vector at a time, each converted to Real once.
template <bool kSplit>
HWY_INLINE void GatherShownIn(const VisibleLayout& layout, const ShownRecord& rec, const PixelRect& rect,
                              const std::uint32_t* pixels, std::size_t count, VisibleBatch& b) {
  const TriangleSetup& t = *rec.setup;
  const hn::ScalableTag<Real> dr;
  const hn::Rebind<std::uint32_t, decltype(dr)> du;
  const hn::Rebind<std::int32_t, decltype(dr)> di;
  using VR = hn::VFromD<decltype(dr)>;
  using VI = hn::VFromD<decltype(di)>;
  using T = std::conditional_t<kSplit, float, double>;
  // The first pixel's edge values (split: its multiple of 256, and the rest), and the steps.
  const int x0 = rect.minX + int(pixels[0] % kTileSize), y0 = rect.minY + int(pixels[0] / kTileSize);
  const std::int64_t half = kSubpixelOne / 2;
  T high[3], low[3], A[3], B[3];
  for (int i = 0; i < 3; ++i) {
    const std::int64_t e = t.edge[i].at(std::int64_t(x0) * kSubpixelOne + half, std::int64_t(y0) * kSubpixelOne + half);
    const std::int64_t rest = kSplit ? (e & (kSubpixelOne - 1)) : 0;
    high[i] = T(e - rest), low[i] = T(rest);
    A[i] = T(std::int64_t(t.edge[i].a) * kSubpixelOne), B[i] = T(std::int64_t(t.edge[i].b) * kSubpixelOne);
  }
  // Edge value i at the lanes' pixels dx, dy from the first one, as Real.
  const auto edgeAt = [&](int i, VI dx, VI dy) -> VR {
#if !ILLUM_USE_DOUBLE
    if constexpr (kSplit) {
      const VR offset = hn::ConvertTo(dr, dx) * hn::Set(dr, A[i]) + hn::ConvertTo(dr, dy) * hn::Set(dr, B[i]);
      return (hn::Set(dr, high[i]) + offset) + hn::Set(dr, low[i]);  // a multiple of 256 plus the rest
    } else
#endif
    {
      const auto exact = [&](auto dd, auto x, auto y) {  // in double lanes
        return hn::Set(dd, high[i]) + (hn::PromoteTo(dd, x) * hn::Set(dd, A[i]) + hn::PromoteTo(dd, y) * hn::Set(dd, B[i]));
      };
#if HWY_TARGET == HWY_SCALAR || ILLUM_USE_DOUBLE
      const hn::Rebind<double, decltype(dr)> dd;
      if constexpr (sizeof(Real) == 8) return exact(dd, dx, dy);
      else return hn::DemoteTo(dr, exact(dd, dx, dy));
#else
      const hn::Half<decltype(dr)> dh;
      const hn::Half<decltype(di)> dih;
      const hn::Rebind<double, decltype(dh)> dd;
      const auto lower = hn::DemoteTo(dh, exact(dd, hn::LowerHalf(dih, dx), hn::LowerHalf(dih, dy)));
      const auto upper = hn::DemoteTo(dh, exact(dd, hn::UpperHalf(dih, dx), hn::UpperHalf(dih, dy)));
      return hn::Combine(dr, upper, lower);
#endif
    }
  };
  const VR invArea = hn::Set(dr, t.invArea), one = hn::Set(dr, Real(1));
  const VR invW[3] = {hn::Set(dr, t.invW[0]), hn::Set(dr, t.invW[1]), hn::Set(dr, t.invW[2])};
  const auto vertex = [&](int k, int value) { return hn::Set(dr, rec.vertex[k][value]); };
  const auto blend = [&](const VR (&p)[3], int value) { return Blend(p, vertex(0, value), vertex(1, value), vertex(2, value)); };
  const auto negate = hn::FirstN(dr, rec.negate ? hn::Lanes(dr) : 0);
  const auto column0 = hn::Set(di, x0 - rect.minX), row0 = hn::Set(di, y0 - rect.minY);
  const std::size_t lanes = hn::Lanes(dr);
  for (std::size_t i = 0; i < count; i += lanes) {
    const auto shown = hn::FirstN(dr, count - i);
    const auto index = hn::LoadU(du, pixels + i);  // (the list has room for a vector past its end)
    const auto indexI = hn::BitCast(di, index);
    static_assert(kTileSize == 64);
    const VI dx = hn::And(indexI, hn::Set(di, kTileSize - 1)) - column0, dy = hn::ShiftRight<6>(indexI) - row0;
    // The centres' barycentrics, as the rasterizer computes them.
    VR l[3];
    for (int e = 0; e < 3; ++e) l[e] = edgeAt(e, dx, dy) * invArea;
    VR p[3];
    PerspectiveWeights(l[0], l[1], l[2], invW[0], invW[1], invW[2], p);
    VR color[4];
    const std::size_t at = b.count;
    // (Compressed in a register and stored whole: the batch has room for a vector past its end,
    // and a compressing store to memory is slow on some CPUs.)
    const auto keep = [&](VR v, Real* plane) { hn::StoreU(hn::Compress(v, shown), dr, plane + at); };
    if (layout.shading == Shading::Flat) {
      for (int c = 0; c < 4; ++c) color[c] = hn::Set(dr, rec.flat[c]);
    } else if (layout.shading == Shading::Gouraud) {
      for (int c = 0; c < 4; ++c) color[c] = blend(p, layout.lit + c);
    } else {
      VR n[3], unit[3];
      for (int c = 0; c < 3; ++c) {
        keep(blend(p, layout.position + c), b.position[c]);
        n[c] = blend(p, layout.normal + c);
      }
      UnitNormal(n, negate, unit);
      for (int c = 0; c < 3; ++c) keep(unit[c], b.normal[c]);
      for (int c = 0; c < 4; ++c) color[c] = layout.color >= 0 ? blend(p, layout.color + c) : one;
    }
    UvLanes<VR> uv;
    if (layout.uv >= 0) uv = UvAt(dr, layout, rec, l, invW, p);
    if (layout.texture) {
      VR texel[4];
      TexelLanes(dr, *layout.texture, uv, texel);
      for (int c = 0; c < 4; ++c) keep(texel[c], b.texel[c]);
      // A base colour texture tints the material's (or the vertex's) colour before lighting.
      if (layout.baseTexel)
        for (int c = 0; c < 4; ++c)
          color[c] = (layout.color >= 0 ? color[c] : hn::Set(dr, layout.baseColor[c])) * texel[c];
    }
    // glTF's maps (withMapTexels, normalFromMap): the material and the normal at each pixel.
    if (const MaterialMaps* maps = layout.maps) {
      VR texel[4];
      if (maps->metallicRoughness && layout.physical) {
        TexelLanes(dr, *maps->metallicRoughness, uv, texel);
        keep(hn::Set(dr, layout.metallic) * texel[2], b.metallic);
        keep(hn::Set(dr, layout.roughness) * texel[1], b.roughness);
      }
      if (maps->emissive) {
        TexelLanes(dr, *maps->emissive, uv, texel);
        for (int c = 0; c < 3; ++c) keep(hn::Set(dr, layout.emission[c]) * texel[c], b.emission[c]);
      }
      if (maps->normal) {
        TexelLanes(dr, *maps->normal, uv, texel);
        // The map bends the front side's normal; two-sided lighting's back faces take its opposite.
        VR n[3], front[3];
        for (int c = 0; c < 3; ++c) n[c] = blend(p, layout.normal + c);
        UnitNormal(n, hn::FirstN(dr, 0), front);
        const Vec3L<VR> bent = NormalFromMapLanes(dr, Vec3L<VR>{front[0], front[1], front[2]}, rec, texel, maps->normalScale);
        const VR out[3] = {bent.x, bent.y, bent.z};
        for (int c = 0; c < 3; ++c) keep(rec.negate ? hn::Neg(out[c]) : out[c], b.normal[c]);
      }
    }
    for (int c = 0; c < 4; ++c) keep(color[c], b.color[c]);
    hn::StoreU(index, du, b.pixel + at);
    const std::size_t n = std::min(lanes, count - i);
    std::fill_n(b.slot + at, n, rec.slot);
    b.count += n;
  }
}

void GatherShown(const VisibleLayout& layout, const ShownRecord& rec, const PixelRect& rect, const std::uint32_t* pixels,
                 std::size_t count, VisibleBatch& b) {
  if (count == 0) return;
#if HWY_TARGET != HWY_SCALAR && !ILLUM_USE_DOUBLE
  {
    // Every edge value over the record's pixels in the tile, and the parts it is summed from,
    // below 2^31.
    const TriangleSetup& t = *rec.setup;
    const int minX = std::max(t.minX, rect.minX), maxX = std::min(t.maxX, rect.maxX);
    const int minY = std::max(t.minY, rect.minY), maxY = std::min(t.maxY, rect.maxY);
    bool split = true;
    const std::int64_t half = kSubpixelOne / 2, limit = (std::int64_t(1) << 31) - 4 * kSubpixelOne;
    for (const EdgeFunction& e : t.edge) {
      const std::int64_t a = std::abs(std::int64_t(e.a)), bb = std::abs(std::int64_t(e.b));
      const std::int64_t first = e.at(std::int64_t(minX) * kSubpixelOne + half, std::int64_t(minY) * kSubpixelOne + half);
      split = split && std::abs(first) + 2 * (a * (maxX - minX) + bb * (maxY - minY)) * kSubpixelOne <= limit;
    }
    if (split) return GatherShownIn<true>(layout, rec, rect, pixels, count, b);
  }
#endif
  GatherShownIn<false>(layout, rec, rect, pixels, count, b);
}

// The (pixel, record) pairs of a tile, pixel by pixel, each record a pixel's samples show once (in
// sample order, as VisibleSamples::forEachShown gives them): whole vectors of winners at a time,
// the empty ones passed over and a pixel whose samples agree taken at once. Returns how many.
std::size_t ShownPairs(const std::uint32_t* winners, int samples, std::uint32_t* pixel, std::uint32_t* slot) {
  const hn::ScalableTag<std::uint32_t> du;
  const int lanes = int(hn::Lanes(du)), words = kTileSize * kTileSize * samples;
  const auto none = hn::Set(du, kNoWinner);
  std::size_t n = 0;
  const VisibleSamples shown{samples, nullptr, const_cast<std::uint32_t*>(winners)};
  const auto one = [&](int index, std::uint32_t s) { pixel[n] = std::uint32_t(index), slot[n] = s, ++n; };
  if (samples == 1) {
    for (int i = 0; i < words; i += lanes) {
      const auto w = hn::LoadU(du, winners + i);
      const auto some = hn::Ne(w, none);
      if (hn::AllFalse(du, some)) continue;
      hn::StoreU(hn::Compress(hn::Iota(du, std::uint32_t(i)), some), du, pixel + n);
      hn::StoreU(hn::Compress(w, some), du, slot + n);
      n += hn::CountTrue(du, some);
    }
    return n;
  }
  if (samples > lanes || lanes > 64) {
    for (int i = 0; i < kTileSize * kTileSize; ++i) shown.forEachShown(i, one);
    return n;
  }
  // Lane k compared with its pixel's first sample.
  HWY_ALIGN std::uint32_t firstOf[hn::MaxLanes(du)];
  for (int k = 0; k < lanes; ++k) firstOf[k] = std::uint32_t(k & ~(samples - 1));
  const auto first = hn::SetTableIndices(du, firstOf);
  // Each lane's pixel (from the vector's first), and the lanes that are a pixel's first sample.
  const int shift = __builtin_ctz(unsigned(samples));
  const auto lanePixel = hn::ShiftRightSame(hn::Iota(du, 0), shift);
  const auto sampleOf = hn::And(hn::Iota(du, 0), hn::Set(du, std::uint32_t(samples - 1)));
  const auto leads = hn::Eq(sampleOf, hn::Zero(du));
  // Row k − 1: each lane's sample k back in its pixel (itself where there is none).
  HWY_ALIGN std::uint32_t back[(kSamplesMax - 1) * hn::MaxLanes(du)];
  for (int k = 1; k < samples; ++k)
    for (int lane = 0; lane < lanes; ++lane)
      back[(k - 1) * lanes + lane] = std::uint32_t((lane & (samples - 1)) >= k ? lane - k : lane);
  for (int i = 0; i < words; i += lanes) {
    const auto w = hn::LoadU(du, winners + i);
    if (hn::AllTrue(du, hn::Eq(w, none))) continue;
    const auto agree = hn::Eq(w, hn::TableLookupLanes(w, first));
    if (hn::AllTrue(du, agree)) {  // every pixel's samples show one record (or none): its first's
      const auto some = hn::And(leads, hn::Ne(w, none));
      hn::StoreU(hn::Compress(lanePixel + hn::Set(du, std::uint32_t(i / samples)), some), du, pixel + n);
      hn::StoreU(hn::Compress(w, some), du, slot + n);
      n += hn::CountTrue(du, some);
      continue;
    }
    // Some pixel's samples differ: a lane shows a record of its own when it has one and none of
    // its pixel's earlier samples (k lanes back, k = 1 .. samples − 1) shows the same. The lanes
    // kept are in pixel order, then sample order, as forEachShown gives them.
    auto fresh = hn::Ne(w, none);
    for (int k = 1; k < samples; ++k) {
      const auto earlier = hn::TableLookupLanes(w, hn::SetTableIndices(du, back + (k - 1) * lanes));
      const auto firstFew = hn::Lt(sampleOf, hn::Set(du, std::uint32_t(k)));  // no sample k back
      fresh = hn::And(fresh, hn::Or(firstFew, hn::Ne(w, earlier)));
    }
    hn::StoreU(hn::Compress(lanePixel + hn::Set(du, std::uint32_t(i / samples)), fresh), du, pixel + n);
    hn::StoreU(hn::Compress(w, fresh), du, slot + n);
    n += hn::CountTrue(du, fresh);
  }
  return n;
}

void GroupByRecord(const std::uint32_t* pixel, const std::uint32_t* slot, std::size_t pairs, std::size_t records,
                   std::uint32_t* start, std::uint32_t* out) {
  // (Each pass over the pairs costs a sixteenth of a scattered store per pair on AVX-512: it pays
  // up to about eight records.)
  constexpr std::size_t kFewRecords = 8;
  if (records > kFewRecords) {
    std::fill_n(start, records + 1, 0u);
    for (std::size_t k = 0; k < pairs; ++k) ++start[slot[k] + 1];
    for (std::size_t r = 0; r < records; ++r) start[r + 1] += start[r];
    for (std::size_t k = 0; k < pairs; ++k) out[start[slot[k]]++] = pixel[k];  // moved to each record's end,
    for (std::size_t r = records; r > 0; --r) start[r] = start[r - 1];          // then back
    start[0] = 0;
    return;
  }
  const hn::ScalableTag<std::uint32_t> du;
  const std::size_t lanes = hn::Lanes(du);
  std::size_t n = 0;
  for (std::size_t r = 0; r < records; ++r) {
    start[r] = std::uint32_t(n);
    const auto mine = hn::Set(du, std::uint32_t(r));
    for (std::size_t i = 0; i < pairs; i += lanes) {  // (both lists have room for a vector past their ends)
      const auto picked = hn::And(hn::FirstN(du, pairs - i), hn::Eq(hn::LoadU(du, slot + i), mine));
      hn::StoreU(hn::Compress(hn::LoadU(du, pixel + i), picked), du, out + n);
      n += hn::CountTrue(du, picked);
    }
  }
  start[records] = std::uint32_t(n);
}

// Each pair's RGBA8 word to the samples of its pixel that show its record (VisibleSamples::write),
// a pixel's samples compared and stored as one vector.
void WriteShown(const VisibleBatch& b, std::uint32_t* color, const std::uint32_t* winners, int samples) {
  if (samples == 1) {
    for (std::size_t k = 0; k < b.count; ++k) color[b.pixel[k]] = b.rgba[k];
    return;
  }
  const hn::CappedTag<std::uint32_t, 16> du;
  if (std::size_t(samples) > hn::Lanes(du)) {
    const VisibleSamples out{samples, color, const_cast<std::uint32_t*>(winners)};
    for (std::size_t k = 0; k < b.count; ++k) out.write(int(b.pixel[k]), b.slot[k], b.rgba[k]);
    return;
  }
  const auto mine = hn::FirstN(du, std::size_t(samples));
  for (std::size_t k = 0; k < b.count; ++k) {
    const std::size_t at = std::size_t(b.pixel[k]) * std::size_t(samples);
    const auto shows = hn::And(mine, hn::Eq(hn::LoadU(du, winners + at), hn::Set(du, b.slot[k])));
    hn::BlendedStore(hn::Set(du, b.rgba[k]), shows, du, color + at);
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
#include "raster/shade/fragment.h"
#include "shading/shade_points.h"

namespace illum {

HWY_EXPORT(GatherShown);
HWY_EXPORT(FinishVisible);
HWY_EXPORT(ShownPairs);
HWY_EXPORT(WriteShown);
HWY_EXPORT(GroupByRecord);

void gatherShown(const VisibleLayout& layout, const ShownRecord& record, const PixelRect& rect,
                 const std::uint32_t* pixels, std::size_t count, VisibleBatch& batch) {
  HWY_DYNAMIC_DISPATCH(GatherShown)(layout, record, rect, pixels, count, batch);
}

void finishVisible(const VisibleLayout& layout, VisibleBatch& batch) {
  HWY_DYNAMIC_DISPATCH(FinishVisible)(layout, batch);
}

std::size_t shownPairs(const std::uint32_t* winners, int samples, std::uint32_t* pixel, std::uint32_t* slot) {
  return HWY_DYNAMIC_DISPATCH(ShownPairs)(winners, samples, pixel, slot);
}

void groupByRecord(const std::uint32_t* pixel, const std::uint32_t* slot, std::size_t pairs, std::size_t records,
                   std::uint32_t* start, std::uint32_t* out) {
  HWY_DYNAMIC_DISPATCH(GroupByRecord)(pixel, slot, pairs, records, start, out);
}

namespace {

// Where an object's per-vertex values go in a ShownRecord, for the frame's shading.
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
  if (mapsDrawn(object, frame.litPerPixel())) {
    const Material& m = object.material;
    v.maps = &object.maps;
    v.physical = m.physicallyBased;
    v.metallic = m.physical.metallic, v.roughness = m.physical.roughness;
    v.emission = Color3(m.emission);
  }
  if (v.texture || v.maps) v.uv = take(2);
  v.baseTexel = texelIsBaseColor(object, frame.model, frame.litPerPixel());
  const Material& m = object.material;
  v.baseColor = Color4(physicalOf(m).baseColor, m.diffuse.a);
  return v;
}

}  // namespace

void VisibleShader::shadeAll(ShownLists& lists) {
  // The pairs, then each record's pixels laid out record by record (groupByRecord).
  const std::size_t n = records_.size(), room = kTileBlock * std::size_t(out_.count) + 16;
  if (lists.pairPixel.size() < room) lists.pairPixel.resize(room), lists.pairSlot.resize(room);
  const std::size_t pairs = shownPairs(out_.winners, out_.count, lists.pairPixel.data(), lists.pairSlot.data());
  if (pairs == 0) return;
  lists.start.resize(n + 1);
  lists.pixels.resize(pairs + 16);  // room for a vector written or read past the last
  groupByRecord(lists.pairPixel.data(), lists.pairSlot.data(), pairs, n, lists.start.data(), lists.pixels.data());
  for (std::size_t r = 0; r < n; ++r)
    if (lists.start[r + 1] > lists.start[r])
      shade(std::uint32_t(r), lists.pixels.data() + lists.start[r], lists.start[r + 1] - lists.start[r]);
  flush();
}

void VisibleShader::shade(std::uint32_t slot, const std::uint32_t* pixels, std::size_t count) {
  const DrawRecord& r = *records_[slot];
  const Object& object = target_.scene.objects[r.object];
  const TriangleSetup& t = r.setup;
  if (b_.count > 0 && r.object != object_) flush();
  if (b_.count == 0) {
    object_ = r.object;
    layout_ = layoutOf(target_.frame, object);
  }
  ShownRecord rec;
  rec.setup = &t;
  rec.slot = slot;
  const AttributeLayout& a = target_.layout(r);
  for (int k = 0; k < 3; ++k) {
    const VertexValues v{r.vertex(k, a), a};
    const auto put = [&](int at, const auto& value, int n) {
      for (int c = 0; c < n; ++c) rec.vertex[k][at + c] = value[c];
    };
    if (layout_.lit >= 0) put(layout_.lit, v.lit(), 4);
    if (layout_.position >= 0) put(layout_.position, v.position(), 3), put(layout_.normal, v.normal(), 3);
    if (layout_.color >= 0) put(layout_.color, v.color(), 4);
    if (layout_.uv >= 0) put(layout_.uv, v.uv(), 2);
  }
  rec.flat = r.flat;
  rec.negate = target_.frame.lightModel.twoSided && !t.frontFacing;
  if (layout_.maps && layout_.maps->normal) {
    const VertexValues v[3] = {{r.vertex(0, a), a}, {r.vertex(1, a), a}, {r.vertex(2, a), a}};
    const TangentFrame f =
        triangleTangents({v[0].position(), v[1].position(), v[2].position()}, {v[0].uv(), v[1].uv(), v[2].uv()});
    rec.dPdu = f.dPdu, rec.dPdv = f.dPdv;
  }
  if (layout_.uv >= 0) {
    // Screen-space barycentrics are linear: one pixel right adds a·256/area, one up adds b·256/area.
    const Real step = Real(kSubpixelOne) / Real(t.area2);
    for (int i = 0; i < 3; ++i)
      rec.stepX[i] = Real(t.edge[std::size_t(i)].a) * step, rec.stepY[i] = Real(t.edge[std::size_t(i)].b) * step;
  }
  // In pieces that fit in the batch.
  for (std::size_t done = 0; done < count;) {
    if (b_.count == VisibleBatch::kSize) flush();
    const std::size_t piece = std::min(count - done, VisibleBatch::kSize - b_.count);
    gatherShown(layout_, rec, rect_, pixels + done, piece, b_);
    done += piece;
  }
}

void VisibleShader::flush() {
  if (b_.count == 0) return;
  const Object& object = target_.scene.objects[object_];
  if (layout_.shading == Shading::Phong) {
    const ShadeSetup setup{target_.frame.lights, target_.frame.lightModel, modelOf(object.material, target_.frame.model),
                           object.material};
    SurfacePoints points;
    points.count = b_.count;
    for (int c = 0; c < 3; ++c) points.position[c] = b_.position[c], points.normal[c] = b_.normal[c];
    if (layout_.color >= 0 || layout_.baseTexel)
      for (int c = 0; c < 4; ++c) points.color[c] = b_.color[c];
    if (layout_.maps && layout_.maps->metallicRoughness && layout_.physical)
      points.metallic = b_.metallic, points.roughness = b_.roughness;
    if (layout_.maps && layout_.maps->emissive)
      for (int c = 0; c < 3; ++c) points.emission[c] = b_.emission[c];
    if (const OcclusionQuery* occlusion = target_.frame.occlusion) {
      // The ambient's open share at each pixel's point, seeded by the pixel.
      for (std::size_t k = 0; k < b_.count; ++k)
        b_.seed[k] = OcclusionQuery::pixelSeed(rect_.minX + int(b_.pixel[k] % kTileSize),
                                               rect_.minY + int(b_.pixel[k] / kTileSize), target_.frame.width);
      const Real* position[3] = {b_.position[0], b_.position[1], b_.position[2]};
      const Real* normal[3] = {b_.normal[0], b_.normal[1], b_.normal[2]};
      occlusion->open(b_.count, position, normal, b_.seed, b_.open);
      points.ambientOpen = b_.open;
    }
    Real* const lit[4] = {b_.lit[0], b_.lit[1], b_.lit[2], b_.lit[3]};
    shadePoints(setup, points, lit);
  } else {
    for (int c = 0; c < 4; ++c) std::copy_n(b_.color[c], b_.count, b_.lit[c]);
  }
  if (blending_) {
    // Each pixel's colour (GL_MODULATE's product too) blended over its samples, in float.
    const bool modulate = layout_.texture && !layout_.baseTexel;
    for (std::size_t k = 0; k < b_.count; ++k) {
      const Color4 lit(b_.lit[0][k], b_.lit[1][k], b_.lit[2][k], b_.lit[3][k]);
      out_.blend(int(b_.pixel[k]), b_.slot[k],
                 modulate ? lit * Vec4(b_.texel[0][k], b_.texel[1][k], b_.texel[2][k], b_.texel[3][k]) : lit);
    }
  } else {
    finishVisible(layout_, b_);
    HWY_DYNAMIC_DISPATCH(WriteShown)(b_, out_.color, out_.winners, out_.count);
  }
  b_.count = 0;
}

void VisibleShader::blendRecord(std::uint32_t slot, ShownLists& lists) {
  const TriangleSetup& t = records_[slot]->setup;
  const int minX = std::max(t.minX, rect_.minX), maxX = std::min(t.maxX, rect_.maxX);
  const int minY = std::max(t.minY, rect_.minY), maxY = std::min(t.maxY, rect_.maxY);
  if (minX > maxX || minY > maxY) return;
  // Its pixels: those of its bounds some sample of which shows it.
  lists.pixels.clear();
  for (int y = minY; y <= maxY; ++y)
    for (int x = minX; x <= maxX; ++x) {
      const int index = (y - rect_.minY) * kTileSize + (x - rect_.minX);
      if (out_.shows(index, slot)) lists.pixels.push_back(std::uint32_t(index));
    }
  const std::size_t count = lists.pixels.size();
  if (count == 0) return;
  lists.pixels.resize(count + 16);  // room for a vector read past the last
  blending_ = true;
  shade(slot, lists.pixels.data(), count);
  flush();
  blending_ = false;
}

}  // namespace illum
#endif  // HWY_ONCE

// Multisampled Phong's tiny triangles lit at setup (tiny_batch.h: coverTinyBatch with a
// ShadeSetup), compiled once per SIMD target (Highway's foreach_target), dispatched at run time.
#include <illum/real.h>

#if !ILLUM_USE_DOUBLE
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/setup/tiny_lit_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/coverage/interpolate-inl.h"
#include "math/iota-inl.h"
#include "raster/setup/tiny_batch.h"
#include "raster/setup/tiny_cover-inl.h"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <span>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Multisampled Phong (CoverTinyLitBatch): each covered sample's values until its colour is known,
// and the pixels (of a triangle) lit once, whichever of their samples are covered.
struct LitScratch {
  static constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);
  static constexpr std::size_t kRoom = kTinyBatchRoom * kSamplesMax + 2 * kMaxLanes;
  // A key per (triangle of the batch, pixel of its bounds): the triangle above kPixelBits, below
  // the pixel's offset from the bounds' first, row · kTileSize + column (< 32 · 64). One more key
  // for the lanes past the last sample.
  static constexpr int kPixelBits = 11;
  static constexpr std::uint32_t kSpareKey = std::uint32_t(TinyBatchLanes::kCapacity) << kPixelBits;
  // Per covered sample: its pixel centre's barycentrics, depth, tag and key.
  alignas(64) float weight[3][kRoom], depth[kRoom];
  alignas(64) std::uint32_t tag[kRoom], key[kRoom];
  // The pixels lit (one sample each): their centre's barycentrics, surface, key and colour.
  alignas(64) float litWeight[3][kRoom], litPosition[3][kRoom], litNormal[3][kRoom];
  alignas(64) std::uint32_t litKey[kRoom], owner[kRoom], rgba[kRoom];
  // Per key: first some sample of it (the one lit), then its place among the lit pixels. Only
  // keys written in the same batch are read, so it is never cleared.
  std::uint32_t of[kSpareKey + 1];
};

// A row of the batch's lanes that holds each triangle's place in it.
alignas(64) inline constexpr std::uint32_t kTriangleInBatch[TinyBatchLanes::kCapacity] = {0, 1, 2,  3,  4,  5,  6,  7,
                                                                                        8, 9, 10, 11, 12, 13, 14, 15};

// Each lane's value of its triangle (0 .. kCapacity − 1) in a row of the batch's lanes: one
// permute where a vector holds the whole row, else a gather.
template <class D, class VI>
HWY_INLINE hn::VFromD<D> LookUpTriangle(D d, const float* row, VI triangle) {
  if constexpr (hn::MaxLanes(D()) == TinyBatchLanes::kCapacity)
    return hn::TableLookupLanes(hn::LoadU(d, row), hn::IndicesFromVec(d, triangle));
  else
    return hn::GatherIndex(d, row, triangle);
}

// The same covered samples as CoverTinyBatch's (Gouraud's), each coloured by Phong's lighting at
// its pixel's centre: the surface there as CoverTinySurfaceBatch has it, lit by shadeOwnedPoints
// as the Surface route lights it, once per pixel of a triangle (its covered samples share the
// centre's surface, so any one of them stands for the others).
std::size_t CoverTinyLitBatch(const TinyBatchLanes& b, std::uint32_t members, const ShadeSetup& lighting,
                              TinyFragment* out, std::uint16_t* covered) {
  const hn::ScalableTag<float> df;
  const hn::RebindToUnsigned<decltype(df)> du;
  const hn::RebindToSigned<decltype(df)> di;
  using VF = hn::VFromD<decltype(df)>;
  using VU = hn::VFromD<decltype(du)>;
  static_assert(hn::MaxLanes(df) <= LitScratch::kMaxLanes);
  thread_local std::unique_ptr<LitScratch> scratch;  // uninitialised: only what a batch uses is touched
  if (!scratch) scratch.reset(new LitScratch);
  LitScratch& s = *scratch;
  const int sampleShift = __builtin_ctz(unsigned(b.samples));
  // The covered samples, each with its pixel centre's barycentrics (a pixel's samples share them).
  const std::size_t n = CoverGroups<true>(
      b, members, covered, [&](std::size_t at, int, const auto& of, VF l0, VF l1, VF l2, VF z, VU tag) {
        hn::Store(l0, df, s.weight[0] + at), hn::Store(l1, df, s.weight[1] + at), hn::Store(l2, df, s.weight[2] + at);
        hn::Store(z, df, s.depth + at);
        hn::Store(tag, du, s.tag + at);
        const VU pixel = hn::ShiftRightSame(hn::Sub(tag, of(b.firstTag)), sampleShift);
        hn::Store(hn::Or(hn::ShiftLeft<LitScratch::kPixelBits>(of(kTriangleInBatch)), pixel), du, s.key + at);
      });
  if (n == 0) return 0;
  const std::size_t lanes = hn::Lanes(du);
  const VU spare = hn::Set(du, LitScratch::kSpareKey);
  hn::StoreU(spare, du, s.key + n);
  const auto indexOf = [&](VU key) { return hn::BitCast(di, key); };
  const auto countUp = [&](std::size_t from) { return IotaFrom(du, std::uint32_t(from)); };
  // Each key names one of its samples (any: they share a surface)...
  for (std::size_t f = 0; f < n; f += lanes)
    hn::ScatterIndex(countUp(f), du, s.of, indexOf(hn::LoadU(du, s.key + f)));
  // ...whose surface is lit, its key's place among the lit ones noted.
  std::size_t lit = 0;
  for (std::size_t f = 0; f < n; f += lanes) {
    const VU key = hn::LoadU(du, s.key + f);
    const auto named = hn::And(hn::GatherIndex(du, s.of, indexOf(key)) == countUp(f), hn::FirstN(du, n - f));
    const auto namedF = hn::RebindMask(df, named);
    // Compressed in registers and stored whole (the room past the end allows): a compressing store
    // to memory is microcoded on AMD's Zen 4, many times slower.
    for (int c = 0; c < 3; ++c) hn::StoreU(hn::Compress(hn::LoadU(df, s.weight[c] + f), namedF), df, s.litWeight[c] + lit);
    hn::StoreU(hn::Compress(key, named), du, s.litKey + lit);
    lit += hn::CountTrue(du, named);
  }
  // Whole vectors of one owner: the last one filled up with copies of the last pixel lit.
  const std::size_t whole = (lit + lanes - 1) / lanes * lanes;
  for (int c = 0; c < 3; ++c) std::fill(s.litWeight[c] + lit, s.litWeight[c] + whole, s.litWeight[c][lit - 1]);
  std::fill(s.litKey + lit, s.litKey + whole, s.litKey[lit - 1]);
  // The surface at each lit pixel's centre, as CoverTinySurfaceBatch has it: computed here, once a
  // pixel, rather than for each of its covered samples.
  for (std::size_t u = 0; u < whole; u += lanes) {
    const auto triangle = hn::BitCast(di, hn::ShiftRight<LitScratch::kPixelBits>(hn::LoadU(du, s.litKey + u)));
    const auto of = [&](const float* row) { return LookUpTriangle(df, row, triangle); };
    const VF l0 = hn::LoadU(df, s.litWeight[0] + u), l1 = hn::LoadU(df, s.litWeight[1] + u);
    const VF l2 = hn::LoadU(df, s.litWeight[2] + u);
    VF p[3];
    PerspectiveWeights(l0, l1, l2, of(b.invW[0]), of(b.invW[1]), of(b.invW[2]), p);
    VF normal[3], unit[3];
    for (int c = 0; c < 3; ++c) {
      hn::StoreU(Blend(p, of(b.position[c][0]), of(b.position[c][1]), of(b.position[c][2])), df, s.litPosition[c] + u);
      normal[c] = Blend(p, of(b.normal[c][0]), of(b.normal[c][1]), of(b.normal[c][2]));
    }
    UnitNormal(normal, of(b.negate) != hn::Zero(df), unit);
    for (int c = 0; c < 3; ++c) hn::StoreU(unit[c], df, s.litNormal[c] + u);
  }
  hn::StoreU(spare, du, s.litKey + lit);
  for (std::size_t u = 0; u < lit; u += lanes) hn::ScatterIndex(countUp(u), du, s.of, indexOf(hn::LoadU(du, s.litKey + u)));
  s.of[LitScratch::kSpareKey] = 0;  // the lanes past the last sample take the first colour
  std::fill_n(s.owner, whole, 0u);
  SurfacePoints points;
  points.count = whole;
  for (int c = 0; c < 3; ++c) points.position[c] = s.litPosition[c], points.normal[c] = s.litNormal[c];
  for (int c = 0; c < 4; ++c) points.color[c] = s.litPosition[0];  // not read: no vertex colours
  const std::uint8_t uncolored = 0;
  shadeOwnedPoints(std::span(&lighting, 1), std::span(&uncolored, 1), points, s.owner, s.rgba);
  for (std::size_t f = 0; f < n; f += lanes) {
    const VU place = hn::GatherIndex(du, s.of, indexOf(hn::LoadU(du, s.key + f)));
    const VU color = hn::GatherIndex(du, s.rgba, indexOf(place));
    hn::StoreInterleaved3(hn::LoadU(du, s.tag + f), hn::BitCast(du, hn::LoadU(df, s.depth + f)), color, du,
                          reinterpret_cast<std::uint32_t*>(out + f));
  }
  return n;
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(CoverTinyLitBatch);

std::size_t coverTinyBatch(const TinyBatchLanes& batch, std::uint32_t members, const ShadeSetup& lighting,
                           TinyFragment* out, std::uint16_t* covered) {
  return HWY_DYNAMIC_DISPATCH(CoverTinyLitBatch)(batch, members, lighting, out, covered);
}

}  // namespace illum
#endif  // HWY_ONCE
#endif  // !ILLUM_USE_DOUBLE

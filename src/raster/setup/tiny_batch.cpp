// coverTinyBatch and setupTinyGroup, compiled once per SIMD target (Highway's foreach_target),
// dispatched at run time.
#include <illum/real.h>

#if !ILLUM_USE_DOUBLE
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/setup/tiny_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/coverage/interpolate-inl.h"
#include "raster/setup/tiny_batch.h"
#include "raster/setup/tiny_cover-inl.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstring>
#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

std::size_t CoverTinyBatch(const TinyBatchLanes& b, std::uint32_t members, bool flat, TinyFragment* out,
                           std::uint16_t* covered) {
  static_assert(sizeof(TinyFragment) == 3 * sizeof(std::uint32_t));
  const hn::ScalableTag<float> df;
  const hn::RebindToUnsigned<decltype(df)> du;
  using VF = hn::VFromD<decltype(df)>;
  const auto emit = [&](std::size_t at, int, const auto& of, VF l0, VF l1, VF l2, VF z, auto tag) {
    hn::VFromD<decltype(du)> color;
    if (flat) {
      color = of(b.packed);
    } else {
      VF p[3];
      PerspectiveWeights(l0, l1, l2, of(b.invW[0]), of(b.invW[1]), of(b.invW[2]), p);
      VF channel[4];
      for (int k = 0; k < 3; ++k) channel[k] = Blend(p, of(b.lit[k][0]), of(b.lit[k][1]), of(b.lit[k][2]));
      color = hn::BitCast(du, PackColors(df, true, channel));
    }
    hn::StoreInterleaved3(tag, hn::BitCast(du, z), color, du, reinterpret_cast<std::uint32_t*>(out + at));
  };
  return b.samples > 1 ? CoverGroups<true>(b, members, covered, emit) : CoverGroups<false>(b, members, covered, emit);
}

// The same covered pixels as Phong's visible surface (CoverTinySurface's values, SurfaceAt's
// formulas), assembled lane by lane into their structs.
std::size_t CoverTinySurfaceBatch(const TinyBatchLanes& b, std::uint32_t members, std::uint32_t owner,
                                  TinySurface* out, std::uint16_t* covered) {
  const hn::ScalableTag<float> df;
  const hn::RebindToUnsigned<decltype(df)> du;
  using VF = hn::VFromD<decltype(df)>;
  constexpr std::size_t kMax = hn::MaxLanes(df);
  return CoverGroups<false>(b, members, covered, [&](std::size_t at, int count, const auto& of, VF l0, VF l1, VF l2, VF z,
                                              auto tag) {
    VF p[3];
    PerspectiveWeights(l0, l1, l2, of(b.invW[0]), of(b.invW[1]), of(b.invW[2]), p);
    VF n[3], normal[3];
    HWY_ALIGN float position[3][kMax], unit[3][kMax], depth[kMax];
    HWY_ALIGN std::uint32_t tags[kMax];
    for (int c = 0; c < 3; ++c) {
      hn::Store(Blend(p, of(b.position[c][0]), of(b.position[c][1]), of(b.position[c][2])), df, position[c]);
      n[c] = Blend(p, of(b.normal[c][0]), of(b.normal[c][1]), of(b.normal[c][2]));
    }
    UnitNormal(n, of(b.negate) != hn::Zero(df), normal);
    for (int c = 0; c < 3; ++c) hn::Store(normal[c], df, unit[c]);
    hn::Store(z, df, depth);
    hn::Store(tag, du, tags);
    for (int k = 0; k < count; ++k)
      out[at + std::size_t(k)] = {tags[k], depth[k], owner, {position[0][k], position[1][k], position[2][k]},
                                  {unit[0][k], unit[1][k], unit[2][k]}};
  });
}

// The rows SetupTinyGroup works from, gathered from the vertices a field at a time over all the
// group's triangles (one lane each): window x and y (their low 32 bits: inside the clip volume
// they are below 2^23, clip.h) and whether all three outcodes are 0, as doubles for the setup's
// integer arithmetic; depth, 1/w and, with `colors`, the lit colours, as the floats they are.
// Lanes from `count` on are zero and outside. A vertex's fields are found at its index times
// its size in 32-bit words, which fits an int32 up to kGatherableVertices vertices.
constexpr std::size_t kVertexWords = sizeof(ShadedVertex) / 4;
constexpr std::size_t kGatherableVertices = (std::size_t(1) << 31) / kVertexWords;
static_assert(sizeof(ShadedVertex) % 4 == 0 && std::endian::native == std::endian::little);

template <int kN>
HWY_INLINE void GatherVertexRows(const TinyGroupSource& src, int count, bool colors, double (&x)[3][kN],
                                 double (&y)[3][kN], double (&inside)[kN], float (&z)[3][kN], float (&invW)[3][kN],
                                 float (&front)[3][4][kN], float (&back)[3][4][kN]) {
  const hn::ScalableTag<std::int32_t> di;
  const hn::RebindToUnsigned<decltype(di)> du;
  const hn::RebindToFloat<decltype(di)> df;
  const hn::ScalableTag<double> dd;
  const hn::Rebind<std::int32_t, decltype(dd)> dih;
  using VI = hn::VFromD<decltype(di)>;
  static_assert(hn::MaxLanes(df) <= kN);
  // The group's indices, past `count` vertex 0's (never read past the source's triangles).
  HWY_ALIGN std::uint32_t index[3 * hn::MaxLanes(du)] = {};
  std::memcpy(index, src.indices, 3 * std::size_t(count) * sizeof(std::uint32_t));
  hn::VFromD<decltype(du)> triangleIndex[3];
  hn::LoadInterleaved3(du, index, triangleIndex[0], triangleIndex[1], triangleIndex[2]);
  const auto valid = hn::FirstN(di, std::size_t(count));
  const auto* words = reinterpret_cast<const std::int32_t*>(src.vertices);
  const auto wordOf = [](std::size_t offset) { return std::ptrdiff_t(offset / 4); };
  // A row of doubles from a vector of int32 lanes.
  HWY_ALIGN std::int32_t wordsOut[hn::MaxLanes(di)];
  const auto rowOfWords = [&](VI v, double* row) {
    hn::Store(hn::IfThenElseZero(valid, v), di, wordsOut);
    for (int j = 0; j < int(hn::Lanes(di)); j += int(hn::Lanes(dd)))
      hn::Store(hn::PromoteTo(dd, hn::Load(dih, wordsOut + j)), dd, row + j);
  };
  // Two neighbouring floats at `offset`, gathered as one 64-bit word (half the lanes a gather
  // fetches), into their rows.
  const hn::ScalableTag<std::int64_t> dq;
  const hn::Rebind<std::int32_t, decltype(dq)> dqi;
  const auto* pairsIn = reinterpret_cast<const std::int64_t*>(src.vertices);
  HWY_ALIGN std::int32_t pairIndex[hn::MaxLanes(di)];
  HWY_ALIGN std::int64_t pairsOut[hn::MaxLanes(df)];
  const auto rowsOfPairs = [&](std::size_t offset, float* first, float* second) {
    for (int j = 0; j < int(hn::Lanes(df)); j += int(hn::Lanes(dq)))
      hn::Store(hn::GatherIndex(dq, pairsIn + offset / 8, hn::PromoteTo(dq, hn::Load(dqi, pairIndex + j))), dq,
                pairsOut + j);
    hn::VFromD<decltype(df)> a, b;
    hn::LoadInterleaved2(df, reinterpret_cast<const float*>(pairsOut), a, b);
    hn::Store(hn::IfThenElseZero(hn::RebindMask(df, valid), a), df, first);
    hn::Store(hn::IfThenElseZero(hn::RebindMask(df, valid), b), df, second);
  };
  constexpr std::size_t kDepth = offsetof(ShadedVertex, window) + offsetof(WindowPosition, z);
  static_assert(offsetof(WindowPosition, invW) == offsetof(WindowPosition, z) + 4 && kDepth % 8 == 0 &&
                offsetof(ShadedVertex, front) % 8 == 0 && offsetof(ShadedVertex, back) % 8 == 0);
  VI codes = hn::Zero(di);
  for (int k = 0; k < 3; ++k) {
    const VI at = hn::BitCast(di, triangleIndex[k]) * hn::Set(di, std::int32_t(kVertexWords));
    hn::Store(hn::ShiftRight<1>(at), di, pairIndex);
    const auto word = [&](std::size_t offset) { return hn::GatherIndex(di, words + wordOf(offset), at); };
    codes = hn::Or(codes, word(offsetof(ShadedVertex, outcode)));  // kOutcodeUnknown is not 0
    rowOfWords(word(offsetof(ShadedVertex, window) + offsetof(WindowPosition, x)), x[k]);
    rowOfWords(word(offsetof(ShadedVertex, window) + offsetof(WindowPosition, y)), y[k]);
    rowsOfPairs(kDepth, z[k], invW[k]);
    if (!colors) continue;
    for (int c = 0; c < 4; c += 2)
      rowsOfPairs(offsetof(ShadedVertex, front) + 4 * std::size_t(c), front[k][c], front[k][c + 1]);
    if (src.twoSided)
      for (int c = 0; c < 4; c += 2)
        rowsOfPairs(offsetof(ShadedVertex, back) + 4 * std::size_t(c), back[k][c], back[k][c + 1]);
  }
  rowOfWords(hn::IfThenElseZero(codes == hn::Zero(di), hn::Set(di, 1)), inside);
}

// setupTriangle (setup.cpp) and TinyBatch::add over lanes, one triangle per double lane: the
// window coordinates are integers of at most 2^23 (the guard band, clip.h) whose products and sums
// here stay below 2^53, so every integer of the scalar setup is exact in double; the float values
// are rounded from them once, as the scalar conversions round.
int TinyGroupCapacity() {
  return std::min<int>(TinyBatchLanes::kCapacity, int(hn::Lanes(hn::ScalableTag<float>())));
}

void SetupTinyGroup(const TinyGroupSource& src, int count, TinyBatchLanes& b, int* tileOut, std::uint32_t& fastOut,
                    std::uint32_t& emptyOut) {
  constexpr int kN = TinyBatchLanes::kCapacity;
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> df;
  const hn::Rebind<std::int32_t, decltype(dd)> di;
  using VD = hn::VFromD<decltype(dd)>;
  using MD = decltype(hn::FirstN(dd, 0));
  const int lanes = int(hn::Lanes(dd));
  // The triangles' vertices as rows of lanes (vertex k of triangle j at [k][j]).
  HWY_ALIGN double x[3][kN], y[3][kN], inside[kN];
  HWY_ALIGN float z[3][kN], invW[3][kN], front[3][4][kN], back[3][4][kN];
  const bool colors = !src.surface && !src.flat;  // lit per pixel, or one colour per triangle (below)
  if (src.vertexCount > 0 && src.vertexCount <= kGatherableVertices) {
    GatherVertexRows(src, count, colors, x, y, inside, z, invW, front, back);
  } else {
    for (int j = 0; j < count; ++j) {
      unsigned codes = 0;
      for (int k = 0; k < 3; ++k) {
        const ShadedVertex& v = src.vertices[src.indices[3 * j + k]];
        codes |= v.outcode;  // kOutcodeUnknown is not 0
        x[k][j] = double(v.window.x), y[k][j] = double(v.window.y);
        z[k][j] = v.window.z, invW[k][j] = v.window.invW;
        if (!colors) continue;
        for (int c = 0; c < 4; ++c) front[k][c][j] = v.front[c];
        if (src.twoSided)
          for (int c = 0; c < 4; ++c) back[k][c][j] = v.back[c];
      }
      inside[j] = codes == 0 ? 1 : 0;
    }
    for (int j = count; j < kN; ++j) {  // the last vector's rest: outside, no values to trip over
      inside[j] = 0;
      for (int k = 0; k < 3; ++k) {
        x[k][j] = y[k][j] = z[k][j] = invW[k][j] = 0;
        for (int c = 0; c < 4; ++c) front[k][c][j] = back[k][c][j] = 0;
      }
    }
  }
  const VD zero = hn::Zero(dd), one = hn::Set(dd, 1.0);
  const VD sub = hn::Set(dd, double(kSubpixelOne)), invSub = hn::Set(dd, 1.0 / double(kSubpixelOne));
  const VD tileSize = hn::Set(dd, double(kTileSize)), invTile = hn::Set(dd, 1.0 / double(kTileSize));
  const VD reachMinX = hn::Set(dd, double(src.reach.minX)), reachMaxX = hn::Set(dd, double(src.reach.maxX));
  const VD reachMinY = hn::Set(dd, double(src.reach.minY)), reachMaxY = hn::Set(dd, double(src.reach.maxY));
  const VD reachSpanX = hn::Set(dd, double(2 * (src.reach.maxX - src.reach.minX)));
  const VD reachSpanY = hn::Set(dd, double(2 * (src.reach.maxY - src.reach.minY)));
  HWY_ALIGN std::int32_t tile[kN], width[kN], pixels[kN], pixel[kN], crosses[kN];
  const int samples = src.samples > 1 ? src.samples : 0;  // multisampled: each sample's box
  // Multisampled: the bounds (pixels) and the triangle's box (sub-pixel units), as integers, for
  // the samples' boxes (below). (The lanes past `count` stay 0, as if empty.)
  HWY_ALIGN std::int32_t boundsX[2][kN] = {}, boundsY[2][kN] = {}, boxX[2][kN] = {}, boxY[2][kN] = {};

  std::uint32_t fast = 0, empty = 0, clockwiseBits = 0, backBits = 0;
  for (int j0 = 0; j0 < count; j0 += lanes) {
    VD X[3], Y[3];
    for (int k = 0; k < 3; ++k) X[k] = hn::Load(dd, x[k] + j0), Y[k] = hn::Load(dd, y[k] + j0);
    const VD area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    const VD minFx = hn::Min(hn::Min(X[0], X[1]), X[2]), maxFx = hn::Max(hn::Max(X[0], X[1]), X[2]);
    const VD minFy = hn::Min(hn::Min(Y[0], Y[1]), Y[2]), maxFy = hn::Max(hn::Max(Y[0], Y[1]), Y[2]);
    // Pixel centres inside the bounds: ⌈(f − ½)/1⌉ and ⌊(f − ½)/1⌋ in pixels, as setup's shifts.
    const VD half = hn::Set(dd, double(kSubpixelOne / 2)), roundUp = hn::Set(dd, double(kSubpixelOne - 1));
    const auto firstCentre = [&](VD f) { return hn::Floor((f - half + roundUp) * invSub); };
    const auto lastCentre = [&](VD f) { return hn::Floor((f - half) * invSub); };
    // Multisampled, every pixel whose samples (the reach from its centre) the triangle may cover.
    const VD minX = hn::Max(zero, firstCentre(minFx - reachMaxX));
    const VD maxX = hn::Min(hn::Set(dd, src.width - 1.0), lastCentre(maxFx - reachMinX));
    const VD minY = hn::Max(zero, firstCentre(minFy - reachMaxY));
    const VD maxY = hn::Min(hn::Set(dd, src.height - 1.0), lastCentre(maxFy - reachMinY));
    const MD in = hn::Load(dd, inside + j0) == one;
    const MD covers = hn::And(hn::And(area2 != zero, minX <= maxX), minY <= maxY);
    const MD swapped = area2 < zero;
    // Counter-clockwise: vertices 1 and 2 swapped for a clockwise triangle.
    const VD PX[3] = {X[0], hn::IfThenElse(swapped, X[2], X[1]), hn::IfThenElse(swapped, X[1], X[2])};
    const VD PY[3] = {Y[0], hn::IfThenElse(swapped, Y[2], Y[1]), hn::IfThenElse(swapped, Y[1], Y[2])};
    const VD w = maxX - minX + one, h = maxY - minY + one;
    MD tiny = w * h <= hn::Set(dd, double(kTinyPixels));
    // As setupTriangle's floatExact: multisampled, at every sample of the bounds' pixels.
    const VD spanX = maxFx - minFx + reachSpanX, spanY = maxFy - minFy + reachSpanY;
    const VD fx = minX * sub + half, fy = minY * sub + half;
    for (int i = 0; i < 3; ++i) {  // edge i: from vertex i + 1 to vertex i + 2, opposite vertex i
      const VD px = PX[(i + 1) % 3], py = PY[(i + 1) % 3], qx = PX[(i + 2) % 3], qy = PY[(i + 2) % 3];
      const VD a = py - qy, bb = qx - px, c = hn::Neg(a * px + bb * py);
      const MD left = qy < py, top = hn::And(qy == py, qx < px);
      tiny = hn::And(tiny, hn::Abs(a) * spanX + hn::Abs(bb) * spanY <= hn::Set(dd, double(1 << 24)));
      hn::Store(hn::DemoteTo(df, a * fx + bb * fy + c), df, b.edge[i] + j0);
      hn::Store(hn::DemoteTo(df, a) * hn::Set(df, float(kSubpixelOne)), df, b.stepX[i] + j0);
      hn::Store(hn::DemoteTo(df, bb) * hn::Set(df, float(kSubpixelOne)), df, b.stepY[i] + j0);
      hn::Store(hn::DemoteTo(df, hn::IfThenZeroElse(hn::Or(left, top), hn::Set(dd, -1.0))), df, b.bias[i] + j0);
    }
    hn::Store(hn::Set(df, 1.0f) / hn::DemoteTo(df, hn::Abs(area2)), df, b.invArea + j0);
    // The lit side: the back of a clockwise triangle under two-sided lighting.
    const MD backSide = src.twoSided ? hn::Not(area2 > zero) : hn::FirstN(dd, 0);
    MD isFast = hn::And(hn::And(in, covers), tiny);  // and opaque (below)
    if (src.frontOnly) isFast = hn::And(isFast, area2 > zero);
    const MD isEmpty = hn::AndNot(covers, in);
    const auto bitsOf = [&](MD m) { return MaskBits(dd, m) << j0; };
    const std::uint32_t valid = (1u << std::min(lanes, count - j0)) - 1;
    fast |= bitsOf(isFast) & (valid << j0);
    empty |= bitsOf(isEmpty) & (valid << j0);
    clockwiseBits |= bitsOf(swapped) & (valid << j0);
    backBits |= bitsOf(backSide) & (valid << j0);
    const VD tileX = hn::Floor(minX * invTile), tileY = hn::Floor(minY * invTile);
    const VD crossesX = hn::IfThenElseZero(hn::Floor(maxX * invTile) != tileX, one);
    const VD crossesY = hn::IfThenElseZero(hn::Floor(maxY * invTile) != tileY, hn::Set(dd, 2.0));
    hn::Store(hn::DemoteTo(di, crossesX + crossesY), di, crosses + j0);
    hn::Store(hn::DemoteTo(di, tileY * hn::Set(dd, double(src.tilesX)) + tileX), di, tile + j0);
    hn::Store(hn::DemoteTo(di, (minY - tileY * tileSize) * tileSize + (minX - tileX * tileSize)), di, pixel + j0);
    hn::Store(hn::DemoteTo(di, hn::IfThenElseZero(isFast, w)), di, width + j0);
    hn::Store(hn::DemoteTo(di, hn::IfThenElseZero(isFast, w * h)), di, pixels + j0);
    if (samples) {
      const VD box[2][2] = {{minX, maxX}, {minY, maxY}}, extent[2][2] = {{minFx, maxFx}, {minFy, maxFy}};
      for (int e = 0; e < 2; ++e) {
        hn::Store(hn::DemoteTo(di, box[0][e]), di, boundsX[e] + j0);
        hn::Store(hn::DemoteTo(di, box[1][e]), di, boundsY[e] + j0);
        hn::Store(hn::DemoteTo(di, extent[0][e]), di, boxX[e] + j0);
        hn::Store(hn::DemoteTo(di, extent[1][e]), di, boxY[e] + j0);
      }
    }
  }
  // Multisampled: each sample's box, the pixels whose sample lies in the triangle's box, as a
  // pass at that sample bounds them (inside the bounds, which take them all in): the pixel centres
  // ⌈(f − o − ½)/1⌉ to ⌊(f − o − ½)/1⌋ as above, in sub-pixel integers (a window coordinate is at
  // most 2^23), where the arithmetic shift is the floor, a whole row of triangles at a time.
  const hn::ScalableTag<std::int32_t> dw;
  for (int j0 = 0; samples && j0 < count; j0 += int(hn::Lanes(dw))) {
    using VW = hn::VFromD<decltype(dw)>;
    const auto isFast = hn::RebindMask(dw, MaskFromBits(hn::RebindToUnsigned<decltype(dw)>(), fast >> j0));
    const VW minX = hn::Load(dw, boundsX[0] + j0), maxX = hn::Load(dw, boundsX[1] + j0);
    const VW minY = hn::Load(dw, boundsY[0] + j0), maxY = hn::Load(dw, boundsY[1] + j0);
    const VW minFx = hn::Load(dw, boxX[0] + j0), maxFx = hn::Load(dw, boxX[1] + j0);
    const VW minFy = hn::Load(dw, boxY[0] + j0), maxFy = hn::Load(dw, boxY[1] + j0);
    const VW firstBias = hn::Set(dw, std::int32_t(kSubpixelOne - 1 - kSubpixelOne / 2));
    const VW lastBias = hn::Set(dw, std::int32_t(kSubpixelOne / 2));
    const auto firstCentre = [&](VW f) { return hn::ShiftRight<kSubpixelBits>(hn::Add(f, firstBias)); };
    const auto lastCentre = [&](VW f) { return hn::ShiftRight<kSubpixelBits>(hn::Sub(f, lastBias)); };
    const VW one = hn::Set(dw, 1);
    for (int smp = 0; smp < samples; ++smp) {
      const SubpixelOffset o = src.sampleOffsets[smp];
      const VW ox = hn::Set(dw, std::int32_t(o.x)), oy = hn::Set(dw, std::int32_t(o.y));
      const VW x0 = hn::Max(minX, firstCentre(hn::Sub(minFx, ox))), x1 = hn::Min(maxX, lastCentre(hn::Sub(maxFx, ox)));
      const VW y0 = hn::Max(minY, firstCentre(hn::Sub(minFy, oy))), y1 = hn::Min(maxY, lastCentre(hn::Sub(maxFy, oy)));
      const auto some = hn::AndNot(hn::Or(hn::Gt(x0, x1), hn::Gt(y0, y1)), isFast);  // (no integer ≤ in Highway 1.0)
      const VW sw = hn::IfThenElseZero(some, hn::Add(hn::Sub(x1, x0), one));
      const VW base = hn::Add(hn::Add(hn::ShiftLeft<4>(hn::Sub(x0, minX)),
                                      hn::ShiftLeft<4 + TinySampleSlot::kRowShift>(hn::Sub(y0, minY))),
                              hn::Set(dw, std::int32_t(TinySampleSlot::of(0, 0, o, smp))));
      hn::Store(hn::IfThenElseZero(some, base), dw, reinterpret_cast<std::int32_t*>(b.sampleBase[smp]) + j0);
      hn::Store(sw, dw, b.sampleWidth[smp] + j0);
      hn::Store(hn::Mul(sw, hn::IfThenElseZero(some, hn::Add(hn::Sub(y1, y0), one))), dw, b.sampleCount[smp] + j0);
    }
  }
  // Depth, 1/w and the colours of the vertices in counter-clockwise order, the colours of the lit
  // side, in float lanes as they were gathered; a colour that is not opaque leaves the fast path.
  const hn::ScalableTag<float> dv;
  for (int j0 = 0; j0 < count; j0 += int(hn::Lanes(dv))) {
    const auto swapped = MaskFromBits(dv, clockwiseBits >> j0), backSide = MaskFromBits(dv, backBits >> j0);
    auto opaque = hn::FirstN(dv, hn::Lanes(dv));
    for (int k = 0; k < 3; ++k) {
      const int from = k == 0 ? 0 : (k == 1 ? 2 : 1);  // vertex k of the swapped order
      const auto pick = [&](const float* kept, const float* other) {
        const auto value = hn::Load(dv, kept + j0);
        return k == 0 ? value : hn::IfThenElse(swapped, hn::Load(dv, other + j0), value);
      };
      hn::Store(pick(z[k], z[from]), dv, b.z[k] + j0);
      hn::Store(pick(invW[k], invW[from]), dv, b.invW[k] + j0);
      if (!colors) continue;
      for (int c = 0; c < 4; ++c) {
        const auto lit = pick(front[k][c], front[from][c]);
        const auto value = src.twoSided ? hn::IfThenElse(backSide, pick(back[k][c], back[from][c]), lit) : lit;
        if (c < 3) hn::Store(value, dv, b.lit[c][k] + j0);
        else opaque = hn::And(opaque, value == hn::Set(dv, 1.0f));
      }
    }
    fast &= ~(MaskBits(dv, hn::Not(opaque)) << j0);
  }
  for (std::uint32_t m = fast; m != 0; m &= m - 1) {
    const int j = __builtin_ctz(m);
    tileOut[j] = tile[j];
    b.firstTag[j] = std::uint32_t(pixel[j] * src.samples);
    b.width[j] = std::uint8_t(width[j]);
    b.count[j] = std::uint8_t(pixels[j]);
    b.crosses[j] = std::uint8_t(crosses[j]);
    if (src.flat) {  // the provoking (last) vertex's colour
      const ShadedVertex& c = src.vertices[src.indices[3 * j + 2]];
      b.packed[j] = packUnorm8((backBits >> j & 1) ? c.back : c.front);
    }
    if (src.surface) {  // counter-clockwise, as setupTriangle's caller orders them
      const std::uint32_t* at = src.indices + 3 * j;
      const bool clockwise = clockwiseBits >> j & 1;
      const std::uint32_t ordered[3] = {at[0], clockwise ? at[2] : at[1], clockwise ? at[1] : at[2]};
      for (int k = 0; k < 3; ++k) {
        const ShadedVertex& v = src.vertices[ordered[k]];
        for (int c = 0; c < 3; ++c) b.position[c][k][j] = v.eyePosition[c], b.normal[c][k][j] = v.eyeNormal[c];
      }
      b.negate[j] = (backBits >> j & 1) ? 1.0f : 0.0f;
    }
  }
  fastOut = fast;
  emptyOut = empty;
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(CoverTinyBatch);
HWY_EXPORT(CoverTinySurfaceBatch);
HWY_EXPORT(TinyGroupCapacity);
HWY_EXPORT(SetupTinyGroup);

int tinyGroupCapacity() { return HWY_DYNAMIC_DISPATCH(TinyGroupCapacity)(); }

void setupTinyGroup(const TinyGroupSource& source, int count, TinyBatchLanes& lanes, int* tile, std::uint32_t& fast,
                    std::uint32_t& empty) {
  HWY_DYNAMIC_DISPATCH(SetupTinyGroup)(source, count, lanes, tile, fast, empty);
}

std::size_t coverTinyBatch(const TinyBatchLanes& batch, std::uint32_t members, bool flat, TinyFragment* out,
                           std::uint16_t* covered) {
  return HWY_DYNAMIC_DISPATCH(CoverTinyBatch)(batch, members, flat, out, covered);
}

std::size_t coverTinyBatch(const TinyBatchLanes& batch, std::uint32_t members, std::uint32_t owner, TinySurface* out,
                           std::uint16_t* covered) {
  return HWY_DYNAMIC_DISPATCH(CoverTinySurfaceBatch)(batch, members, owner, out, covered);
}

void setTinyLanes(TinyBatchLanes& b, int j, const TriangleSetup& t, const Color4* lit, std::uint32_t packed,
                  std::uint32_t recordsBefore) {
  const std::int64_t half = kSubpixelOne / 2;
  const std::int64_t fx = std::int64_t(t.minX) * kSubpixelOne + half, fy = std::int64_t(t.minY) * kSubpixelOne + half;
  for (int i = 0; i < 3; ++i) {
    b.edge[i][j] = Real(t.edge[i].at(fx, fy));
    b.stepX[i][j] = Real(t.edge[i].a) * Real(kSubpixelOne);
    b.stepY[i][j] = Real(t.edge[i].b) * Real(kSubpixelOne);
    b.bias[i][j] = Real(t.edge[i].bias);
    b.z[i][j] = t.z[std::size_t(i)];
    b.invW[i][j] = t.invW[std::size_t(i)];
  }
  b.invArea[j] = t.invArea;
  if (lit)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) b.lit[c][k][j] = lit[k][c];
  b.packed[j] = packed;
  b.firstTag[j] =
      TinyTag::of(recordsBefore, std::uint32_t(((t.minY % kTileSize) * kTileSize + t.minX % kTileSize) * b.samples));
  b.width[j] = std::uint8_t(t.maxX - t.minX + 1);
  b.count[j] = std::uint8_t(b.width[j] * (t.maxY - t.minY + 1));
  b.crosses[j] = 0;
}

void setTinySurfaceLanes(TinyBatchLanes& b, int j, const SurfaceVertices& v) {
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) b.position[c][k][j] = v.position[k][c], b.normal[c][k][j] = v.normal[k][c];
  b.negate[j] = v.negate ? 1.0f : 0.0f;
}

template <class Pixel>
void TinyBatch<Pixel>::add(const TriangleSetup& t, const Color4* lit, std::uint32_t packed, std::uint32_t recordsBefore,
                    int tile) {
  const int j = size_++;
  members_ |= 1u << j;
  setTinyLanes(lanes_, j, t, lit, packed, recordsBefore);
  tile_[j] = tile;
  if (size_ == TinyBatchLanes::kCapacity) flush();
}

template <class Pixel>
TinyBatch<Pixel>::TinyBatch(TinyRuns<Pixel>& out, bool flat, int tilesX, std::uint32_t owner, int samples,
                            const ShadeSetup* lighting)
    : out_(out), flat_(flat), tilesX_(tilesX), owner_(owner), lighting_(lighting) {
  lanes_.samples = samples;
}

template <class Pixel>
void TinyBatch<Pixel>::commitAcrossTiles(int j, Pixel* pixels, std::size_t count) {
  // Its tags are the bounds' first pixel in the first tile plus row · kTileSize + column, times
  // the samples, plus the sample.
  const int shift = __builtin_ctz(unsigned(lanes_.samples));
  const std::uint32_t first = lanes_.firstTag[j], firstPixel = first >> shift, sampleMask = (1u << shift) - 1;
  const std::uint32_t x0 = firstPixel % kTileSize, y0 = firstPixel / kTileSize;
  std::uint8_t pieceOf[kTinyPixels * kSamplesMax];
  std::uint32_t size[4] = {};
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t offset = pixels[k].tag - first, pixel = offset >> shift;
    const std::uint32_t x = x0 + pixel % kTileSize, y = y0 + pixel / kTileSize;
    const unsigned p = unsigned(x >= kTileSize) | unsigned(y >= kTileSize) << 1;
    pieceOf[k] = std::uint8_t(p);
    ++size[p];
    pixels[k].tag = TinyTag::of(recordsBefore_[j][p],
                                ((y % kTileSize) * kTileSize + x % kTileSize) << shift | (offset & sampleMask));
  }
  // Covered in one tile only (the bounds cross, the pixels need not): already in place.
  for (unsigned p = 0; p < 4; ++p)
    if (size[p] == count) {
      out_.commit(count, pieceTile(j, p));
      return;
    }
  // Otherwise each piece's pixels after the previous piece's, each in the order it came.
  Pixel sorted[kTinyPixels * kSamplesMax];
  std::uint32_t at[4] = {0, size[0], size[0] + size[1], size[0] + size[1] + size[2]};
  for (std::size_t k = 0; k < count; ++k) sorted[at[pieceOf[k]]++] = pixels[k];
  for (std::size_t k = 0; k < count; ++k) pixels[k] = sorted[k];
  for (unsigned p = 0; p < 4; ++p) out_.commit(size[p], pieceTile(j, p));
}

template <class Pixel>
void TinyBatch<Pixel>::flush() {
  if (members_ == 0) return;
  std::uint16_t covered[TinyBatchLanes::kCapacity];
  Pixel* pixels = out_.room(kTinyBatchRoom * std::size_t(lanes_.samples));
  if constexpr (std::is_same_v<Pixel, TinySurface>) coverTinyBatch(lanes_, members_, owner_, pixels, covered);
  else if (lighting_) coverTinyBatch(lanes_, members_, *lighting_, pixels, covered);
  else coverTinyBatch(lanes_, members_, flat_, pixels, covered);
  for (std::uint32_t m = members_; m != 0; m &= m - 1) {
    const int j = __builtin_ctz(m);
    if (lanes_.crosses[j] == 0) out_.commit(covered[j], tile_[j]);
    else commitAcrossTiles(j, pixels, covered[j]);
    pixels += covered[j];
  }
  members_ = 0;
  size_ = 0;
}

template class TinyBatch<TinyFragment>;
template class TinyBatch<TinySurface>;

}  // namespace illum
#endif  // HWY_ONCE
#endif  // !ILLUM_USE_DOUBLE

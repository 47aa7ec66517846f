// rasterizeDepth, compiled once per SIMD target (Highway's foreach_target), dispatched at run time.
#include <illum/real.h>

#if ILLUM_USE_DOUBLE
// Double channels (-DILLUM_DOUBLE=ON): the depth pass by the scalar rasterizer (rasterize.h), with
// the same formulas; the colouring passes are float-only and not used.
#include "raster/tile/framebuffer.h"
#include "raster/coverage/tile_raster.h"

namespace illum {

std::size_t rasterizeDepth(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t slot,
                           std::uint32_t* winners, std::uint32_t* owner) {
  std::size_t passed = 0;
  rasterizeTriangle(t, tile, [&](int x, int y, Real l0, Real l1, Real l2) {
    const Real z = l0 * t.z[0] + l1 * t.z[1] + l2 * t.z[2];
    const int at = (y - tile.minY) * kTileSize + (x - tile.minX);
    if (!(z < depth[at])) return;
    depth[at] = z;
    winners[at] = slot;
    if (owner) owner[at] = kNoWinner;
    ++passed;
  });
  return passed;
}

std::size_t rasterizeSamples(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                             std::uint32_t slot) {
  std::size_t passed = 0;
  for (int s = 0; s < planes.count; ++s) {
    const TriangleSetup moved = atSample(t, planes.offsets[s]);
    rasterizeTriangle(moved, tile, [&](int x, int y, Real l0, Real l1, Real l2) {
      const Real z = l0 * t.z[0] + l1 * t.z[1] + l2 * t.z[2];
      const std::size_t at = std::size_t((y - tile.minY) * kTileSize + (x - tile.minX)) * std::size_t(planes.count) + std::size_t(s);
      if (!(z < planes.depth[at])) return;
      planes.depth[at] = z;
      planes.winners[at] = slot;
      ++passed;
    });
  }
  return passed;
}

std::size_t rasterizeSamples(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                             std::uint32_t slot, std::uint32_t* listed, std::size_t& listedCount) {
  const std::size_t passed = rasterizeSamples(t, tile, planes, slot);
  // The bounds' pixels that show the slot: those where a sample passed, as their winners hold it.
  listedCount = 0;
  const int minX = std::max(t.minX, tile.minX), maxX = std::min(t.maxX, tile.maxX);
  const int minY = std::max(t.minY, tile.minY), maxY = std::min(t.maxY, tile.maxY);
  for (int y = minY; y <= maxY; ++y)
    for (int x = minX; x <= maxX; ++x) {
      const std::size_t index = std::size_t((y - tile.minY) * kTileSize + (x - tile.minX));
      bool shows = false;
      for (int s = 0; s < planes.count; ++s) shows = shows || planes.winners[index * std::size_t(planes.count) + std::size_t(s)] == slot;
      if (shows) listed[listedCount++] = std::uint32_t(index);
    }
  return passed;
}

}  // namespace illum
#else
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/coverage/tile_raster.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/coverage/interpolate-inl.h"
#include "math/iota-inl.h"

#include "raster/tile/framebuffer.h"
#include "raster/coverage/row_span.h"
#include "raster/coverage/tile_raster.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DD = hn::ScalableTag<double>;            // edge functions, exact
using DR = hn::Rebind<Real, DD>;                // barycentrics, depth, colour: as the scalar path rounds them
using DU = hn::Rebind<std::uint32_t, DD>;
using VR = hn::VFromD<DR>;
using MR = decltype(hn::FirstN(DR(), 0));

// The depth pass over the triangle's pixels in `tile`; for each span of lanes that has fragments
// passing GL_LESS, write(x, pass, l0, l1, l2) stores what the draw keeps (tile-local x). The edge
// functions are evaluated exactly: in double lanes, or with kFloatEdges (a small triangle, whose
// every edge value inside its bounds is an integer of at most 2^24: TriangleSetup::floatExact) in
// the narrow lanes themselves; lanes beyond the bounds may round there, and are masked.
template <bool kFloatEdges, class Write>
HWY_INLINE std::size_t DepthPass(const TriangleSetup& t, const PixelRect& tile, Real* depth, const Write& write) {
  const int minX = std::max(t.minX, tile.minX), maxX = std::min(t.maxX, tile.maxX);
  const int minY = std::max(t.minY, tile.minY), maxY = std::min(t.maxY, tile.maxY);
  if (minX > maxX || minY > maxY) return 0;
  const DD dd;
  const DR dr;
  const int lanes = int(hn::Lanes(dd));
  // Rows start at the triangle's first column: a vector may run past the tile's row into the next
  // row or the tile's padding (framebuffer.h), never into another tile; those lanes are masked.
  const int startX = minX;
  const auto xIota = IotaFrom(dr, Real(startX - tile.minX));
  const auto hi = hn::Set(dr, Real(maxX - tile.minX));
  const auto invArea = hn::Set(dr, t.invArea);
  const auto z0 = hn::Set(dr, t.z[0]), z1 = hn::Set(dr, t.z[1]), z2 = hn::Set(dr, t.z[2]);
  const auto zero = hn::Zero(dr);
  std::int64_t step[3];
  hn::VFromD<DD> laneStep[3], blockStep[3], bias[3];
  VR laneStepR[3], biasR[3];
  for (int i = 0; i < 3; ++i) {
    step[i] = t.edge[i].a * kSubpixelOne;
    if constexpr (kFloatEdges) {
      laneStepR[i] = hn::Iota(dr, Real(0)) * hn::Set(dr, Real(step[i]));
      biasR[i] = hn::Set(dr, Real(t.edge[i].bias));
    } else {
      laneStep[i] = hn::Iota(dd, 0.0) * hn::Set(dd, double(step[i]));
      blockStep[i] = hn::Set(dd, double(lanes * step[i]));
      bias[i] = hn::Set(dd, double(t.edge[i].bias));
    }
  }
  const auto toReal = [&](hn::VFromD<DD> v) {
    if constexpr (sizeof(Real) == 4) return hn::DemoteTo(dr, v);  // rounds as int64 → float does
    else return v;
  };
  const std::int64_t half = kSubpixelOne / 2;
  std::size_t passed = 0;
  for (int y = minY; y <= maxY; ++y) {
    const std::int64_t fy = std::int64_t(y) * kSubpixelOne + half;
    const std::int64_t fx = std::int64_t(startX) * kSubpixelOne + half;
    std::int64_t e[3] = {t.edge[0].at(fx, fy), t.edge[1].at(fx, fy), t.edge[2].at(fx, fy)};
    // Double lanes step along the row exactly (integers far below 2^53).
    hn::VFromD<DD> D[3];
    if constexpr (!kFloatEdges)
      for (int i = 0; i < 3; ++i) D[i] = hn::Set(dd, double(e[i])) + laneStep[i];
    const int row = (y - tile.minY) * kTileSize - tile.minX;  // tile-local index of (0, y)
    auto xs = xIota;
    for (int x = startX; x <= maxX; x += lanes, xs = xs + hn::Set(dr, Real(lanes))) {
      // Inside ⇔ E + bias ≥ 0 (the top-left rule folded into the bias).
      VR E0, E1, E2;
      MR inside;
      if constexpr (kFloatEdges) {
        E0 = hn::Set(dr, Real(e[0])) + laneStepR[0];
        E1 = hn::Set(dr, Real(e[1])) + laneStepR[1];
        E2 = hn::Set(dr, Real(e[2])) + laneStepR[2];
        inside = hn::And(hn::And(E0 + biasR[0] >= zero, E1 + biasR[1] >= zero), E2 + biasR[2] >= zero);
      } else {
        const auto D0 = D[0], D1 = D[1], D2 = D[2];
        for (int i = 0; i < 3; ++i) D[i] = D[i] + blockStep[i];
        E0 = toReal(D0), E1 = toReal(D1), E2 = toReal(D2);
        // Converting to Real keeps the sign and zero, so the test can run in the narrow lanes.
        inside = hn::And(hn::And(toReal(D0 + bias[0]) >= zero, toReal(D1 + bias[1]) >= zero),
                         toReal(D2 + bias[2]) >= zero);
      }
      for (int i = 0; i < 3; ++i) e[i] += lanes * step[i];
      inside = hn::And(inside, xs <= hi);
      if (hn::AllFalse(dr, inside)) continue;
      const auto l0 = E0 * invArea, l1 = E1 * invArea, l2 = E2 * invArea;
      const auto z = l0 * z0 + l1 * z1 + l2 * z2;
      const auto stored = hn::LoadU(dr, depth + row + x);
      const auto pass = hn::And(inside, z < stored);
      if (hn::AllFalse(dr, pass)) continue;
      hn::BlendedStore(z, pass, dr, depth + row + x);
      write(row + x, pass, l0, l1, l2);
      passed += hn::CountTrue(dr, pass);
    }
  }
  return passed;
}

#if HWY_TARGET != HWY_SCALAR
// Whether every edge value inside the triangle's bounds in `tile` is below 2^32 in magnitude (the
// float-exact triangles' are below 2^24), bounded from the first pixel's value and the spans.
HWY_INLINE bool BlockRowsExact(const TriangleSetup& t, const PixelRect& tile) {
  const int minX = std::max(t.minX, tile.minX), maxX = std::min(t.maxX, tile.maxX);
  const int minY = std::max(t.minY, tile.minY), maxY = std::min(t.maxY, tile.maxY);
  const std::int64_t half = kSubpixelOne / 2, limit = (std::int64_t(1) << 32) - kSubpixelOne;
  for (const EdgeFunction& e : t.edge) {
    if (std::abs(std::int64_t(e.a)) > (1 << 24) || std::abs(std::int64_t(e.b)) > (1 << 24)) return false;
    const std::int64_t first = e.at(std::int64_t(minX) * kSubpixelOne + half, std::int64_t(minY) * kSubpixelOne + half);
    if (std::abs(first) + (std::abs(std::int64_t(e.a)) * (maxX - minX) + std::abs(std::int64_t(e.b)) * (maxY - minY)) * kSubpixelOne > limit)
      return false;
  }
  return true;
}

// The depth pass of a triangle whose edge values fit (BlockRowsExact) two rows at a time: a
// float vector holds twice as many lanes as a double one, so each vector is a block of two rows
// of Lanes(DR) pixels, tested and depth-compared whole, then handed to `write` one row at a time.
// Same values as DepthPass.
//
// With `wide`, wide(at0, at1, pass0, pass1, l0, l1, l2) is handed the whole block instead: its
// lower half is the row at tile index at0, its upper half the row at at1, pass0 and pass1 the
// halves' masks (the work per pixel then runs on twice the lanes).
template <class Write, class Wide = std::nullptr_t>
HWY_INLINE std::size_t DepthPassTwoRows(const TriangleSetup& t, const PixelRect& tile, Real* depth,
                                        const Write& write, const Wide& wide = nullptr) {
  const int minX = std::max(t.minX, tile.minX), maxX = std::min(t.maxX, tile.maxX);
  const int minY = std::max(t.minY, tile.minY), maxY = std::min(t.maxY, tile.maxY);
  if (minX > maxX || minY > maxY) return 0;
  const hn::ScalableTag<float> df;
  const DR dh;  // one row: half of df
  using VF = hn::VFromD<decltype(df)>;
  const int columns = int(hn::Lanes(dh));
  // An edge value E is kept as S + lo: lo = E mod 256 at the bounds' first pixel, and S, a whole
  // multiple of 256 of at most 2^32 inside the bounds (BlockRowsExact), exact in float. Lane k is
  // the pixel (k mod columns, k / columns) of the block; its S differs from the block's first
  // pixel's by c·A + r·B (A = 256a, B = 256b: |a|, |b| ≤ 2^24 here, exact in float), also such a
  // multiple inside the bounds: exact however the multiply-add rounds; lanes outside the bounds
  // are masked. S + lo rounds once, as converting E to float does, and S + (lo + bias) keeps the
  // sign of E + bias, so the test and the barycentrics are the scalar path's.
  const VF iota = hn::Iota(df, 0.0f);
  const VF rowOf = hn::IfThenElseZero(iota >= hn::Set(df, float(columns)), hn::Set(df, 1.0f));
  const VF columnOf = hn::NegMulAdd(rowOf, hn::Set(df, float(columns)), iota);
  VF off[3];
  for (int i = 0; i < 3; ++i) {
    const VF A = hn::Set(df, float(t.edge[i].a) * float(kSubpixelOne));
    const VF B = hn::Set(df, float(t.edge[i].b) * float(kSubpixelOne));
    off[i] = hn::MulAdd(columnOf, A, rowOf * B);
  }
  const VF hi = hn::Set(df, float(maxX - tile.minX));
  const VF invArea = hn::Set(df, t.invArea);
  const VF z0 = hn::Set(df, t.z[0]), z1 = hn::Set(df, t.z[1]), z2 = hn::Set(df, t.z[2]);
  const VF zero = hn::Zero(df);
  // The block moves by `columns` pixels along a row and by two rows: its lanes inside the bounds
  // come from lanes inside the bounds of the block before, so adding the (exact) steps keeps them
  // exact.
  VF stepX[3], stepY[3], rowStart[3], lo[3], loBias[3];
  const std::int64_t half = kSubpixelOne / 2;
  for (int i = 0; i < 3; ++i) {
    stepX[i] = hn::Set(df, float(columns) * float(t.edge[i].a) * float(kSubpixelOne));
    stepY[i] = hn::Set(df, 2.0f * float(t.edge[i].b) * float(kSubpixelOne));
    const std::int64_t first = t.edge[i].at(std::int64_t(minX) * kSubpixelOne + half, std::int64_t(minY) * kSubpixelOne + half);
    const std::int64_t low = first & (kSubpixelOne - 1);  // E mod 256, in [0, 256)
    rowStart[i] = hn::Set(df, float(first - low)) + off[i];
    lo[i] = hn::Set(df, float(low));
    loBias[i] = hn::Set(df, float(low + t.edge[i].bias));
  }
  const auto halves = [&](auto mask, auto& lower, auto& higher) {
    const VF v = hn::VecFromMask(df, mask);
    lower = hn::MaskFromVec(hn::LowerHalf(dh, v));
    higher = hn::MaskFromVec(hn::UpperHalf(dh, v));
  };
  std::size_t passed = 0;
  for (int y = minY; y <= maxY; y += 2) {
    VF S0 = rowStart[0], S1 = rowStart[1], S2 = rowStart[2];
    for (int i = 0; i < 3; ++i) rowStart[i] = rowStart[i] + stepY[i];
    const int row0 = (y - tile.minY) * kTileSize - tile.minX;
    const bool two = y + 1 <= maxY;
    const int row1 = two ? row0 + kTileSize : row0;  // never past the tile: the lanes are masked
    const auto rows = rowOf < hn::Set(df, two ? 2.0f : 1.0f);
    for (int x = minX; x <= maxX; x += columns, S0 = S0 + stepX[0], S1 = S1 + stepX[1], S2 = S2 + stepX[2]) {
      const VF xs = hn::Set(df, float(x - tile.minX)) + columnOf;
      const auto inside =
          hn::And(hn::And(hn::And(S0 + loBias[0] >= zero, S1 + loBias[1] >= zero), S2 + loBias[2] >= zero),
                  hn::And(xs <= hi, rows));
      const VF E0 = S0 + lo[0], E1 = S1 + lo[1], E2 = S2 + lo[2];
      // An empty block is cheaper to test through than to branch around (which mispredicts).
      const VF l0 = E0 * invArea, l1 = E1 * invArea, l2 = E2 * invArea;
      const VF z = l0 * z0 + l1 * z1 + l2 * z2;
      const VF stored = hn::Combine(df, hn::LoadU(dh, depth + row1 + x), hn::LoadU(dh, depth + row0 + x));
      const auto pass = hn::And(inside, z < stored);
      if (hn::AllFalse(df, pass)) continue;
      MR pass0, pass1;
      halves(pass, pass0, pass1);
      if constexpr (!std::is_same_v<Wide, std::nullptr_t>) {
        hn::BlendedStore(hn::LowerHalf(dh, z), pass0, dh, depth + row0 + x);
        hn::BlendedStore(hn::UpperHalf(dh, z), pass1, dh, depth + row1 + x);
        wide(row0 + x, row1 + x, pass0, pass1, l0, l1, l2);
        passed += hn::CountTrue(df, pass);
        continue;
      }
      const int rowOfHalf[2] = {row0, row1};
      const MR passOfHalf[2] = {pass0, pass1};
      for (int h = 0; h < 2; ++h) {
        if (hn::AllFalse(dh, passOfHalf[h])) continue;
        const auto pick = [&](VF v) { return h == 0 ? hn::LowerHalf(dh, v) : hn::UpperHalf(dh, v); };
        hn::BlendedStore(pick(z), passOfHalf[h], dh, depth + rowOfHalf[h] + x);
        write(rowOfHalf[h] + x, passOfHalf[h], pick(l0), pick(l1), pick(l2));
        passed += hn::CountTrue(dh, passOfHalf[h]);
      }
    }
  }
  return passed;
}
#endif

// The covered pixels of a triangle of a few pixels (most of a dense mesh's), each alone, in
// one-lane vectors, which costs far less than setting full vectors up for it: visit(x, y, l0, l1,
// l2, z) in rows from the bottom. The same values as DepthPass: an edge value converts to Real as
// the double lanes' demotion rounds it, and every formula is the same.
template <class Visit>
HWY_INLINE void VisitFewPixels(const TriangleSetup& t, int minX, int maxX, int minY, int maxY, const Visit& visit) {
  const std::int64_t half = kSubpixelOne / 2;
  for (int y = minY; y <= maxY; ++y) {
    const std::int64_t fy = std::int64_t(y) * kSubpixelOne + half;
    for (int x = minX; x <= maxX; ++x) {
      const std::int64_t fx = std::int64_t(x) * kSubpixelOne + half;
      const std::int64_t e0 = t.edge[0].at(fx, fy), e1 = t.edge[1].at(fx, fy), e2 = t.edge[2].at(fx, fy);
      if (e0 + t.edge[0].bias < 0 || e1 + t.edge[1].bias < 0 || e2 + t.edge[2].bias < 0) continue;
      const Real l0 = Real(e0) * t.invArea, l1 = Real(e1) * t.invArea, l2 = Real(e2) * t.invArea;
      visit(x, y, l0, l1, l2, l0 * t.z[0] + l1 * t.z[1] + l2 * t.z[2]);
    }
  }
}

template <class Write>
HWY_INLINE std::size_t DepthPassFewPixels(const TriangleSetup& t, int minX, int maxX, int minY, int maxY,
                                          const PixelRect& tile, Real* depth, const Write& write) {
  const hn::CappedTag<Real, 1> d1;
  std::size_t passed = 0;
  VisitFewPixels(t, minX, maxX, minY, maxY, [&](int x, int y, Real l0, Real l1, Real l2, Real z) {
    const int at = (y - tile.minY) * kTileSize + (x - tile.minX);
    Real& stored = depth[at];
    if (!(z < stored)) return;
    stored = z;
    write(at, hn::FirstN(d1, 1), hn::Set(d1, l0), hn::Set(d1, l1), hn::Set(d1, l2));
    ++passed;
  });
  return passed;
}

// Triangles whose pixels in the tile are at most this many go one pixel at a time.
constexpr int kFewPixels = 4;

template <class Write, class Wide = std::nullptr_t>
HWY_INLINE std::size_t DepthPass(const TriangleSetup& t, const PixelRect& tile, Real* depth, const Write& write,
                                 const Wide& wide = nullptr) {
  {
    const int minX = std::max(t.minX, tile.minX), maxX = std::min(t.maxX, tile.maxX);
    const int minY = std::max(t.minY, tile.minY), maxY = std::min(t.maxY, tile.maxY);
    if (minX > maxX || minY > maxY) return 0;
    if ((maxX - minX + 1) * (maxY - minY + 1) <= kFewPixels)
      return DepthPassFewPixels(t, minX, maxX, minY, maxY, tile, depth, write);
  }
#if HWY_TARGET != HWY_SCALAR
  if (sizeof(Real) == 4 && BlockRowsExact(t, tile)) return DepthPassTwoRows(t, tile, depth, write, wide);
#else
  (void)wide;
#endif
  if (sizeof(Real) == 4 && t.floatExact) return DepthPass<true>(t, tile, depth, write);
  return DepthPass<false>(t, tile, depth, write);
}

// A pixel drawn here shows nothing another route kept there (a record, an owner) any more.
template <class DU, class M>
HWY_INLINE void ClearWinners(DU du, std::uint32_t* winners, int at, M pass) {
  if (winners) hn::BlendedStore(hn::Set(du, kNoWinner), hn::RebindMask(du, pass), du, winners + at);
}

std::size_t RasterizeDepth(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t slot,
                           std::uint32_t* winners, std::uint32_t* owner) {
  return DepthPass(t, tile, depth, [&](int at, auto pass, auto l0, auto, auto) {
    const hn::Rebind<std::uint32_t, hn::DFromV<decltype(l0)>> du;
    hn::BlendedStore(hn::Set(du, slot), hn::RebindMask(du, pass), du, winners + at);
    ClearWinners(du, owner, at, pass);
  });
}

std::size_t RasterizeFlat(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t* color,
                          std::uint32_t* winners, std::uint32_t packed) {
  return DepthPass(t, tile, depth, [&](int at, auto pass, auto l0, auto, auto) {
    const hn::Rebind<std::uint32_t, hn::DFromV<decltype(l0)>> du;
    hn::BlendedStore(hn::Set(du, packed), hn::RebindMask(du, pass), du, color + at);
    ClearWinners(du, winners, at, pass);
  });
}

// perspectiveWeights (fragment.h), lane by lane, for one triangle.
template <class V>
HWY_INLINE void PerspectiveWeights(const TriangleSetup& t, V l0, V l1, V l2, V (&p)[3]) {
  const hn::DFromV<V> dr;
  PerspectiveWeights(l0, l1, l2, hn::Set(dr, t.invW[0]), hn::Set(dr, t.invW[1]), hn::Set(dr, t.invW[2]), p);
}

// gouraudColor, lane by lane (c[3] only unless `opaque`).
template <class V>
HWY_INLINE void GouraudColors(const TriangleSetup& t, const Color4* lit, bool opaque, V l0, V l1, V l2, V (&c)[4]) {
  const hn::DFromV<V> dr;
  V p[3];
  PerspectiveWeights(t, l0, l1, l2, p);
  for (int k = 0; k < (opaque ? 3 : 4); ++k)
    c[k] = Blend(p, hn::Set(dr, lit[0][k]), hn::Set(dr, lit[1][k]), hn::Set(dr, lit[2][k]));
}

template <class V>
HWY_INLINE auto GouraudPixels(const TriangleSetup& t, const Color4* lit, bool opaque, V l0, V l1, V l2) {
  V c[4];
  GouraudColors(t, lit, opaque, l0, l1, l2, c);
  return PackColors(hn::DFromV<V>(), opaque, c);
}

// Σ p_i · a_i of one triangle's values.
template <class V>
HWY_INLINE V Blend(const V (&p)[3], Real a0, Real a1, Real a2) {
  const hn::DFromV<V> dr;
  return Blend(p, hn::Set(dr, a0), hn::Set(dr, a1), hn::Set(dr, a2));
}

// phongSurface's position and renormalized normal (negated for a back face under two-sided
// lighting), lane by lane, from the perspective weights p.
template <class V>
struct SurfaceLanes {
  V position[3], normal[3];
};
template <class V>
HWY_INLINE SurfaceLanes<V> SurfaceAt(const SurfaceVertices& v, const V (&p)[3]) {
  const hn::DFromV<V> dr;
  SurfaceLanes<V> s;
  V n[3];
  for (int c = 0; c < 3; ++c) {
    s.position[c] = Blend(p, v.position[0][c], v.position[1][c], v.position[2][c]);
    n[c] = Blend(p, v.normal[0][c], v.normal[1][c], v.normal[2][c]);
  }
  UnitNormal(n, hn::FirstN(dr, v.negate ? hn::Lanes(dr) : 0), s.normal);
  return s;
}

HWY_INLINE bool Opaque(const Color4* lit) { return lit[0].a == 1 && lit[1].a == 1 && lit[2].a == 1; }

std::size_t RasterizeGouraud(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t* color,
                             std::uint32_t* winners, const Color4* lit) {
  const bool opaque = Opaque(lit);
  const auto narrow = [&](int at, auto pass, auto l0, auto l1, auto l2) {
    const hn::Rebind<std::uint32_t, hn::DFromV<decltype(l0)>> du;
    hn::BlendedStore(GouraudPixels(t, lit, opaque, l0, l1, l2), hn::RebindMask(du, pass), du, color + at);
    ClearWinners(du, winners, at, pass);
  };
#if HWY_TARGET == HWY_SCALAR
  return DepthPass(t, tile, depth, narrow);
#else
  // Colours on the whole block, two rows at once.
  return DepthPass(t, tile, depth, narrow, [&](int at0, int at1, MR pass0, MR pass1, auto l0, auto l1, auto l2) {
    const DU du;
    using V = decltype(l0);
    V c[4];
    GouraudColors(t, lit, opaque, l0, l1, l2, c);
    const auto packed = PackColors(hn::DFromV<V>(), opaque, c);
    hn::BlendedStore(hn::LowerHalf(du, packed), hn::RebindMask(du, pass0), du, color + at0);
    hn::BlendedStore(hn::UpperHalf(du, packed), hn::RebindMask(du, pass1), du, color + at1);
    ClearWinners(du, winners, at0, pass0);
    ClearWinners(du, winners, at1, pass1);
  });
#endif
}

// A tiny triangle's covered pixels, without a depth test: visit(d, inside, l0, l1, l2, z, offset)
// for each vector of them, `offset` holding each lane's pixel from the bounds' first pixel in the
// tile. The whole bounds are one or two vectors: lane k is the pixel (k mod w, k / w) from the
// bottom-left one, whose edge values differ from that pixel's by c·A + r·B (A = 256a, B = 256b):
// as in DepthPassTwoRows, exact in float inside the bounds of a float-exact triangle, the lanes
// past the bounds masked. Others (a long sliver whose bounds the viewport cut small) go pixel by
// pixel in one-lane vectors, to the same values.
template <class Visit>
HWY_INLINE void VisitTiny(const TriangleSetup& t, const Visit& visit) {
  if (sizeof(Real) != 4 || !t.floatExact || HWY_TARGET == HWY_SCALAR) {
    const hn::CappedTag<Real, 1> d1;
    const hn::Rebind<std::uint32_t, decltype(d1)> du1;
    VisitFewPixels(t, t.minX, t.maxX, t.minY, t.maxY, [&](int x, int y, Real l0, Real l1, Real l2, Real z) {
      visit(d1, hn::FirstN(d1, 1), hn::Set(d1, l0), hn::Set(d1, l1), hn::Set(d1, l2), hn::Set(d1, z),
            hn::Set(du1, std::uint32_t((y - t.minY) * kTileSize + (x - t.minX))));
    });
    return;
  }
#if HWY_TARGET != HWY_SCALAR
  const DR dr;
  const DU du;
  const int w = t.maxX - t.minX + 1, count = w * (t.maxY - t.minY + 1);
  const std::int64_t half = kSubpixelOne / 2;
  const std::int64_t fx = std::int64_t(t.minX) * kSubpixelOne + half, fy = std::int64_t(t.minY) * kSubpixelOne + half;
  VR base[3], A[3], B[3], bias[3];
  for (int i = 0; i < 3; ++i) {
    base[i] = hn::Set(dr, Real(t.edge[i].at(fx, fy)));
    A[i] = hn::Set(dr, Real(t.edge[i].a) * Real(kSubpixelOne));
    B[i] = hn::Set(dr, Real(t.edge[i].b) * Real(kSubpixelOne));
    bias[i] = hn::Set(dr, Real(t.edge[i].bias));
  }
  const VR invArea = hn::Set(dr, t.invArea), zero = hn::Zero(dr);
  const VR z0 = hn::Set(dr, t.z[0]), z1 = hn::Set(dr, t.z[1]), z2 = hn::Set(dr, t.z[2]);
  const int lanes = int(hn::Lanes(dr));
  for (int k0 = 0; k0 < count; k0 += lanes) {
    const VR column = hn::LoadU(dr, kTinyLanes.column[w] + k0), row = hn::LoadU(dr, kTinyLanes.row[w] + k0);
    VR E[3];
    for (int i = 0; i < 3; ++i) E[i] = base[i] + hn::MulAdd(column, A[i], row * B[i]);
    const MR inside = hn::And(hn::And(hn::FirstN(dr, std::size_t(count - k0)), E[0] + bias[0] >= zero),
                              hn::And(E[1] + bias[1] >= zero, E[2] + bias[2] >= zero));
    const VR l0 = E[0] * invArea, l1 = E[1] * invArea, l2 = E[2] * invArea;
    visit(dr, inside, l0, l1, l2, l0 * z0 + l1 * z1 + l2 * z2, hn::LoadU(du, kTinyLanes.offset[w] + k0));
  }
#endif
}

// Lanes of a tiny triangle's vectors kept in memory, so that its covered pixels can be written one
// by one: write(k) for each lane k set in `inside`.
constexpr std::size_t kTinyLanesMax = 16;
template <class D, class M, class Write>
HWY_INLINE void ForEachCovered(D d, M inside, const Write& write) {
  static_assert(hn::MaxLanes(D()) <= kTinyLanesMax);
  std::uint8_t bits[(kTinyLanesMax + 7) / 8] = {};
  hn::StoreMaskBits(d, inside, bits);
  for (unsigned m = unsigned(bits[0]) | unsigned(bits[1]) << 8; m != 0; m &= m - 1) write(__builtin_ctz(m));
}

// A tiny triangle's covered pixels as fragments coloured as RasterizeFlat (lit null) or
// RasterizeGouraud colour them.
std::size_t CoverTiny(const TriangleSetup& t, const Color4* lit, std::uint32_t packed, std::uint32_t recordsBefore,
                      TinyFragment* out) {
  const bool opaque = lit && Opaque(lit);
  const std::uint32_t first =
      TinyTag::of(recordsBefore, std::uint32_t((t.minY % kTileSize) * kTileSize + t.minX % kTileSize));
  std::size_t n = 0;
  VisitTiny(t, [&](auto d, auto inside, auto l0, auto l1, auto l2, auto z, auto offset) {
    const hn::Rebind<std::uint32_t, decltype(d)> du;
    HWY_ALIGN Real depth[kTinyLanesMax];
    HWY_ALIGN std::uint32_t color[kTinyLanesMax], pixel[kTinyLanesMax];
    hn::Store(z, d, depth);
    hn::Store(lit ? GouraudPixels(t, lit, opaque, l0, l1, l2) : hn::Set(du, packed), du, color);
    hn::Store(offset, du, pixel);
    ForEachCovered(d, inside, [&](int k) { out[n++] = {first + pixel[k], depth[k], color[k]}; });
  });
  return n;
}

// A tiny triangle's covered pixels as Phong's visible surface, as RasterizeSurface keeps it (no
// vertex colours).
std::size_t CoverTinySurface(const TriangleSetup& t, const SurfaceVertices& v, std::uint32_t recordsBefore,
                             TinySurface* out) {
  const std::uint32_t first =
      TinyTag::of(recordsBefore, std::uint32_t((t.minY % kTileSize) * kTileSize + t.minX % kTileSize));
  std::size_t n = 0;
  VisitTiny(t, [&](auto d, auto inside, auto l0, auto l1, auto l2, auto z, auto offset) {
    using V = decltype(l0);
    // Many of a dense mesh's tiny triangles cover no pixel centre of their bounds.
    if (hn::AllFalse(d, inside)) return;
    HWY_ALIGN Real depth[kTinyLanesMax], position[3][kTinyLanesMax], normal[3][kTinyLanesMax];
    HWY_ALIGN std::uint32_t pixel[kTinyLanesMax];
    V p[3];
    PerspectiveWeights(t, l0, l1, l2, p);
    const SurfaceLanes<V> s = SurfaceAt(v, p);
    hn::Store(z, d, depth);
    hn::Store(offset, hn::Rebind<std::uint32_t, decltype(d)>(), pixel);
    for (int c = 0; c < 3; ++c) hn::Store(s.position[c], d, position[c]), hn::Store(s.normal[c], d, normal[c]);
    ForEachCovered(d, inside, [&](int k) {
      out[n++] = {first + pixel[k], depth[k], v.owner, {position[0][k], position[1][k], position[2][k]},
                  {normal[0][k], normal[1][k], normal[2][k]}};
    });
  });
  return n;
}

std::size_t RasterizeSurface(const TriangleSetup& t, const PixelRect& tile, Real* depth, const SurfaceVertices& v,
                             const SurfaceTile& out, std::uint32_t* winners) {
  // The planes of the pixels where `pass` (per half: StoreRows) holds.
  const auto keep = [&](const auto& store, auto l0, auto l1, auto l2) {
    using V = decltype(l0);
    V p[3];
    PerspectiveWeights(t, l0, l1, l2, p);
    const SurfaceLanes<V> s = SurfaceAt(v, p);
    for (int c = 0; c < 3; ++c) store(s.position[c], out.position[c]), store(s.normal[c], out.normal[c]);
    if (v.colors)
      for (int c = 0; c < 4; ++c) store(Blend(p, v.color[0][c], v.color[1][c], v.color[2][c]), out.color[c]);
  };
  const auto owner = [&](auto dr, int at, auto pass) {
    const hn::Rebind<std::uint32_t, decltype(dr)> du;
    hn::BlendedStore(hn::Set(du, v.owner), hn::RebindMask(du, pass), du, out.owner + at);
    ClearWinners(du, winners, at, pass);
  };
  const auto narrow = [&](int at, auto pass, auto l0, auto l1, auto l2) {
    const hn::DFromV<decltype(l0)> dr;
    keep([&](auto value, Real* plane) { hn::BlendedStore(value, pass, dr, plane + at); }, l0, l1, l2);
    owner(dr, at, pass);
  };
#if HWY_TARGET == HWY_SCALAR
  return DepthPass(t, tile, depth, narrow);
#else
  return DepthPass(t, tile, depth, narrow, [&](int at0, int at1, MR pass0, MR pass1, auto l0, auto l1, auto l2) {
    const DR dh;
    keep(
        [&](auto value, Real* plane) {
          hn::BlendedStore(hn::LowerHalf(dh, value), pass0, dh, plane + at0);
          hn::BlendedStore(hn::UpperHalf(dh, value), pass1, dh, plane + at1);
        },
        l0, l1, l2);
    owner(dh, at0, pass0);
    owner(dh, at1, pass1);
  });
#endif
}

// ---- Multisampling in one pass ----

// narrowRows (row_span.h), a vector of rows at a time in double lanes. Each edge's bound is the
// quotient clamped to ±kFar pixels (beyond any tile), so that a row the edge leaves whole or empty
// takes a bound that keeps all of it or none, as the quotient's own side of the row does.
HWY_INLINE void NarrowRows(const RowSpans& s, const TriangleSetup& t, int count, int maxX, std::int32_t* first,
                           std::int32_t* last) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<std::int32_t, decltype(dd)> di;
  constexpr double kSlack = 1e-3, kFar = 32768;  // a thousandth of a pixel
  static_assert(hn::MaxLanes(dd) <= kRowSpansRoom);
  const auto far = hn::Set(dd, kFar), near = hn::Set(dd, -kFar), slack = hn::Set(dd, kSlack);
  const auto left = hn::Set(dd, double(s.minX)), right = hn::Set(dd, double(maxX)), none = hn::Set(dd, double(maxX + 1));
  for (int r = 0; r < count; r += int(hn::Lanes(dd))) {
    const auto dy = hn::PromoteTo(dd, IotaFrom(di, r));
    auto lo = left, hi = right;
    for (int i = 0; i < 3; ++i) {
      if (t.edge[i].a == 0) {  // E is the same along the row: all of it or none
        const auto out = hn::Set(dd, double(s.need[i])) - hn::Set(dd, double(s.B[i])) * dy > hn::Zero(dd);
        lo = hn::IfThenElse(out, none, lo);  // (exact: integers below 2^53)
        continue;
      }
      const auto q = hn::Min(hn::Max(hn::MulAdd(hn::Set(dd, s.dq[i]), dy, hn::Set(dd, s.q0[i])), near), far);
      if (s.rising[i]) lo = hn::Max(lo, left + hn::Ceil(q - slack));
      else hi = hn::Min(hi, left + hn::Floor(q + slack));
    }
    hn::StoreU(hn::DemoteTo(di, lo), di, first + r);
    hn::StoreU(hn::DemoteTo(di, hi), di, last + r);
  }
}


// The depth pass at every sample of the triangle's pixels in `tile`. A vector's lanes are a row's
// samples in the tile's order (SamplePlanes: pixel by pixel, each pixel's samples side by side),
// so whole vectors load and store; each row only over the pixels that may have a sample inside
// (RowSpans). For each vector with a sample passing GL_LESS, write(at, pass, l0, l1, l2): `at` the
// vector's first sample in the tile, each lane's mask and its pixel centre's barycentrics. A
// sample's edge value is its pixel centre's plus a·ox + b·oy, an integer as exact as the
// centre's, so coverage, barycentrics and depth come out as a whole pass at that sample finds them
// (DepthPass of atSample). The edge values are kept in double lanes, or in int32 lanes where every
// one of them stays below 2^31 (SamplesIntExact): the lanes' conversion to Real rounds as the
// integer's does, and the test is the integer's. kEveryVector: write is called for every vector,
// also under an empty mask, where it must change nothing (no branch on whether a sample passed).
// With `shade` (not null), write(at, pass, color) instead: color the lanes' pixels' RGBA8 words,
// shade(l0, l1, l2) of their centres' barycentrics worked out for as many pixels of a row as a
// vector has lanes at once (the first time one of them has a sample passing), not for each vector
// of samples, which holds a few pixels (or part of one) each.
template <bool kEveryVector, class D, class Write, class Shade = std::nullptr_t>
HWY_INLINE std::size_t SamplesPassIn(D d, const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                                     const Write& write, const Shade& shade = nullptr) {
  constexpr bool kShade = !std::is_same_v<Shade, std::nullptr_t>;
  const int minX = std::max(t.minX, tile.minX), maxX = std::min(t.maxX, tile.maxX);
  const int minY = std::max(t.minY, tile.minY), maxY = std::min(t.maxY, tile.maxY);
  using T = hn::TFromD<D>;  // the edge values' lanes: int32 or double
  constexpr bool kInt = std::is_integral_v<T>;
  const hn::Rebind<Real, D> dr;
  const int samples = planes.count, lanes = int(hn::Lanes(d));
  // A vector holds whole pixels (lanes ≥ samples) or a pixel spans whole vectors: the tables of
  // lane offsets cover one such group, `pixels` pixels in `vectors` vectors.
  const int group = std::max(lanes, samples), pixels = std::max(1, lanes / samples), vectors = group / lanes;
  // The tables of a group's lanes (lane k: sample k mod samples of pixel k / samples): each edge
  // value's offset from the pixel's first, k/samples·256a + a·ox + b·oy, and from the pixel's
  // centre, k/samples·256a. The samples lie on sixteenths of a pixel (ox = 16·x'), so
  // t = a·x' + b·y' is an int32 (|a|, |b| < 2^24) and a·ox + b·oy = 16t. (Int32 lanes wrap as
  // integers modulo 2^32 do: a sum or product whose value fits comes out exact, whatever its parts
  // did.)
  HWY_ALIGN T high[3][2 * kSamplesMax], centre[3][2 * kSamplesMax];
  HWY_ALIGN Real pixelOf[2 * kSamplesMax];
  HWY_ALIGN std::uint32_t pixelIndex[2 * kSamplesMax];  // pixelOf as an index
  {
    const hn::Rebind<std::int32_t, D> di;
    const int shift = __builtin_ctz(unsigned(samples));  // samples is a power of two
    const auto toT = [&](auto i) {
      if constexpr (kInt) return i;
      else return hn::PromoteTo(d, i);
    };
    const auto sixteen = hn::Set(d, T(16));
    for (int k = 0; k < group; k += lanes) {
      const auto pixel = hn::ShiftRightSame(IotaFrom(di, k), shift);
      const auto x = hn::LoadU(di, planes.laneX + k), y = hn::LoadU(di, planes.laneY + k);
      hn::Store(hn::ConvertTo(dr, pixel), dr, pixelOf + k);
      hn::Store(hn::BitCast(hn::Rebind<std::uint32_t, D>(), pixel), hn::Rebind<std::uint32_t, D>(), pixelIndex + k);
      const auto pixelT = toT(pixel);
      for (int i = 0; i < 3; ++i) {
        const auto s = x * hn::Set(di, t.edge[i].a) + y * hn::Set(di, t.edge[i].b);
        const auto along = pixelT * hn::Set(d, T(std::int64_t(t.edge[i].a) * kSubpixelOne));
        hn::Store(along, d, centre[i] + k);
        hn::Store(toT(s) * sixteen + along, d, high[i] + k);
      }
    }
  }
  using V = hn::VFromD<D>;
  // At most kSamplesMax samples a pixel: the vectors a group of pixels takes.
  constexpr int kRowVectors = std::max(1, kSamplesMax / int(hn::MaxLanes(D())));
  // E + bias ≥ 0 as E > −bias − 1 (integers, exact either way).
  V below[3];
  for (int i = 0; i < 3; ++i) below[i] = hn::Set(d, T(-std::int64_t(t.edge[i].bias) - 1));
  // Each to Real as the integer's conversion rounds (in double lanes, exact below 2^53).
  const auto toRealIn = [](auto dn, auto v) {
    if constexpr (kInt) return hn::ConvertTo(dn, v);
    else if constexpr (sizeof(T) == sizeof(Real)) return v;
    else return hn::DemoteTo(dn, v);
  };
  const auto toReal = [&](V v) { return toRealIn(dr, v); };
  const auto insideEdges = [&](const V (&E)[3]) {
    if constexpr (kInt) return hn::RebindMask(dr, hn::And(hn::And(E[0] > below[0], E[1] > below[1]), E[2] > below[2]));
    else {  // (E − below ≥ 1 where inside: positive in Real too)
      const auto zero = hn::Zero(dr);
      return hn::And(hn::And(toReal(E[0] - below[0]) > zero, toReal(E[1] - below[1]) > zero),
                     toReal(E[2] - below[2]) > zero);
    }
  };
  const auto invArea = hn::Set(dr, t.invArea);
  const auto z0 = hn::Set(dr, t.z[0]), z1 = hn::Set(dr, t.z[1]), z2 = hn::Set(dr, t.z[2]);
  const std::int64_t half = kSubpixelOne / 2;
  // A row of at most two vectors is tested whole (the tests are exact either way; narrowing only
  // skips vectors). Measured: spheres_1m_8lights_phong at 4 samples −15 % CPU time,
  // 2CylinderEngine −5 to −8 % (then narrowing stepped rather than solved per row:
  // 2CylinderEngine −3 %). The spans are worked out only for such wide bounds, all rows at once
  // (testing rows of three vectors whole as well: spheres_48k_8lights_gouraud at 4 samples +6 %).
  const bool narrowed = maxX - minX + 1 > 2 * pixels;
  std::int32_t rowFirst[kTileSize + kRowSpansRoom], rowLast[kTileSize + kRowSpansRoom];
  if (narrowed)
    NarrowRows(RowSpans(t, std::span(planes.offsets, std::size_t(samples)), minX, minY), t, maxY - minY + 1, maxX,
               rowFirst, rowLast);
  // A row's first edge value is the last row's plus b·256, a pixel's the row's plus a·256·dx: in
  // general registers, each row's broadcast once (T of an int64: modulo 2^32 in int32 lanes, as
  // the sums it joins are taken).
  std::int64_t rowValue[3], stepX[3];
  V step[3], laneStep[3];  // laneStep: lane k's k·a·256 (kShade's vectors of a row's pixels)
  for (int i = 0; i < 3; ++i) {
    rowValue[i] = t.edge[i].at(std::int64_t(minX) * kSubpixelOne + half, std::int64_t(minY) * kSubpixelOne + half) -
                  std::int64_t(t.edge[i].b) * kSubpixelOne;  // (the row before the first)
    stepX[i] = std::int64_t(t.edge[i].a) * kSubpixelOne;
    step[i] = hn::Set(d, T(stepX[i] * pixels));
    if constexpr (kShade) laneStep[i] = hn::Iota(d, 0) * hn::Set(d, T(stepX[i]));
  }
  std::size_t passed = 0;
  for (int y = minY; y <= maxY; ++y) {
    for (int i = 0; i < 3; ++i) rowValue[i] += std::int64_t(t.edge[i].b) * kSubpixelOne;
    int first = minX, last = maxX;
    if (narrowed) {
      first = rowFirst[y - minY], last = rowLast[y - minY];
      if (first > last) continue;
    }
    const int row = (y - tile.minY) * kTileSize - tile.minX;  // tile-local index of (0, y)
    // The edge values at the row's first pixel (each group of pixels on adds a·256·pixels), and
    // each vector's.
    V Ehigh[3], h[3][kRowVectors];
    for (int i = 0; i < 3; ++i) {
      Ehigh[i] = hn::Set(d, T(rowValue[i] + (first - minX) * stepX[i]));
      for (int v = 0; v < vectors; ++v) h[i][v] = Ehigh[i] + hn::Load(d, high[i] + v * lanes);
    }
    // kShade: the colours of the row's pixels [shadedFrom, shadedFrom + lanes), once asked for.
    [[maybe_unused]] int shadedFrom = -1;
    [[maybe_unused]] hn::VFromD<hn::Rebind<std::uint32_t, D>> shaded = hn::Zero(hn::Rebind<std::uint32_t, D>());
    for (int x = first; x <= last; x += pixels) {
      if (x != first)
        for (int i = 0; i < 3; ++i) {
          Ehigh[i] = Ehigh[i] + step[i];
          for (int v = 0; v < vectors; ++v) h[i][v] = h[i][v] + step[i];
        }
      const auto inRow = hn::Set(dr, Real(last - x));
      for (int v = 0; v < vectors; ++v) {
        const int k = v * lanes;
        const V E[3] = {h[0][v], h[1][v], h[2][v]};
        const auto inside = hn::And(insideEdges(E), hn::LoadU(dr, pixelOf + k) <= inRow);
        // (A vector with no sample inside, about a quarter of a small triangle's at 4 samples, skips
        // its depths: spheres_48k_8lights_gouraud at 4 samples −3 %, 8 samples unchanged. Where
        // write is called for every vector, the branch cost more than it saved: 2CylinderEngine +5 %.)
        if (!kEveryVector && hn::AllFalse(dr, inside)) continue;
        const auto z = (toReal(E[0]) * invArea) * z0 + (toReal(E[1]) * invArea) * z1 + (toReal(E[2]) * invArea) * z2;
        const std::size_t at = std::size_t(row + x) * std::size_t(samples) + std::size_t(k);
        Real* depth = planes.depth + at;
        const auto pass = hn::And(inside, z < hn::LoadU(dr, depth));
        if (!kEveryVector && hn::AllFalse(dr, pass)) continue;
        hn::BlendedStore(z, pass, dr, depth);
        passed += hn::CountTrue(dr, pass);
        const auto centreAt = [&](int i) { return toReal(Ehigh[i] + hn::Load(d, centre[i] + k)) * invArea; };
        if constexpr (kShade) {
          const hn::Rebind<std::uint32_t, D> du;
          const int from = first + (x - first) / lanes * lanes;  // (x − first is a multiple of pixels)
          if (from != shadedFrom) {
            // Each pixel's exact edge values (the same integers centreAt sums, so the same bits),
            // in half the lanes where the row's pixels from `from` on fit them (a small
            // triangle's rows: half the work, each lane's colour the same bits).
            shadedFrom = from;
            const auto shadeIn = [&](auto dn) {
              const hn::Rebind<Real, decltype(dn)> drn;
              const auto invAreaN = hn::Set(drn, t.invArea);
              const auto at = [&](int i) {
                const auto atFrom = hn::Set(dn, T(rowValue[i] + (from - minX) * stepX[i]));
                if constexpr (std::is_same_v<decltype(dn), D>) return toRealIn(drn, atFrom + laneStep[i]) * invAreaN;
                else return toRealIn(drn, atFrom + hn::LowerHalf(dn, laneStep[i])) * invAreaN;
              };
              return shade(at(0), at(1), at(2));
            };
#if HWY_TARGET != HWY_SCALAR
            if constexpr (hn::MaxLanes(D()) >= 8) {
              if (last - from < lanes / 2) shaded = hn::ZeroExtendVector(du, shadeIn(hn::Half<D>()));
              else shaded = shadeIn(d);
            } else
#endif
            {
              shaded = shadeIn(d);
            }
          }
          const auto lanesPixel = hn::Add(hn::Set(du, std::uint32_t(x - from)), hn::Load(du, pixelIndex + k));
          write(at, pass, hn::TableLookupLanes(shaded, hn::IndicesFromVec(du, lanesPixel)));
        } else {
          write(at, pass, centreAt(0), centreAt(1), centreAt(2));
        }
      }
    }
  }
  return passed;
}

// Whether the triangle's edge values at every sample of its pixels in `tile` stay below 2^31 in
// magnitude, with room for the bias, for SamplesPassIn's int32 lanes: the value at the bounds'
// first pixel plus the steps across them and the samples' offsets.
HWY_INLINE bool SamplesIntExact(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes) {
  const int minX = std::max(t.minX, tile.minX), maxX = std::min(t.maxX, tile.maxX);
  const int minY = std::max(t.minY, tile.minY), maxY = std::min(t.maxY, tile.maxY);
  std::int64_t reach = 0;
  for (int s = 0; s < planes.count; ++s)
    reach = std::max({reach, std::abs(planes.offsets[s].x), std::abs(planes.offsets[s].y)});
  const std::int64_t half = kSubpixelOne / 2, limit = (std::int64_t(1) << 31) - 4 * kSubpixelOne;
  for (const EdgeFunction& e : t.edge) {
    const std::int64_t a = std::abs(std::int64_t(e.a)), b = std::abs(std::int64_t(e.b));
    if (a > (1 << 24) || b > (1 << 24)) return false;
    const std::int64_t first = e.at(std::int64_t(minX) * kSubpixelOne + half, std::int64_t(minY) * kSubpixelOne + half);
    if (std::abs(first) + (a * (maxX - minX) + b * (maxY - minY)) * kSubpixelOne + (a + b) * reach > limit) return false;
  }
  return true;
}

template <bool kEveryVector, class Write, class Shade = std::nullptr_t>
HWY_INLINE std::size_t SamplesPass(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                                   const Write& write, const Shade& shade = nullptr) {
  if (std::max(t.minX, tile.minX) > std::min(t.maxX, tile.maxX) || std::max(t.minY, tile.minY) > std::min(t.maxY, tile.maxY))
    return 0;
#if HWY_TARGET != HWY_SCALAR
  if constexpr (sizeof(Real) == 4)
    if (SamplesIntExact(t, tile, planes))
      return SamplesPassIn<kEveryVector>(hn::ScalableTag<std::int32_t>(), t, tile, planes, write, shade);
#endif
  return SamplesPassIn<kEveryVector>(DD(), t, tile, planes, write, shade);
}

std::size_t RasterizeSamples(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                             std::uint32_t slot) {
  // A masked store of the slot: under an empty mask cheaper than the branch around it, which a
  // thin triangle's vectors (about a quarter of them with a sample passing) mispredict often.
  // Measured: 2CylinderEngine at 1280×720, 4 samples, −2 % CPU time.
  return SamplesPass<true>(t, tile, planes, [&](std::size_t at, auto pass, auto l0, auto, auto) {
    const hn::Rebind<std::uint32_t, hn::DFromV<decltype(l0)>> du;
    hn::BlendedStore(hn::Set(du, slot), hn::RebindMask(du, pass), du, planes.winners + at);
  });
}

// The places of the set bits of each 4-bit mask, in order (the rest 0).
struct SetBitPlaces {
  alignas(16) std::uint32_t of[16][4];
};
constexpr SetBitPlaces makeSetBitPlaces() {
  SetBitPlaces p{};
  for (unsigned m = 0; m < 16; ++m)
    for (unsigned k = 0, n = 0; k < 4; ++k)
      if (m >> k & 1) p.of[m][n++] = k;
  return p;
}
alignas(16) inline constexpr SetBitPlaces kSetBitPlaces = makeSetBitPlaces();

// Bit k of the result: bit k·samples of `bits` (a pixel's first sample), for the `pixels` pixels;
// `firsts` has those bits set (FirstSamples).
HWY_INLINE std::uint64_t FirstSamples(int samples) {
  std::uint64_t firsts = 0;
  for (int k = 0; k < 64; k += samples) firsts |= std::uint64_t(1) << k;
  return firsts;
}
HWY_INLINE std::uint32_t FirstSampleBits(std::uint64_t bits, [[maybe_unused]] std::uint64_t firsts, int samples,
                                         int pixels) {
#if HWY_TARGET == HWY_AVX2 || HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
  (void)samples, (void)pixels;
  return std::uint32_t(_pext_u64(bits, firsts));  // (BMI2, part of these targets: one instruction)
#else
  std::uint32_t out = 0;
  for (int k = 0; k < pixels; ++k) out |= std::uint32_t(bits >> (k * samples) & 1) << k;
  return out;
#endif
}

std::size_t RasterizeSamplesListed(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                                   std::uint32_t slot, std::uint32_t* listed, std::size_t& listedCount) {
  // Each vector's pixels where a sample passed: a vector holds `lanes / samples` whole pixels, whose
  // samples' pass bits are folded onto the pixel's first, in a general register (a chain of vector
  // shuffles and a compress was a fifth of this pass), and those pixels listed four at a time from
  // a table of the places of a 4-bit mask's set bits; or a pixel spans whole vectors, listed at the
  // first of them that has a sample passing.
  const int samples = planes.count, shift = __builtin_ctz(unsigned(samples));  // (a power of two)
  std::uint32_t* const begin = listed;
  std::uint32_t* end = listed;
  // (Every 64 bits' pixel firsts: a vector's mask has no bits past its lanes.)
  [[maybe_unused]] const std::uint64_t firsts = FirstSamples(samples);
  const std::size_t passed = SamplesPass<true>(t, tile, planes, [&](std::size_t at, auto pass, auto l0, auto, auto) {
    const hn::DFromV<decltype(l0)> dr;
    const hn::Rebind<std::uint32_t, decltype(dr)> du;
    const auto mask = hn::RebindMask(du, pass);
    hn::BlendedStore(hn::Set(du, slot), mask, du, planes.winners + at);
    const std::uint32_t pixel = std::uint32_t(at >> shift);
#if HWY_TARGET != HWY_SCALAR
    if constexpr (hn::MaxLanes(du) >= 4) {
      const int lanes = int(hn::Lanes(du));
      if (samples <= lanes && samples <= 8 && lanes <= 64) {
        std::uint8_t bytes[8] = {};
        hn::StoreMaskBits(du, mask, bytes);
        std::uint64_t bits = 0;
        std::memcpy(&bits, bytes, sizeof bits);
        bits |= bits >> 1;
        if (samples >= 4) bits |= bits >> 2;
        if (samples >= 8) bits |= bits >> 4;
        const int pixels = lanes / samples;
        const std::uint32_t any = FirstSampleBits(bits, firsts, samples, pixels);
        const hn::CappedTag<std::uint32_t, 4> d4;  // (the list has room for a vector past its end)
        for (int k = 0; k < pixels; k += 4) {
          const unsigned four = (any >> k) & 15u;
          hn::StoreU(hn::Add(hn::Load(d4, kSetBitPlaces.of[four]), hn::Set(d4, pixel + std::uint32_t(k))), d4, end);
          end += __builtin_popcount(four);
        }
        return;
      }
    }
#endif
    if (hn::AllFalse(du, mask)) return;
    HWY_ALIGN std::uint32_t lane[hn::MaxLanes(du)];
    hn::Store(hn::VecFromMask(du, mask), du, lane);
    for (int k = 0; k < int(hn::Lanes(du)); ++k) {
      const std::uint32_t p = pixel + std::uint32_t(k / samples);
      if (lane[k] && (end == begin || end[-1] != p)) *end++ = p;
    }
  });
  listedCount = std::size_t(end - begin);
  return passed;
}

std::size_t RasterizeSamplesColored(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                                    const Color4* lit, std::uint32_t packed, bool clearWinners) {
  const auto store = [&](std::size_t at, auto pass, auto color) {
    const hn::DFromV<decltype(color)> du;
    hn::BlendedStore(color, hn::RebindMask(du, pass), du, planes.color + at);
    if (clearWinners) hn::BlendedStore(hn::Set(du, kNoWinner), hn::RebindMask(du, pass), du, planes.winners + at);
  };
  if (!lit)
    return SamplesPass<false>(t, tile, planes, [&](std::size_t at, auto pass, auto l0, auto, auto) {
      store(at, pass, hn::Set(hn::Rebind<std::uint32_t, hn::DFromV<decltype(l0)>>(), packed));
    });
  // Gouraud: each pixel's colour worked out once, not once per vector of its samples.
  const bool opaque = Opaque(lit);
  return SamplesPass<false>(t, tile, planes, store,
                            [&](auto l0, auto l1, auto l2) { return GouraudPixels(t, lit, opaque, l0, l1, l2); });
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(RasterizeDepth);
HWY_EXPORT(RasterizeFlat);
HWY_EXPORT(RasterizeGouraud);
HWY_EXPORT(RasterizeSurface);
HWY_EXPORT(CoverTiny);
HWY_EXPORT(CoverTinySurface);
HWY_EXPORT(RasterizeSamples);
HWY_EXPORT(RasterizeSamplesListed);
HWY_EXPORT(RasterizeSamplesColored);
HWY_EXPORT(NarrowRows);

void narrowRows(const RowSpans& spans, const TriangleSetup& t, int count, int maxX, std::int32_t* first,
                std::int32_t* last) {
  HWY_DYNAMIC_DISPATCH(NarrowRows)(spans, t, count, maxX, first, last);
}

std::size_t rasterizeSamples(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                             std::uint32_t slot) {
  return HWY_DYNAMIC_DISPATCH(RasterizeSamples)(t, tile, planes, slot);
}

std::size_t rasterizeSamples(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                             std::uint32_t slot, std::uint32_t* listed, std::size_t& listedCount) {
  return HWY_DYNAMIC_DISPATCH(RasterizeSamplesListed)(t, tile, planes, slot, listed, listedCount);
}

std::size_t rasterizeSamplesColored(const TriangleSetup& t, const PixelRect& tile, const SamplePlanes& planes,
                                    const Color4* lit, std::uint32_t packed, bool clearWinners) {
  return HWY_DYNAMIC_DISPATCH(RasterizeSamplesColored)(t, tile, planes, lit, packed, clearWinners);
}

std::size_t rasterizeDepth(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t slot,
                           std::uint32_t* winners, std::uint32_t* owner) {
  return HWY_DYNAMIC_DISPATCH(RasterizeDepth)(t, tile, depth, slot, winners, owner);
}

std::size_t rasterizeFlat(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t* color,
                          std::uint32_t* winners, std::uint32_t packed) {
  return HWY_DYNAMIC_DISPATCH(RasterizeFlat)(t, tile, depth, color, winners, packed);
}

std::size_t rasterizeGouraud(const TriangleSetup& t, const PixelRect& tile, Real* depth, std::uint32_t* color,
                             std::uint32_t* winners, const Color4* lit) {
  return HWY_DYNAMIC_DISPATCH(RasterizeGouraud)(t, tile, depth, color, winners, lit);
}

std::size_t rasterizeSurface(const TriangleSetup& t, const PixelRect& tile, Real* depth, const SurfaceVertices& v,
                             const SurfaceTile& out, std::uint32_t* winners) {
  return HWY_DYNAMIC_DISPATCH(RasterizeSurface)(t, tile, depth, v, out, winners);
}

std::size_t coverTinyFlat(const TriangleSetup& t, std::uint32_t packed, std::uint32_t recordsBefore, TinyFragment* out) {
  return HWY_DYNAMIC_DISPATCH(CoverTiny)(t, nullptr, packed, recordsBefore, out);
}

std::size_t coverTinyGouraud(const TriangleSetup& t, const Color4* lit, std::uint32_t recordsBefore, TinyFragment* out) {
  return HWY_DYNAMIC_DISPATCH(CoverTiny)(t, lit, 0, recordsBefore, out);
}

std::size_t coverTinySurface(const TriangleSetup& t, const SurfaceVertices& v, std::uint32_t recordsBefore,
                             TinySurface* out) {
  return HWY_DYNAMIC_DISPATCH(CoverTinySurface)(t, v, recordsBefore, out);
}

}  // namespace illum
#endif  // HWY_ONCE
#endif  // ILLUM_USE_DOUBLE

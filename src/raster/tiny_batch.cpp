// coverTinyBatch, compiled once per SIMD target (Highway's foreach_target), dispatched at run time.
#include <illum/real.h>

#if !ILLUM_USE_DOUBLE
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/tiny_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/interpolate-inl.h"
#include "raster/tiny_batch.h"

#include <algorithm>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The batch in groups of as many triangles as a float vector has lanes. A group's pixels are
// laid out in slots, triangle after triangle (each its bounds' pixels, kTinyLanes' order), and
// each vector of slots looks its triangles' values up in the group's rows (TableLookupLanes): the
// edge values c·A + r·B from the first pixel's, exact in float as in VisitTiny, then barycentrics,
// depth and colour as the tile rasterizer has them. The covered slots are compressed and stored
// as fragments, so they keep the slots' order.
std::size_t CoverTinyBatch(const TinyBatchLanes& b, int size, bool flat, TinyFragment* out, std::uint8_t* covered) {
  static_assert(sizeof(TinyFragment) == 3 * sizeof(std::uint32_t));
  const hn::ScalableTag<float> df;
  const hn::RebindToUnsigned<decltype(df)> du;
  const hn::RebindToSigned<decltype(df)> di;
  using VF = hn::VFromD<decltype(df)>;
  using VU = hn::VFromD<decltype(du)>;
  constexpr int kGroupMax = std::min<int>(TinyBatchLanes::kCapacity, int(hn::MaxLanes(df)));
  static_assert(TinyBatchLanes::kCapacity % kGroupMax == 0);
  const int group = std::min<int>(kGroupMax, int(hn::Lanes(df)));
  constexpr int kSlots = kGroupMax * kTinyPixels;
  static_assert(kSlots <= 128, "a group's coverage is one 128-bit mask");
  const VF zero = hn::Zero(df);
  std::size_t n = 0;
  for (int g = 0; g < size; g += group) {
    const int members = std::min(group, size - g);
    // Slot s: triangle slotOf[s] of the group, pixel (column, row) of its bounds.
    HWY_ALIGN std::int32_t slotOf[kSlots + kGroupMax];
    HWY_ALIGN float column[kSlots + kGroupMax], row[kSlots + kGroupMax];
    HWY_ALIGN std::uint32_t offset[kSlots + kGroupMax];
    int start[kGroupMax + 1];
    int slots = 0;
    for (int j = 0; j < members; ++j) {
      const int w = b.width[g + j];
      for (int k = 0; k < kTinyPixels; ++k) {  // a whole row of the tables: no branch per pixel
        slotOf[slots + k] = j;
        column[slots + k] = kTinyLanes.column[w][k];
        row[slots + k] = kTinyLanes.row[w][k];
        offset[slots + k] = kTinyLanes.offset[w][k];
      }
      start[j] = slots;
      slots += b.count[g + j];
    }
    for (int k = slots; k < slots + group; ++k) slotOf[k] = 0, column[k] = row[k] = 0, offset[k] = 0;  // the last vector's rest
    std::uint64_t inside[kSlots / 64 + 1] = {};  // bit s % 64 of word s / 64: slot s is covered
    for (int s0 = 0; s0 < slots; s0 += group) {
      const auto lanesOf = hn::IndicesFromVec(df, hn::Load(di, slotOf + s0));
      const auto of = [&](const float* values) { return hn::TableLookupLanes(hn::LoadU(df, values + g), lanesOf); };
      const auto ofU = [&](const std::uint32_t* values) {
        return hn::TableLookupLanes(hn::LoadU(du, values + g), hn::IndicesFromVec(du, hn::Load(di, slotOf + s0)));
      };
      const VF c = hn::Load(df, column + s0), r = hn::Load(df, row + s0);
      VF E[3];
      auto covers = hn::FirstN(df, std::size_t(slots - s0));
      for (int i = 0; i < 3; ++i) {
        E[i] = of(b.edge[i]) + hn::MulAdd(c, of(b.stepX[i]), r * of(b.stepY[i]));
        covers = hn::And(covers, E[i] + of(b.bias[i]) >= zero);
      }
      const VF invArea = of(b.invArea);
      const VF l0 = E[0] * invArea, l1 = E[1] * invArea, l2 = E[2] * invArea;
      const VF z = l0 * of(b.z[0]) + l1 * of(b.z[1]) + l2 * of(b.z[2]);
      VU color;
      if (flat) {
        color = ofU(b.packed);
      } else {
        VF p[3];
        PerspectiveWeights(l0, l1, l2, of(b.invW[0]), of(b.invW[1]), of(b.invW[2]), p);
        VF channel[4];
        for (int k = 0; k < 3; ++k) channel[k] = Blend(p, of(b.lit[k][0]), of(b.lit[k][1]), of(b.lit[k][2]));
        color = hn::BitCast(du, PackColorsWide(df, true, channel));
      }
      const VU tag = hn::Add(ofU(b.firstTag), hn::Load(du, offset + s0));
      const auto keep = hn::RebindMask(du, covers);
      hn::StoreInterleaved3(hn::Compress(tag, keep), hn::Compress(hn::BitCast(du, z), keep), hn::Compress(color, keep),
                            du, reinterpret_cast<std::uint32_t*>(out + n));
      n += hn::CountTrue(df, covers);
      std::uint8_t bits[8] = {};
      hn::StoreMaskBits(df, covers, bits);
      std::uint64_t word = 0;
      for (int k = 0; k < (group + 7) / 8; ++k) word |= std::uint64_t(bits[k]) << (8 * k);
      inside[s0 / 64] |= word << (s0 % 64);  // a vector's slots never straddle two words
    }
    for (int j = 0; j < members; ++j) {
      const int word = start[j] / 64, bit = start[j] % 64;
      std::uint64_t bits = inside[word] >> bit;
      if (bit > 64 - kTinyPixels) bits |= inside[word + 1] << (64 - bit);
      covered[g + j] = std::uint8_t(__builtin_popcountll(bits & ((1u << b.count[g + j]) - 1)));
    }
  }
  return n;
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(CoverTinyBatch);

std::size_t coverTinyBatch(const TinyBatchLanes& batch, int size, bool flat, TinyFragment* out,
                           std::uint8_t* covered) {
  return HWY_DYNAMIC_DISPATCH(CoverTinyBatch)(batch, size, flat, out, covered);
}

void TinyBatch::add(const TriangleSetup& t, const Color4* lit, std::uint32_t packed, std::uint32_t recordsBefore,
                    int tile) {
  const int j = size_++;
  const std::int64_t half = kSubpixelOne / 2;
  const std::int64_t fx = std::int64_t(t.minX) * kSubpixelOne + half, fy = std::int64_t(t.minY) * kSubpixelOne + half;
  TinyBatchLanes& b = lanes_;
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
  b.firstTag[j] = TinyTag::of(recordsBefore, std::uint32_t((t.minY % kTileSize) * kTileSize + t.minX % kTileSize));
  b.width[j] = std::uint8_t(t.maxX - t.minX + 1);
  b.count[j] = std::uint8_t(b.width[j] * (t.maxY - t.minY + 1));
  tile_[j] = tile;
  if (size_ == TinyBatchLanes::kCapacity) flush();
}

void TinyBatch::flush() {
  if (size_ == 0) return;
  std::uint8_t covered[TinyBatchLanes::kCapacity];
  coverTinyBatch(lanes_, size_, flat_, out_.room(kTinyBatchRoom), covered);
  for (int j = 0; j < size_; ++j) out_.commit(covered[j], tile_[j]);
  size_ = 0;
}

}  // namespace illum
#endif  // HWY_ONCE
#endif  // !ILLUM_USE_DOUBLE

// Covering a batch of tiny triangles (tiny_batch.h) a group of them at a time, one pixel (or
// sample) of its own triangle per lane: the coverage kernels of the batches of fragments (flat,
// Gouraud, lit Phong) and of visible surface share it. Included once per target (Highway's -inl.h
// convention).

#if defined(ILLUM_RASTER_TINY_COVER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_RASTER_TINY_COVER_INL_H_
#undef ILLUM_RASTER_TINY_COVER_INL_H_
#else
#define ILLUM_RASTER_TINY_COVER_INL_H_
#endif

#include <hwy/highway.h>

#include "raster/setup/tiny_batch.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Bit j: lane j of the mask `m` (of at most 16 lanes); and back.
template <class D, class M>
HWY_INLINE std::uint32_t MaskBits(D d, M m) {
  std::uint8_t bits[8] = {};
  hn::StoreMaskBits(d, m, bits);
  return std::uint32_t(bits[0]) | std::uint32_t(bits[1]) << 8;
}
template <class D>
HWY_INLINE auto MaskFromBits(D d, std::uint32_t bits) {
  const std::uint8_t bytes[8] = {std::uint8_t(bits), std::uint8_t(bits >> 8)};
  return hn::LoadMaskBits(d, bytes);
}

// A box of pixels `w` wide as TinySampleSlot's fields: lane k at column k mod w, row k / w.
struct TinySampleRows {
  std::uint32_t offset[kTinyPixels + 1][kTinyPixels];
};
constexpr TinySampleRows makeTinySampleRows() {
  TinySampleRows rows{};
  for (int w = 1; w <= kTinyPixels; ++w)
    for (int k = 0; k < kTinyPixels; ++k)
      rows.offset[w][k] = std::uint32_t(16 * (k % w)) | std::uint32_t(16 * (k / w)) << TinySampleSlot::kRowShift;
  return rows;
}
alignas(64) inline constexpr TinySampleRows kTinySampleRows = makeTinySampleRows();

// The batch in groups of as many triangles as a float vector has lanes. A group's pixels are
// laid out in slots, triangle after triangle (each its bounds' pixels, kTinyLanes' order), and
// each vector of slots looks its triangles' values up in the group's rows (TableLookupLanes): the
// edge values c·A + r·B from the first pixel's, exact in float as in VisitTiny, then barycentrics,
// depth and the rest as the tile rasterizer has them: coverage for every slot, then, for the
// covered ones, compressed in the slots' order, emit(at, count, of, l0, l1, l2, z, tag) stores
// a vector's `count` pixels from out[at] on (or its whole vector: the last one's rest lands in the
// room past them); of(row) looks each lane's triangle's value up in a row of the batch's lanes.
// Multisampled (kSamples), a slot is one sample of a pixel (TinySampleSlot): its coverage and
// depth from the edge values at the sample, (c + x')·A + (r + y')·B with the sample's offset
// (x', y') in sixteenths — each product and sum an integer of at most 2^24 (floatExact at every
// sample of the bounds), so exact as rasterizeSamples' — and l0, l1, l2 the pixel centre's, for
// the colour. Returns how many pixels (samples) are covered.
template <bool kSamples, class Emit>
std::size_t CoverGroups(const TinyBatchLanes& b, std::uint32_t members, std::uint16_t* covered, const Emit& emit) {
  const hn::ScalableTag<float> df;
  const hn::RebindToUnsigned<decltype(df)> du;
  const hn::RebindToSigned<decltype(df)> di;
  using VF = hn::VFromD<decltype(df)>;
  using VU = hn::VFromD<decltype(du)>;
  constexpr int kGroupMax = std::min<int>(TinyBatchLanes::kCapacity, int(hn::MaxLanes(df)));
  static_assert(TinyBatchLanes::kCapacity % kGroupMax == 0);
  const int group = std::min<int>(kGroupMax, int(hn::Lanes(df)));
  constexpr int kSlots = kGroupMax * kTinyPixels * (kSamples ? kSamplesMax : 1);
  // A slot: its triangle in the group above kTriangleShift, below it the pixel's offset (row <<
  // kTileShift | column) or, multisampled, TinySampleSlot's fields.
  constexpr int kOffsetBits = kSamples ? TinySampleSlot::kBits : 12, kTileShift = 6;
  constexpr std::uint32_t kOffsetMask = (1u << kOffsetBits) - 1;
  static_assert(kTileSize == 1 << kTileShift && (kTinyPixels - 1) * (kTileSize + 1) < 1 << 12);
  const int sampleShift = __builtin_ctz(unsigned(b.samples));
  // A row of the offset table from `base` on (offsets fit below kOffsetBits): whole rows, no
  // branch per pixel, but a box is mostly a few pixels, so the rest of the row only where it has
  // more.
  constexpr int kFewSlots = 16;
  const auto writeRow = [](std::uint32_t* to, std::uint32_t base, const std::uint32_t* offsets, int count) {
    for (int k = 0; k < kFewSlots; ++k) to[k] = base + offsets[k];
    if (count > kFewSlots)
      for (int k = kFewSlots; k < kTinyPixels; ++k) to[k] = base + offsets[k];
  };
  const VF zero = hn::Zero(df);
  std::size_t n = 0;
  for (int g = 0; g < TinyBatchLanes::kCapacity; g += group) {
    const std::uint32_t inGroup = (members >> g) & ((1u << group) - 1);
    if (inGroup == 0) continue;
    // Slot s: triangle slot[s] >> kOffsetBits of the group, pixel (or sample) slot[s] & kOffsetMask
    // of its bounds.
    HWY_ALIGN std::uint32_t slot[kSlots + kGroupMax];
    int slots = 0;
    [[maybe_unused]] int slotsOf[TinyBatchLanes::kCapacity];  // multisampled: each triangle's
    for (std::uint32_t m = inGroup; m != 0; m &= m - 1) {
      const int j = __builtin_ctz(m);
      if constexpr (kSamples) {
        // Each sample's box of pixels, a whole row of the table at a time.
        const int before = slots;
        for (int s = 0; s < b.samples; ++s) {
          const std::uint32_t base = std::uint32_t(j) << kOffsetBits | b.sampleBase[s][g + j];
          const std::uint32_t* offsets = kTinySampleRows.offset[b.sampleWidth[s][g + j]];
          const int count = b.sampleCount[s][g + j];
          writeRow(slot + slots, base, offsets, count);
          slots += count;
        }
        slotsOf[j] = slots - before;
      } else {
        const std::uint32_t* offsets = kTinyLanes.offset[b.width[g + j]];
        const int count = b.count[g + j];
        writeRow(slot + slots, std::uint32_t(j) << kOffsetBits, offsets, count);
        slots += count;
      }
    }
    for (int k = slots; k < slots + group; ++k) slot[k] = 0;  // the rest
    const auto triangleOf = [&](VU v) {
      return hn::IndicesFromVec(df, hn::BitCast(di, hn::ShiftRight<kOffsetBits>(v)));
    };
    const VU offsetMask = hn::Set(du, kOffsetMask), columnMask = hn::Set(du, kTileSize - 1);
    // A slot's pixel column and row in its bounds; multisampled, also its sample's (in pixels).
    const auto toFloat = [&](VU u) { return hn::ConvertTo(df, hn::BitCast(di, u)); };
    const auto pixelOf = [&](VU v, VF& c, VF& r) {
      if constexpr (kSamples) {
        c = toFloat(hn::ShiftRight<TinySampleSlot::kSubShift>(hn::And(v, hn::Set(du, TinySampleSlot::kFieldMask))));
        r = toFloat(hn::ShiftRight<TinySampleSlot::kSubShift>(
            hn::And(hn::ShiftRight<TinySampleSlot::kRowShift>(v), hn::Set(du, TinySampleSlot::kFieldMask))));
      } else {
        const VU offset = hn::And(v, offsetMask);
        c = toFloat(hn::And(offset, columnMask));
        r = toFloat(hn::ShiftRight<kTileShift>(offset));
      }
    };
    const auto sampleOf = [&](VU v, VF& c, VF& r) {
      const VF sixteenth = hn::Set(df, 1.0f / 16);
      c = toFloat(hn::And(v, hn::Set(du, TinySampleSlot::kFieldMask))) * sixteenth -
          hn::Set(df, float(TinySampleSlot::kColumnBias) / 16);
      r = toFloat(hn::And(hn::ShiftRight<TinySampleSlot::kRowShift>(v), hn::Set(du, TinySampleSlot::kFieldMask))) *
              sixteenth -
          hn::Set(df, float(TinySampleSlot::kRowBias) / 16);
    };
    // The edge values at (c, r) of the bounds: c·A + r·B from the first pixel's.
    const auto edgeValues = [&](VF c, VF r, const auto& of, VF (&E)[3]) {
      for (int i = 0; i < 3; ++i) E[i] = of(b.edge[i]) + hn::MulAdd(c, of(b.stepX[i]), r * of(b.stepY[i]));
    };
    const auto coveredAt = [&](VU v, VF& c, VF& r) {
      if constexpr (kSamples) sampleOf(v, c, r);
      else pixelOf(v, c, r);
    };
    // First the coverage of every slot; the covered ones' slots are kept, in order, for the rest
    // (fewer than half of a dense mesh's slots are covered, and working their edge values out
    // again costs less than keeping every slot's).
    // Per vector of slots: its covered lanes and how many slots before it are covered.
    std::uint32_t coveredLanes[kSlots + 1];
    int keptBefore[kSlots + 1];
    HWY_ALIGN std::uint32_t keptSlot[kSlots + kGroupMax];
    int kept = 0;
    for (int s0 = 0; s0 < slots; s0 += group) {
      const VU v = hn::Load(du, slot + s0);
      const auto lanesOf = triangleOf(v);
      const auto of = [&](const float* values) { return hn::TableLookupLanes(hn::LoadU(df, values + g), lanesOf); };
      VF c, r, E[3];
      coveredAt(v, c, r);
      edgeValues(c, r, of, E);
      auto covers = hn::FirstN(df, std::size_t(slots - s0));
      for (int i = 0; i < 3; ++i) covers = hn::And(covers, E[i] + of(b.bias[i]) >= zero);
      hn::StoreU(hn::Compress(v, hn::RebindMask(du, covers)), du, keptSlot + kept);
      coveredLanes[s0 / group] = MaskBits(df, covers);
      keptBefore[s0 / group] = kept;
      kept += int(hn::CountTrue(df, covers));
    }
    coveredLanes[(slots + group - 1) / group] = 0;  // the slots' end
    keptBefore[(slots + group - 1) / group] = kept;
    for (int k = kept; k < kept + group; ++k) keptSlot[k] = 0;  // the last vector's rest
    // Then depth and the rest of the covered pixels.
    for (int k0 = 0; k0 < kept; k0 += group) {
      const VU v = hn::Load(du, keptSlot + k0);
      const auto lanesOf = triangleOf(v);
      const auto of = [&](const auto* values) {
        const VF value = hn::TableLookupLanes(hn::LoadU(df, reinterpret_cast<const float*>(values) + g), lanesOf);
        if constexpr (std::is_same_v<std::remove_cv_t<std::remove_pointer_t<decltype(values)>>, float>) return value;
        else return hn::BitCast(du, value);  // the same lanes, as bits
      };
      VF c, r, E[3];
      coveredAt(v, c, r);
      edgeValues(c, r, of, E);
      const VF invArea = of(b.invArea);
      VF l0 = E[0] * invArea, l1 = E[1] * invArea, l2 = E[2] * invArea;
      const VF z = l0 * of(b.z[0]) + l1 * of(b.z[1]) + l2 * of(b.z[2]);
      VU tag;
      if constexpr (kSamples) {
        // The pixel centre's weights, and the sample's place in the tile's sample planes.
        pixelOf(v, c, r);
        edgeValues(c, r, of, E);
        l0 = E[0] * invArea, l1 = E[1] * invArea, l2 = E[2] * invArea;
        const VU pixel = hn::Add(hn::ShiftLeft<kTileShift>(hn::BitCast(du, hn::ConvertTo(di, r))),
                                 hn::BitCast(du, hn::ConvertTo(di, c)));
        const VU sample = hn::And(hn::ShiftRight<TinySampleSlot::kSampleShift>(v), hn::Set(du, kSamplesMax - 1));
        tag = hn::Add(of(b.firstTag), hn::Add(hn::ShiftLeftSame(pixel, sampleShift), sample));
      } else {
        tag = hn::Add(of(b.firstTag), hn::And(v, offsetMask));
      }
      emit(n + std::size_t(k0), std::min(group, kept - k0), of, l0, l1, l2, z, tag);
    }
    n += std::size_t(kept);
    // How many of the slots before slot s are covered.
    const auto keptAt = [&](int s) {
      return keptBefore[s / group] + __builtin_popcount(coveredLanes[s / group] & ((1u << (s % group)) - 1));
    };
    int end = 0, before = 0;  // the members' slots, one after another from slot 0
    for (std::uint32_t m = inGroup; m != 0; m &= m - 1) {
      const int j = __builtin_ctz(m);
      if constexpr (kSamples) end += slotsOf[j];
      else end += b.count[g + j];
      const int after = keptAt(end);
      covered[g + j] = std::uint16_t(after - before);
      before = after;
    }
  }
  return n;
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_RASTER_TINY_COVER_INL_H_

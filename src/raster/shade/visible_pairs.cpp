// shade_visible.h's (pixel, record) pairs of a multisampled tile: found in its winners, grouped by
// record, kept where a listed pixel still shows its record, and each pair's colour written to the
// samples that show it. Compiled once per SIMD target (Highway's foreach_target), dispatched at
// run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/shade/visible_pairs.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "math/iota-inl.h"
#include "raster/shade/shade_visible.h"

#include <cstddef>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
      hn::StoreU(hn::Compress(IotaFrom(du, std::uint32_t(i)), some), du, pixel + n);
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
      hn::StoreU(hn::Compress(lanePixel + hn::Set(du, std::uint32_t(i >> shift)), some), du, pixel + n);
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
    hn::StoreU(hn::Compress(lanePixel + hn::Set(du, std::uint32_t(i >> shift)), fresh), du, pixel + n);
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

// f(d), d the tag of a vector of exactly one pixel's samples (2, 4, 8 or 16, as far as the
// target's vectors hold them: a 128-bit compare for 4 samples, not a masked 512-bit one): true;
// false (f not called) where there is no such tag.
template <class F>
HWY_INLINE bool WithPixelSamples(int samples, const F& f) {
  const auto exactly = [&](auto d) {
    if (int(hn::Lanes(d)) != samples) return false;
    f(d);
    return true;
  };
  switch (samples) {
    case 2: return exactly(hn::CappedTag<std::uint32_t, 2>());
    case 4: return exactly(hn::CappedTag<std::uint32_t, 4>());
    case 8: return exactly(hn::CappedTag<std::uint32_t, 8>());
    case 16: return exactly(hn::CappedTag<std::uint32_t, 16>());
    default: return false;
  }
}

void KeepShown(const std::uint32_t* winners, int samples, const std::uint32_t* start, std::size_t records,
               std::uint32_t* pixels, std::uint32_t* kept) {
  // A pixel's samples compared as one vector (the tile has room for a vector past its last).
  if (WithPixelSamples(samples, [&](auto du) {
        for (std::size_t r = 0; r < records; ++r) {
          const auto wanted = hn::Set(du, std::uint32_t(r));
          std::uint32_t* list = pixels + start[r];
          std::uint32_t n = 0;
          for (std::uint32_t k = 0, count = start[r + 1] - start[r]; k < count; ++k) {
            const std::uint32_t p = list[k];
            list[n] = p;
            n += !hn::AllFalse(du, hn::Eq(hn::LoadU(du, winners + std::size_t(p) * std::size_t(samples)), wanted));
          }
          kept[r] = n;
        }
      }))
    return;
  const VisibleSamples shown{samples, nullptr, const_cast<std::uint32_t*>(winners)};
  for (std::size_t r = 0; r < records; ++r) {
    std::uint32_t* list = pixels + start[r];
    std::uint32_t n = 0;
    for (std::uint32_t k = 0, count = start[r + 1] - start[r]; k < count; ++k) {
      list[n] = list[k];
      n += shown.shows(int(list[k]), std::uint32_t(r));
    }
    kept[r] = n;
  }
}

// Each pair's RGBA8 word to the samples of its pixel that show its record (VisibleSamples::write),
// a pixel's samples compared and stored as one vector.
void WriteShown(const VisibleBatch& b, std::uint32_t* color, const std::uint32_t* winners, int samples) {
  if (samples == 1) {
    for (std::size_t k = 0; k < b.count; ++k) color[b.pixel[k]] = b.rgba[k];
    return;
  }
  if (WithPixelSamples(samples, [&](auto du) {
        for (std::size_t k = 0; k < b.count; ++k) {
          const std::size_t at = std::size_t(b.pixel[k]) * std::size_t(samples);
          const auto shows = hn::Eq(hn::LoadU(du, winners + at), hn::Set(du, b.slot[k]));
          hn::BlendedStore(hn::Set(du, b.rgba[k]), shows, du, color + at);
        }
      }))
    return;
  const VisibleSamples out{samples, color, const_cast<std::uint32_t*>(winners)};
  for (std::size_t k = 0; k < b.count; ++k) out.write(int(b.pixel[k]), b.slot[k], b.rgba[k]);
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace illum {

HWY_EXPORT(ShownPairs);
HWY_EXPORT(WriteShown);
HWY_EXPORT(GroupByRecord);
HWY_EXPORT(KeepShown);

std::size_t shownPairs(const std::uint32_t* winners, int samples, std::uint32_t* pixel, std::uint32_t* slot) {
  return HWY_DYNAMIC_DISPATCH(ShownPairs)(winners, samples, pixel, slot);
}

void keepShown(const std::uint32_t* winners, int samples, const std::uint32_t* start, std::size_t records,
               std::uint32_t* pixels, std::uint32_t* kept) {
  HWY_DYNAMIC_DISPATCH(KeepShown)(winners, samples, start, records, pixels, kept);
}

void groupByRecord(const std::uint32_t* pixel, const std::uint32_t* slot, std::size_t pairs, std::size_t records,
                   std::uint32_t* start, std::uint32_t* out) {
  HWY_DYNAMIC_DISPATCH(GroupByRecord)(pixel, slot, pairs, records, start, out);
}

void writeShown(const VisibleBatch& batch, std::uint32_t* color, const std::uint32_t* winners, int samples) {
  HWY_DYNAMIC_DISPATCH(WriteShown)(batch, color, winners, samples);
}

}  // namespace illum
#endif  // HWY_ONCE

// The pairs a tile's visible samples are shaded by: on every SIMD target, each record a pixel's
// samples show, once, in pixel and then sample order, as forEachShown lists them one pixel at a
// time; then grouped record by record, each record's pixels in the pairs' order.
#include "raster/shade/shade_visible.h"

#include <hwy/targets.h>
#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace illum {
namespace {

TEST(ShownPairs, AreForEachShownsPixelByPixelOnEveryTarget) {
  std::uint32_t state = 99;
  const auto next = [&] { return state = state * 1664525u + 1013904223u; };
  for (const int samples : {1, 2, 4, 8, 16}) {
    const std::size_t pixels = std::size_t(kTileSize) * kTileSize, room = kTileBlock * std::size_t(samples) + 16;
    std::vector<std::uint32_t> winners(kTileBlock * std::size_t(samples), kNoWinner);
    // Empty pixels, pixels of one record, of two or three (record 0 among them), in runs.
    for (std::size_t p = 0; p < pixels; ++p) {
      const std::uint32_t kind = (next() >> 28) % 4, a = next() >> 29, b = next() >> 30;
      for (int s = 0; s < samples; ++s) {
        std::uint32_t& w = winners[p * std::size_t(samples) + std::size_t(s)];
        const std::uint32_t pick = next() >> 30;
        if (kind == 0) w = kNoWinner;
        else if (kind == 1) w = a;
        else if (kind == 2) w = pick & 1 ? a : b;
        else w = pick == 0 ? kNoWinner : pick == 1 ? a : pick == 2 ? b : 0;
      }
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> expected;
    const VisibleSamples shown{samples, nullptr, winners.data()};
    for (std::size_t p = 0; p < pixels; ++p)
      shown.forEachShown(int(p), [&](int index, std::uint32_t slot) { expected.emplace_back(std::uint32_t(index), slot); });
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
      hwy::SetSupportedTargetsForTest(target);
      std::vector<std::uint32_t> pixel(room), slot(room);
      const std::size_t n = shownPairs(winners.data(), samples, pixel.data(), slot.data());
      std::vector<std::pair<std::uint32_t, std::uint32_t>> actual;
      for (std::size_t k = 0; k < n; ++k) actual.emplace_back(pixel[k], slot[k]);
      EXPECT_EQ(actual, expected) << hwy::TargetName(target) << ", " << samples << " samples";
    }
    hwy::SetSupportedTargetsForTest(0);
  }
}

TEST(GroupByRecord, LaysThePairsOutRecordByRecordInTheirOrderOnEveryTarget) {
  std::uint32_t state = 5;
  const auto next = [&] { return state = state * 1664525u + 1013904223u; };
  // Few records (each picked out a vector at a time) and many (a counting sort); pair counts that
  // end inside a vector; records no pixel shows.
  for (const std::size_t records : {1, 2, 5, 8, 9, 40})
    for (const std::size_t pairs : {1, 15, 16, 17, 1000, 4096}) {
      std::vector<std::uint32_t> pixel(pairs + 16), slot(pairs + 16);
      // Runs of one record, as neighbouring pixels have them, of 1 to 40 pairs.
      for (std::size_t k = 0; k < pairs;) {
        const std::uint32_t record = (next() >> 8) % std::uint32_t(records == 40 ? 20 : records);
        for (std::size_t run = 1 + (next() >> 8) % 40; run > 0 && k < pairs; --run, ++k) pixel[k] = next() % 4096, slot[k] = record;
      }
      for (std::size_t k = pairs; k < pairs + 16; ++k) pixel[k] = 7, slot[k] = 0;  // past the end: not pairs
      std::vector<std::uint32_t> expected, expectedStart;
      for (std::uint32_t r = 0; r < records; ++r) {
        expectedStart.push_back(std::uint32_t(expected.size()));
        for (std::size_t k = 0; k < pairs; ++k)
          if (slot[k] == r) expected.push_back(pixel[k]);
      }
      expectedStart.push_back(std::uint32_t(expected.size()));
      for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        std::vector<std::uint32_t> start(records + 1, 12345), out(pairs + 16);
        groupByRecord(pixel.data(), slot.data(), pairs, records, start.data(), out.data());
        out.resize(pairs);
        EXPECT_EQ(out, expected) << hwy::TargetName(target) << ", " << records << " records, " << pairs << " pairs";
        EXPECT_EQ(start, expectedStart) << hwy::TargetName(target) << ", " << records << " records, " << pairs << " pairs";
      }
      hwy::SetSupportedTargetsForTest(0);
    }
}

TEST(KeepShown, KeepsThePixelsSomeSampleOfWhichShowsTheRecordInOrderOnEveryTarget) {
  std::uint32_t state = 17;
  const auto next = [&] { return state = state * 1664525u + 1013904223u; };
  for (const int samples : {1, 2, 4, 8, 16}) {
    // Pixels whose samples show records 0 to 4 or none, each record's list of pixels where it
    // might show (some of them where it does not), record 3's empty.
    std::vector<std::uint32_t> winners(kTileBlock * std::size_t(samples), kNoWinner);
    for (std::uint32_t& w : winners) {
      const std::uint32_t pick = (next() >> 24) % 6;
      w = pick == 3 || pick == 5 ? kNoWinner : pick;
    }
    const std::size_t records = 5;
    std::vector<std::uint32_t> pixels, start, expected, expectedKept;
    const VisibleSamples shown{samples, nullptr, winners.data()};
    for (std::uint32_t r = 0; r < records; ++r) {
      start.push_back(std::uint32_t(pixels.size()));
      std::uint32_t kept = 0;
      if (r != 3)
        for (std::uint32_t p = next() % 5; p < std::uint32_t(kTileSize * kTileSize); p += 1 + next() % 5) pixels.push_back(p);
      for (std::size_t k = start.back(); k < pixels.size(); ++k)
        if (shown.shows(int(pixels[k]), r)) expected.push_back(pixels[k]), ++kept;
      expectedKept.push_back(kept);
      ASSERT_TRUE(r == 3 || (kept > 100 && kept < pixels.size() - start.back()));
    }
    start.push_back(std::uint32_t(pixels.size()));
    pixels.resize(pixels.size() + 16);
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
      hwy::SetSupportedTargetsForTest(target);
      std::vector<std::uint32_t> list = pixels, kept(records, 12345), actual;
      keepShown(winners.data(), samples, start.data(), records, list.data(), kept.data());
      for (std::size_t r = 0; r < records; ++r) actual.insert(actual.end(), list.begin() + start[r], list.begin() + start[r] + kept[r]);
      EXPECT_EQ(kept, expectedKept) << hwy::TargetName(target) << ", " << samples << " samples";
      EXPECT_EQ(actual, expected) << hwy::TargetName(target) << ", " << samples << " samples";
    }
    hwy::SetSupportedTargetsForTest(0);
  }
}

}  // namespace
}  // namespace illum

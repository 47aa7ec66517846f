// Tiny triangles of flat and Gouraud shading covered a batch at a time. One tiny triangle alone
// (tile_raster.h: coverTinyGouraud) is one long chain of dependent steps, edges to coverage to
// colour, that leaves most of a vector and of the core idle; a batch lays the pixels of up to 16
// triangles side by side in the lanes, one pixel per lane, each lane with its own triangle's
// values, and works them out together: the same formulas (interpolate-inl.h), so the same depths
// and colours, written in the same order, triangle after triangle.
#pragma once

#include <illum/real.h>

#if !ILLUM_USE_DOUBLE
#include "raster/bin.h"
#include "raster/setup.h"
#include "raster/tiny_fragment.h"

#include <illum/lighting.h>

#include <cstddef>
#include <cstdint>

namespace illum {

// Up to kCapacity tiny triangles, each field a row of lanes (one per triangle).
struct TinyBatchLanes {
  static constexpr int kCapacity = 16;
  // Edge values at the bounds' first pixel centre, their steps per column and per row, and the
  // top-left rule's bias, as VisitTiny (tile_raster.cpp) has them.
  alignas(64) float edge[3][kCapacity], stepX[3][kCapacity], stepY[3][kCapacity], bias[3][kCapacity];
  alignas(64) float invArea[kCapacity], z[3][kCapacity], invW[3][kCapacity];
  alignas(64) float lit[3][3][kCapacity];  // Gouraud: channel, vertex (counter-clockwise), triangle
  alignas(64) std::uint32_t packed[kCapacity];  // flat: the RGBA8 colour
  alignas(64) std::uint32_t firstTag[kCapacity];  // the bounds' first pixel, tagged (TinyTag)
  std::uint8_t width[kCapacity], count[kCapacity];  // the bounds' width and pixel count
};

// Covers the batch's first `size` triangles: their covered pixels go to `out` (room for
// kTinyBatchRoom), triangle after triangle, each triangle's in rows from the bottom, as
// coverTinyFlat (`flat`) or coverTinyGouraud writes them; covered[j] is how many triangle j has.
// Returns how many were written.
constexpr std::size_t kTinyBatchRoom = TinyBatchLanes::kCapacity * (kTinyPixels + 1);
std::size_t coverTinyBatch(const TinyBatchLanes& batch, int size, bool flat, TinyFragment* out,
                           std::uint8_t* covered);

// Gathers the tiny triangles of one setup run and hands their pixels to the bins, in the order
// they came. Only float-exact triangles (TriangleSetup::floatExact) of opaque colours join.
class TinyBatch {
 public:
  explicit TinyBatch(TinyRuns<TinyFragment>& out, bool flat) : out_(out), flat_(flat) {}
  TinyBatch(const TinyBatch&) = delete;
  TinyBatch& operator=(const TinyBatch&) = delete;

  static bool joins(const TriangleSetup& t, const Color4* lit) {
    return t.floatExact && (!lit || (lit[0].a == 1 && lit[1].a == 1 && lit[2].a == 1));
  }
  // Adds a triangle of `tile` after `recordsBefore` of its records: its three vertex colours
  // (`lit`, counter-clockwise) or, flat, its colour `packed`.
  void add(const TriangleSetup& t, const Color4* lit, std::uint32_t packed, std::uint32_t recordsBefore, int tile);
  // Covers what was added and appends it to the bins' runs (before anything else is appended
  // there, and once the run is over).
  void flush();

 private:
  TinyRuns<TinyFragment>& out_;
  bool flat_;
  int size_ = 0;
  int tile_[TinyBatchLanes::kCapacity];
  TinyBatchLanes lanes_;
};

}  // namespace illum
#endif  // !ILLUM_USE_DOUBLE

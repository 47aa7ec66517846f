// How the rasterizer's AVX-512 sampler (texture_lanes-inl.h) looks texel bytes up in a decode
// table: with AVX-512 VBMI's byte permutes where the CPU has them (a third of the instructions of
// float permutes), else with float permutes. Both give the table's own bits; tests draw both ways.
#pragma once

#include <atomic>

namespace illum {

bool cpuHasVbmi();  // asked of the CPU (texture.cpp)
inline std::atomic<bool> texelByteLookupsAllowed{true};

// True where the CPU has AVX-512 VBMI, unless a test has turned the byte permutes off. Inline: a
// call from a sampler's lanes would make the compiler save every vector register around it.
inline bool texelByteLookups() {
  static const bool vbmi = cpuHasVbmi();
  return vbmi && texelByteLookupsAllowed.load(std::memory_order_relaxed);
}
inline void setTexelByteLookupsForTest(bool allowed) { texelByteLookupsAllowed.store(allowed); }

}  // namespace illum

// How the rasterizer's AVX-512 sampler (texture_lanes-inl.h) looks texel bytes up in a decode
// table: with AVX-512 VBMI's byte permutes where the CPU has them (a third of the instructions of
// float permutes), else with float permutes. Both give the table's own bits; tests draw both ways.
#pragma once

namespace illum {

// True where the CPU has AVX-512 VBMI, unless a test has turned the byte permutes off.
bool texelByteLookups();
void setTexelByteLookupsForTest(bool allowed);

}  // namespace illum

// applyDisplay's pass over the pixels (display.cpp), a vector of pixels at a time: each colour
// byte through a table, the background's stored bytes replaced by its shown ones.
#pragma once

#include <cstddef>
#include <cstdint>

namespace illum {

struct DisplayBytes {
  std::uint32_t table[256];  // a colour byte's displayed value (alpha is kept)
  std::uint32_t stored = 0, shown = 0;  // the background's pixel as drawn and as displayed (RGBA words)
  bool hasBackground = false;
};

// Pixels [0, count) of `rgba` (RGBA8, 4-byte aligned), in place; each pixel on its own.
void mapDisplayBytes(std::uint8_t* rgba, std::size_t count, const DisplayBytes& map);

}  // namespace illum

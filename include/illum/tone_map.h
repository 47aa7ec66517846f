// The two steps from a linear value to a picture's byte that every renderer names: a tone map for
// radiance above 1 and an encoding. Their formulas are src/math/tone_map-inl.h and display.h's;
// these are only the names, so that the lowest layers can take them without the display's code.
#pragma once

namespace illum {

enum class ToneMap { None, Reinhard, Aces };
enum class Encoding { Linear, Srgb };

}  // namespace illum

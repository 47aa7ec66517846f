// Parsing of command-line values (vectors and colours) with messages that name the option.
#pragma once

#include <illum/real.h>

#include <string>

namespace illum::cli {

// "x,y,z" → Vec3. Throws InputError("--normal: expected 3 numbers x,y,z, got \"1,2\"").
Vec3 parseVec3(const std::string& option, const std::string& text);
// "R,G,B" with each channel a finite number ≥ 0 (and ≤ 1 when `unitRange`), or "#rrggbb".
Vec3 parseColor(const std::string& option, const std::string& text, bool unitRange);
// A finite number in [min, max].
Real parseNumber(const std::string& option, const std::string& text, Real min, Real max);

}  // namespace illum::cli

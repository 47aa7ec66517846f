// Parsing of command-line values (vectors and colours) with messages that name the option.
#pragma once

#include <illum/real.h>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace illum::cli {

// "x,y,z" → Vec3. Throws InputError("--normal: expected 3 numbers x,y,z, got \"1,2\"").
Vec3 parseVec3(const std::string& option, const std::string& text);
// "R,G,B" with each channel a finite number ≥ 0 (and ≤ 1 when `unitRange`), or "#rrggbb".
Vec3 parseColor(const std::string& option, const std::string& text, bool unitRange);
// A number in [min, max], finite in the renderer's precision (1e39 is refused where Real is float).
Real parseNumber(const std::string& option, const std::string& text, Real min, Real max);
// A whole number in [min, max] ("10.5" is refused).
int parseInteger(const std::string& option, const std::string& text, int min, int max);

// The check of every real-valued option: a finite number in [min, max]. CLI11's own Range lets
// NaN through (every comparison with it is false) and reads "inf" as a number.
CLI::Validator finiteRange(double min, double max);
// The check of a count: a whole number in [min, max] (0 frames or -5 light turns are refused).
CLI::Validator wholeRange(long long min, long long max);

// The candidate closest to `given`, if one is close enough to be what was meant: a known synonym
// (`synonyms`: pairs of what people type and what illum calls it), one that contains it whole (the
// shortest), or one within a few typing slips (Damerau-Levenshtein distance at most a third of
// its length, at least 1, at most 3).
std::optional<std::string> closestName(const std::string& given, const std::vector<std::string>& candidates,
                                       const std::vector<std::pair<std::string, std::string>>& synonyms = {});

// `option`'s value is not one of `choices`: "--shading: expected flat, gouraud or phong, got
// \"phongg\"; did you mean phong?" (InputError).
// An input as file managers give it: "file:///home/a/My%20Duck.glb" is /home/a/My Duck.glb (a
// host other than localhost is refused: the file is not on this machine); anything else as it is.
std::string fromFileUri(const std::string& input);
// The same as a CLI11 transform, for the options that take input files.
CLI::Validator fileUriInput();

// The lighting models' names, as the options take them.
std::vector<std::string> lightingModelChoices();
// The conventions' names (gl and the lecture notes').
std::vector<std::string> conventionChoices();

[[noreturn]] void badChoice(const std::string& option, const std::string& given, const std::vector<std::string>& choices);

}  // namespace illum::cli

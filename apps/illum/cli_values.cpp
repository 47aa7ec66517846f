#include "cli_values.h"

#include <illum/error.h>
#include <illum/lighting.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <limits>
#include <cmath>
#include <sstream>
#include <vector>

namespace illum::cli {
namespace {

bool toNumber(const std::string& s, double& out) {
  std::size_t begin = s.find_first_not_of(" \t");
  std::size_t end = s.find_last_not_of(" \t");
  if (begin == std::string::npos) return false;
  const char* first = s.data() + begin;
  const char* last = s.data() + end + 1;
  if (*first == '+') ++first;
  auto [ptr, ec] = std::from_chars(first, last, out);
  // Finite as the renderer computes: a double beyond float's range would become infinity.
  return ec == std::errc() && ptr == last && std::isfinite(out) && std::abs(out) <= double(std::numeric_limits<Real>::max());
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) parts.push_back(part);
  if (!text.empty() && text.back() == ',') parts.push_back("");
  return parts;
}

}  // namespace

Real parseNumber(const std::string& option, const std::string& text, Real min, Real max) {
  double v = 0;
  if (!toNumber(text, v))
    throw InputError(option + ": expected a finite number" +
                     (sizeof(Real) == 4 ? " (at most 3.4e38 in magnitude, single precision)" : "") + ", got \"" + text + "\"");
  if (v < min || v > max) {
    std::ostringstream s;
    s << option << ": expected a number in [" << min << ", " << max << "], got " << text;
    throw InputError(s.str());
  }
  return Real(v);
}

int parseInteger(const std::string& option, const std::string& text, int min, int max) {
  double v = 0;
  if (!toNumber(text, v) || v != std::floor(v))
    throw InputError(option + ": expected a whole number, got \"" + text + "\"");
  if (v < min || v > max)
    throw InputError(option + ": expected a whole number in [" + std::to_string(min) + ", " + std::to_string(max) +
                     "], got " + text);
  return int(v);
}

Vec3 parseVec3(const std::string& option, const std::string& text) {
  const auto parts = split(text);
  Vec3 v(0);
  double x = 0;
  if (parts.size() != 3) throw InputError(option + ": expected 3 numbers x,y,z, got \"" + text + "\"");
  for (int i = 0; i < 3; ++i) {
    if (!toNumber(parts[std::size_t(i)], x)) throw InputError(option + ": expected 3 finite numbers x,y,z, got \"" + text + "\"");
    v[i] = Real(x);
  }
  return v;
}

Vec3 parseColor(const std::string& option, const std::string& text, bool unitRange) {
  if (!text.empty() && text[0] == '#') {
    // #rrggbb: the bytes themselves. illum, like GL without an sRGB framebuffer, writes colours
    // to the image as round(c·255), so #rrggbb gives exactly those bytes back.
    unsigned value = 0;
    auto [ptr, ec] = std::from_chars(text.data() + 1, text.data() + text.size(), value, 16);
    if (text.size() != 7 || ec != std::errc() || ptr != text.data() + text.size())
      throw InputError(option + ": expected a colour R,G,B or #rrggbb, got \"" + text + "\"");
    Vec3 c;
    for (int i = 0; i < 3; ++i) c[i] = Real((value >> (16 - 8 * i)) & 0xffu) / Real(255);
    return c;
  }
  const auto parts = split(text);
  if (parts.size() != 3) throw InputError(option + ": expected a colour R,G,B (3 numbers), got \"" + text + "\"");
  Vec3 c;
  for (int i = 0; i < 3; ++i) {
    double x = 0;
    if (!toNumber(parts[std::size_t(i)], x) || x < 0 || (unitRange && x > 1))
      throw InputError(option + ": expected a colour R,G,B with each channel a number in " +
                       (unitRange ? "[0, 1]" : "[0, ∞)") + ", got \"" + text + "\"");
    c[i] = Real(x);
  }
  return c;
}

CLI::Validator finiteRange(double min, double max) {
  std::ostringstream range;
  range << "[" << min << ", " << max << "]";
  return CLI::Validator(
      [min, max, range = range.str()](std::string& text) -> std::string {
        double v = 0;
        if (!toNumber(text, v)) return "expected a finite number in " + range + ", got \"" + text + "\"";
        if (v < min || v > max) return "expected a number in " + range + ", got " + text;
        return {};
      },
      "FINITE in " + range.str());
}

CLI::Validator wholeRange(long long min, long long max) {
  const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        double v = 0;
        if (!toNumber(text, v) || v != std::floor(v)) return "expected a whole number in " + range + ", got \"" + text + "\"";
        if (v < double(min) || v > double(max)) return "expected a whole number in " + range + ", got " + text;
        return {};
      },
      "INT in " + range);
}

namespace {

// Damerau-Levenshtein (optimal string alignment): insertions, deletions, substitutions and swaps
// of neighbours, the slips of typing.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::optional<std::string> closestName(const std::string& given, const std::vector<std::string>& candidates,
                                       const std::vector<std::pair<std::string, std::string>>& synonyms) {
  const std::string g = lower(given);
  for (const auto& [typed, meant] : synonyms)
    if (g == typed) return meant;
  // The core of a name: without its leading dashes.
  const auto core = [](const std::string& s) { return s.substr(std::min(s.find_first_not_of('-'), s.size())); };
  const std::string gc = core(g);
  std::optional<std::string> best;
  if (gc.size() >= 3)
    for (const std::string& c : candidates)
      if (lower(c).find(gc) != std::string::npos && (!best || c.size() < best->size())) best = c;
  if (best) return best;
  std::size_t bestDistance = std::max<std::size_t>(1, std::min<std::size_t>(3, gc.size() / 3)) + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = editDistance(gc, core(lower(c)));
    if (d < bestDistance) bestDistance = d, best = c;
  }
  return best;
}

std::string fromFileUri(const std::string& input) {
  if (input.rfind("file://", 0) != 0) return input;
  std::string rest = input.substr(7);
  if (rest.rfind("localhost/", 0) == 0) rest = rest.substr(9);
  if (rest.empty() || rest[0] != '/')
    throw InputError(input + ": a file:// address of another machine; expected file:///path (this machine's files)");
  std::string path;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const auto hex = [&](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
    if (rest[i] == '%' && i + 2 < rest.size() && hex(rest[i + 1]) && hex(rest[i + 2])) {
      path += char(std::stoi(rest.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else if (rest[i] == '?' || rest[i] == '#') {
      break;  // a query or fragment is no part of a file's name
    } else {
      path += rest[i];
    }
  }
  if (path.find('\0') != std::string::npos) throw InputError(input + ": a file name cannot hold a NUL byte (%00)");
  return path;
}

CLI::Validator fileUriInput() {
  return CLI::Validator(
      [](std::string& value) {
        try {
          value = fromFileUri(value);
          return std::string();
        } catch (const InputError& e) {
          return std::string(e.what());
        }
      },
      "", "file URI");
}

namespace {
template <class E, std::size_t N>
std::vector<std::string> choicesOf(const E (&all)[N]) {
  std::vector<std::string> names;
  for (const E e : all) names.emplace_back(toString(e));
  return names;
}
}  // namespace

std::vector<std::string> lightingModelChoices() { return choicesOf(kLightingModels); }
std::vector<std::string> conventionChoices() { return choicesOf(kConventions); }

void badChoice(const std::string& option, const std::string& given, const std::vector<std::string>& choices) {
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i)
    list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  const std::optional<std::string> meant = closestName(given, choices);
  throw InputError(option + ": expected " + list + ", got \"" + given + "\"" + (meant ? "; did you mean " + *meant + "?" : ""));
}

}  // namespace illum::cli

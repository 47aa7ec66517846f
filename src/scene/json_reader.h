// Strict reading of scene JSON: every value is checked for type, length, finiteness and range,
// and every failure names the file, the JSON pointer and what was expected.
#pragma once

#include <illum/error.h>
#include <illum/real.h>

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <vector>

namespace illum {

using Json = nlohmann::json;

// A key as a JSON pointer token ("~" → "~0", "/" → "~1").
std::string jsonPointerToken(const std::string& key);

// How much JSON a parse may build: nesting depth, and values (an array or object counts 4: it
// costs a container besides its slot), so that neither a deep nest nor a flood of empty arrays
// can take more memory than a small multiple of the text's size limit.
struct JsonBudget {
  int maxDepth = 64;
  std::uint64_t maxValues = std::uint64_t(16) << 20;
  const char* raiseDepthWith = "--max-json-depth";
  const char* raiseValuesWith = "--max-scene-size";
};

// Parses JSON text, refusing duplicate keys (which JSON parsers silently resolve, so that a
// repeated key would render as if the first were never written) and anything over `budget`, at
// the value that crosses it. `name` is used in messages.
Json parseJsonStrict(const std::string& text, const std::string& name, const JsonBudget& budget = {});

class JsonReader {
 public:
  JsonReader(const Json& value, std::string file, std::string pointer = "")
      : value_(value), file_(std::move(file)), pointer_(std::move(pointer)) {}

  const Json& value() const { return value_; }
  const std::string& pointer() const { return pointer_; }
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& expected) const;

  // Object access. `expectObject` also rejects keys outside `allowed`.
  void expectObject(std::initializer_list<const char*> allowed) const;
  bool has(const char* key) const { return value_.contains(key); }
  JsonReader at(const char* key) const;
  JsonReader item(std::size_t index) const;
  std::size_t arraySize() const;  // fails unless an array

  // Scalars.
  Real number(Real min, Real max) const;  // inclusive range, finite
  Real positive() const;                  // > 0, finite
  Real nonNegative() const;               // ≥ 0, finite
  int integer(int min, int max) const;
  bool boolean() const;
  std::string string() const;

  // Fixed-length number arrays: "expected 3 numbers, got 2".
  std::vector<Real> numbers(std::size_t count) const;
  std::vector<Real> numbers(std::size_t minCount, std::size_t maxCount) const;
  Vec3 vec3() const;
  Vec4 vec4() const;
  // Colours are in [0,1]; [r,g,b] or [r,g,b,a] (alpha defaults to 1).
  Vec3 color3() const;
  Vec4 color34() const;
  // Light colours are intensities: each channel ≥ 0 with no upper bound (as glLight allows);
  // [r,g,b] or [r,g,b,a] with alpha in [0,1].
  Vec4 intensity34() const;

 private:
  std::string describe() const;  // "a string", "an array of 2", ...

  const Json& value_;
  std::string file_;
  std::string pointer_;
};

}  // namespace illum

#include "scene/json_reader.h"

#include <illum/limits.h>

#include <cmath>
#include <functional>
#include <set>
#include <sstream>

namespace illum {
std::string jsonPointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

namespace {

std::string formatReal(Real v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

void JsonReader::fail(const std::string& expected) const {
  throw InputError(file_ + ": " + (pointer_.empty() ? "/" : pointer_) + ": " + expected);
}

namespace {

// Follows the parser's events to know the JSON pointer of every key, and the keys seen so far
// in each open object.
class DuplicateKeyCheck {
 public:
  DuplicateKeyCheck(const std::string& name, const JsonBudget& budget) : name_(name), budget_(budget) {}

  bool operator()(int depth, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start: {
        std::string token = nextToken();
        if (depth >= budget_.maxDepth)
          throw InputError(name_ + ": " + pointer() + "/" + token + ": nested more than " + std::to_string(budget_.maxDepth) +
                           " arrays and objects deep (raise it with " + budget_.raiseDepthWith + ")");
        count(4, token);
        stack_.push_back({event == Json::parse_event_t::array_start, 0, {}, std::move(token)});
        break;
      }
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        stack_.pop_back();
        break;
      case Json::parse_event_t::key: {
        const std::string key = parsed.get<std::string>();
        pendingKey_ = jsonPointerToken(key);
        if (!stack_.back().keys.insert(key).second)
          throw InputError(name_ + ": " + pointer() + "/" + pendingKey_ + ": duplicate key \"" + key +
                           "\" (expected each key once; the first would be silently replaced)");
        break;
      }
      case Json::parse_event_t::value:
        count(1, nextToken());
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array;
    std::size_t next;
    std::set<std::string> keys;
    std::string token;  // where this container sits in its parent
  };

  // The token of the value that starts now: the next index in an array, the last key in an object.
  std::string nextToken() {
    if (stack_.empty()) return "";
    Frame& top = stack_.back();
    return top.array ? std::to_string(top.next++) : pendingKey_;
  }
  std::string pointer() const {
    std::string p;
    for (std::size_t i = 1; i < stack_.size(); ++i) p += "/" + stack_[i].token;
    return p;
  }

  void count(std::uint64_t cost, const std::string& token) {
    values_ += cost;
    if (values_ > budget_.maxValues)
      throw InputError(name_ + ": " + pointer() + "/" + token + ": more than " + withThousands(budget_.maxValues) +
                       " JSON values (an array or object counts 4; raise it with " + budget_.raiseValuesWith + ")");
  }

  const std::string& name_;
  const JsonBudget& budget_;
  std::vector<Frame> stack_;
  std::string pendingKey_;
  std::uint64_t values_ = 0;
};

}  // namespace

Json parseJsonStrict(const std::string& text, const std::string& name, const JsonBudget& budget) {
  DuplicateKeyCheck check(name, budget);
  return Json::parse(text, std::ref(check));
}

std::string JsonReader::describe() const {
  switch (value_.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::string: return "a string";
    case Json::value_t::array: return "an array of " + std::to_string(value_.size());
    case Json::value_t::object: return "an object";
    default: return "a number";
  }
}

void JsonReader::expectObject(std::initializer_list<const char*> allowed) const {
  if (!value_.is_object()) fail("expected an object, got " + describe());
  for (const auto& [key, unused] : value_.items()) {
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (known) continue;
    std::string list;
    for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
    JsonReader(unused, file_, pointer_ + "/" + jsonPointerToken(key))
        .fail("unknown key \"" + key + "\" (expected one of: " + list + ")");
  }
}

JsonReader JsonReader::at(const char* key) const {
  return JsonReader(value_.at(key), file_, pointer_ + "/" + jsonPointerToken(key));
}

JsonReader JsonReader::item(std::size_t index) const {
  return JsonReader(value_.at(index), file_, pointer_ + "/" + std::to_string(index));
}

std::size_t JsonReader::arraySize() const {
  if (!value_.is_array()) fail("expected an array, got " + describe());
  return value_.size();
}

Real JsonReader::number(Real min, Real max) const {
  if (!value_.is_number()) fail("expected a number, got " + describe());
  const double v = value_.get<double>();
  if (!std::isfinite(v) || !std::isfinite(Real(v))) fail("expected a finite number");
  if (v < min || v > max)
    fail("expected a number in [" + formatReal(min) + ", " + formatReal(max) + "], got " + formatReal(Real(v)));
  return Real(v);
}

Real JsonReader::positive() const {
  const Real v = number(-std::numeric_limits<Real>::max(), std::numeric_limits<Real>::max());
  if (!(v > 0)) fail("expected a positive number, got " + formatReal(v));
  return v;
}

Real JsonReader::nonNegative() const {
  const Real v = number(-std::numeric_limits<Real>::max(), std::numeric_limits<Real>::max());
  if (!(v >= 0)) fail("expected a number ≥ 0, got " + formatReal(v));
  return v;
}

int JsonReader::integer(int min, int max) const {
  if (!value_.is_number()) fail("expected an integer, got " + describe());
  const double v = value_.get<double>();
  if (!std::isfinite(v) || v != std::floor(v)) fail("expected an integer, got " + value_.dump());
  if (v < min || v > max)
    fail("expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + value_.dump());
  return int(v);
}

bool JsonReader::boolean() const {
  if (!value_.is_boolean()) fail("expected true or false, got " + describe());
  return value_.get<bool>();
}

std::string JsonReader::string() const {
  if (!value_.is_string()) fail("expected a string, got " + describe());
  return value_.get<std::string>();
}

std::vector<Real> JsonReader::numbers(std::size_t count) const { return numbers(count, count); }

std::vector<Real> JsonReader::numbers(std::size_t minCount, std::size_t maxCount) const {
  const std::string want = minCount == maxCount ? std::to_string(minCount)
                                                : std::to_string(minCount) + " or " + std::to_string(maxCount);
  if (!value_.is_array()) fail("expected " + want + " numbers, got " + describe());
  const std::size_t n = value_.size();
  if (n < minCount || n > maxCount) fail("expected " + want + " numbers, got " + std::to_string(n));
  std::vector<Real> out;
  out.reserve(n);
  const Real big = std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < n; ++i) out.push_back(item(i).number(-big, big));
  return out;
}

Vec3 JsonReader::vec3() const {
  const auto v = numbers(3);
  return {v[0], v[1], v[2]};
}

Vec4 JsonReader::vec4() const {
  const auto v = numbers(4);
  return {v[0], v[1], v[2], v[3]};
}

Vec3 JsonReader::color3() const {
  numbers(3);
  return {item(0).number(0, 1), item(1).number(0, 1), item(2).number(0, 1)};
}

Vec4 JsonReader::color34() const {
  const auto v = numbers(3, 4);
  Vec4 c(0, 0, 0, 1);
  for (std::size_t i = 0; i < v.size(); ++i) c[int(i)] = item(i).number(0, 1);
  return c;
}

Vec4 JsonReader::intensity34() const {
  const auto v = numbers(3, 4);
  Vec4 c(0, 0, 0, 1);
  for (std::size_t i = 0; i < v.size(); ++i) c[int(i)] = i < 3 ? item(i).nonNegative() : item(i).number(0, 1);
  return c;
}

}  // namespace illum

#include "scene/model_precheck.h"

#include <illum/error.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <vector>

namespace illum {
namespace {

namespace fs = std::filesystem;
using u64 = std::uint64_t;

constexpr u64 kSaturated = ~u64(0);
u64 add(u64 a, u64 b) { return a > kSaturated - b ? kSaturated : a + b; }
u64 mul(u64 a, u64 b) { return b != 0 && a > kSaturated / b ? kSaturated : a * b; }

std::string readPrefix(const fs::path& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), std::streamsize(n));
  s.resize(std::size_t(in.gcount()));
  return s;
}

[[noreturn]] void refuse(const fs::path& path, const std::string& why) { throw InputError(path.string() + ": " + why); }

void checkTriangles(const fs::path& path, u64 triangles, const Limits& limits, const std::string& what) {
  if (triangles > limits.maxTriangles)
    refuse(path, what + " would make " + (triangles == kSaturated ? std::string("billions of") : withThousands(triangles)) +
                     " triangles, more than the limit of " + withThousands(limits.maxTriangles) +
                     " (raise it with --max-triangles)");
}

void checkDeclaredBytes(const fs::path& path, u64 needed, u64 available, const std::string& what) {
  if (needed > available)
    refuse(path, "the header declares " + what + ", which needs at least " +
                     (needed == kSaturated ? std::string("more") : withThousands(needed)) + " bytes, but only " +
                     withThousands(available) + " follow (is the file truncated or corrupt?)");
}

// PLY: the header must end (assimp loops or crashes when it does not), and its elements must fit.
void checkPly(const fs::path& path, u64 fileSize, const Limits& limits) {
  constexpr std::size_t kMaxHeader = 1 << 16;
  const std::string head = readPrefix(path, kMaxHeader);
  const std::size_t end = head.find("end_header");
  if (end == std::string::npos)
    refuse(path, "the PLY header has no end_header line within its first 64 KiB (is the file truncated?)");
  std::size_t dataStart = head.find('\n', end);
  dataStart = dataStart == std::string::npos ? head.size() : dataStart + 1;
  const u64 available = fileSize - std::min<u64>(fileSize, dataStart);

  std::istringstream lines(head.substr(0, end));
  std::string line, format;
  struct Element { std::string name; u64 count = 0, minBytes = 0, properties = 0; };
  std::vector<Element> elements;
  static const std::map<std::string, u64> kSizes = {
      {"char", 1}, {"uchar", 1}, {"int8", 1}, {"uint8", 1}, {"short", 2}, {"ushort", 2}, {"int16", 2},
      {"uint16", 2}, {"int", 4}, {"uint", 4}, {"int32", 4}, {"uint32", 4}, {"float", 4}, {"float32", 4},
      {"double", 8}, {"float64", 8}};
  const auto sizeOf = [](const std::string& t) { auto it = kSizes.find(t); return it == kSizes.end() ? u64(1) : it->second; };
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      words >> format;
    } else if (keyword == "element") {
      Element e;
      words >> e.name >> e.count;
      if (!words) refuse(path, "the PLY header line \"" + line + "\" has no element count");
      elements.push_back(e);
    } else if (keyword == "property" && !elements.empty()) {
      std::string type;
      words >> type;
      if (type == "list") {
        std::string countType;
        words >> countType;
        type = countType;  // a list takes at least its count
      }
      elements.back().minBytes += sizeOf(type);
      elements.back().properties += 1;
    }
  }
  const bool ascii = format == "ascii";
  u64 needed = 0;
  std::string what;
  for (const Element& e : elements) {
    // ASCII: every value takes at least a character and a separator.
    const u64 each = ascii ? 2 * std::max<u64>(e.properties, 1) : e.minBytes;
    needed = add(needed, mul(e.count, each));
    if (!what.empty()) what += ", ";
    what += withThousands(e.count) + " " + e.name + (e.count == 1 ? "" : "s");
    if (e.name == "face") checkTriangles(path, e.count, limits, "the header's " + withThousands(e.count) + " faces");
  }
  checkDeclaredBytes(path, needed, available + (ascii ? 1 : 0), what);
}

// OFF: "OFF" (with ST, C, N, 4 or n prefixes), then the vertex, face and edge counts.
void checkOff(const fs::path& path, u64 fileSize, const Limits& limits) {
  const std::string head = readPrefix(path, 4096);
  std::istringstream in(head);
  std::string word;
  std::vector<u64> counts;
  bool sawKeyword = false;
  while (counts.size() < 2 && in >> word) {
    if (word[0] == '#') {
      std::getline(in, word);
      continue;
    }
    if (!sawKeyword && word.find("OFF") != std::string::npos) {
      if (word.find("BINARY") != std::string::npos) return;  // binary OFF: counts follow in binary
      sawKeyword = true;
      std::string rest;
      if (in >> rest && rest == "BINARY") return;
      if (!rest.empty() && std::isdigit(static_cast<unsigned char>(rest[0]))) counts.push_back(std::stoull(rest));
      continue;
    }
    if (!std::isdigit(static_cast<unsigned char>(word[0]))) return;  // not a header we understand: let the reader say
    try {
      counts.push_back(std::stoull(word));
    } catch (const std::exception&) {
      counts.push_back(kSaturated);
    }
  }
  if (counts.size() < 2) return;
  checkTriangles(path, counts[1], limits, "the header's " + withThousands(counts[1]) + " faces");
  // A vertex is at least three numbers ("0 0 0\n"), a face at least its vertex count ("0\n").
  const u64 needed = add(mul(counts[0], 6), mul(counts[1], 2));
  checkDeclaredBytes(path, needed, fileSize + 1,
                     withThousands(counts[0]) + " vertices and " + withThousands(counts[1]) + " faces");
}

// Binary STL: an 80-byte header, a triangle count, then 50 bytes per triangle.
void checkStl(const fs::path& path, u64 fileSize, const Limits& limits) {
  const std::string head = readPrefix(path, 84);
  if (head.size() < 84 || head.rfind("solid", 0) == 0) return;  // ASCII STL (or too short: the reader says)
  std::uint32_t count = 0;
  std::memcpy(&count, head.data() + 80, 4);
  checkTriangles(path, count, limits, "the header's " + withThousands(count) + " triangles");
  checkDeclaredBytes(path, add(84, mul(count, 50)), fileSize, withThousands(count) + " triangles");
}

// Calls `each(keyword, rest of the line)` for every line of a text format.
template <class Fn>
void forEachLine(const fs::path& path, Fn&& each) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    each(keyword, words);
  }
}

// base·4^n, saturating.
u64 timesPowerOfFour(u64 base, u64 n) {
  for (u64 i = 0; i < n && base != kSaturated; ++i) base = mul(base, 4);
  return base;
}

// AC3D: "subdiv N" asks for N rounds of subdivision, each quadrupling the surfaces.
void checkAc3d(const fs::path& path, const Limits& limits) {
  u64 subdiv = 0, triangles = 0;
  forEachLine(path, [&](const std::string& keyword, std::istringstream& words) {
    if (keyword == "OBJECT") subdiv = 0;
    else if (keyword == "subdiv") words >> subdiv;
    else if (keyword == "numsurf" && subdiv > 0) {
      u64 surfaces = 0;
      words >> surfaces;
      triangles = add(triangles, timesPowerOfFour(mul(surfaces, 2), subdiv));
    }
  });
  checkTriangles(path, triangles, limits, "AC3D subdivision");
}

// NFF: "tess N" sets how finely later spheres are made: an icosahedron subdivided N times,
// 20·4^N triangles each.
void checkNff(const fs::path& path, const Limits& limits) {
  u64 tess = 4, triangles = 0;
  forEachLine(path, [&](const std::string& keyword, std::istringstream& words) {
    if (keyword == "tess") words >> tess;
    else if (keyword == "s") triangles = add(triangles, timesPowerOfFour(20, tess));
  });
  checkTriangles(path, triangles, limits, "NFF tessellation");
}

// glTF: nodes may share children, and every path from a scene root is one instance; count them
// (and their triangles) without expanding the graph, and refuse cycles.
void checkGltfJson(const fs::path& path, const nlohmann::json& doc, const Limits& limits) {
  if (!doc.is_object() || !doc.contains("nodes") || !doc["nodes"].is_array()) return;
  const auto& nodes = doc["nodes"];
  const auto accessorCount = [&](const nlohmann::json& index) -> u64 {
    if (!index.is_number_unsigned() || !doc.contains("accessors") || !doc["accessors"].is_array()) return 0;
    const auto i = index.get<u64>();
    if (i >= doc["accessors"].size()) return 0;
    const auto& a = doc["accessors"][i];
    return a.is_object() && a.contains("count") && a["count"].is_number_unsigned() ? a["count"].get<u64>() : 0;
  };
  const auto meshTriangles = [&](const nlohmann::json& node) -> u64 {
    if (!node.is_object() || !node.contains("mesh") || !node["mesh"].is_number_unsigned() || !doc.contains("meshes"))
      return 0;
    const auto m = node["mesh"].get<u64>();
    if (!doc["meshes"].is_array() || m >= doc["meshes"].size()) return 0;
    const auto& mesh = doc["meshes"][m];
    u64 sum = 0;
    if (mesh.is_object() && mesh.contains("primitives") && mesh["primitives"].is_array())
      for (const auto& p : mesh["primitives"]) {
        if (!p.is_object()) continue;
        if (p.contains("indices")) sum = add(sum, accessorCount(p["indices"]) / 3);
        else if (p.contains("attributes") && p["attributes"].is_object() && p["attributes"].contains("POSITION"))
          sum = add(sum, accessorCount(p["attributes"]["POSITION"]) / 3);
      }
    return sum;
  };
  struct Total { u64 instances = 0, triangles = 0; };
  std::vector<int> state(nodes.size(), 0);  // 0 unseen, 1 on the path, 2 done
  std::vector<Total> totals(nodes.size());
  std::function<Total(std::size_t)> visit = [&](std::size_t i) -> Total {
    if (state[i] == 1) refuse(path, "the glTF node " + std::to_string(i) + " is its own ancestor (a cycle)");
    if (state[i] == 2) return totals[i];
    state[i] = 1;
    Total t{1, meshTriangles(nodes[i])};
    if (nodes[i].is_object() && nodes[i].contains("children") && nodes[i]["children"].is_array())
      for (const auto& c : nodes[i]["children"])
        if (c.is_number_unsigned() && c.get<u64>() < nodes.size()) {
          const Total child = visit(std::size_t(c.get<u64>()));
          t.instances = add(t.instances, child.instances);
          t.triangles = add(t.triangles, child.triangles);
        }
    state[i] = 2;
    return totals[i] = t;
  };
  Total all;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (state[i] != 0) continue;
    const Total t = visit(i);
    all.instances = add(all.instances, t.instances);
    all.triangles = add(all.triangles, t.triangles);
  }
  constexpr u64 kMaxInstances = 1'000'000;
  if (all.instances > kMaxInstances)
    refuse(path, "the glTF node graph expands to " + (all.instances == kSaturated ? std::string("billions of") : withThousands(all.instances)) +
                     " node instances (shared children), more than " + withThousands(kMaxInstances));
  checkTriangles(path, all.triangles, limits, "the glTF node graph's instances");
}

void checkGltf(const fs::path& path, u64 fileSize, const Limits& limits, const std::string& ext) {
  std::string text;
  if (ext == ".glb") {
    const std::string head = readPrefix(path, 20);
    if (head.size() < 20 || head.compare(0, 4, "glTF") != 0) return;
    std::uint32_t length = 0;
    std::memcpy(&length, head.data() + 12, 4);
    if (u64(length) + 20 > fileSize) return;  // the reader reports a truncated file
    text = readPrefix(path, 20 + length).substr(20);
  } else {
    text = readPrefix(path, std::size_t(fileSize));
  }
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded()) return;  // not JSON: the reader gives its own message
  checkGltfJson(path, doc, limits);
}

}  // namespace

void precheckModelFile(const fs::path& path, const Limits& limits, const std::string& ext) {
  std::error_code ec;
  const u64 size = fs::file_size(path, ec);
  if (ec) return;
  if (ext == ".ply") checkPly(path, size, limits);
  else if (ext == ".off") checkOff(path, size, limits);
  else if (ext == ".stl") checkStl(path, size, limits);
  else if (ext == ".ac" || ext == ".acc" || ext == ".ac3d") checkAc3d(path, limits);
  else if (ext == ".nff") checkNff(path, limits);
  else if (ext == ".gltf" || ext == ".glb") checkGltf(path, size, limits, ext);
}

}  // namespace illum

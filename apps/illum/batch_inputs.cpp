#include "batch_inputs.h"

#include <illum/error.h>
#include <illum/import.h>
#include <illum/file_names.h>

#include <algorithm>
#include <regex>
#include <set>
#include <system_error>

namespace illum::cli {
namespace {

namespace fs = std::filesystem;

bool hasWildcard(const std::string& s) { return s.find_first_of("*?[") != std::string::npos; }

bool isRenderable(const fs::path& p) {
  return isSceneFileName(p) || isModelFileName(p);
}

// A glob as a regular expression over '/'-separated relative paths: ** crosses folders.
std::regex globRegex(const std::string& glob) {
  std::string re;
  for (std::size_t i = 0; i < glob.size(); ++i) {
    const char c = glob[i];
    if (c == '*' && i + 1 < glob.size() && glob[i + 1] == '*') {
      const bool slash = i + 2 < glob.size() && glob[i + 2] == '/';
      re += slash ? "(?:.*/)?" : ".*";
      i += slash ? 2 : 1;
    } else if (c == '*') {
      re += "[^/]*";
    } else if (c == '?') {
      re += "[^/]";
    } else if (std::string("\\^$.|+(){}[]").find(c) != std::string::npos) {
      re += '\\';
      re += c;
    } else {
      re += c;
    }
  }
  return std::regex(re);
}

// Every regular file under `dir`, sorted by path (links to folders are not followed).
std::vector<fs::path> walk(const fs::path& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end;
       it.increment(ec))
    if (it->is_regular_file(ec)) files.push_back(it->path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::vector<BatchJob> expandInputs(const std::vector<std::string>& inputs) {
  std::vector<std::pair<std::string, std::string>> paths;  // (file, root)
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (input == "-") {
      paths.push_back({input, ""});
    } else if (!hasWildcard(input) || fs::exists(input, ec)) {
      if (fs::is_directory(input, ec)) {
        const std::size_t before = paths.size();
        for (const fs::path& f : walk(input))
          if (isRenderable(f)) paths.push_back({f.string(), input});
        if (paths.size() == before) throw InputError(input + ": the folder holds no model or scene file");
      } else {
        paths.push_back({input, ""});  // a file, or a missing one, which its job reports
      }
    } else {
      // The folder part before the first wildcard is walked; the rest is matched.
      const std::size_t wild = input.find_first_of("*?[");
      const std::size_t slash = input.rfind('/', wild);
      const std::string base = slash == std::string::npos ? "." : input.substr(0, slash == 0 ? 1 : slash);
      const std::string rest = slash == std::string::npos ? input : input.substr(slash + 1);
      const std::regex re = globRegex(rest);
      const std::size_t before = paths.size();
      if (fs::is_directory(base, ec))
        for (const fs::path& f : walk(base)) {
          const std::string relative = f.lexically_relative(base).generic_string();
          if (std::regex_match(relative, re)) paths.push_back({slash == std::string::npos ? relative : f.string(), base});
        }
      if (paths.size() == before) throw InputError(input + ": no file matches the pattern");
    }
  }
  std::vector<BatchJob> jobs;
  std::set<std::string> seen;
  for (const auto& [p, root] : paths)
    if (p == "-" || seen.insert(fs::path(p).lexically_normal().string()).second) jobs.push_back({p, jobs.size(), root});
  return jobs;
}

std::vector<BatchJob> shardOf(const std::vector<BatchJob>& jobs, const std::string& shard) {
  static const std::regex form(R"((\d{1,9})/(\d{1,9}))");
  std::smatch m;
  if (!std::regex_match(shard, m, form)) throw InputError("--shard: expected I/N (I from 0 to N−1), got \"" + shard + "\"");
  const std::size_t i = std::stoul(m[1]), n = std::stoul(m[2]);
  if (n == 0 || i >= n) throw InputError("--shard: expected I/N with 0 ≤ I < N, got \"" + shard + "\"");
  const std::size_t count = jobs.size();
  return {jobs.begin() + long(i * count / n), jobs.begin() + long((i + 1) * count / n)};
}

bool isTemplate(const std::string& pattern) {
  return std::regex_search(pattern, std::regex(R"(\{(stem|name|ext|dir|n|frame)(:0?\d+)?\})"));
}

namespace {

// {dir} under --output-dir (see expandTemplate).
std::string confinedDir(const BatchJob& job) {
  const fs::path folder = fs::path(job.input).parent_path();
  if (!job.root.empty()) {
    const fs::path relative = folder.lexically_relative(job.root);
    if (!relative.empty() && *relative.begin() != "..") return relative.string();
  }
  fs::path kept;
  for (const fs::path& part : folder.lexically_normal().relative_path())
    if (part != ".." && part != ".") kept /= part;
  return kept.empty() ? "." : kept.string();
}

}  // namespace

std::string OutputPattern::name(const BatchJob& job, int frame) const {
  const std::string expanded = expandTemplate(pattern, job, frame, !dir.empty());
  if (dir.empty()) return expanded;
  const fs::path inside = fs::path(expanded).lexically_normal();
  if (inside.is_absolute() || (!inside.empty() && *inside.begin() == ".."))
    throw InputError("-o " + pattern + ": " + expanded + " would leave --output-dir " + dir +
                     " (expected a name inside it: no leading / or ..)");
  return (fs::path(dir) / inside).string();
}

std::string expandTemplate(const std::string& pattern, const BatchJob& job, int frame, bool confined) {
  // Standard input is named stdin, the built-in scene (no input) illum, as its one picture is.
  const fs::path in = job.input == "-" ? fs::path("stdin") : job.input.empty() ? fs::path("illum") : fs::path(job.input);
  std::string out;
  for (std::size_t i = 0; i < pattern.size();) {
    if (pattern[i] != '{') {
      out += pattern[i++];
      continue;
    }
    const std::size_t close = pattern.find('}', i);
    if (close == std::string::npos) throw InputError("-o: an unclosed { in \"" + pattern + "\"");
    std::string field = pattern.substr(i + 1, close - i - 1), width;
    if (const auto colon = field.find(':'); colon != std::string::npos) width = field.substr(colon + 1), field = field.substr(0, colon);
    std::string value;
    if (field == "stem") value = in.stem().string();
    else if (field == "name") value = in.filename().string();
    else if (field == "ext") value = in.extension().string().empty() ? "" : in.extension().string().substr(1);
    else if (field == "dir") value = confined ? confinedDir(job) : in.parent_path().empty() ? "." : in.parent_path().string();
    else if (field == "n" || field == "frame") value = std::to_string(field == "n" ? job.index + 1 : std::size_t(frame));
    else throw InputError("-o: unknown field {" + field + "} (expected {stem}, {name}, {ext}, {dir}, {n} or {frame})");
    if (!width.empty()) {
      if (!std::all_of(width.begin(), width.end(), ::isdigit) || width.size() > 2 || (field != "n" && field != "frame"))
        throw InputError("-o: {" + field + ":" + width + "}: a width such as {n:03} or {frame:04} is for numbers");
      const std::size_t w = std::stoul(width);
      if (value.size() < w) value.insert(0, w - value.size(), '0');
    }
    out += value;
    i = close + 1;
  }
  return out;
}

}  // namespace illum::cli

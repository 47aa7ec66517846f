#include "output_guard.h"

#include <illum/error.h>

#include <sys/stat.h>

namespace illum::cli {

namespace fs = std::filesystem;

fs::path resolvedOutput(const fs::path& output) {
  std::error_code ec;
  fs::path p = fs::absolute(output, ec).lexically_normal();
  // Follow the last component's links by hand: canonical() stops at one whose target is missing.
  for (int hops = 0; hops < 40 && fs::is_symlink(p, ec); ++hops) {
    const fs::path target = fs::read_symlink(p, ec);
    if (ec) break;
    p = (target.is_absolute() ? target : p.parent_path() / target).lexically_normal();
  }
  const fs::path resolved = fs::weakly_canonical(p, ec);
  return ec ? p : resolved;
}

std::vector<std::string> OutputGuard::keysOf(const fs::path& file) {
  std::vector<std::string> keys{"path:" + resolvedOutput(file).string()};
  struct stat st{};
  if (::stat(file.c_str(), &st) == 0)
    keys.push_back("node:" + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino));
  return keys;
}

void OutputGuard::protect(const fs::path& file) {
  for (const std::string& key : keysOf(file)) protected_.emplace(key, file.string());
}

void OutputGuard::checkNotInput(const std::string& output) const {
  for (const std::string& key : keysOf(output))
    if (const auto it = protected_.find(key); it != protected_.end())
      throw InputError("-o: " + output + (it->second == output ? "" : " (that is " + it->second + ")") +
                       " is a file illum reads for this render; an output never replaces an input (choose another "
                       "name, such as '{stem}.png', or --output-dir)");
}

void OutputGuard::claim(const std::string& output, const std::string& owner) {
  const std::vector<std::string> keys = keysOf(output);
  for (const std::string& key : keys)
    if (const auto it = claimed_.find(key); it != claimed_.end() && it->second != owner)
      throw InputError("-o: " + it->second + " and " + owner + " would both be written to " + output +
                       " (the same file, through a link or another name); add {dir} or {n} to the template");
  for (const std::string& key : keys) claimed_.emplace(key, owner);
}

void checkOutputsSpareScene(const Scene& scene, const std::vector<std::string>& outputs) {
  OutputGuard guard;
  for (const fs::path& file : scene.files) guard.protect(file);
  for (const std::string& output : outputs) guard.checkNotInput(output);
}

}  // namespace illum::cli

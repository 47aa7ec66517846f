#include <illum/output_file.h>

#include <illum/error.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

#include <climits>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace illum {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& why) {
  throw Error(path.string() + ": cannot write: " + why);
}

std::string errnoText() { return std::strerror(errno); }

// Follows a chain of symlinks to the path that will really be written. Links into /proc (such as
// /dev/stdout → /proc/self/fd/1 → pipe:[…]) name no path of their own: `magic` is set instead,
// and the caller opens the original path, which the kernel resolves.
fs::path followLinks(const fs::path& path, bool& magic) {
  fs::path p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st{};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::string target(PATH_MAX, '\0');
    const ssize_t n = ::readlink(p.c_str(), target.data(), target.size());
    if (n < 0) fail(path, errnoText());
    target.resize(std::size_t(n));
    const fs::path next = fs::path(target).is_absolute() ? fs::path(target) : p.parent_path() / target;
    const std::string s = next.lexically_normal().string();
    if (s.rfind("/proc/", 0) == 0 || s.rfind("/dev/fd/", 0) == 0) {
      magic = true;
      return path;
    }
    p = next;
  }
  fail(path, "too many levels of symbolic links");
}

// Writes every byte; returns why it could not (empty on success).
std::string writeAll(int fd, const std::vector<std::uint8_t>& bytes) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errnoText() : "nothing was written";
    written += std::size_t(n);
  }
  return {};
}

// Devices, FIFOs, terminals and files with several hard links: the node itself is what the user
// named, so the bytes go into it. A FIFO waits for its reader, as `cat > FIFO` does.
void writeInPlace(const fs::path& path, const std::vector<std::uint8_t>& bytes, bool truncate) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | (truncate ? O_TRUNC : 0));
  if (fd < 0) fail(path, errnoText());
  if (const std::string why = writeAll(fd, bytes); !why.empty()) {
    ::close(fd);
    fail(path, why);
  }
  if (::close(fd) != 0 && errno != EINTR) fail(path, errnoText());
}

// A new file or a regular one: a temporary file beside it, then rename(2) over it. The temporary
// name is short (".illum-XXXXXX"), so a target name at the file system's limit still works.
void replaceAtomically(const fs::path& target, const struct stat* existing,
                       const std::vector<std::uint8_t>& bytes, const fs::path& shownPath) {
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::string name = (dir / ".illum-XXXXXX").string();
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) {
    // A folder we may not create files in, holding a file we may write: write that file in place.
    if (existing && errno == EACCES && ::access(target.c_str(), W_OK) == 0) return writeInPlace(target, bytes, true);
    fail(shownPath, errnoText());
  }
  const auto discard = [&](const std::string& why) {
    ::close(fd);
    ::unlink(name.c_str());
    fail(shownPath, why);
  };
  if (const std::string why = writeAll(fd, bytes); !why.empty()) discard(why);
  if (existing) {
    // Keep what the old file was: its permission bits and, where allowed, its owner.
    if (::fchown(fd, existing->st_uid, existing->st_gid) != 0) { /* not ours to give away: keep ours */ }
    ::fchmod(fd, existing->st_mode & 07777);
  } else {
    // mkstemp creates 0600; a new file gets what open(2) with 0666 would give it.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
  }
  if (::fsync(fd) != 0) discard(errnoText());
  if (::close(fd) != 0) {
    const std::string why = errnoText();
    ::unlink(name.c_str());
    fail(shownPath, why);
  }
  if (::rename(name.c_str(), target.c_str()) != 0) {
    const std::string why = errnoText();
    ::unlink(name.c_str());
    fail(shownPath, why);
  }
}

}  // namespace

void writeOutputFile(const fs::path& path, const std::vector<std::uint8_t>& bytes, const OutputOptions& options) {
  if (path.empty()) fail(path, "the output path is empty");
  bool magic = false;
  const fs::path target = followLinks(path, magic);
  if (magic) return writeInPlace(path, bytes, false);

  struct stat st{};
  if (::stat(target.c_str(), &st) != 0) {
    if (errno != ENOENT) fail(path, errnoText());
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    struct stat ds{};
    if (::stat(dir.c_str(), &ds) != 0 || !S_ISDIR(ds.st_mode))
      fail(path, "the folder " + dir.string() + " does not exist");
    return replaceAtomically(target, nullptr, bytes, path);
  }
  if (S_ISDIR(st.st_mode)) fail(path, "it is a directory");
  if (S_ISSOCK(st.st_mode)) fail(path, "it is a socket");
  if (!S_ISREG(st.st_mode)) return writeInPlace(target, bytes, false);  // device, FIFO
  const bool readOnly = (st.st_mode & 0222) == 0 || (::access(target.c_str(), W_OK) != 0 && errno == EACCES);
  if (readOnly && !options.force)
    fail(path, "the file is read-only (--force replaces it, keeping its permissions)");
  if (st.st_nlink > 1 && !readOnly) return writeInPlace(target, bytes, true);  // every hard link sees the new bytes
  replaceAtomically(target, &st, bytes, path);
}

}  // namespace illum

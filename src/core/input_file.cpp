#include "core/input_file.h"

#include <illum/error.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace illum {
namespace {

std::string mib(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1 << 20));
  return text;
}

[[noreturn]] void refuseOpen(const std::filesystem::path& path, const InputFileKind& kind, int error) {
  if (error == ENOENT || error == ENOTDIR) throw InputError(path.string() + ": no such " + kind.noun);
  throw InputError(path.string() + ": cannot open the " + kind.noun + ": " + std::strerror(error));
}

[[noreturn]] void refuseType(const std::filesystem::path& path, unsigned mode) {
  throw InputError(path.string() + ": not a regular file (" + describeFileType(mode) + ")");
}

}  // namespace

std::string describeFileType(unsigned mode) {
  switch (mode & S_IFMT) {
    case S_IFIFO: return "a FIFO";
    case S_IFDIR: return "a folder";
    case S_IFCHR: return "a character device";
    case S_IFBLK: return "a block device";
    case S_IFSOCK: return "a socket";
    default: return "not a file of data";
  }
}

void checkRegularFile(const std::filesystem::path& path, const InputFileKind& kind) {
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0) refuseOpen(path, kind, errno);
  if (!S_ISREG(st.st_mode)) refuseType(path, st.st_mode);
}

std::string readInputFile(const std::filesystem::path& path, std::uint64_t maxBytes, const InputFileKind& kind) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer; the descriptor's own
  // type is checked next, and a regular file ignores the flag.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) refuseOpen(path, kind, errno);
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st{};
  if (::fstat(fd, &st) != 0) refuseOpen(path, kind, errno);
  if (!S_ISREG(st.st_mode)) refuseType(path, st.st_mode);
  const auto tooLarge = [&](std::uint64_t size) {
    throw InputError(path.string() + ": the " + kind.noun + " is " + mib(size) + ", more than the limit of " + mib(maxBytes) +
                     (kind.raiseWith ? std::string(" (raise it with ") + kind.raiseWith + ")" : std::string()));
  };
  if (std::uint64_t(st.st_size) > maxBytes) tooLarge(std::uint64_t(st.st_size));
  std::string bytes(std::size_t(st.st_size), '\0');
  std::size_t got = 0;
  // The file may grow while it is read: no more than the limit, and one byte more to know.
  for (;;) {
    if (got == bytes.size()) {
      if (bytes.size() > maxBytes) tooLarge(bytes.size());
      bytes.resize(std::min<std::uint64_t>(maxBytes + 1, std::max<std::uint64_t>(bytes.size() * 2, 4096)));
    }
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(path.string() + ": cannot read the " + kind.noun + ": " + std::strerror(errno));
    if (n == 0) break;
    got += std::size_t(n);
  }
  bytes.resize(got);
  return bytes;
}

}  // namespace illum

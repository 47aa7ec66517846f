// Writing an output file without ever losing what was there.
//
// What happens depends on what the path names (after following symlinks, as `cat > PATH` would):
//   - nothing yet, or a regular file with one link: the bytes go to a short temporary file beside
//     the target, which is then renamed over it (atomic: a failure leaves the old file as it was);
//     an existing file keeps its permission bits (and, for root, its owner);
//   - a character device, a FIFO, a terminal, /dev/stdout or another /proc/self/fd link, or a
//     regular file with several hard links: written in place, so the node itself survives;
//   - a read-only regular file: refused, unless `force` (then replaced, keeping its mode);
//   - a directory, a socket, a folder that does not exist: refused.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace illum {

struct OutputOptions {
  bool force = false;  // replace a read-only file (its permission bits are kept)
};

// Throws Error (exit 1, like every output failure) naming the path and the reason: a directory, a
// read-only file, a missing folder, a full disk, a device that refuses the bytes.
void writeOutputFile(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                     const OutputOptions& options = {});

}  // namespace illum

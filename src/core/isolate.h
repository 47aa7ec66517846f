// Running untrusted work (a third-party importer or decoder) in a child process with limits, the
// way desktop thumbnailers do: whatever the work does (crash, abort, loop, allocate without end),
// the caller gets an outcome it can report, never a crash of its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace illum {

struct IsolationLimits {
  std::size_t memoryBytes = std::size_t(1) << 30;  // the child's data segment (and resident size)
  double cpuSeconds = 10;                          // CPU time
  double wallSeconds = 0;                          // wall-clock time; 0: cpuSeconds
  std::size_t outputBytes = std::size_t(1) << 30;  // what the child may hand back
};

// What the child handed back, mapped from its memory file rather than copied: a big model is not
// held twice.
class MappedBytes {
 public:
  MappedBytes() = default;
  MappedBytes(int fd, std::size_t size);  // maps the first `size` bytes of `fd` read-only
  ~MappedBytes();
  MappedBytes(MappedBytes&& other) noexcept;
  MappedBytes& operator=(MappedBytes&& other) noexcept;
  MappedBytes(const MappedBytes&) = delete;
  MappedBytes& operator=(const MappedBytes&) = delete;

  const std::uint8_t* begin() const { return data_; }
  const std::uint8_t* end() const { return data_ + size_; }
  std::size_t size() const { return size_; }

 private:
  const std::uint8_t* data_ = nullptr;
  std::size_t size_ = 0;
  void* mapping_ = nullptr;
};

struct IsolationOutcome {
  enum class Kind {
    Finished,      // the work returned: `payload` holds what it wrote
    Refused,       // the work threw InputError: `message` is its text
    Failed,        // the work threw another exception: `message` is its text
    OutOfMemory,   // it needed more than the memory limit
    TimedOut,      // it ran past the CPU or wall-clock limit
    OutputTooBig,  // it tried to hand back more than the output limit
    Crashed,       // it died: `message` names the signal and the last line it printed, if any
  };
  Kind kind = Kind::Crashed;
  MappedBytes payload;
  std::string message;
};

// Writes the child's result; buffered, and bounded by IsolationLimits::outputBytes.
class IsolatedWriter {
 public:
  explicit IsolatedWriter(int fd) : fd_(fd) {}
  void write(const void* data, std::size_t size);
  void flush();

 private:
  int fd_;
  std::vector<std::uint8_t> buffer_;
};

// Runs `work` in a forked child under `limits`. The child must not touch the parent's threads or
// locks beyond what fork() makes safe: call this while the process is single-threaded, or from
// work that only allocates and reads files. With ILLUM_NO_ISOLATION=1 in the environment the work
// runs in this process (for debuggers and profilers), with the same outcomes for exceptions.
IsolationOutcome runIsolated(const std::function<void(IsolatedWriter&)>& work, const IsolationLimits& limits);

}  // namespace illum

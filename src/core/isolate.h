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

// A child that startIsolated started, running on its own while the parent does other work (a
// batch draws one picture while the next files are read); wait() watches it against its limits
// until it ends. Destroying a child that was not waited for kills it.
class IsolatedChild {
 public:
  IsolatedChild() = default;
  IsolatedChild(IsolatedChild&& other) noexcept;
  IsolatedChild& operator=(IsolatedChild&& other) noexcept;
  IsolatedChild(const IsolatedChild&) = delete;
  IsolatedChild& operator=(const IsolatedChild&) = delete;
  ~IsolatedChild();

  // How the work ended. The time limits count from the start: a child whose wall-clock deadline
  // passed while the parent was busy is killed now.
  IsolationOutcome wait();

 private:
  friend IsolatedChild startIsolated(const std::function<void(IsolatedWriter&)>& work, const IsolationLimits& limits);
  void release();

  int pid_ = -1;
  int resultFd_ = -1, logFd_ = -1;
  int doneFd_ = -1;  // the child writes its exit code here once its result is whole, before it exits
  IsolationLimits limits_;
  double deadline_ = 0;          // steady-clock seconds
  std::size_t inherited_ = 0;    // the parent's resident size at the fork
  bool ranInProcess_ = false;    // ILLUM_NO_ISOLATION: the outcome is already known
  int inProcessCode_ = 0;
};

// Starts `work` in a forked child under `limits`. Fork from the thread that owns the process's
// other threads' work, between pieces of it (the forked child must find no lock held): the main
// thread before or between renders, never a helper thread while a render runs. With
// ILLUM_NO_ISOLATION=1 in the environment the work runs here, in this process (for debuggers and
// profilers), with the same outcomes for exceptions.
IsolatedChild startIsolated(const std::function<void(IsolatedWriter&)>& work, const IsolationLimits& limits);

// startIsolated(work, limits).wait().
IsolationOutcome runIsolated(const std::function<void(IsolatedWriter&)>& work, const IsolationLimits& limits);

}  // namespace illum

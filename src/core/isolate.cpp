#include "isolate.h"

#include <illum/error.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <mutex>
#include <new>
#include <optional>
#include <sstream>
#include <thread>
#include <utility>

#include <poll.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define ILLUM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ILLUM_ASAN 1
#endif
#endif

namespace illum {
namespace {

// The child's exit codes for the ways work can end; anything else (a signal, a sanitizer's report)
// is a crash.
enum ChildExit : int { kFinished = 0, kRefused = 2, kOutOfMemory = 3, kFailed = 4, kOutputTooBig = 6 };

struct OutputLimitReached {};

// AddressSanitizer reserves terabytes of address space for its shadow, so RLIMIT_DATA cannot be
// used under it, and its quarantine and shadow inflate the resident size: the parent's watch of
// the resident size is the limit there, with room for that overhead.
#ifdef ILLUM_ASAN
constexpr bool kRlimitUsable = false;
constexpr double kResidentAllowance = 1.5;
#else
constexpr bool kRlimitUsable = true;
constexpr double kResidentAllowance = 1;
#endif

int makeMemoryFile(const char* name) {
  const int fd = ::memfd_create(name, MFD_CLOEXEC);
  if (fd < 0) throw Error(std::string("cannot create a memory file: ") + std::strerror(errno));
  return fd;
}

std::vector<std::uint8_t> readWhole(int fd) {
  struct stat st{};
  if (::fstat(fd, &st) != 0) throw Error(std::string("cannot read the isolated result: ") + std::strerror(errno));
  std::vector<std::uint8_t> bytes(std::size_t(st.st_size));
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::pread(fd, bytes.data() + done, bytes.size() - done, off_t(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error(std::string("cannot read the isolated result: ") + std::strerror(errno));
    done += std::size_t(n);
  }
  return bytes;
}

std::string asText(const std::vector<std::uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

// The line of what the child printed that best says why it died: a sanitizer's or assimp's own
// verdict if there is one, otherwise the last line.
std::string lastWords(int fd) {
  const std::string text = asText(readWhole(fd));
  std::string best, last;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    if (!line.empty()) {
      last = line;
      if (best.empty() && (line.find("ERROR:") != std::string::npos || line.find("ai_assert") != std::string::npos ||
                           line.find("what():") != std::string::npos))
        best = line;
    }
    start = end + 1;
  }
  std::string words = best.empty() ? last : best;
  words.erase(0, words.find_first_not_of(" \t"));
  if (words.size() > 200) words = words.substr(0, 200) + "…";
  return words;
}

std::size_t residentBytes(pid_t pid) {
  std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
  std::size_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * std::size_t(::sysconf(_SC_PAGESIZE));
}

// The data segment a process has now (VmData): the child's limit is on top of what it inherited.
std::size_t dataBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmData:", 0) == 0) {
      std::istringstream in(line.substr(7));
      std::size_t kib = 0;
      in >> kib;
      return kib * 1024;
    }
  return 0;
}

// CPU seconds (user + system) a process has used so far, from /proc/PID/stat.
double cpuSeconds(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  const std::size_t close = text.rfind(')');
  if (close == std::string::npos) return 0;
  std::istringstream fields(text.substr(close + 2));
  std::string field;
  unsigned long long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14) utime = std::stoull(field);
    if (i == 15) stime = std::stoull(field);
  }
  return double(utime + stime) / double(::sysconf(_SC_CLK_TCK));
}

void setLimit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit limit{soft, hard};
  ::setrlimit(resource, &limit);
}

void replaceWith(int fd, const std::string& message) {
  if (::ftruncate(fd, 0) != 0) return;
  if (::lseek(fd, 0, SEEK_SET) != 0) return;
  std::size_t done = 0;
  while (done < message.size()) {
    const ssize_t n = ::write(fd, message.data() + done, message.size() - done);
    if (n <= 0) return;
    done += std::size_t(n);
  }
}

// Runs the work and says how it ended; the message, if any, replaces the result.
int runWork(const std::function<void(IsolatedWriter&)>& work, int resultFd) {
  try {
    IsolatedWriter writer(resultFd);
    work(writer);
    writer.flush();
    return kFinished;
  } catch (const OutputLimitReached&) {
    return kOutputTooBig;
  } catch (const std::bad_alloc&) {
    return kOutOfMemory;
  } catch (const InputError& e) {
    replaceWith(resultFd, e.what());
    return kRefused;
  } catch (const std::exception& e) {
    replaceWith(resultFd, e.what());
    return kFailed;
  } catch (...) {
    replaceWith(resultFd, "an unknown exception");
    return kFailed;
  }
}

IsolationOutcome outcomeOf(int code, int resultFd) {
  IsolationOutcome o;
  switch (code) {
    case kFinished: {
      o.kind = IsolationOutcome::Kind::Finished;
      struct stat st{};
      if (::fstat(resultFd, &st) != 0) throw Error(std::string("cannot read the isolated result: ") + std::strerror(errno));
      o.payload = MappedBytes(resultFd, std::size_t(st.st_size));
      break;
    }
    case kRefused: o.kind = IsolationOutcome::Kind::Refused; o.message = asText(readWhole(resultFd)); break;
    case kFailed: o.kind = IsolationOutcome::Kind::Failed; o.message = asText(readWhole(resultFd)); break;
    case kOutOfMemory: o.kind = IsolationOutcome::Kind::OutOfMemory; break;
    case kOutputTooBig: o.kind = IsolationOutcome::Kind::OutputTooBig; break;
    default: o.kind = IsolationOutcome::Kind::Crashed; o.message = "exit status " + std::to_string(code); break;
  }
  return o;
}

[[noreturn]] void childMain(const std::function<void(IsolatedWriter&)>& work, const IsolationLimits& limits,
                            int resultFd, int logFd, int doneFd) {
  // What the importer prints (assertions, sanitizer reports) is kept for the parent's message.
  ::dup2(logFd, STDOUT_FILENO);
  ::dup2(logFd, STDERR_FILENO);
  std::signal(SIGXFSZ, SIG_IGN);  // the output limit shows as EFBIG from write(2)
  // A crash in the child is a signal the parent reads, not a report by whatever handler (a
  // sanitizer's, a fuzzer's) the parent installed.
  for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL}) std::signal(sig, SIG_DFL);
  setLimit(RLIMIT_CORE, 0, 0);
  // The parent watches CPU time to the tick; the kernel's limit, in whole seconds, is the backstop.
  const auto cpu = rlim_t(std::ceil(limits.cpuSeconds)) + 1;
  setLimit(RLIMIT_CPU, cpu, cpu + 1);
  setLimit(RLIMIT_FSIZE, rlim_t(limits.outputBytes), rlim_t(limits.outputBytes));
  if (kRlimitUsable) {
    const auto data = rlim_t(dataBytes() + limits.memoryBytes);
    setLimit(RLIMIT_DATA, data, data);
  }
  const int code = runWork(work, resultFd);
  // The result is whole: the parent may go on with it while this process's memory is torn down
  // (a few milliseconds for an importer's hundred megabytes).
  const auto byte = static_cast<unsigned char>(code);
  while (::write(doneFd, &byte, 1) < 0 && errno == EINTR) {
  }
  ::_exit(code);
}

// Children whose work is done and that are still exiting, reaped when they have (never waited
// for: the parent has gone on without them).
std::mutex exitingMutex;
std::vector<pid_t> exiting;

void reapExited() {
  const std::lock_guard lock(exitingMutex);
  std::erase_if(exiting, [](pid_t pid) {
    int status = 0;
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    return r == pid || (r < 0 && errno == ECHILD);
  });
}

void letExit(pid_t pid) {
  const std::lock_guard lock(exitingMutex);
  exiting.push_back(pid);
}

}  // namespace

MappedBytes::MappedBytes(int fd, std::size_t size) : size_(size) {
  if (size == 0) return;
  mapping_ = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
  if (mapping_ == MAP_FAILED) {
    mapping_ = nullptr;
    throw Error(std::string("cannot map the isolated result: ") + std::strerror(errno));
  }
  data_ = static_cast<const std::uint8_t*>(mapping_);
}

MappedBytes::~MappedBytes() {
  if (mapping_) ::munmap(mapping_, size_);
}

MappedBytes::MappedBytes(MappedBytes&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)),
      mapping_(std::exchange(other.mapping_, nullptr)) {}

MappedBytes& MappedBytes::operator=(MappedBytes&& other) noexcept {
  if (this != &other) {
    if (mapping_) ::munmap(mapping_, size_);
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
    mapping_ = std::exchange(other.mapping_, nullptr);
  }
  return *this;
}

void IsolatedWriter::write(const void* data, std::size_t size) {
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  buffer_.insert(buffer_.end(), bytes, bytes + size);
  if (buffer_.size() >= (std::size_t(1) << 20)) flush();
}

void IsolatedWriter::flush() {
  std::size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EFBIG) throw OutputLimitReached{};
    if (n <= 0) throw Error(std::string("cannot hand the result back: ") + std::strerror(errno));
    done += std::size_t(n);
  }
  buffer_.clear();
}

namespace {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

IsolatedChild startIsolated(const std::function<void(IsolatedWriter&)>& work, const IsolationLimits& limits) {
  IsolatedChild child;
  child.limits_ = limits;
  child.resultFd_ = makeMemoryFile("illum-result");
  child.logFd_ = makeMemoryFile("illum-log");
  if (const char* inProcess = std::getenv("ILLUM_NO_ISOLATION"); inProcess && std::string(inProcess) == "1") {
    child.ranInProcess_ = true;
    child.inProcessCode_ = runWork(work, child.resultFd_);
    return child;
  }
  reapExited();
  int done[2];
  if (::pipe2(done, O_CLOEXEC) != 0) throw Error(std::string("cannot start the isolated importer: ") + std::strerror(errno));
  std::fflush(nullptr);  // nothing buffered is written twice
  child.inherited_ = residentBytes(::getpid());
  child.deadline_ = steadySeconds() + (limits.wallSeconds > 0 ? limits.wallSeconds : limits.cpuSeconds);
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(done[0]), ::close(done[1]);
    throw Error(std::string("cannot start the isolated importer: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(done[0]);
    childMain(work, limits, child.resultFd_, child.logFd_, done[1]);
  }
  ::close(done[1]);
  child.doneFd_ = done[0];
  child.pid_ = pid;
  return child;
}

IsolationOutcome runIsolated(const std::function<void(IsolatedWriter&)>& work, const IsolationLimits& limits) {
  return startIsolated(work, limits).wait();
}

IsolatedChild::IsolatedChild(IsolatedChild&& other) noexcept { *this = std::move(other); }

IsolatedChild& IsolatedChild::operator=(IsolatedChild&& other) noexcept {
  if (this != &other) {
    release();
    pid_ = std::exchange(other.pid_, -1);
    resultFd_ = std::exchange(other.resultFd_, -1);
    logFd_ = std::exchange(other.logFd_, -1);
    doneFd_ = std::exchange(other.doneFd_, -1);
    limits_ = other.limits_;
    deadline_ = other.deadline_;
    inherited_ = other.inherited_;
    ranInProcess_ = other.ranInProcess_;
    inProcessCode_ = other.inProcessCode_;
  }
  return *this;
}

IsolatedChild::~IsolatedChild() { release(); }

void IsolatedChild::release() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
  }
  for (int* fd : {&resultFd_, &logFd_, &doneFd_})
    if (*fd >= 0) ::close(std::exchange(*fd, -1));
}

IsolationOutcome IsolatedChild::wait() {
  if (resultFd_ < 0) throw Error("the isolated work was already waited for");
  struct Release {
    IsolatedChild& child;
    ~Release() { child.release(); }
  } releaseAtEnd{*this};
  if (ranInProcess_) return outcomeOf(inProcessCode_, resultFd_);

  // Watch the child: its CPU time and the wall clock, each against its time limit (a child that
  // waits, or shares a busy machine, is held to the same promise), and its resident size (the
  // limit that works under every allocator and sanitizer).
  const auto residentLimit = inherited_ + std::size_t(double(limits_.memoryBytes) * kResidentAllowance);
  // Between looks, wait on a pidfd (readable once the child has ended) rather than sleep, so that
  // the parent goes on the moment the child is done; without pidfds (kernels before 5.3), sleep.
  auto pause = std::chrono::microseconds(200);
  // (By syscall: glibc 2.36's <sys/pidfd.h> declares pidfd_open without C linkage.)
  const int pidfd = int(::syscall(SYS_pidfd_open, pid_, 0));
  int status = 0;
  std::optional<IsolationOutcome::Kind> killedFor;
  std::optional<int> reported;  // the exit code the child sent before exiting
  for (;;) {
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_) break;
    if (!killedFor && doneFd_ >= 0) {
      pollfd notice{doneFd_, POLLIN, 0};
      unsigned char code = 0;
      if (::poll(&notice, 1, 0) == 1) {
        const ssize_t n = ::read(doneFd_, &code, 1);
        if (n == 1) {
          reported = code;
          break;
        }
        if (n == 0) ::close(std::exchange(doneFd_, -1));  // ended without a word: its exit status tells
      }
    }
    if (done < 0 && errno != EINTR) {
      if (pidfd >= 0) ::close(pidfd);
      throw Error(std::string("cannot wait for the importer: ") + std::strerror(errno));
    }
    if (!killedFor) {
      if (steadySeconds() > deadline_ || cpuSeconds(pid_) > limits_.cpuSeconds) killedFor = IsolationOutcome::Kind::TimedOut;
      else if (residentBytes(pid_) > residentLimit) killedFor = IsolationOutcome::Kind::OutOfMemory;
      if (killedFor) ::kill(pid_, SIGKILL);
    }
    if (pidfd >= 0) {
      pollfd ended[2] = {{pidfd, POLLIN, 0}, {doneFd_, POLLIN, 0}};
      ::poll(ended, doneFd_ >= 0 ? 2 : 1, int(std::chrono::duration_cast<std::chrono::milliseconds>(pause).count()) + 1);
    } else {
      std::this_thread::sleep_for(pause);
    }
    pause = std::min(pause * 2, std::chrono::microseconds(5000));
  }
  if (pidfd >= 0) ::close(pidfd);
  if (reported) {
    // Its work is done and handed back; it is reaped once it has exited (reapExited).
    letExit(std::exchange(pid_, -1));
    return outcomeOf(*reported, resultFd_);
  }
  pid_ = -1;  // reaped

  if (killedFor) {
    IsolationOutcome o;
    o.kind = *killedFor;
    return o;
  }
  if (WIFEXITED(status)) {
    IsolationOutcome o = outcomeOf(WEXITSTATUS(status), resultFd_);
    if (o.kind == IsolationOutcome::Kind::Crashed) {
      const std::string words = lastWords(logFd_);
      if (!words.empty()) o.message += ", after printing \"" + words + "\"";
    }
    return o;
  }
  IsolationOutcome o;
  const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  if (sig == SIGXCPU) {
    o.kind = IsolationOutcome::Kind::TimedOut;
    return o;
  }
  o.kind = IsolationOutcome::Kind::Crashed;
  const char* name = sig ? sigabbrev_np(sig) : nullptr;
  o.message = name ? "SIG" + std::string(name) + ", " + strsignal(sig) : "an unknown signal";
  if (const std::string words = lastWords(logFd_); !words.empty()) o.message += ", after printing \"" + words + "\"";
  return o;
}

}  // namespace illum

// Running the built `illum` binary from tests, and temporary folders for its output.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace illum::test {

namespace fs = std::filesystem;

struct RunResult {
  int exitCode = -1;
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs a shell command line; stdout and stderr are captured separately.
inline RunResult runShell(const std::string& command) {
  const fs::path errFile = fs::temp_directory_path() / ("illum_test_err_" + std::to_string(::getpid()));
  const std::string cmd = command + " 2>" + errFile.string();
  RunResult r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = slurp(errFile);
  fs::remove(errFile);
  return r;
}

// Runs `illum ARGS` through the shell.
inline RunResult runIllum(const std::string& args) { return runShell(std::string(ILLUM_CLI) + " " + args); }

class TempDir {
 public:
  TempDir() {
    // A parameterized test's name is NAME/INDEX: one directory, not a directory left behind around it.
    std::string name = testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');
    path_ = fs::temp_directory_path() / ("illum_test_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }
  std::size_t fileCount() const {
    return std::size_t(std::distance(fs::directory_iterator(path_), fs::directory_iterator()));
  }

 private:
  fs::path path_;
};

}  // namespace illum::test

#include <chrono>
#include <sys/resource.h>

namespace illum::test {

struct MeasuredRun {
  int exitCode = -1;
  std::string err;
  double seconds = 0;
  double peakMiB = 0;  // the largest resident size of illum and every process it started
};

// Runs `illum ARGS` (stdout discarded) and measures its wall time and peak memory, children
// (the isolated importer) included.
inline MeasuredRun runIllumMeasured(const std::string& args) {
  const fs::path errFile = fs::temp_directory_path() / ("illum_test_merr_" + std::to_string(::getpid()));
  const std::string cmd = "exec " + std::string(ILLUM_CLI) + " " + args + " >/dev/null 2>" + errFile.string();
  MeasuredRun r;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  ::wait4(pid, &status, 0, &usage);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peakMiB = double(usage.ru_maxrss) / 1024.0;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = slurp(errFile);
  fs::remove(errFile);
  return r;
}

}  // namespace illum::test

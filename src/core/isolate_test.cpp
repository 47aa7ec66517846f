#include "core/isolate.h"

#include <illum/error.h>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <list>
#include <sstream>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace illum {
namespace {

using Kind = IsolationOutcome::Kind;

IsolationLimits smallLimits() {
  IsolationLimits l;
  l.memoryBytes = std::size_t(256) << 20;
  l.cpuSeconds = 1;
  l.outputBytes = std::size_t(1) << 20;
  return l;
}

TEST(Isolate, HandsBackWhatTheWorkWrote) {
  const IsolationOutcome o = runIsolated([](IsolatedWriter& w) { w.write("hello", 5); }, smallLimits());
  ASSERT_EQ(o.kind, Kind::Finished) << o.message;
  EXPECT_EQ(std::string(o.payload.begin(), o.payload.end()), "hello");
}

// The outcome comes as soon as the child's result is whole, before the child has finished
// exiting; the children left exiting are reaped when the next one starts: none accumulates.
// This process's children that have not exited yet (not zombies), from /proc.
int runningChildren() {
  int running = 0;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    const auto close = line.rfind(')');  // the command name may hold spaces and parentheses
    if (close == std::string::npos) continue;
    std::istringstream rest(line.substr(close + 2));
    char state = 0;
    int parent = 0;
    rest >> state >> parent;
    if (parent == ::getpid() && state != 'Z') ++running;
  }
  return running;
}

// Waits (up to 20 s, however busy the machine) until every child has exited.
void waitForChildrenToExit() {
  for (int i = 0; i < 2000 && runningChildren() > 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(runningChildren(), 0);
}

TEST(Isolate, ChildrenLeftExitingAreReaped) {
  for (int i = 0; i < 20; ++i)
    ASSERT_EQ(runIsolated([](IsolatedWriter& w) { w.write("x", 1); }, smallLimits()).kind, Kind::Finished);
  waitForChildrenToExit();
  ASSERT_EQ(runIsolated([](IsolatedWriter& w) { w.write("y", 1); }, smallLimits()).kind, Kind::Finished);
  waitForChildrenToExit();
  // At most the last child is left to reap (none, when it had exited before its result was
  // taken): the twenty were reaped when it started.
  int status = 0, zombies = 0;
  while (::waitpid(-1, &status, WNOHANG) > 0) ++zombies;
  EXPECT_LE(zombies, 1);
}

TEST(Isolate, InputErrorIsARefusalWithItsMessage) {
  const IsolationOutcome o = runIsolated([](IsolatedWriter&) { throw InputError("file.ply: bad header"); }, smallLimits());
  EXPECT_EQ(o.kind, Kind::Refused);
  EXPECT_EQ(o.message, "file.ply: bad header");
}

TEST(Isolate, OtherExceptionsFail) {
  const IsolationOutcome o = runIsolated([](IsolatedWriter&) { throw std::runtime_error("odd"); }, smallLimits());
  EXPECT_EQ(o.kind, Kind::Failed);
  EXPECT_EQ(o.message, "odd");
}

TEST(Isolate, SegmentationFaultIsACrashNamedBySignal) {
  const IsolationOutcome o = runIsolated(
      [](IsolatedWriter&) {
        std::signal(SIGSEGV, SIG_DFL);
        std::raise(SIGSEGV);
      },
      smallLimits());
  EXPECT_EQ(o.kind, Kind::Crashed);
  EXPECT_NE(o.message.find("SIGSEGV"), std::string::npos) << o.message;
}

TEST(Isolate, AbortIsACrashWithTheLastWordsPrinted) {
  const IsolationOutcome o = runIsolated(
      [](IsolatedWriter&) {
        std::fprintf(stderr, "noise\nai_assert failure in Reader.cpp(12): x == y\n");
        std::fflush(stderr);
        std::abort();
      },
      smallLimits());
  EXPECT_EQ(o.kind, Kind::Crashed);
  EXPECT_NE(o.message.find("SIGABRT"), std::string::npos) << o.message;
  EXPECT_NE(o.message.find("ai_assert failure in Reader.cpp(12)"), std::string::npos) << o.message;
}

TEST(Isolate, EndlessAllocationIsOutOfMemoryQuickly) {
  const auto start = std::chrono::steady_clock::now();
  const IsolationOutcome o = runIsolated(
      [](IsolatedWriter&) {
        std::list<std::vector<char>> hoard;
        for (;;) hoard.emplace_back(std::size_t(1) << 20, 'x');  // touched, so resident
      },
      smallLimits());
  EXPECT_EQ(o.kind, Kind::OutOfMemory);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10);
}

TEST(Isolate, EndlessLoopTimesOut) {
  IsolationLimits limits = smallLimits();
  limits.cpuSeconds = 0.3;
  const IsolationOutcome o = runIsolated(
      [](IsolatedWriter&) {
        volatile unsigned long n = 0;
        for (;;) n = n + 1;
      },
      limits);
  EXPECT_EQ(o.kind, Kind::TimedOut);
}

TEST(Isolate, BlockedChildTimesOutByTheWallClock) {
  IsolationLimits limits = smallLimits();
  limits.cpuSeconds = 0.2;
  const auto start = std::chrono::steady_clock::now();
  const IsolationOutcome o = runIsolated([](IsolatedWriter&) { ::pause(); }, limits);
  EXPECT_EQ(o.kind, Kind::TimedOut);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5);
}

// Children started at once run side by side while the parent works, and are waited for in any
// order; one whose wall clock ran out meanwhile is stopped when it is waited for.
TEST(Isolate, ChildrenRunWhileTheParentWorks) {
  IsolationLimits limits = smallLimits();
  limits.cpuSeconds = 0.2;
  limits.wallSeconds = 0.3;
  IsolatedChild blocked = startIsolated([](IsolatedWriter&) { ::pause(); }, limits);
  IsolatedChild first = startIsolated([](IsolatedWriter& w) { w.write("one", 3); }, smallLimits());
  IsolatedChild second = startIsolated([](IsolatedWriter& w) { w.write("two", 3); }, smallLimits());
  ::usleep(400000);  // the parent's own work, past the blocked child's deadline
  const auto start = std::chrono::steady_clock::now();
  const IsolationOutcome b = blocked.wait();
  EXPECT_EQ(b.kind, Kind::TimedOut);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.2);
  const IsolationOutcome two = second.wait(), one = first.wait();
  ASSERT_EQ(two.kind, Kind::Finished);
  ASSERT_EQ(one.kind, Kind::Finished);
  EXPECT_EQ(std::string(one.payload.begin(), one.payload.end()), "one");
  EXPECT_EQ(std::string(two.payload.begin(), two.payload.end()), "two");
  // A child never waited for is stopped and reaped when dropped.
  { IsolatedChild dropped = startIsolated([](IsolatedWriter&) { ::pause(); }, smallLimits()); }
  EXPECT_THROW(first.wait(), Error);
}

TEST(Isolate, TooMuchOutputIsRefused) {
  const IsolationOutcome o = runIsolated(
      [](IsolatedWriter& w) {
        const std::vector<char> block(1 << 16, 'x');
        for (int i = 0; i < 64; ++i) w.write(block.data(), block.size());
      },
      smallLimits());
  EXPECT_EQ(o.kind, Kind::OutputTooBig);
}

}  // namespace
}  // namespace illum

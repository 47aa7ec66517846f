// The second campaign against what was added after the first (../shared/fuzz/, tests/regressions/):
// files read outside every limit, outputs that destroyed inputs or left their folder, standard
// input, memory that grew with a count, values that slipped past range checks, a batch stopped by
// one name, sequences cut short. Each test failed before its fix.
#include "cli_support.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <thread>

namespace illum {
namespace {

using test::MeasuredRun;
using test::runIllum;
using test::runIllumMeasured;
using test::runShell;
using test::slurp;
using test::TempDir;
namespace fs = std::filesystem;

#if defined(__SANITIZE_ADDRESS__)
constexpr double kSlowdown = 4;
constexpr double kMemoryGrowth = 1.5;
#else
constexpr double kSlowdown = 1;
constexpr double kMemoryGrowth = 1;
#endif

const fs::path kRegressions = ILLUM_REGRESSIONS_DIR;
const std::string kTetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";

void write(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

// Exit 2 naming `reason`, within 2 s and 1 GiB.
void expectQuickRefusal(const MeasuredRun& r, const std::string& reason) {
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
  EXPECT_LT(r.seconds, 2 * kSlowdown) << r.err;
  EXPECT_LT(r.peakMiB, 1024 * kMemoryGrowth);
}

// ---- 1. Files read outside every limit ----

TEST(FilesReadWithinLimits, ZeroSizeEnvironmentMapIsRefusedNotDividedBy) {
  TempDir dir;
  const MeasuredRun r = runIllumMeasured("render " + (kRegressions / "envmap-zero-size-sigfpe.json").string() + " -o " +
                                         (dir / "out.png").string());
  expectQuickRefusal(r, "the map has no pixels (0×0)");
  EXPECT_NE(r.err.find("/environment_map"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(FilesReadWithinLimits, TruncatedRunLengthMapIsRefusedWithAnyRenderer) {
  TempDir dir;
  for (const char* renderer : {"raster", "path"}) {
    const MeasuredRun r = runIllumMeasured("render " + (kRegressions / "envmap-truncated-rle-hang.json").string() +
                                           " --renderer " + renderer + " -o " + (dir / "out.png").string());
    expectQuickRefusal(r, "cut short");
  }
  // A run of length 0 inside a complete file: stb_image would never advance past it.
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n";
  hdr += std::string("\x02\x02\x00\x08", 4) + std::string(1, '\0') + std::string(64, '\x01');
  write(dir / "zero_run.hdr", hdr);
  write(dir / "s.json", R"({"renderer":"path","environment_map":"zero_run.hdr","objects":[{}]})");
  expectQuickRefusal(runIllumMeasured("render " + (dir / "s.json").string() + " -o " + (dir / "out.png").string()),
                     "a run of length 0");
}

TEST(FilesReadWithinLimits, FifosAreRefusedNotWaitedOn) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "scene.json").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((dir / "map.hdr").c_str(), 0600), 0);
  expectQuickRefusal(runIllumMeasured("render " + (dir / "scene.json").string() + " -o " + (dir / "a.png").string()),
                     "not a regular file (a FIFO)");
  write(dir / "s.json", R"({"renderer":"path","environment_map":"map.hdr","objects":[{}]})");
  expectQuickRefusal(runIllumMeasured("render " + (dir / "s.json").string() + " -o " + (dir / "b.png").string()),
                     "not a regular file (a FIFO)");
}

TEST(FilesReadWithinLimits, SceneJsonIsCappedInDepthSizeAndValues) {
  TempDir dir;
  write(dir / "deep.json", std::string(2'000'000, '[') + std::string(2'000'000, ']'));
  expectQuickRefusal(runIllumMeasured("render " + (dir / "deep.json").string() + " -o " + (dir / "a.png").string()),
                     "nested more than 64 arrays and objects deep (raise it with --max-json-depth)");
  std::string flood = "[";
  for (int i = 0; i < 1'000'000; ++i) flood += "[],";
  write(dir / "flood.json", flood + "[]]");
  expectQuickRefusal(runIllumMeasured("render " + (dir / "flood.json").string() + " --max-scene-size 4 -o " +
                                      (dir / "b.png").string()),
                     "JSON values (an array or object counts 4; raise it with --max-scene-size)");
  expectQuickRefusal(runIllumMeasured("render " + (dir / "flood.json").string() + " --max-scene-size 1 -o " +
                                      (dir / "c.png").string()),
                     "more than the limit of 1.0 MiB (raise it with --max-scene-size)");
}

// ---- 2. Outputs that destroy inputs or leave their folder ----

class Outputs : public testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_ / "models/a");
    fs::create_directories(dir_ / "models/c");
    fs::create_directories(dir_ / "work");
    write(dir_ / "models/a/m.obj", kTetrahedron);
    write(dir_ / "models/c/m.obj", kTetrahedron + "v 0 0 2\n");
    write(dir_ / "p.obj", kTetrahedron);
    write(dir_ / "q.obj", kTetrahedron);
  }
  test::RunResult illumIn(const std::string& folder, const std::string& args) {
    return runShell("cd '" + (dir_ / folder).string() + "' && " + std::string(ILLUM_CLI) + " " + args);
  }
  TempDir dir_;
};

TEST_F(Outputs, AnOutputNeverReplacesAnInput) {
  for (const std::string& args : {std::string("render p.obj q.obj -o '{dir}/{name}'"), std::string("render p.obj -o p.obj"),
                                  std::string("render p.obj -o ./p.obj")}) {
    const test::RunResult r = illumIn(".", args + " --resolution 32,24 -q");
    EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
    // (A model's extension is no picture's either: refused as a format illum does not write, or as
    // the input it is.)
    EXPECT_TRUE(r.err.find("an output never replaces an input") != std::string::npos ||
                r.err.find("illum does not write .obj files") != std::string::npos)
        << r.err;
    EXPECT_EQ(slurp(dir_ / "p.obj"), kTetrahedron);
    EXPECT_EQ(slurp(dir_ / "q.obj"), kTetrahedron);
  }
  // A hard link to an input is the input.
  fs::create_hard_link(dir_ / "p.obj", dir_ / "link.png");
  EXPECT_EQ(illumIn(".", "render p.obj -o link.png -q").exitCode, 2);
  EXPECT_EQ(slurp(dir_ / "p.obj"), kTetrahedron);
}

TEST_F(Outputs, AFileTheSceneReadsIsNotReplaced) {
  write(dir_ / "t.mtl", "newmtl a\nKd 1 1 1\nmap_Kd tex.png\n");
  write(dir_ / "t.obj", "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\nf 1/1 2/2 3/3\n");
  ASSERT_EQ(illumIn(".", "render --resolution 4,4 -o tex.png -q").exitCode, 0);
  const std::string texture = slurp(dir_ / "tex.png");
  const test::RunResult r = illumIn(".", "render t.obj --resolution 32,24 -o tex.png -q");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(slurp(dir_ / "tex.png"), texture);
  write(dir_ / "scene.json", R"({"width":32,"height":24,"objects":[{"mesh":{"type":"file","path":"p.obj"}}]})");
  EXPECT_EQ(illumIn(".", "render scene.json -o p.obj -q").exitCode, 2);
  EXPECT_EQ(slurp(dir_ / "p.obj"), kTetrahedron);
}

TEST_F(Outputs, TemplatedNamesStayInsideTheOutputFolder) {
  const test::RunResult r =
      illumIn("work", "render ../models/a/m.obj ../models/c/m.obj --resolution 32,24 --output-dir thumbs -o '{dir}/{stem}.png' -q");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "work/thumbs/models/a/m.png"));
  EXPECT_TRUE(fs::exists(dir_ / "work/thumbs/models/c/m.png"));
  EXPECT_FALSE(fs::exists(dir_ / "models/a/m.png"));
  // A folder named on the command line: {dir} is relative to it (the cluster examples' template).
  const test::RunResult folder =
      illumIn("work", "render " + (dir_ / "models").string() + " --resolution 32,24 --output-dir t2 -o '{dir}/{stem}.png' -q");
  EXPECT_EQ(folder.exitCode, 0) << folder.err;
  EXPECT_TRUE(fs::exists(dir_ / "work/t2/a/m.png"));
  EXPECT_EQ(illumIn("work", "render ../p.obj ../q.obj --output-dir t3 -o '../{stem}.png' -q").exitCode, 2);
  const test::RunResult absolute = illumIn("work", "render ../p.obj ../q.obj --output-dir t4 -o '/tmp/{stem}.png' -q");
  EXPECT_EQ(absolute.exitCode, 2);
  EXPECT_NE(absolute.err.find("expected one of them"), std::string::npos) << absolute.err;
}

TEST_F(Outputs, TwoJobsNeverWriteOneFileThroughALink) {
  fs::create_directories(dir_ / "sy");
  fs::create_symlink("1.png", dir_ / "sy/2.png");
  const test::RunResult r = illumIn(".", "render models/a/m.obj models/c/m.obj --resolution 32,24 -o 'sy/{n}.png' -q");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("would both be written to"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "sy/1.png"));
}

TEST(SharedFuzzScripts, OutputTemplatesNoLongerDestroyInputs) {
  const test::RunResult r = runShell("sh " + (kRegressions / "output-template-destroys-inputs-and-escapes-output-dir.sh").string() +
                                     " " + ILLUM_CLI + " 2>&1");
  EXPECT_EQ(r.out.find("PNG image data"), std::string::npos) << r.out;  // the models stay models
  EXPECT_NE(r.out.find("work/thumbs/models/a/m.png"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("work/models/"), std::string::npos) << r.out;
}

// ---- 3. Standard input ----

TEST(StandardInput, IsBoundedLeavesNothingAndSaysStandardInput) {
  TempDir dir;
  fs::create_directories(dir / "tmp");
  const std::string env = "cd '" + dir.path().string() + "' && TMPDIR='" + (dir / "tmp").string() + "' ";
  const test::RunResult endless = runShell(env + "yes 'v 1 2 3' | timeout -s KILL 20 " + ILLUM_CLI +
                                           " render - --format obj --max-stdin-size 4 -o a.png -q");
  EXPECT_EQ(endless.exitCode, 2) << endless.err;
  EXPECT_NE(endless.err.find("standard input: more than 4 MiB (raise it with --max-stdin-size)"), std::string::npos)
      << endless.err;
  const test::RunResult empty = runShell(env + ILLUM_CLI + " render - --format ply -o d.png -q </dev/null");
  EXPECT_EQ(empty.exitCode, 2);
  EXPECT_NE(empty.err.find("standard input is empty"), std::string::npos) << empty.err;
  const test::RunResult broken = runShell(env + "printf 'ply\\nformat ascii 1.0\\nelement vertex 99999\\nproperty float x\\n"
                                          "end_header\\n0\\n' | " + ILLUM_CLI + " render - --format ply -o e.png -q");
  EXPECT_EQ(broken.exitCode, 2);
  EXPECT_EQ(broken.err.rfind("illum: error: standard input: ", 0), 0u) << broken.err;
  EXPECT_EQ(broken.err.find("/proc/"), std::string::npos) << broken.err;
  EXPECT_TRUE(fs::is_empty(dir / "tmp"));
  EXPECT_FALSE(fs::exists(dir / "a.png"));
}

TEST(StandardInput, APipedSceneResolvesAgainstTheWorkingFolder) {
  TempDir dir;
  write(dir / "tri.obj", kTetrahedron);
  const test::RunResult r = runShell("cd '" + dir.path().string() + "' && printf '%s' '" +
                                     R"({"width":32,"height":24,"objects":[{"mesh":{"type":"file","path":"tri.obj"}}]})" +
                                     "' | " + ILLUM_CLI + " render - --format json -o c.png -q");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "c.png"));
}

// ---- 4. Memory that grows with a count ----

TEST(BoundedMemory, TurntableFramesAreEncodedAsTheyAreDrawn) {
  TempDir dir;
  write(dir / "m.obj", kTetrahedron);
  // 240 frames of 640×480 held at once were 295 MB of pictures alone.
  const MeasuredRun r = runIllumMeasured("render " + (dir / "m.obj").string() + " --turntable 240 --resolution 640,480 "
                                         "--samples 1 -o " + (dir / "t.gif").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
#if !defined(__SANITIZE_ADDRESS__)  // AddressSanitizer's quarantine keeps 256 MB of freed frames resident
  EXPECT_LT(r.peakMiB, 150);
#endif
  EXPECT_TRUE(fs::exists(dir / "t.gif"));
}

TEST(BoundedMemory, SheetsAndWideLinesAreCheckedBeforeDrawing) {
  TempDir dir;
  write(dir / "one.json", R"({"width":64,"height":48,"objects":[{}]})");
  expectQuickRefusal(runIllumMeasured("compare " + (dir / "one.json").string() + " --resolution 4096,4096 "
                                      "--rows shininess=1,2,3,4,5,6,7,8 --cols 'material.diffuse=1;0.9;0.8;0.7;0.6;0.5;0.4;0.3' "
                                      "-o " + (dir / "big.png").string()),
                     "the sheet would hold 64 panels of 4096×4096");
  expectQuickRefusal(runIllumMeasured("render " + (kRegressions / "lines-21k-segments.obj").string() +
                                      " --line-width 256 --samples 16 -o " + (dir / "l.png").string()),
                     "(narrower --line-width or --point-size, fewer --samples, or raise it with --max-fill)");
  EXPECT_FALSE(fs::exists(dir / "l.png"));
  // At the defaults it is drawn, in bounded time.
  const MeasuredRun drawn = runIllumMeasured("render " + (kRegressions / "lines-21k-segments.obj").string() + " -o " +
                                             (dir / "d.png").string());
  EXPECT_EQ(drawn.exitCode, 0) << drawn.err;
  EXPECT_LT(drawn.seconds, 6 * kSlowdown);
}

// ---- 5. Values ----

TEST(Values, NanInfinityAndZeroCountsAreRefused) {
  for (const char* args : {"--point-size nan", "--line-width inf", "--max-time nan", "--max-time -inf",
                           "--turntable 0", "--turntable -1", "--orbit-light -5", "--fps 0 --turntable 3"}) {
    const test::RunResult r = runIllum(std::string("render ") + args + " -o /dev/null");
    EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("expected a"), std::string::npos) << args << ": " << r.err;
  }
}

TEST(Values, HugeMemoryLimitsMeanUnlimitedNotZero) {
  TempDir dir;
  write(dir / "m.obj", kTetrahedron);
  const test::RunResult r = runIllum("render " + (dir / "m.obj").string() + " --max-memory 9000000000000 --resolution 32,24 -o " +
                                     (dir / "m.png").string() + " -q");
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

// ---- 6. A batch stopped by one name ----

TEST(JsonBatch, BytesThatAreNotUtf8NeverStopIt) {
  TempDir dir;
  const test::RunResult r = runIllum((kRegressions / "json-batch-non-utf8-texture-name").string() +
                                     " --json --resolution 32,24 --output-dir " + dir.path().string());
  EXPECT_NE(r.exitCode, 1) << r.err;
  std::istringstream lines(r.out);
  int count = 0;
  for (std::string line; std::getline(lines, line); ++count) {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << line;
    EXPECT_TRUE(j.at("ok").get<bool>()) << line;
  }
  EXPECT_EQ(count, 2) << r.out << r.err;
}

// ---- 7. Interrupted sequences ----

TEST(Interrupted, ASequenceCutShortRemovesTheFramesItWrote) {
  TempDir dir;
  write(dir / "m.obj", kTetrahedron);
  fs::create_directories(dir / "seq");
  const std::string command = "exec " + std::string(ILLUM_CLI) + " render " + (dir / "m.obj").string() +
                              " --turntable 3600 -o '" + (dir / "seq").string() + "/f_{frame:04}.png' -q 2>" +
                              (dir / "err.txt").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Wait for the first frames, then Ctrl-C.
  for (int i = 0; i < 200 && fs::is_empty(dir / "seq"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_FALSE(fs::is_empty(dir / "seq"));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 130) << slurp(dir / "err.txt");
  EXPECT_TRUE(fs::is_empty(dir / "seq"));
  EXPECT_NE(slurp(dir / "err.txt").find(" of 3600 frames (what it wrote is removed)"), std::string::npos)
      << slurp(dir / "err.txt");
}

}  // namespace
}  // namespace illum

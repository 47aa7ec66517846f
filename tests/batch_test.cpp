// Batches as a user runs them: a folder of models into thumbnails in one command, one broken file
// reported while the rest are drawn, templates, shards whose union is the whole, resuming,
// turntables as GIF and WebP, standard input, and Ctrl-C.
#include "cli_support.h"

#include <illum/image.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <set>
#include <sstream>
#include <thread>

namespace {

namespace fs = std::filesystem;
using illum::test::RunResult;
using illum::test::slurp;
using illum::test::TempDir;

RunResult run(const std::string& args) { return illum::test::runIllum(args); }

const fs::path kModels = "/usr/share/assimp/models";

// A folder with three good models (one in a subfolder) and one broken one.
fs::path modelFolder(const TempDir& dir) {
  const fs::path in = dir / "in";
  fs::create_directories(in / "sub");
  fs::copy_file(kModels / "PLY/Wuson.ply", in / "wuson.ply");
  fs::copy_file(kModels / "STL/Spider_binary.stl", in / "spider.stl");
  fs::copy_file(kModels / "OBJ/box.obj", in / "sub/box.obj");
  std::ofstream(in / "broken.ply") << "ply\nformat ascii 1.0\nelement vertex 3\n";  // no end_header
  std::ofstream(in / "notes.txt") << "not a model";
  return in;
}

std::vector<nlohmann::json> jsonLines(const std::string& out) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

TEST(CliBatch, AFolderBecomesThumbnailsAndABrokenFileLeavesTheRestDone) {
  TempDir dir;
  const fs::path in = modelFolder(dir);
  const RunResult r = run("render " + in.string() + " --resolution 96,64 --output-dir " + (dir / "thumbs").string() +
                          " -o '{n:02}_{stem}.png' --json");
  EXPECT_EQ(r.exitCode, 2) << r.err;  // something failed: a bad input
  const auto lines = jsonLines(r.out);
  ASSERT_EQ(lines.size(), 4u);  // notes.txt is not a model: not a job
  int ok = 0;
  for (const auto& l : lines) {
    if (l["ok"]) {
      ++ok;
      EXPECT_GT(l["triangles"].get<int>(), 0);
      const illum::Image thumb = illum::readPng(l["output"].get<std::string>());
      EXPECT_EQ(thumb.width, 96);
    } else {
      EXPECT_NE(l["input"].get<std::string>().find("broken.ply"), std::string::npos);
      EXPECT_NE(l["error"].get<std::string>().find("end_header"), std::string::npos) << l.dump();
    }
  }
  EXPECT_EQ(ok, 3);
  EXPECT_TRUE(fs::exists(dir / "thumbs/01_broken.png") == false);
  EXPECT_TRUE(fs::exists(dir / "thumbs/03_box.png"));  // sorted: broken, spider, sub/box, wuson
  EXPECT_NE(r.err.find("broken.ply"), std::string::npos);
  EXPECT_NE(r.err.find("1 of 4 inputs failed"), std::string::npos) << r.err;
  // --fail-fast stops at the first failure (broken.ply sorts first).
  const RunResult fast = run("render " + in.string() + " --resolution 96,64 --output-dir " + (dir / "fast").string() +
                             " --fail-fast --json");
  EXPECT_EQ(fast.exitCode, 2);
  EXPECT_EQ(jsonLines(fast.out).size(), 1u);
}

// The next models are read while one is drawn: the pictures, warnings and errors are each job's
// own, as single renders give them.
TEST(CliBatch, ModelsReadAheadGiveWhatSingleRendersGive) {
  TempDir dir;
  const std::vector<fs::path> inputs = {kModels / "PLY/Wuson.ply", kModels / "Collada/teapots.DAE",
                                        kModels / "OBJ/box.obj", kModels / "OFF/invalid.off", kModels / "STL/Spider_binary.stl"};
  std::string list;
  for (const fs::path& p : inputs) list += p.string() + " ";
  const RunResult batch = run("render " + list + "--resolution 64,48 --threads 2 --json -o '" + (dir / "{stem}.png").string() + "'");
  EXPECT_EQ(batch.exitCode, 2) << batch.err;
  const auto lines = jsonLines(batch.out);
  ASSERT_EQ(lines.size(), inputs.size());
  EXPECT_NE(lines[1]["warnings"].dump().find("fully transparent"), std::string::npos) << lines[1].dump();
  EXPECT_EQ(lines[2]["warnings"].size(), 0u) << lines[2].dump();
  EXPECT_FALSE(lines[3]["ok"].get<bool>());
  EXPECT_NE(lines[3]["error"].get<std::string>().find("invalid.off"), std::string::npos);
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (i == 3) continue;
    const fs::path single = dir / ("single" + std::to_string(i) + ".png");
    ASSERT_EQ(run("render " + inputs[i].string() + " --resolution 64,48 -o " + single.string()).exitCode, 0);
    EXPECT_EQ(slurp(single), slurp(dir / (inputs[i].stem().string() + ".png"))) << inputs[i] << "\n" << batch.err;
  }
}

TEST(CliBatch, NamesAreCheckedBeforeAnythingIsDrawn) {
  TempDir dir;
  const RunResult same = run("render " + (kModels / "PLY/Wuson.ply").string() + " " + (kModels / "STL/Wuson.stl").string() +
                             " --output-dir " + (dir / "out").string());
  EXPECT_EQ(same.exitCode, 2);
  EXPECT_NE(same.err.find("would both be written to"), std::string::npos) << same.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  const RunResult fixed = run("render " + (kModels / "PLY/Wuson.ply").string() + " " + (kModels / "STL/Wuson.stl").string() +
                              " --resolution 64,48 -q -o '" + (dir / "{ext}/{stem}.png").string() + "'");
  EXPECT_EQ(fixed.exitCode, 0) << fixed.err;
  EXPECT_TRUE(fs::exists(dir / "ply/Wuson.png"));
  EXPECT_TRUE(fs::exists(dir / "stl/Wuson.png"));
  const RunResult bad = run("render a.ply b.ply -o out.png");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("use a template"), std::string::npos) << bad.err;
  EXPECT_EQ(run("render 'nowhere/**/*.ply'").exitCode, 2);
}

TEST(CliBatch, ShardsTogetherAreTheWholeBatchByteForByte) {
  TempDir dir;
  // assimp-testmodels' PLY folder, point clouds and a truncated file included: each of those fails
  // in whichever shard it falls.
  const std::string inputs = "'" + (kModels / "PLY").string() + "/*.ply' --resolution 80,60 -q --samples 1";
  const int whole = run("render " + inputs + " --output-dir " + (dir / "all").string()).exitCode;
  EXPECT_TRUE(whole == 0 || whole == 2);
  for (int i = 0; i < 3; ++i) run("render " + inputs + " --shard " + std::to_string(i) + "/3 --output-dir " + (dir / "shards").string());
  std::set<std::string> all, shards;
  for (const auto& e : fs::directory_iterator(dir / "all")) all.insert(e.path().filename().string());
  for (const auto& e : fs::directory_iterator(dir / "shards")) shards.insert(e.path().filename().string());
  EXPECT_GE(all.size(), 5u);
  EXPECT_EQ(all, shards);
  for (const std::string& name : all) EXPECT_EQ(slurp(dir / "all" / name), slurp(dir / "shards" / name)) << name;
  EXPECT_EQ(run("render " + inputs + " --shard 3/3").exitCode, 2);
}

TEST(CliBatch, SkipExistingResumes) {
  TempDir dir;
  const fs::path in = modelFolder(dir);
  fs::remove(in / "broken.ply");
  const std::string args = "render " + in.string() + " --resolution 64,48 --output-dir " + (dir / "out").string() + " --json";
  const RunResult first = run(args);
  ASSERT_EQ(first.exitCode, 0) << first.err;
  const auto before = fs::last_write_time(dir / "out/wuson.png");
  fs::remove(dir / "out/spider.png");
  const auto lines = jsonLines(run(args + " --skip-existing").out);
  int skipped = 0;
  for (const auto& l : lines) skipped += l["skipped"].get<bool>();
  EXPECT_EQ(skipped, 2);
  EXPECT_TRUE(fs::exists(dir / "out/spider.png"));
  EXPECT_EQ(fs::last_write_time(dir / "out/wuson.png"), before);
}

TEST(CliBatch, TurntablesBecomeAnimationsOrNumberedPictures) {
  TempDir dir;
  const std::string model = (kModels / "STL/Spider_binary.stl").string();
  ASSERT_EQ(run("render " + model + " --turntable 6 --resolution 80,60 -q -o " + (dir / "spin.gif").string()).exitCode, 0);
  const std::string gif = slurp(dir / "spin.gif");
  EXPECT_EQ(gif.substr(0, 6), "GIF89a");
  std::size_t frames = 0;
  for (std::size_t at = 0; (at = gif.find("\x21\xF9\x04", at)) != std::string::npos; ++at) ++frames;  // graphic controls
  EXPECT_EQ(frames, 6u);
  ASSERT_EQ(run("render " + model + " --orbit-light 4 --resolution 80,60 -q -o " + (dir / "light.webp").string()).exitCode, 0);
  const std::string webp = slurp(dir / "light.webp");
  EXPECT_EQ(webp.substr(0, 4), "RIFF");
  EXPECT_EQ(webp.substr(8, 4), "WEBP");
  std::size_t anmf = 0;
  for (std::size_t at = 0; (at = webp.find("ANMF", at)) != std::string::npos; ++at) ++anmf;
  EXPECT_EQ(anmf, 4u);
  ASSERT_EQ(run("render " + model + " --turntable 3 --resolution 80,60 -q -o '" + (dir / "f_{frame:02}.png").string() + "'").exitCode, 0);
  for (const char* f : {"f_00.png", "f_01.png", "f_02.png"}) EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_NE(slurp(dir / "f_00.png"), slurp(dir / "f_01.png"));  // the camera moved
  const RunResult noFrame = run("render " + model + " --turntable 3 -o " + (dir / "x.png").string());
  EXPECT_EQ(noFrame.exitCode, 2);
  EXPECT_NE(noFrame.err.find("{frame}"), std::string::npos) << noFrame.err;
}

TEST(CliBatch, StandardInputWithItsFormat) {
  TempDir dir;
  const RunResult r = illum::test::runShell("cat " + (kModels / "PLY/Wuson.ply").string() + " | " + ILLUM_CLI +
                                            " render - --format ply --resolution 64,48 -q -o " + (dir / "w.png").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(illum::readPng(dir / "w.png").width, 64);
  const RunResult noFormat = illum::test::runShell("echo x | " + std::string(ILLUM_CLI) + " render - -o " + (dir / "v.png").string());
  EXPECT_EQ(noFormat.exitCode, 2);
  EXPECT_NE(noFormat.err.find("--format"), std::string::npos);
}

TEST(CliBatch, CtrlCStopsAfterThePictureInHandAndLeavesNoPartialFile) {
  TempDir dir;
  // Slow pictures: path-traced, one at a time.
  const std::string cmd = std::string(ILLUM_CLI) + " render " + (kModels / "PLY/Wuson.ply").string() + " " +
                          (kModels / "STL/Spider_binary.stl").string() + " " + (kModels / "OBJ/box.obj").string() +
                          " --renderer path --samples 256 --resolution 200,150 --threads 1 -q --output-dir " +
                          (dir / "out").string() + " 2>" + (dir / "err.txt").string() + " & echo $!";
  FILE* p = ::popen(cmd.c_str(), "r");
  char pid[32] = {};
  ASSERT_TRUE(std::fgets(pid, sizeof pid, p));
  ::pclose(p);
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  ::kill(std::stoi(pid), SIGINT);
  for (int i = 0; i < 200 && ::kill(std::stoi(pid), 0) == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const std::string err = slurp(dir / "err.txt");
  EXPECT_NE(err.find("illum: interrupted: "), std::string::npos) << err;
  EXPECT_NE(err.find(" of 3 inputs done; --skip-existing resumes"), std::string::npos) << err;
  // Whatever was written is a whole picture; nothing else is in the folder.
  std::size_t pictures = 0;
  if (fs::exists(dir / "out"))
    for (const auto& e : fs::directory_iterator(dir / "out")) {
      EXPECT_EQ(e.path().extension(), ".png") << e.path();
      EXPECT_EQ(illum::readPng(e.path()).width, 200);
      ++pictures;
    }
  EXPECT_LT(pictures, 3u);
}

}  // namespace

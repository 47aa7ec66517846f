// `illum thumbnail` as GNOME runs a thumbnailer (gnome-desktop's thumbnail script): inside
// bubblewrap with a read-only /usr, a minimal /dev, no network, no display, the input file alone
// bound into the sandbox's /tmp under a name that keeps only its extension, the output written
// there. Over every model file of Debian's assimp-testmodels: a thumbnail, or a clean failure.
#include "cli_support.h"

#include <illum/image.h>
#include <illum/import.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace illum {
namespace {

namespace fs = std::filesystem;
using test::runShell;
using test::TempDir;

const fs::path kModels = "/usr/share/assimp/models";
const fs::path kRepo = ILLUM_REPO_DIR;

// The thumbnailer's command inside the sandbox: illum from the build folder at /opt/illum.
std::string sandboxed(const fs::path& input, const fs::path& outDir, int size) {
  const fs::path cli = ILLUM_CLI;
  const std::string ext = input.extension().string(), inside = "/tmp/gnome-desktop-file-to-thumbnail" + ext;
  return "bwrap --ro-bind /usr /usr --ro-bind-try /etc/ld.so.cache /etc/ld.so.cache --symlink usr/lib /lib "
         "--symlink usr/lib64 /lib64 --symlink usr/bin /bin --symlink usr/sbin /sbin --proc /proc --dev /dev "
         "--chdir / --unshare-all --die-with-parent --clearenv --setenv PATH /usr/bin:/bin "
         "--bind '" + outDir.string() + "' /tmp --ro-bind '" + input.string() + "' '" + inside +
         "' --ro-bind '" + cli.parent_path().string() + "' /opt/illum /opt/illum/" + cli.filename().string() +
         " thumbnail '" + inside + "' /tmp/gnome-desktop-thumbnailer.png " + std::to_string(size);
}

bool sandboxWorks() { return runShell("bwrap --ro-bind /usr /usr --symlink usr/lib64 /lib64 --symlink usr/lib /lib --unshare-all /usr/bin/true").exitCode == 0; }

TEST(Thumbnailer, EveryTestModelGivesAThumbnailOrACleanFailureInTheSandbox) {
  if (!sandboxWorks()) GTEST_SKIP() << "bubblewrap cannot make a sandbox here (no user namespaces?)";
  TempDir dir;
  int drawn = 0, refused = 0;
  double slowest = 0;
  std::string slowestName;
  for (const auto& entry : fs::recursive_directory_iterator(kModels)) {
    if (!entry.is_regular_file() || !isModelFileName(entry.path())) continue;
    const fs::path out = dir / "gnome-desktop-thumbnailer.png";
    fs::remove(out);
    const auto start = std::chrono::steady_clock::now();
    const test::RunResult r = runShell(sandboxed(entry.path(), dir.path(), 128));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > slowest) slowest = seconds, slowestName = entry.path().string();
    const std::string name = entry.path().lexically_relative(kModels).string();
    // Within the budget (5 s of import) and then some: never a hang.
    EXPECT_LT(seconds, 15.0) << name;
    if (r.exitCode == 0) {
      ++drawn;
      ASSERT_TRUE(fs::exists(out)) << name;
      const Image thumbnail = readPng(out);
      EXPECT_EQ(thumbnail.width, 128) << name;
      EXPECT_EQ(thumbnail.height, 128) << name;
      EXPECT_EQ(thumbnail.pixel(0, 0)[3], 0) << name << ": the background is transparent";
      EXPECT_EQ(r.out, "") << name << ": quiet";
    } else {
      ++refused;
      EXPECT_TRUE(r.exitCode == 1 || r.exitCode == 2) << name << " exit " << r.exitCode << "\n" << r.err;
      EXPECT_EQ(r.err.rfind("illum: error: ", 0), 0u) << name << ": " << r.err;
      EXPECT_FALSE(fs::exists(out)) << name << ": a failure leaves no file";
    }
  }
  std::printf("thumbnails in the sandbox: %d drawn, %d refused; slowest %.2f s (%s)\n", drawn, refused, slowest,
              slowestName.c_str());
  EXPECT_GE(drawn, 150);
}

// The installed files say what a file manager needs: the command with its %i %o %s, and MIME types
// that the system or illum's own shared-mime-info package names.
TEST(Thumbnailer, ItsFilesNameTheCommandAndKnownTypes) {
  std::ifstream in(kRepo / "data/illum.thumbnailer");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("[Thumbnailer Entry]"), std::string::npos);
  EXPECT_NE(text.find("\nExec=illum thumbnail %i %o %s\n"), std::string::npos) << text;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(\nMimeType=([^\n]+)\n)")));
  std::ifstream system("/usr/share/mime/packages/freedesktop.org.xml"), own(kRepo / "data/illum-mime.xml");
  const std::string known = std::string((std::istreambuf_iterator<char>(system)), std::istreambuf_iterator<char>()) +
                            std::string((std::istreambuf_iterator<char>(own)), std::istreambuf_iterator<char>());
  std::stringstream types(m[1].str());
  int count = 0;
  for (std::string type; std::getline(types, type, ';');) {
    if (type.empty()) continue;
    ++count;
    EXPECT_NE(known.find("type=\"" + type + "\""), std::string::npos) << type << " is named by no MIME package";
  }
  EXPECT_GE(count, 10);
}

// Outside the sandbox, as a user would try it: a URI as input, the longest side, quiet.
TEST(Thumbnailer, TakesAFileManagersArguments) {
  TempDir dir;
  const fs::path out = dir / "thumb.png";
  const test::RunResult r = test::runIllum("thumbnail file://" + (kModels / "Collada/duck.dae").string() + " " +
                                           out.string() + " 96");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const Image thumbnail = readPng(out);
  EXPECT_EQ(thumbnail.width, 96);
  EXPECT_EQ(thumbnail.height, 96);
  EXPECT_EQ(thumbnail.pixel(0, 0)[3], 0);
  int opaque = 0;
  for (std::size_t i = 3; i < thumbnail.rgba.size(); i += 4) opaque += thumbnail.rgba[i] == 255;
  EXPECT_GT(opaque, 96 * 96 / 10) << "the duck fills its frame";
  const test::RunResult missing = test::runIllum("thumbnail " + (dir / "none.glb").string() + " " + out.string() + " 96");
  EXPECT_EQ(missing.exitCode, 2);
}

// A thumbnail is what `illum render` previews, square and transparent around the model; one whose
// model has more triangles than it has pixels is lit per vertex (its triangles are smaller than
// pixels), unless --shading says otherwise. The duck's 4,212 triangles: Phong's at 96², Gouraud's at 32².
TEST(Thumbnailer, IsTheRenderersPreviewLitPerVertexWhenTrianglesAreSmallerThanPixels) {
  TempDir dir;
  const std::string duck = (kModels / "Collada/duck.dae").string();
  const auto same = [&](const std::string& thumbnail, const std::string& render) {
    const test::RunResult t = test::runIllum("thumbnail " + duck + " " + (dir / "t.png").string() + " " + thumbnail);
    const test::RunResult r = test::runIllum("render " + duck + " --no-background -o " + (dir / "r.png").string() + " " + render);
    EXPECT_EQ(t.exitCode, 0) << t.err;
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readPng(dir / "t.png").rgba == readPng(dir / "r.png").rgba;
  };
  EXPECT_TRUE(same("96", "--resolution 96,96"));
  EXPECT_FALSE(same("96", "--resolution 96,96 --shading gouraud"));
  EXPECT_TRUE(same("32", "--resolution 32,32 --shading gouraud"));
  EXPECT_FALSE(same("32", "--resolution 32,32"));
  EXPECT_TRUE(same("32 --shading phong", "--resolution 32,32"));
}

}  // namespace
}  // namespace illum

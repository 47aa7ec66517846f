// The docs say what happens: every `sh` example in README.md and docs/*.md runs as written (with
// the built illum first on PATH, in a scratch folder that has the repository's examples/), every
// `python` example runs with the built module (Debian's /usr/bin/python3), every `cpp` example is
// compiled against the built library's public headers and runs, and where the docs show an
// example's output in the block that follows, that is the output. Every link and
// every model path the docs name exists.
#include "cli_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

const fs::path kRepo = ILLUM_REPO_DIR;

struct Block {
  std::string language;  // "sh", "" (plain: shown output), ...
  std::string text;
  int line = 0;
};

std::vector<Block> codeBlocks(const fs::path& markdown) {
  std::ifstream in(markdown);
  std::vector<Block> blocks;
  std::string line;
  bool inside = false;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("```", 0) == 0) {
      if (!inside) blocks.push_back({line.substr(3), "", number});
      inside = !inside;
      continue;
    }
    if (inside) blocks.back().text += line + "\n";
  }
  return blocks;
}

std::vector<fs::path> documents() {
  std::vector<fs::path> docs = {kRepo / "README.md"};
  for (const auto& e : fs::directory_iterator(kRepo / "docs"))
    if (e.path().extension() == ".md") docs.push_back(e.path());
  std::sort(docs.begin(), docs.end());
  return docs;
}

// Build and set-up commands are what CI itself runs; they are not examples of illum.
bool isSetUp(const std::string& script) {
  return script.find("scripts/dev.sh") != std::string::npos || script.find("cmake ") != std::string::npos;
}

// Runs an example of `language` (sh, python or cpp) in `cwd`; nullopt when this build has nothing
// to run it with (a sanitized build has no Python module, and its library links only sanitized).
std::optional<illum::test::RunResult> runExample(const std::string& language, const std::string& script, const fs::path& cwd) {
  const fs::path bin = cwd / "bin";
  fs::create_directories(bin);
  if (!fs::exists(bin / "illum")) fs::create_symlink(ILLUM_CLI, bin / "illum");
  if (!fs::exists(cwd / "examples")) fs::create_directory_symlink(kRepo / "examples", cwd / "examples");
  const std::string in = "cd '" + cwd.string() + "' && PATH='" + bin.string() + "':\"$PATH\" ";
  if (language == "sh") {
    std::ofstream(cwd / "example.sh") << "set -e\n" << script;
    return illum::test::runShell(in + "sh example.sh");
  }
  if (language == "python") {
    if (std::string(ILLUM_DOCS_PYTHON_PATH).empty()) return std::nullopt;
    std::ofstream(cwd / "example.py") << script;
    return illum::test::runShell(in + "PYTHONPATH='" + ILLUM_DOCS_PYTHON_PATH + "' /usr/bin/python3 example.py");
  }
  if (std::string(ILLUM_DOCS_LIBRARY_DIR).empty()) return std::nullopt;
  std::ofstream(cwd / "example.cpp") << script;
  const illum::test::RunResult built = illum::test::runShell(
      in + "g++ -std=c++17 -I'" + ILLUM_DOCS_PUBLIC_INCLUDE + "' example.cpp -o example -L'" + ILLUM_DOCS_LIBRARY_DIR +
      "' -lillum -Wl,-rpath,'" + ILLUM_DOCS_LIBRARY_DIR + "'");
  if (built.exitCode != 0) return built;
  return illum::test::runShell(in + "./example");
}

TEST(Docs, EveryShellExampleRunsAndShowsItsOutput) {
  int examples = 0;
  for (const fs::path& doc : documents()) {
    const std::vector<Block> blocks = codeBlocks(doc);
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      const std::string& language = blocks[i].language;
      if ((language != "sh" && language != "python" && language != "cpp") || (language == "sh" && isSetUp(blocks[i].text)))
        continue;
      const fs::path cwd = fs::temp_directory_path() / ("illum_docs_" + std::to_string(::getpid()) + "_" + std::to_string(examples++));
      fs::remove_all(cwd);
      fs::create_directories(cwd);
      const std::optional<illum::test::RunResult> run = runExample(language, blocks[i].text, cwd);
      if (!run) {
        fs::remove_all(cwd);
        continue;
      }
      const illum::test::RunResult& r = *run;
      const std::string where = doc.filename().string() + ":" + std::to_string(blocks[i].line);
      EXPECT_EQ(r.exitCode, 0) << where << "\n" << blocks[i].text << r.err;
      if (i + 1 < blocks.size() && blocks[i + 1].language.empty() && blocks[i + 1].line <= blocks[i].line + 20) {
        EXPECT_EQ(r.out, blocks[i + 1].text) << where << ": the output shown after the example";
      }
      fs::remove_all(cwd);
    }
  }
  EXPECT_GE(examples, 4);
}

TEST(Docs, EveryLinkAndModelPathExists) {
  const std::regex link(R"(\]\(([^)#\s]+)(#[^)]*)?\))");
  const std::regex model(R"((/usr/share/assimp/models/[^\s`)'"]+))");
  const std::regex example(R"((examples/[A-Za-z0-9_]+\.json))");
  for (const fs::path& doc : documents()) {
    std::ifstream in(doc);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
      const std::string target = (*it)[1];
      if (target.rfind("http", 0) == 0) continue;
      EXPECT_TRUE(fs::exists(doc.parent_path() / target)) << doc.filename() << " links to " << target;
    }
    for (std::sregex_iterator it(text.begin(), text.end(), model), end; it != end; ++it)
      EXPECT_TRUE(fs::exists(std::string((*it)[1]))) << doc.filename() << " names " << (*it)[1];
    for (std::sregex_iterator it(text.begin(), text.end(), example), end; it != end; ++it)
      EXPECT_TRUE(fs::exists(kRepo / std::string((*it)[1]))) << doc.filename() << " names " << (*it)[1];
  }
}

// Every picture the docs show is what its command draws, byte for byte, or is marked as an
// illustration and says where it comes from (docs/images/sources.txt); no picture goes unlisted.
TEST(Docs, EveryPictureIsWhatItsCommandDraws) {
  std::map<std::string, std::string> sources;  // picture → its illum arguments, or "illustration: ..."
  {
    std::ifstream in(kRepo / "docs/images/sources.txt");
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      const std::size_t colon = line.find(": ");
      ASSERT_NE(colon, std::string::npos) << "sources.txt: " << line;
      sources[line.substr(0, colon)] = line.substr(colon + 2);
    }
  }
  const std::regex image(R"(docs/images/([A-Za-z0-9_]+\.png))");
  std::set<std::string> shown;
  for (const fs::path& doc : documents()) {
    std::ifstream in(doc);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    for (std::sregex_iterator it(text.begin(), text.end(), image), end; it != end; ++it) shown.insert((*it)[1]);
  }
  for (const std::string& name : shown) EXPECT_TRUE(sources.count(name)) << name << " is not in docs/images/sources.txt";
  illum::test::TempDir dir;
  int drawn = 0;
  for (const auto& [name, source] : sources) {
    EXPECT_TRUE(fs::exists(kRepo / "docs/images" / name)) << name;
    if (source.rfind("illustration: ", 0) == 0) continue;
    const std::string out = (dir / name).string();
    const std::string args = std::regex_replace(source, std::regex(R"(\bOUT\b)"), out);
    const auto r = illum::test::runShell("cd '" + kRepo.string() + "' && " + ILLUM_CLI + " " + args + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << name << ": illum " << args << "\n" << r.err;
    EXPECT_TRUE(illum::test::slurp(out) == illum::test::slurp(kRepo / "docs/images" / name))
        << name << " is not what `illum " << source << "` draws now: run scripts/pictures.sh " << name;
    ++drawn;
  }
  EXPECT_GE(drawn, 10);
}

}  // namespace

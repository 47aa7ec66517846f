#include <illum/output_file.h>

#include <illum/error.h>

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace illum {
namespace {

namespace fs = std::filesystem;

class OutputFileTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("illum_output_" + std::to_string(::getpid()) + "_" + testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
    fs::remove_all(dir_);
  }
  static std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  static void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
  static mode_t modeOf(const fs::path& p) {
    struct stat st{};
    EXPECT_EQ(::lstat(p.c_str(), &st), 0);
    return st.st_mode;
  }
  std::size_t entries() const {
    return std::size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }
  fs::path dir_;
  const std::vector<std::uint8_t> bytes_{'n', 'e', 'w'};
};

TEST_F(OutputFileTest, NewFileGetsTheUmaskMode) {
  const mode_t old = ::umask(022);
  writeOutputFile(dir_ / "a.png", bytes_);
  ::umask(old);
  EXPECT_EQ(read(dir_ / "a.png"), "new");
  EXPECT_EQ(modeOf(dir_ / "a.png") & 07777, 0644u);
  EXPECT_EQ(entries(), 1u);  // no temporary left behind
}

TEST_F(OutputFileTest, ReplacedFileKeepsItsMode) {
  put(dir_ / "a.png", "old");
  ::chmod((dir_ / "a.png").c_str(), 0640);
  writeOutputFile(dir_ / "a.png", bytes_);
  EXPECT_EQ(read(dir_ / "a.png"), "new");
  EXPECT_EQ(modeOf(dir_ / "a.png") & 07777, 0640u);
}

TEST_F(OutputFileTest, ReadOnlyFileIsRefusedUnlessForced) {
  put(dir_ / "a.png", "old");
  ::chmod((dir_ / "a.png").c_str(), 0444);
  try {
    writeOutputFile(dir_ / "a.png", bytes_);
    FAIL() << "a read-only file was replaced";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("read-only"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--force"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(dir_ / "a.png"), "old");
  writeOutputFile(dir_ / "a.png", bytes_, OutputOptions{true});
  EXPECT_EQ(read(dir_ / "a.png"), "new");
  EXPECT_EQ(modeOf(dir_ / "a.png") & 07777, 0444u);
}

TEST_F(OutputFileTest, SymlinkIsFollowedAndKept) {
  put(dir_ / "target.png", "old");
  fs::create_symlink("target.png", dir_ / "link.png");
  writeOutputFile(dir_ / "link.png", bytes_);
  EXPECT_TRUE(S_ISLNK(modeOf(dir_ / "link.png")));
  EXPECT_EQ(read(dir_ / "target.png"), "new");
  // A dangling link creates its target, as `cat > link` would.
  fs::create_symlink("sub/made.png", dir_ / "dangling.png");
  fs::create_directory(dir_ / "sub");
  writeOutputFile(dir_ / "dangling.png", bytes_);
  EXPECT_TRUE(S_ISLNK(modeOf(dir_ / "dangling.png")));
  EXPECT_EQ(read(dir_ / "sub" / "made.png"), "new");
}

TEST_F(OutputFileTest, FifoIsWrittenInPlace) {
  const fs::path fifo = dir_ / "pipe.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = read(fifo); });
  writeOutputFile(fifo, bytes_);
  reader.join();
  EXPECT_EQ(received, "new");
  EXPECT_TRUE(S_ISFIFO(modeOf(fifo)));
}

TEST_F(OutputFileTest, ProcSelfFdLinkIsWrittenInPlace) {
  // /dev/stdout is a link to /proc/self/fd/1: writing must go into the descriptor, not replace it.
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  writeOutputFile("/proc/self/fd/" + std::to_string(fds[1]), bytes_);
  ::close(fds[1]);
  char buf[8] = {};
  EXPECT_EQ(::read(fds[0], buf, sizeof buf), 3);
  ::close(fds[0]);
  EXPECT_EQ(std::string(buf, 3), "new");
  // And a symlink of ours pointing there, like /dev/stdout.
  ASSERT_EQ(::pipe(fds), 0);
  fs::create_symlink("/proc/self/fd/" + std::to_string(fds[1]), dir_ / "stdout");
  writeOutputFile(dir_ / "stdout", bytes_);
  ::close(fds[1]);
  EXPECT_EQ(::read(fds[0], buf, sizeof buf), 3);
  ::close(fds[0]);
  EXPECT_TRUE(S_ISLNK(modeOf(dir_ / "stdout")));
}

TEST_F(OutputFileTest, HardLinkedFileIsWrittenInPlace) {
  put(dir_ / "a.png", "old");
  fs::create_hard_link(dir_ / "a.png", dir_ / "b.png");
  writeOutputFile(dir_ / "a.png", bytes_);
  EXPECT_EQ(read(dir_ / "b.png"), "new");
}

TEST_F(OutputFileTest, NameAtTheLengthLimitWorks) {
  const std::string name = std::string(251, 'x') + ".png";  // 255 bytes: NAME_MAX
  writeOutputFile(dir_ / name, bytes_);
  EXPECT_EQ(read(dir_ / name), "new");
  writeOutputFile(dir_ / name, bytes_);  // and replacing it
  EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputFileTest, DirectoriesAndMissingFoldersAreRefused) {
  EXPECT_THROW(writeOutputFile(dir_, bytes_), Error);
  try {
    writeOutputFile(dir_ / "missing" / "a.png", bytes_);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
}

TEST_F(OutputFileTest, FailedWriteLeavesTheOldFileAndNoTemporary) {
  put(dir_ / "a.png", "old");
  // A child whose file-size limit is 2 bytes: its write fails half-way, as on a full disk.
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{2, 2};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      writeOutputFile(dir_ / "a.png", std::vector<std::uint8_t>(1000, 'x'));
    } catch (const Error&) {
      ::_exit(7);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 7);
  EXPECT_EQ(read(dir_ / "a.png"), "old");
  EXPECT_EQ(entries(), 1u);
}

}  // namespace
}  // namespace illum

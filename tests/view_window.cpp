#include "view_window.h"

#include <csignal>
#include <cstdlib>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace illum::test {
namespace {

using Clock = std::chrono::steady_clock;

// A child running `argv`, its output to files (or inherited when empty), with `env` added.
pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env, const fs::path& folder,
            const fs::path& out, const fs::path& err, int keepFd = -1) {
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  if (!folder.empty() && ::chdir(folder.c_str()) != 0) ::_exit(127);
  for (const std::string& e : env) ::putenv(const_cast<char*>(e.c_str()));
  const auto redirect = [](const fs::path& to, int fd) {
    const int f = ::open(to.empty() ? "/dev/null" : to.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (f >= 0) ::dup2(f, fd), ::close(f);
  };
  redirect(out, STDOUT_FILENO);
  redirect(err, STDERR_FILENO);
  const int devNull = ::open("/dev/null", O_RDONLY);
  if (devNull >= 0) ::dup2(devNull, STDIN_FILENO);
  for (int fd = 3; fd < 1024; ++fd)
    if (fd != keepFd) ::close(fd);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  ::execvp(args[0], args.data());
  ::_exit(127);
}

void stop(pid_t pid) {
  if (pid <= 0) return;
  ::kill(pid, SIGTERM);
  for (int i = 0; i < 50; ++i) {
    if (::waitpid(pid, nullptr, WNOHANG) == pid) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace

VirtualDisplay::VirtualDisplay() {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("pipe");
  pid_ = spawn({"Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0", "1920x1080x24", "-nolisten", "tcp"}, {}, {},
               {}, {}, fds[1]);
  ::close(fds[1]);
  std::string number;
  char c = 0;
  while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
  ::close(fds[0]);
  if (number.empty()) {
    stop(pid_);
    throw std::runtime_error("Xvfb did not start (Debian's xvfb; scripts/dev.sh installs it)");
  }
  name_ = ":" + number;
}

VirtualDisplay::~VirtualDisplay() { stop(pid_); }

Viewer::Viewer(const VirtualDisplay& display, const fs::path& folder, const std::string& args)
    : display_(display), folder_(folder) {
  std::vector<std::string> argv = {ILLUM_CLI, "view"};
  // The arguments, split at spaces (the tests' paths have none).
  std::string word;
  for (char c : args + " ") {
    if (c != ' ') word += c;
    else if (!word.empty()) argv.push_back(word), word.clear();
  }
  pid_ = spawn(argv, {"DISPLAY=" + display.name()}, folder, folder / "view.out", folder / "view.err");
  // The window, once it is mapped.
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (Clock::now() < deadline) {
    const RunResult r = runShell("DISPLAY=" + display.name() + " xdotool search --onlyvisible --name '^illum view'");
    if (r.exitCode == 0 && !trimmed(r.out).empty()) {
      window_ = trimmed(r.out).substr(0, trimmed(r.out).find('\n'));
      break;
    }
    if (::waitpid(pid_, nullptr, WNOHANG) == pid_) {
      pid_ = -1;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (window_.empty()) throw std::runtime_error("no illum view window appeared; its errors: " + err());
}

Viewer::~Viewer() { stop(pid_); }

void Viewer::xdotool(const std::string& args) const {
  const RunResult r = runShell("DISPLAY=" + display_.name() + " xdotool " + args);
  if (r.exitCode != 0) throw std::runtime_error("xdotool " + args + ": " + r.err);
}

void Viewer::key(const std::string& keys) const { xdotool("windowfocus --sync " + window_ + " key --clearmodifiers " + keys); }

void Viewer::click(int x, int y) const {
  xdotool("mousemove --window " + window_ + " " + std::to_string(x) + " " + std::to_string(y) + " click 1");
}

void Viewer::drag(int x0, int y0, int x1, int y1, int button) const {
  const std::string b = std::to_string(button);
  std::string steps = "mousemove --window " + window_ + " " + std::to_string(x0) + " " + std::to_string(y0) + " mousedown " + b;
  // In steps, as a hand moves.
  for (int i = 1; i <= 8; ++i)
    steps += " sleep 0.02 mousemove --window " + window_ + " " + std::to_string(x0 + (x1 - x0) * i / 8) + " " +
             std::to_string(y0 + (y1 - y0) * i / 8);
  xdotool(steps + " mouseup " + b);
}

Image Viewer::screenshot() const {
  const fs::path shot = folder_ / "screenshot.png";
  const RunResult r = runShell("import -display " + display_.name() + " -window " + window_ + " png:" + shot.string());
  if (r.exitCode != 0) throw std::runtime_error("import (ImageMagick) failed: " + r.err);
  Image image = readPng(shot);
  fs::remove(shot);
  return image;
}

Image Viewer::waitFor(const std::function<bool(const Image&)>& ready) const {
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  Image last = screenshot();
  while (Clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    Image next = screenshot();
    if (next.width == last.width && next.height == last.height && next.rgba == last.rgba && ready(next)) return next;
    last = std::move(next);
  }
  return last;
}

int Viewer::quit() {
  // Not key(): the viewer may be gone before the key is let go, and xdotool then fails (BadWindow).
  runShell("DISPLAY=" + display_.name() + " xdotool windowfocus --sync " + window_ + " key --clearmodifiers Escape");
  int status = 0;
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  while (Clock::now() < deadline) {
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return -1;  // still running: the destructor stops it
}

Image crop(const Image& image, int width, int height) {
  Image out(width, height);
  for (int y = 0; y < height && y < image.height; ++y)
    for (int x = 0; x < width && x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      std::uint8_t* q = out.pixel(x, y);
      q[0] = p[0], q[1] = p[1], q[2] = p[2], q[3] = 255;
    }
  return out;
}

std::size_t differingPixels(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return std::size_t(-1);
  std::size_t n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
      n += p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
    }
  return n;
}

}  // namespace illum::test

// A real `illum view` window for tests: a virtual X server (Xvfb), the viewer started in it, real
// input events (xdotool, through the XTEST extension) and screenshots of the window (ImageMagick's
// import). scripts/dev.sh installs the tools.
#pragma once

#include "cli_support.h"

#include <illum/image.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace illum::test {

// Xvfb on the first free display number (it says which on a pipe: -displayfd).
class VirtualDisplay {
 public:
  VirtualDisplay();
  ~VirtualDisplay();
  VirtualDisplay(const VirtualDisplay&) = delete;
  VirtualDisplay& operator=(const VirtualDisplay&) = delete;
  const std::string& name() const { return name_; }  // ":N"

 private:
  pid_t pid_ = -1;
  std::string name_;
};

// `illum view ARGS` in `display`, its working folder `folder` (where it saves), its standard
// output and error kept.
class Viewer {
 public:
  Viewer(const VirtualDisplay& display, const fs::path& folder, const std::string& args);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // The window's screenshot: what a person sees.
  Image screenshot() const;
  // Waits (up to 30 s) until `ready` holds of a screenshot whose next one is the same (the frame
  // drawn, not one in flight); the last screenshot either way.
  Image waitFor(const std::function<bool(const Image&)>& ready) const;
  // Until the screenshot stands still.
  Image settled() const {
    return waitFor([](const Image&) { return true; });
  }

  void key(const std::string& keys) const;         // xdotool's names: "e", "Tab", "ctrl+s", "F12"
  void click(int x, int y) const;                  // left button, in window pixels
  void drag(int x0, int y0, int x1, int y1, int button = 1) const;
  // Standard output and error so far.
  std::string out() const { return slurp(folder_ / "view.out"); }
  std::string err() const { return slurp(folder_ / "view.err"); }
  // Esc, and the exit status.
  int quit();

 private:
  void xdotool(const std::string& args) const;
  const VirtualDisplay& display_;
  fs::path folder_;
  pid_t pid_ = -1;
  std::string window_;  // the X window id
};

// The top-left width × height of `image`.
Image crop(const Image& image, int width, int height);
// How many pixels of two pictures of one size differ.
std::size_t differingPixels(const Image& a, const Image& b);

}  // namespace illum::test

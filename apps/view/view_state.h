// What the viewer shows and what the person has done to it: the files stepped through, the scene
// prepared from the current one as `illum render` prepares it, the camera moved by the trackball
// (a model preview's light rig following it), f3d's toggles, and the watched pixel. State and
// actions only, no window: view_window.cpp maps input onto them, and the unit tests drive them.
#pragma once

#include <illum/scene.h>

#include "scene_options.h"
#include "trackball.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace illum::view {

// What the viewer draws over the picture and beside it.
struct Toggles {
  bool frameRate = false;  // Z: frame rate and the last frame's time
  bool help = false;       // H or ?: the list of keys
  bool panels = true;      // the panels
};

class ViewState {
 public:
  // `files` to step through (none: the built-in scene); `options` as `illum render` takes them.
  ViewState(std::vector<std::string> files, cli::SceneOptions options);

  // Reads the current file again (after it changed on disk, or to open it): the scene prepared
  // and framed anew, the person's toggles kept. Throws InputError for a file that cannot be
  // drawn; the state is then unchanged.
  void load();
  const std::vector<std::string>& files() const { return files_; }
  std::size_t index() const { return index_; }
  const std::string& current() const;
  // Steps through the files (Page Up/Down, arrows), wrapping; loads the one stepped to. False
  // when there is nothing else.
  bool step(int delta);
  // A dropped file: put after the current one and opened.
  void open(const std::string& path);

  // The scene to draw now, at the window's size.
  const Scene& scene() const { return scene_; }
  // The scene for the panels to change (lights, materials, models): every change is a new frame.
  Scene& edit() {
    ++version_;
    return scene_;
  }
  void resize(int width, int height);
  bool isModel() const { return model_; }

  Trackball& trackball() { return trackball_; }
  // After the trackball moved: the scene's camera, and a model preview's rig with it.
  void cameraMoved();
  // Whether a model preview's lights turn with the camera (they do until the person places one).
  bool lightsFollow() const { return lightsFollow_; }
  void setLightsFollow(bool follow);

  // f3d's keys.
  void toggleEdges();
  void toggleAxes();
  void toggleGrid();
  void toggleAntiAliasing();  // A: 8 samples (a preview's) or 1
  void toggleOcclusion();     // Q
  Toggles& toggles() { return toggles_; }

  // The watched pixel (a click), in picture coordinates; its report is the --debug-pixel one.
  const std::optional<std::pair<int, int>>& probe() const { return probe_; }
  void watch(int x, int y);
  void unwatch();

  // Bumped by every change: a frame drawn for an older version is out of date.
  std::uint64_t version() const { return version_; }

 private:
  void rig();
  std::vector<std::string> files_;
  std::size_t index_ = 0;
  cli::SceneOptions options_;
  cli::ModelCache cache_;
  Scene scene_;
  bool model_ = false, lightsFollow_ = false;
  // A rig light's direction in the camera's frame (right, up, towards the viewer) at framing.
  std::vector<Vec3> rigDirections_;
  Trackball trackball_;
  Toggles toggles_;
  std::optional<std::pair<int, int>> probe_;
  std::uint64_t version_ = 1;
  int width_ = 1000, height_ = 600;
};

}  // namespace illum::view

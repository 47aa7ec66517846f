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

// The terms of the lighting equation, each switched on or off so that a student sees what it adds.
// Off is said in the scene's own keys (what a saved scene holds): emission, every material's
// `emission`; global ambient, `light_model.ambient`; ambient, diffuse and specular, every light's
// colour of that term. Every model reads them so, Cook-Torrance and the tracers included.
struct Terms {
  bool emission = true, globalAmbient = true, ambient = true, diffuse = true, specular = true;
  bool all() const { return emission && globalAmbient && ambient && diffuse && specular; }
};
// `scene` with the terms that are off set to zero.
Scene withTerms(Scene scene, const Terms& terms);

// Where a light's handle is, over the picture (pixels from the top-left) and in depth (normalized
// device depth), so that a drag moves the light across the view: a positional light at its
// position, a directional one on a sphere about the focal point in its direction. A light beside
// the picture has its handle drawn at the picture's edge, towards it.
struct Handle {
  Vec2 pixel{0};  // where the light projects, perhaps outside the picture
  Vec2 shown{0};  // where the handle is drawn: `pixel`, or the nearest point a little inside the edge
  Real depth = 0;
  bool inFront = false;  // in front of the camera: otherwise it has no handle
  bool inside = false;   // `pixel` is in the picture
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
  // --renderer: a preview's display follows as `illum render MODEL --renderer R` shows it (the path
  // tracer's through ACES) unless --tone-map chose one.
  void setRenderer(RendererKind renderer);
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
  // F: environment lighting for every material, by the scene's map or illum's studio, or off
  // (as f3d's F turns its HDRI lighting on and off).
  void toggleEnvironment();
  Toggles& toggles() { return toggles_; }

  // The terms of the equation drawn (all by default).
  const Terms& terms() const { return terms_; }
  void setTerms(const Terms& terms);
  // What the window shows and a saved scene holds: the scene with the terms that are off at zero.
  Scene drawn() const { return withTerms(scene_, terms_); }

  // Light i's handle, and the light moved by a drag of (dx, dy) pixels across the view at the
  // same depth. A model preview's lights stop turning with the camera once one is placed.
  Handle handle(std::size_t light) const;
  void dragLight(std::size_t light, Real dx, Real dy);

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
  Terms terms_;
  std::optional<std::pair<int, int>> probe_;
  std::uint64_t version_ = 1;
  int width_ = 0, height_ = 0;  // the picture's size: none until the first file is read
};

}  // namespace illum::view

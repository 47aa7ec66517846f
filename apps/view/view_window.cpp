#include "view_window.h"

#include <illum/error.h>
#include <illum/image.h>

#include "key_map.h"
#include "panels.h"
#include "picture_texture.h"
#include "render_worker.h"
#include "save_view.h"
#include "view_state.h"

#include <SDL.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>
#include <ctime>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>

namespace illum::view {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

const char* kNoDisplay = "no display: illum view needs a window; use illum render";

// The window, its renderer and ImGui, torn down in order.
struct Window {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  std::unique_ptr<PictureTexture> picture;
  // The panels' strip as last drawn (drawWindowAround): what ImGui drew there and where the picture
  // and the window's edges were. The window's surface keeps it from one frame to the next.
  struct {
    std::uint64_t drawn = 0;
    SDL_Rect picture{0, 0, 0, 0};
    int width = 0, height = 0;
    bool valid = false;
  } strip;
  bool imgui = false;
  ~Window() {
    if (imgui) {
      ImGui_ImplSDLRenderer_Shutdown();
      ImGui_ImplSDL2_Shutdown();
      ImGui::DestroyContext();
    }
    picture.reset();
    if (renderer) SDL_DestroyRenderer(renderer);
    if (window) SDL_DestroyWindow(window);
    // No SDL_Quit: the process ends here, and the window and renderer, which the X server holds
    // for us, are gone. SDL_Quit would also unload the libraries SDL opened (X11's extensions,
    // D-Bus), whose own leftovers the leak checker could then no longer name (tests/lsan.supp
    // names those it can: libX11's and libdbus's).
  }
};

// When the file last changed, if it can be read.
std::optional<fs::file_time_type> changedAt(const std::string& path) {
  if (path.empty()) return std::nullopt;
  std::error_code error;
  const auto t = fs::last_write_time(path, error);
  if (error) return std::nullopt;
  return t;
}

// The light whose handle is within reach of pixel (x, y), if any: the nearest.
std::optional<std::size_t> handleAt(const ViewState& state, int x, int y) {
  std::optional<std::size_t> found;
  Real best = 10;  // pixels
  for (std::size_t i = 0; i < state.scene().lights.size(); ++i) {
    const Handle h = state.handle(i);
    const Real d = glm::length(h.shown - Vec2(Real(x), Real(y)));
    if (h.inFront && d <= best) best = d, found = i;
  }
  return found;
}

// The lights' handles: a disc in the light's diffuse colour, ringed, named as the panel names it.
void drawHandles(const ViewState& state) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  for (std::size_t i = 0; i < state.scene().lights.size(); ++i) {
    const Handle h = state.handle(i);
    if (!h.inFront) continue;
    // The light's hue at full brightness: a dim light is still seen for what colour it is.
    const Color3 d = state.scene().lights[i].diffuse;
    const Real peak = std::max({d.r, d.g, d.b});
    const Color3 c = peak > 0 ? d / peak : Color3(0.5f);
    const ImVec2 at(float(h.shown.x), float(h.shown.y));
    draw->AddCircleFilled(at, 7, IM_COL32(int(c.r * 255), int(c.g * 255), int(c.b * 255), 255), 16);
    draw->AddCircle(at, 8, IM_COL32(255, 255, 255, 230), 16, 2);
    if (!h.inside) {  // beside the picture: a line pointing towards it
      const Vec2 towards = glm::normalize(h.pixel - h.shown) * Real(14);
      draw->AddLine(at, ImVec2(at.x + float(towards.x), at.y + float(towards.y)), IM_COL32(255, 255, 255, 230), 2);
    }
    draw->AddText(ImVec2(at.x + 11, at.y - 7), IM_COL32(255, 255, 255, 230), ("light." + std::to_string(i)).c_str());
  }
}

// Fills the window but `picture`: in the panels' background colour when they are shown (they
// stand to its right), black otherwise.
void fillAround(const Window& w, const SDL_Rect& picture, bool panels) {
  int width = 0, height = 0;
  SDL_GetRendererOutputSize(w.renderer, &width, &height);
  const auto [r, g, b] = panels ? panelBackground() : std::array<unsigned char, 3>{0, 0, 0};
  SDL_SetRenderDrawBlendMode(w.renderer, SDL_BLENDMODE_NONE);
  SDL_SetRenderDrawColor(w.renderer, r, g, b, 255);
  const SDL_Rect right{picture.w, 0, width - picture.w, height};
  const SDL_Rect below{0, picture.h, picture.w, height - picture.h};
  for (const SDL_Rect& rect : {right, below})
    if (rect.w > 0 && rect.h > 0) SDL_RenderFillRect(w.renderer, &rect);
}

// Around the picture just copied to its place (`shown`): the rest of the window filled and ImGui's
// frame drawn over both. The panels' strip is only drawn again when what ImGui draws there changed
// (the window's surface keeps it): while a drag turns the view, the panels stay as they were, and
// filling and drawing them took half of presenting's own time. ImGui's lists are told apart by
// where they draw: the panels' lie wholly in the strip; the foreground list (the lights'
// handles, the watched pixel's mark: marks on the picture) is clipped to the picture; another list
// reaching into the strip (the list of keys, dragged over the edge) has it all drawn again. A
// list's place is its vertices' (the panels' clipping rectangle is the whole window).
void drawWindowAround(Window& w, const SDL_Rect& shown, bool panels) {
  ImDrawData& data = *ImGui::GetDrawData();
  const ImDrawList* foreground = ImGui::GetForegroundDrawList();
  const float right = float(shown.w);
  std::uint64_t drawn = 1469598103934665603ull;  // FNV-1a over the strip's lists
  const auto mix = [&](const void* bytes, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    for (std::size_t i = 0; i < size; ++i) drawn = (drawn ^ p[i]) * 1099511628211ull;
  };
  std::vector<ImDrawList*> onPicture;
  bool reachesStrip = false;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    ImDrawList& list = *data.CmdLists[l];
    if (&list == foreground)
      for (ImDrawCmd& cmd : list.CmdBuffer) cmd.ClipRect.z = std::min(cmd.ClipRect.z, right);
    float left = right, last = 0;  // the list's vertices' extent across
    for (const ImDrawVert& v : list.VtxBuffer) left = std::min(left, v.pos.x), last = std::max(last, v.pos.x);
    bool callback = false;
    for (const ImDrawCmd& cmd : list.CmdBuffer) callback = callback || cmd.UserCallback;
    if (left < right || callback) {
      onPicture.push_back(&list);
      reachesStrip = reachesStrip || callback || (&list != foreground && last > right);
      continue;
    }
    mix(list.VtxBuffer.Data, std::size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert));
    mix(list.IdxBuffer.Data, std::size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      mix(&cmd.ClipRect, sizeof cmd.ClipRect);
      mix(&cmd.TextureId, sizeof cmd.TextureId);
      mix(&cmd.VtxOffset, sizeof cmd.VtxOffset);
      mix(&cmd.IdxOffset, sizeof cmd.IdxOffset);
      mix(&cmd.ElemCount, sizeof cmd.ElemCount);
    }
  }
  int width = 0, height = 0;
  SDL_GetRendererOutputSize(w.renderer, &width, &height);
  mix(&panels, sizeof panels);
  const bool kept = w.strip.valid && !reachesStrip && drawn == w.strip.drawn && width == w.strip.width &&
                    height == w.strip.height && SDL_RectEquals(&shown, &w.strip.picture);
  w.strip = {drawn, shown, width, height, !reachesStrip};
  if (!kept) {
    fillAround(w, shown, panels);
    ImGui_ImplSDLRenderer_RenderDrawData(&data);
    return;
  }
  ImDrawData picture = data;
  picture.CmdLists = onPicture.data();
  picture.CmdListsCount = int(onPicture.size());
  if (picture.CmdListsCount > 0) ImGui_ImplSDLRenderer_RenderDrawData(&picture);
}

// The CPU time this thread has used, in milliseconds: presenting's own cost, apart from the
// time it waits for a core the frame's workers hold.
double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// How the frames came, for -v: how many were shown and how fast while they came one after the
// other (gaps of half a second or more, when nothing moved, are not counted: a rate taken from the
// first frame would count the wait before a drag), how long drawing and presenting took.
struct Pace {
  int frames = 0, steady = 0;  // frames shown; of them, those that followed another closely
  double drawMs = 0, presentMs = 0, presentCpuMs = 0, steadySeconds = 0;
  Clock::time_point last;
  void shown(double draw, double present, double presentCpu) {
    const auto now = Clock::now();
    if (frames++ > 0) {
      const double gap = std::chrono::duration<double>(now - last).count();
      if (gap < 0.5) ++steady, steadySeconds += gap;
    }
    last = now;
    drawMs += draw, presentMs += present, presentCpuMs += presentCpu;
  }
  void report() const {
    if (frames == 0) return;
    std::fprintf(stderr,
                 "illum view: %d frames shown, %.1f frames/s while they came one after another; drawing a frame took "
                 "%.2f ms, presenting it (texture, panels, window) %.2f ms on average, %.2f ms of them on a core\n",
                 frames, steadySeconds > 0 ? steady / steadySeconds : 0.0, drawMs / frames, presentMs / frames,
                 presentCpuMs / frames);
  }
};

// Notices go to the panel and to the terminal, where a script that drives the window reads them.
void say(PanelState& panels, const std::string& message) {
  panels.message = message;
  std::fprintf(stderr, "illum view: %s\n", message.c_str());
}

}  // namespace

int runViewer(const std::vector<std::string>& files, const cli::SceneOptions& options) {
  // A machine without a display: one clear sentence, before SDL falls back to drawing nowhere.
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland)) throw InputError(kNoDisplay);
  if (SDL_Init(SDL_INIT_VIDEO) != 0) throw InputError(kNoDisplay);
  Window w;
  const char* driver = SDL_GetCurrentVideoDriver();
  if (!driver || !std::strcmp(driver, "offscreen") || !std::strcmp(driver, "dummy")) throw InputError(kNoDisplay);

  ViewState state(files, options);
  state.load();  // the first file must draw: its error is the command's
  const Scene& first = state.scene();
  w.window = SDL_CreateWindow("illum view", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, first.width + kPanelWidth, first.height,
                              SDL_WINDOW_RESIZABLE | SDL_WINDOW_HIDDEN);
  if (!w.window) throw InputError(kNoDisplay);
  // The picture is drawn on the CPU; presenting it is a texture copy and the panels' triangles
  // (picture_texture.h chooses how).
  w.renderer = createPresentingRenderer(w.window);
  if (!w.renderer) throw Error(std::string("illum view: no renderer for the window: ") + SDL_GetError());
  w.picture = std::make_unique<PictureTexture>(w.window, w.renderer);
  // Shown only now: choosing the renderer may make the window again (SDL does for a GL one), and
  // what finds the window by its name (a window manager, a test) should find the one that stays.
  SDL_ShowWindow(w.window);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left behind
  ImGui::StyleColorsDark();
  ImGui_ImplSDL2_InitForSDLRenderer(w.window);
  ImGui_ImplSDLRenderer_Init(w.renderer);
  w.imgui = true;

  // A finished frame wakes the event loop, which otherwise sleeps until there is input.
  const Uint32 frameReady = SDL_RegisterEvents(1);
  RenderWorker worker([frameReady] {
    SDL_Event e{};
    e.type = frameReady;
    SDL_PushEvent(&e);
  });
  Pace pace;
  PanelState panels;
  Frame frame;
  bool haveFrame = false;
  std::uint64_t requested = 0;
  auto watched = changedAt(state.current());
  auto lastPoll = Clock::now(), lastFrame = Clock::now(), lastDrawn = Clock::now();
  bool redraw = true;
  double fps = 0;
  // A drag: which button, where it started and where it was last (a click is a press and release
  // that did not move).
  int dragButton = 0, downX = 0, downY = 0, lastX = 0, lastY = 0;
  bool moved = false, panning = false;
  std::optional<std::size_t> draggedLight;
  // A save waits for the final frame of what is shown; a watched pixel's report is printed once
  // its frame is drawn.
  bool savePending = false, reportPending = false;
  const auto setTitle = [&] {
    const std::string title = "illum view — " + (state.current().empty() ? std::string("the built-in scene") : state.current());
    SDL_SetWindowTitle(w.window, title.c_str());
  };
  const auto tryTo = [&](auto&& action) {
    panels.message.clear();
    try {
      action();
    } catch (const std::exception& e) {
      say(panels, e.what());  // the last good picture stays
    }
  };
  // The picture fills the window beside the panels (or the whole window without them).
  const auto layout = [&] {
    int width = 0, height = 0;
    SDL_GetWindowSize(w.window, &width, &height);
    state.resize(width - (state.toggles().panels ? kPanelWidth : 0), height);
  };
  setTitle();

  for (bool running = true; running;) {
    // ---- Input ----
    // ---- Input (or a frame ready, or a tenth of a second to look at the file) ----
    SDL_Event event;
    if (SDL_WaitEventTimeout(&event, 100)) {
      do {
        ImGui_ImplSDL2_ProcessEvent(&event);
        const ImGuiIO& io = ImGui::GetIO();
        // The window is drawn again for anything but a drag's step over the picture, whose
        // result is the next frame (drawing the window at each step would take the cores the
        // frame needs).
        redraw |= !(event.type == SDL_MOUSEMOTION && dragButton && !io.WantCaptureMouse);
        switch (event.type) {
          case SDL_QUIT: running = false; break;
          case SDL_WINDOWEVENT:
            if (event.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) layout();
            break;
          case SDL_DROPFILE: {
            const std::string path = event.drop.file;
            SDL_free(event.drop.file);
            tryTo([&] { state.open(path); });
            watched = changedAt(state.current());
            setTitle();
            break;
          }
          case SDL_MOUSEBUTTONDOWN:
            if (io.WantCaptureMouse) break;
            dragButton = event.button.button;
            draggedLight.reset();
            if (dragButton == SDL_BUTTON_LEFT && state.toggles().panels && panels.handles)
              draggedLight = handleAt(state, event.button.x, event.button.y);
            panning = dragButton == SDL_BUTTON_MIDDLE || (dragButton == SDL_BUTTON_LEFT && (SDL_GetModState() & KMOD_SHIFT));
            downX = lastX = event.button.x, downY = lastY = event.button.y;
            moved = false;
            break;
          case SDL_MOUSEMOTION: {
            if (!dragButton) break;
            const int dx = event.motion.x - lastX, dy = event.motion.y - lastY;
            lastX = event.motion.x, lastY = event.motion.y;
            if (std::abs(lastX - downX) + std::abs(lastY - downY) > 2) moved = true;
            if (!moved) break;
            if (draggedLight) {
              state.dragLight(*draggedLight, Real(dx), Real(dy));
              break;
            }
            const int height = state.scene().height;
            if (panning) state.trackball().pan(Real(dx), Real(dy), height);
            else if (dragButton == SDL_BUTTON_LEFT) state.trackball().orbit(Real(dx), Real(dy), height);
            else if (dragButton == SDL_BUTTON_RIGHT) state.trackball().zoom(std::pow(Real(1.01), Real(-dy)));
            state.cameraMoved();
            break;
          }
          case SDL_MOUSEBUTTONUP:
            if (dragButton == SDL_BUTTON_LEFT && !moved && !panning && !draggedLight) {
              state.watch(event.button.x, event.button.y);
              reportPending = state.probe().has_value();
            }
            dragButton = 0;
            draggedLight.reset();
            break;
          case SDL_MOUSEWHEEL:
            if (io.WantCaptureMouse) break;
            state.trackball().zoom(std::pow(Real(1.1), Real(event.wheel.y)));
            state.cameraMoved();
            break;
          case SDL_KEYDOWN: {
            if (io.WantCaptureKeyboard) break;
            const auto action = actionFor(event.key.keysym.sym, event.key.keysym.mod);
            if (!action) break;
            switch (*action) {
              case Action::Quit: running = false; break;
              case Action::Reset: state.trackball().reset(), state.cameraMoved(); break;
              case Action::Front: state.trackball().look(AxisView::Front), state.cameraMoved(); break;
              case Action::Back: state.trackball().look(AxisView::Back), state.cameraMoved(); break;
              case Action::Right: state.trackball().look(AxisView::Right), state.cameraMoved(); break;
              case Action::Left: state.trackball().look(AxisView::Left), state.cameraMoved(); break;
              case Action::Top: state.trackball().look(AxisView::Top), state.cameraMoved(); break;
              case Action::Bottom: state.trackball().look(AxisView::Bottom), state.cameraMoved(); break;
              case Action::Edges: state.toggleEdges(); break;
              case Action::Axes: state.toggleAxes(); break;
              case Action::Grid: state.toggleGrid(); break;
              case Action::FrameRate: state.toggles().frameRate = !state.toggles().frameRate; break;
              case Action::AntiAliasing: state.toggleAntiAliasing(); break;
              case Action::Occlusion: state.toggleOcclusion(); break;
              case Action::Environment: state.toggleEnvironment(); break;
              case Action::Help: state.toggles().help = !state.toggles().help; break;
              case Action::Panels: {
                // The window grows or shrinks by the panels: the picture keeps its size.
                state.toggles().panels = !state.toggles().panels;
                SDL_SetWindowSize(w.window, state.scene().width + (state.toggles().panels ? kPanelWidth : 0),
                                  state.scene().height);
                break;
              }
              case Action::Next:
              case Action::Previous:
                tryTo([&] { state.step(*action == Action::Next ? 1 : -1); });
                watched = changedAt(state.current());
                setTitle();
                break;
              case Action::Save: savePending = true; break;
              case Action::Unwatch: state.unwatch(); break;
            }
            break;
          }
          default: break;
        }
      } while (running && SDL_PollEvent(&event));
    }

    // ---- A file changed on disk: read again (an invalid version keeps the last good picture) ----
    if (Clock::now() - lastPoll > std::chrono::milliseconds(400)) {
      lastPoll = Clock::now();
      const auto now = changedAt(state.current());
      if (now && watched && *now != *watched) {
        watched = now;
        tryTo([&] { state.load(); });
        if (panels.message.empty()) say(panels, "reloaded " + state.current());
      }
    }

    // ---- The newest state to the worker; its newest frame to the texture ----
    if (requested != state.version()) {
      requested = state.version();
      worker.request(std::make_shared<Scene>(state.drawn()), requested, state.probe());
    }
    const auto presenting = Clock::now();
    const double presentingCpu = threadCpuMs();
    const bool fresh = worker.take(frame);  // the frame shown so far goes back to be drawn into
    if (fresh) {
      const auto now = Clock::now();
      const double seconds = std::chrono::duration<double>(now - lastFrame).count();
      lastFrame = now;
      fps = seconds > 0 ? 1 / seconds : 0;
      haveFrame = true;
      w.picture->update(frame.image);
    }
    const bool current = haveFrame && frame.final && frame.version == state.version();
    if (current && reportPending && frame.probe) {
      std::fputs(frame.report.c_str(), stdout);
      std::fflush(stdout);
      reportPending = false;
    }
    savePending |= std::exchange(panels.save, false);
    if (current && savePending) {
      savePending = false;
      tryTo([&] {
        const Saved saved = saveView(frame, panels.exr);
        say(panels, "saved " + saved.picture.string() + " and " + saved.scene.string());
      });
    }

    // ---- The window: the picture, the panels beside it ----
    redraw |= fresh || Clock::now() - lastDrawn > std::chrono::milliseconds(250);
    if (!redraw) continue;
    redraw = false;
    lastDrawn = Clock::now();
    ImGui_ImplSDLRenderer_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    ImGui::NewFrame();
    if (state.toggles().panels)
      drawPanels(state, panels, haveFrame ? &frame : nullptr, fps, state.scene().width, state.scene().height);
    if (state.toggles().panels && panels.handles) drawHandles(state);
    if (state.toggles().help) drawHelp();
    if (haveFrame && frame.probe && state.probe()) {
      // The watched pixel, marked.
      const auto [x, y] = *state.probe();
      ImGui::GetForegroundDrawList()->AddCircle(ImVec2(float(x) + 0.5f, float(y) + 0.5f), 6, IM_COL32(255, 64, 64, 255), 16, 2);
    }
    ImGui::Render();
    // The picture, opaque, over its place; only the rest of the window is filled (the panels'
    // strip in their background colour): clearing the whole window first would write every
    // pixel twice.
    SDL_Rect shown{0, 0, 0, 0};
    if (const PictureTexture& p = *w.picture; p.texture()) {
      // A tracer's quick picture (half the pixels each way) stretched over the picture's place.
      const bool quick = p.width() * 2 <= state.scene().width || p.height() * 2 <= state.scene().height;
      shown = {0, 0, quick ? state.scene().width : p.width(), quick ? state.scene().height : p.height()};
      SDL_RenderCopy(w.renderer, p.texture(), nullptr, &shown);
    }
    drawWindowAround(w, shown, state.toggles().panels);
    SDL_RenderPresent(w.renderer);
    if (fresh)
      pace.shown(frame.ms, std::chrono::duration<double, std::milli>(Clock::now() - presenting).count(),
                 threadCpuMs() - presentingCpu);
  }
  if (options.verbose) pace.report();
  return 0;
}

}  // namespace illum::view

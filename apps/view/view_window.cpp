#include "view_window.h"

#include <illum/error.h>
#include <illum/image.h>

#include "key_map.h"
#include "panels.h"
#include "render_worker.h"
#include "view_state.h"

#include <SDL.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>

namespace illum::view {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

const char* kNoDisplay = "no display: illum view needs a window; use illum render";

// The window, its renderer and ImGui, torn down in order.
struct Window {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  SDL_Texture* texture = nullptr;
  int textureWidth = 0, textureHeight = 0;
  bool imgui = false;
  ~Window() {
    if (imgui) {
      ImGui_ImplSDLRenderer_Shutdown();
      ImGui_ImplSDL2_Shutdown();
      ImGui::DestroyContext();
    }
    if (texture) SDL_DestroyTexture(texture);
    if (renderer) SDL_DestroyRenderer(renderer);
    if (window) SDL_DestroyWindow(window);
    SDL_Quit();
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

// The first name illum_view_N.png that is free, in the working folder.
fs::path pictureName() {
  for (int n = 1;; ++n) {
    const fs::path p = "illum_view_" + std::to_string(n) + ".png";
    if (!fs::exists(p)) return p;
  }
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
  w.window = SDL_CreateWindow("illum view", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, first.width, first.height,
                              SDL_WINDOW_RESIZABLE);
  if (!w.window) throw InputError(kNoDisplay);
  w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_ACCELERATED | SDL_RENDERER_PRESENTVSYNC);
  if (!w.renderer) w.renderer = SDL_CreateRenderer(w.window, -1, 0);
  if (!w.renderer) throw Error(std::string("illum view: no renderer for the window: ") + SDL_GetError());
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left behind
  ImGui::StyleColorsDark();
  ImGui_ImplSDL2_InitForSDLRenderer(w.window);
  ImGui_ImplSDLRenderer_Init(w.renderer);
  w.imgui = true;

  RenderWorker worker;
  PanelState panels;
  Frame frame;
  bool haveFrame = false;
  std::uint64_t requested = 0;
  auto watched = changedAt(state.current());
  auto lastPoll = Clock::now(), lastFrame = Clock::now();
  double fps = 0;
  // A drag: which button, where it started and where it was last (a click is a press and release
  // that did not move).
  int dragButton = 0, downX = 0, downY = 0, lastX = 0, lastY = 0;
  bool moved = false, panning = false;
  const auto setTitle = [&] {
    const std::string title = "illum view — " + (state.current().empty() ? std::string("the built-in scene") : state.current());
    SDL_SetWindowTitle(w.window, title.c_str());
  };
  const auto tryTo = [&](auto&& action) {
    try {
      action();
      panels.message.clear();
    } catch (const std::exception& e) {
      panels.message = e.what();  // the last good picture stays
    }
  };
  setTitle();

  for (bool running = true; running;) {
    // ---- Input ----
    SDL_Event event;
    const bool idle = !worker.busy() && requested == state.version();
    if (SDL_WaitEventTimeout(&event, idle ? 50 : 1)) {
      do {
        ImGui_ImplSDL2_ProcessEvent(&event);
        const ImGuiIO& io = ImGui::GetIO();
        switch (event.type) {
          case SDL_QUIT: running = false; break;
          case SDL_WINDOWEVENT:
            if (event.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) state.resize(event.window.data1, event.window.data2);
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
            const int height = state.scene().height;
            if (panning) state.trackball().pan(Real(dx), Real(dy), height);
            else if (dragButton == SDL_BUTTON_LEFT) state.trackball().orbit(Real(dx), Real(dy), height);
            else if (dragButton == SDL_BUTTON_RIGHT) state.trackball().zoom(std::pow(Real(1.01), Real(-dy)));
            state.cameraMoved();
            break;
          }
          case SDL_MOUSEBUTTONUP:
            if (dragButton == SDL_BUTTON_LEFT && !moved && !panning) state.watch(event.button.x, event.button.y);
            dragButton = 0;
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
              case Action::Environment: panels.message = "F: illum has no environment lighting yet"; break;
              case Action::Help: state.toggles().help = !state.toggles().help; break;
              case Action::Panels: state.toggles().panels = !state.toggles().panels; break;
              case Action::Next:
              case Action::Previous:
                tryTo([&] { state.step(*action == Action::Next ? 1 : -1); });
                watched = changedAt(state.current());
                setTitle();
                break;
              case Action::Save:
                if (haveFrame) {
                  const fs::path name = pictureName();
                  tryTo([&] { writePng(name, frame.image); });
                  if (panels.message.empty()) panels.message = "saved " + name.string();
                }
                break;
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
      }
    }

    // ---- The newest state to the worker; its newest frame to the texture ----
    if (requested != state.version()) {
      requested = state.version();
      worker.request(std::make_shared<Scene>(state.scene()), requested, state.probe());
    }
    Frame next;
    if (worker.take(next)) {
      const auto now = Clock::now();
      const double seconds = std::chrono::duration<double>(now - lastFrame).count();
      lastFrame = now;
      fps = seconds > 0 ? 1 / seconds : 0;
      frame = std::move(next);
      haveFrame = true;
      if (!w.texture || w.textureWidth != frame.image.width || w.textureHeight != frame.image.height) {
        if (w.texture) SDL_DestroyTexture(w.texture);
        w.texture = SDL_CreateTexture(w.renderer, SDL_PIXELFORMAT_ABGR8888, SDL_TEXTUREACCESS_STREAMING,
                                      frame.image.width, frame.image.height);
        w.textureWidth = frame.image.width, w.textureHeight = frame.image.height;
      }
      SDL_UpdateTexture(w.texture, nullptr, frame.image.rgba.data(), frame.image.width * 4);
    }

    // ---- The window: the picture, the panels over it ----
    ImGui_ImplSDLRenderer_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    ImGui::NewFrame();
    if (state.toggles().panels) drawPanels(state, panels, haveFrame ? &frame : nullptr, fps);
    if (state.toggles().help) drawHelp();
    if (haveFrame && frame.probe && state.probe()) {
      // The watched pixel, marked.
      const auto [x, y] = *state.probe();
      ImGui::GetForegroundDrawList()->AddCircle(ImVec2(float(x) + 0.5f, float(y) + 0.5f), 6, IM_COL32(255, 64, 64, 255), 16, 2);
    }
    ImGui::Render();
    SDL_SetRenderDrawColor(w.renderer, 0, 0, 0, 255);
    SDL_RenderClear(w.renderer);
    if (w.texture) {
      const SDL_Rect to{0, 0, w.textureWidth, w.textureHeight};
      SDL_RenderCopy(w.renderer, w.texture, nullptr, &to);
    }
    ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
    SDL_RenderPresent(w.renderer);
  }
  return 0;
}

}  // namespace illum::view

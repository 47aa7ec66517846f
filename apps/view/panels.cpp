#include "panels.h"

#include "key_map.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace illum::view {
namespace {

bool color3(const char* label, Color3& c) {
  float v[3] = {float(c.r), float(c.g), float(c.b)};
  if (!ImGui::ColorEdit3(label, v, ImGuiColorEditFlags_Float)) return false;
  c = Color3(Real(v[0]), Real(v[1]), Real(v[2]));
  return true;
}

bool color4(const char* label, Color4& c) {
  float v[4] = {float(c.r), float(c.g), float(c.b), float(c.a)};
  if (!ImGui::ColorEdit4(label, v, ImGuiColorEditFlags_Float)) return false;
  c = Color4(Real(v[0]), Real(v[1]), Real(v[2]), Real(v[3]));
  return true;
}

bool drag3(const char* label, Vec3& p, float speed, float lo = 0, float hi = 0) {
  float v[3] = {float(p.x), float(p.y), float(p.z)};
  if (!ImGui::DragFloat3(label, v, speed, lo, hi)) return false;
  p = Vec3(Real(v[0]), Real(v[1]), Real(v[2]));
  return true;
}

bool slider(const char* label, Real& x, float lo, float hi, const char* format = "%.3f") {
  float v = float(x);
  if (!ImGui::SliderFloat(label, &v, lo, hi, format)) return false;
  x = Real(v);
  return true;
}

// A combo over a closed set, by the names the CLI takes.
template <class T, std::size_t N>
bool combo(const char* label, T& value, const std::array<T, N>& values) {
  bool changed = false;
  if (ImGui::BeginCombo(label, std::string(toString(value)).c_str())) {
    for (const T& v : values)
      if (ImGui::Selectable(std::string(toString(v)).c_str(), v == value)) value = v, changed = true;
    ImGui::EndCombo();
  }
  return changed;
}

void scenePanel(ViewState& state) {
  const Scene& s = state.scene();
  ImGui::TextUnformatted(state.current().empty() ? "the built-in scene" : state.current().c_str());
  if (state.files().size() > 1) ImGui::Text("file %zu of %zu (Page Up/Down)", state.index() + 1, state.files().size());
  RendererKind renderer = s.renderer;
  if (combo("renderer (--renderer)", renderer,
            std::array{RendererKind::Raster, RendererKind::Whitted, RendererKind::Hall, RendererKind::Path}))
    state.setRenderer(renderer);
  LightingModel model = s.model;
  if (combo("model (--model)", model,
            std::array{LightingModel::Wylie, LightingModel::Bouknight, LightingModel::Lambert, LightingModel::Phong,
                       LightingModel::BlinnPhong, LightingModel::CookTorrance})) {
    // As --model: every material's own model too.
    Scene& e = state.edit();
    e.model = model;
    for (Object& o : e.objects) o.material.model.reset();
  }
  Shading shading = s.shading;
  if (combo("shading (--shading)", shading, std::array{Shading::Flat, Shading::Gouraud, Shading::Phong}))
    state.edit().shading = shading;
  // GL's equation or a lecture note's way of computing it (lighting.h).
  Convention convention = s.lightModel.convention;
  if (combo("convention (--convention)", convention, std::to_array(kConventions)))
    state.edit().lightModel.convention = convention;
  if (s.renderer == RendererKind::Raster) {
    int samples = s.multisample;
    const std::array counts{1, 4, 8, 16};
    if (ImGui::BeginCombo("samples (--samples)", std::to_string(samples).c_str())) {
      for (int n : counts)
        if (ImGui::Selectable(std::to_string(n).c_str(), n == samples)) state.edit().multisample = n;
      ImGui::EndCombo();
    }
    bool occlusion = s.ambientOcclusion.enabled;
    if (ImGui::Checkbox("ambient occlusion (--ambient-occlusion, Q)", &occlusion)) state.toggleOcclusion();
  } else {
    int rays = samplesPerPixel(s);
    if (ImGui::SliderInt("samples (--samples)", &rays, 1, 1024, "%d", ImGuiSliderFlags_Logarithmic))
      state.edit().rayTracing.samples = rays;
    int depth = s.rayTracing.maxDepth;
    if (ImGui::SliderInt("ray depth (--max-depth)", &depth, 0, 16)) state.edit().rayTracing.maxDepth = depth;
    bool shadows = s.rayTracing.shadows;
    if (ImGui::Checkbox("shadows (--no-shadows)", &shadows)) state.edit().rayTracing.shadows = shadows;
  }
  bool environment = s.environment.lighting == EnvironmentLighting::All;
  if (ImGui::Checkbox("environment lighting (--environment, F)", &environment)) state.toggleEnvironment();
  if (s.rayTracing.environmentMap) {
    float rotation = float(s.environment.rotation);
    if (ImGui::SliderFloat("rotation (--environment-rotation)", &rotation, -180, 180, "%.0f°"))
      state.edit().environment.rotation = Real(rotation);
    float intensity = float(s.rayTracing.environment.g);
    if (ImGui::SliderFloat("intensity (--environment-intensity)", &intensity, 0, 4, "%.2f"))
      state.edit().rayTracing.environment = Color3(Real(intensity));
    EnvironmentBackground background = s.environment.background;
    const std::array backgrounds{EnvironmentBackground::None, EnvironmentBackground::Sharp, EnvironmentBackground::Blurred};
    if (combo("background (--environment-background)", background, backgrounds))
      state.edit().environment.background = background;
  }
  bool edges = s.overlays.edges, grid = s.overlays.grid, axes = s.overlays.axes;
  if (ImGui::Checkbox("edges (E)", &edges)) state.toggleEdges();
  ImGui::SameLine();
  if (ImGui::Checkbox("grid (G)", &grid)) state.toggleGrid();
  ImGui::SameLine();
  if (ImGui::Checkbox("axes (X)", &axes)) state.toggleAxes();
  if (state.isModel()) {
    bool follow = state.lightsFollow();
    if (ImGui::Checkbox("lights turn with the camera", &follow)) state.setLightsFollow(follow);
  }
}

// Each term of the equation on or off, so that a student sees what it adds.
void termsPanel(ViewState& state) {
  Terms t = state.terms();
  bool changed = ImGui::Checkbox("emission (materials' emission)", &t.emission);
  changed |= ImGui::Checkbox("global ambient (light_model.ambient)", &t.globalAmbient);
  changed |= ImGui::Checkbox("ambient (lights' ambient)", &t.ambient);
  changed |= ImGui::Checkbox("diffuse (lights' diffuse)", &t.diffuse);
  changed |= ImGui::Checkbox("specular (lights' specular)", &t.specular);
  if (changed) state.setTerms(t);
}

void lightPanel(ViewState& state, PanelState& panels) {
  const Scene& s = state.scene();
  ImGui::Checkbox("handles in the picture (drag to move)", &panels.handles);
  panels.parked.resize(s.lights.size());
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    ImGui::PushID(int(i));
    const std::string title = "light." + std::to_string(i);
    bool on = !panels.parked[i];
    if (ImGui::Checkbox("##on", &on)) {
      Light& l = state.edit().lights[i];
      if (on) {
        l = *panels.parked[i];
        panels.parked[i].reset();
      } else {
        panels.parked[i] = l;
        l.ambient = l.diffuse = l.specular = Color3(0);
      }
    }
    ImGui::SameLine();
    if (ImGui::TreeNode(title.c_str())) {
      Light l = panels.parked[i] ? *panels.parked[i] : s.lights[i];
      bool changed = false;
      int kind = l.position.w == 0 ? 0 : 1;
      if (ImGui::RadioButton("directional", &kind, 0) || ImGui::RadioButton("positional", &kind, 1)) {
        l.position.w = Real(kind), changed = true;
      }
      Vec3 p(l.position);
      const bool follows = state.isModel() && state.lightsFollow();
      if (follows) ImGui::BeginDisabled();
      if (drag3(kind ? "position" : "direction", p, 0.02f)) l.position = Vec4(p, l.position.w), changed = true;
      if (follows) ImGui::EndDisabled();
      changed |= color3("ambient", l.ambient);
      changed |= color3("diffuse", l.diffuse);
      changed |= color3("specular", l.specular);
      if (kind) {
        changed |= drag3("attenuation (c, l, q)", l.attenuation, 0.005f, 0, 100);
        float cutoff = float(l.spotCutoff);
        if (ImGui::SliderFloat("spot cutoff (180: none)", &cutoff, 0, 180, "%.1f°")) {
          l.spotCutoff = Real(cutoff > 90 ? 180 : cutoff), changed = true;
        }
        if (l.spotCutoff != 180) {
          changed |= slider("spot exponent", l.spotExponent, 0, 128, "%.1f");
          changed |= drag3("spot direction", l.spotDirection, 0.02f);
        }
      }
      if (changed) {
        if (panels.parked[i]) panels.parked[i] = l;
        else state.edit().lights[i] = l;
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

void materialPanel(ViewState& state) {
  const Scene& s = state.scene();
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    ImGui::PushID(int(i));
    const std::string title = "object." + std::to_string(i) + ".material";
    if (ImGui::TreeNode(title.c_str())) {
      Material m = s.objects[i].material;
      bool changed = false;
      if (m.physicallyBased) {
        PhysicalMaterial p = m.physical;
        bool pbr = color3("base colour", p.baseColor);
        pbr |= slider("metallic", p.metallic, 0, 1);
        pbr |= slider("roughness", p.roughness, 0, 1);
        if (pbr) glFromPhysical(m, p), changed = true;
        changed |= color4("emission", m.emission);
      } else {
        changed |= color4("ambient", m.ambient);
        changed |= color4("diffuse", m.diffuse);
        changed |= color4("specular", m.specular);
        changed |= color4("emission", m.emission);
        changed |= slider("shininess", m.shininess, 0, 256, "%.1f");
      }
      if (changed) state.edit().objects[i].material = m;
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

}  // namespace

void drawPanels(ViewState& state, PanelState& panels, const Frame* frame, double fps, int left, int height) {
  ImGui::SetNextWindowPos(ImVec2(float(left), 0));
  ImGui::SetNextWindowSize(ImVec2(float(kPanelWidth), float(height)));
  ImGui::Begin("illum view", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBackground);
  ImGui::PushItemWidth(float(kPanelWidth) * 0.42f);  // room for the labels, which name the keys and options
  scenePanel(state);
  if (ImGui::CollapsingHeader("lights")) lightPanel(state, panels);
  if (ImGui::CollapsingHeader("materials")) materialPanel(state);
  if (ImGui::CollapsingHeader("terms of the equation")) termsPanel(state);
  if (ImGui::Button("save picture and scene (F12)")) panels.save = true;
  ImGui::SameLine();
  ImGui::Checkbox("as OpenEXR", &panels.exr);
  if (frame && frame->probe) {
    if (ImGui::CollapsingHeader("watched pixel (--debug-pixel)", ImGuiTreeNodeFlags_DefaultOpen)) {
      ImGui::BeginChild("report", ImVec2(0, 260), true, ImGuiWindowFlags_HorizontalScrollbar);
      ImGui::TextUnformatted(frame->report.c_str());
      ImGui::EndChild();
    }
  } else {
    ImGui::TextDisabled("click a pixel to see its equation");
  }
  if (frame && state.toggles().frameRate)
    ImGui::Text("%.1f frames/s, last frame %.1f ms, %d sample%s", fps, frame->ms, frame->samples,
                frame->samples == 1 ? "" : "s");
  if (!panels.message.empty()) ImGui::TextWrapped("%s", panels.message.c_str());
  ImGui::PopItemWidth();
  ImGui::End();
}

std::array<unsigned char, 3> panelBackground() {
  const ImVec4 c = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  const auto over = [&](float v) { return static_cast<unsigned char>(std::lround(std::clamp(v * c.w, 0.0f, 1.0f) * 255)); };
  return {over(c.x), over(c.y), over(c.z)};
}

void drawHelp() {
  ImGui::SetNextWindowPos(ImVec2(400, 8), ImGuiCond_FirstUseEver);
  ImGui::Begin("keys (H)");
  for (const KeyHelp& k : keyHelp()) {
    ImGui::TextUnformatted(k.keys.data(), k.keys.data() + k.keys.size());
    ImGui::SameLine(210);
    ImGui::TextUnformatted(k.what.data(), k.what.data() + k.what.size());
  }
  ImGui::End();
}

}  // namespace illum::view

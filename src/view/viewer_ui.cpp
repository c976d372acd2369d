#include "view/viewer_ui.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "settings/fields.h"
#include "view/overlays.h"

namespace proxygi::view {

void FrameTimes::add(double ms) {
  ms_[next_] = ms;
  next_ = (next_ + 1) % kCount;
  count_ = std::min(count_ + 1, kCount);
}
double FrameTimes::mean() const {
  double sum = 0.0;
  for (std::size_t i = 0; i < count_; ++i) sum += ms_[i];
  return count_ ? sum / double(count_) : 0.0;
}
double FrameTimes::min() const { return count_ ? *std::min_element(ms_.begin(), ms_.begin() + count_) : 0.0; }
double FrameTimes::max() const { return count_ ? *std::max_element(ms_.begin(), ms_.begin() + count_) : 0.0; }
std::vector<float> FrameTimes::ordered() const {
  std::vector<float> out;
  for (std::size_t i = 0; i < count_; ++i) out.push_back(float(ms_[(next_ + kCount - count_ + i) % kCount]));
  return out;
}

void SteadyTimes::add(double ms) {
  if (skipped_ < warmup_) {
    ++skipped_;
    return;
  }
  min_ = frames_ ? std::min(min_, ms) : ms;
  max_ = frames_ ? std::max(max_, ms) : ms;
  sum_ += ms;
  ++frames_;
}

namespace {

constexpr float kSettingsWidth = 352.0f;

constexpr const char* kKeyMap[][2] = {
    {"orbit", "left drag (middle drag too)"},   {"pan", "right drag, Shift+left, Shift+middle"},
    {"zoom", "wheel; Ctrl+middle drag"},        {"frame all", "Home (also F)"},
    {"scene / free camera", "C"},               {"play / pause; reverse", "Space; Shift+Ctrl+Space"},
    {"step -1 / +1 frame (pauses)", "Left / Right"}, {"step -10 / +10 frames", "Down / Up"},
    {"jump to start / end", "Shift+Left / Shift+Right (End)"}, {"speed - / + / reset", "- / = / Backspace"},
    {"loop-once / ping-pong", "L / P"},         {"screenshot (with UI / without)", "F12 / Ctrl+F12"},
    {"bones, proxies, wireframe, grid", "B, O, W, G"}, {"next / previous view", "V / Shift+V"}, {"HUD / whole UI", "H / F10"},
    {"help / quit", "F1 / Esc"},
};

void draw_hud(UiContext& ui, UiRequests& requests) {
  const HudInfo& hud = ui.hud;
  const Playback& playback = ui.core.state().playback;
  ImGui::SetNextWindowPos({8, 8}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.6f);
  ImGui::Begin("HUD", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  const double mean = ui.times.mean();
  ImGui::Text("%.1f fps   frame %.1f ms (min %.1f, max %.1f over %zu frames)", mean > 0 ? 1000.0 / mean : 0.0, mean,
              ui.times.min(), ui.times.max(), ui.times.size());
  const auto plot = ui.times.ordered();
  if (!plot.empty()) ImGui::PlotLines("##times", plot.data(), int(plot.size()), 0, nullptr, 0.0f, float(ui.times.max() * 1.2), {260, 40});
  ImGui::Text("display %ux%u  internal %ux%u  %s  (swapchain rebuilt %d)", hud.display_width, hud.display_height,
              hud.internal_width, hud.internal_height, hud.present.c_str(), hud.swapchain_recreations);
  ImGui::Text("proxies %zu  receivers %llu  triangles %zu", hud.proxies, (unsigned long long)hud.receivers, hud.triangles);
  ImGui::Text("%s (%s)", hud.device.c_str(), hud.driver.c_str());
  ImGui::Text("time %.3f s  frame %d of %d..%d at %g fps  speed %gx %s", playback.time_s, playback.frame(),
              playback.first_frame, playback.last_frame, playback.fps, playback.speed * playback.direction,
              std::string(loop_mode_name(playback.loop)).c_str());
  if (ui.world) {
    std::string clips = "clips:";
    for (const auto& instance : ui.world->instances()) {
      const auto& character = instance.model->character;
      const bool posed = instance.clip >= 0 && instance.clip < int(character.clips.size());
      clips.append(" ").append(instance.model->file.filename().string()).append(":");
      clips.append(posed ? character.clips[std::size_t(instance.clip)].name : std::string("rest"));
      if (clips.size() > 120) {
        clips += " ...";
        break;
      }
    }
    ImGui::TextUnformatted(clips.c_str());
  }
  if (!hud.quality.empty()) {
    ImGui::TextUnformatted(hud.quality.c_str());
    for (const std::string& reason : hud.quality_reasons) ImGui::Text("  %s", reason.c_str());
  }
  // Closed by default: the HUD stays small (on a CPU device every pixel the UI covers is blended
  // over each frame); the times keep being measured while it is closed.
  if (ImGui::CollapsingHeader("pass times")) {
    if (!hud.passes.empty()) {
      ImGui::Text("%s:", hud.pass_clock.c_str());
      for (const PassTime& pass : hud.passes) ImGui::Text("  %-20s %7.2f ms", pass.name.c_str(), pass.ms);
    }
    if (ImGui::SmallButton("time passes")) requests.time_passes = true;
  }
  ImGui::End();
}

void draw_playback(UiContext& ui, UiRequests& requests) {
  ViewerCore& core = ui.core;
  Playback& playback = core.state().playback;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({8, display.y - 92}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({std::max(display.x - kSettingsWidth - 24, 200.0f), 84}, ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.6f);
  ImGui::Begin("Playback", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize);
  if (ImGui::Button(playback.playing ? "Pause" : "Play")) playback.playing = !playback.playing;
  ImGui::SameLine();
  if (ImGui::Button("|<")) core.seek(playback.start_s());
  ImGui::SameLine();
  if (ImGui::Button("<")) core.step_frames(-1);
  ImGui::SameLine();
  if (ImGui::Button(">")) core.step_frames(1);
  ImGui::SameLine();
  if (ImGui::Button(">|")) core.seek(playback.end_s());
  ImGui::SameLine();
  bool reverse = playback.direction < 0;
  if (ImGui::Checkbox("reverse", &reverse)) playback.direction = reverse ? -1 : 1;
  ImGui::SameLine();
  ImGui::Checkbox("fixed step", &playback.fixed_step);
  ImGui::SameLine();
  int loop = int(playback.loop);
  ImGui::SetNextItemWidth(100);
  if (ImGui::Combo("##loop", &loop, "loop\0once\0ping-pong\0")) playback.loop = LoopMode(loop);
  ImGui::SameLine();
  float speed = float(playback.speed);
  ImGui::SetNextItemWidth(120);
  if (ImGui::SliderFloat("speed", &speed, 1.0f / 16, 16.0f, "%.3gx", ImGuiSliderFlags_Logarithmic)) playback.speed = speed;
  ImGui::SameLine();
  ImGui::Checkbox("free camera (C)", &core.state().free_camera);
  ImGui::SameLine();
  if (ImGui::Button("Screenshot (F12)")) requests.screenshot = true;
  int frame = playback.frame();
  ImGui::SetNextItemWidth(-1);
  char label[64];
  std::snprintf(label, sizeof label, "frame %%d  (%.3f s)", playback.time_s);
  if (ImGui::SliderInt("##timeline", &frame, playback.first_frame, playback.last_frame, label)) {
    playback.playing = false;  // dragging the timeline pauses
    playback.time_s = frame / playback.fps;
  }
  ImGui::End();
}

// One widget per settings field: the table says the kind, the range and the choices.
void draw_settings(UiContext& ui) {
  settings::RenderSettings& values = ui.core.state().settings;
  for (const settings::Field& field : settings::fields()) {
    const std::string key(field.key);
    double value = field.get(values);
    bool changed = false;
    switch (field.kind) {
      case settings::FieldKind::boolean: {
        bool on = value != 0.0;
        changed = ImGui::Checkbox(key.c_str(), &on);
        value = on ? 1.0 : 0.0;
        break;
      }
      case settings::FieldKind::integer: {
        int v = int(value);
        if (!field.allowed.empty()) {
          const std::string current = std::to_string(v);
          if (ImGui::BeginCombo(key.c_str(), current.c_str())) {
            for (int allowed : field.allowed)
              if (ImGui::Selectable(std::to_string(allowed).c_str(), allowed == v)) v = allowed, changed = true;
            ImGui::EndCombo();
          }
        } else {
          changed = ImGui::SliderInt(key.c_str(), &v, int(field.min), int(field.max));
        }
        value = v;
        break;
      }
      case settings::FieldKind::real: {
        if (field.accepts_auto) {  // "auto" as a checkbox; unticked, the default number
          bool automatic = settings::is_auto(field, value);
          if (ImGui::Checkbox((key + " auto").c_str(), &automatic)) {
            value = automatic ? double(settings::kEtaFromLighting) : field.get(settings::RenderSettings{});
            changed = true;
          }
          if (automatic) break;
        }
        if (!field.named.empty()) {  // the names as a combo ("manual", "balanced", ...); a number below
          const auto current = settings::value_name(field, value);
          if (ImGui::BeginCombo(key.c_str(), current ? std::string(*current).c_str() : "target")) {
            for (const settings::NamedValue& named : field.named)
              if (ImGui::Selectable(std::string(named.name).c_str(), named.value == value)) value = named.value, changed = true;
            ImGui::EndCombo();
          }
          if (settings::check_number(field, value)) break;  // a sentinel ("manual"): no number to slide
        }
        float v = float(value);
        changed = ImGui::SliderFloat((field.named.empty() ? key : key + " target").c_str(), &v, float(field.ui_min),
                                     float(field.ui_max), "%.3g") || changed;
        value = v;
        break;
      }
      case settings::FieldKind::choice: {
        const int v = int(value);
        if (ImGui::BeginCombo(key.c_str(), std::string(settings::choice_name(field, v)).c_str())) {
          for (const settings::Choice& choice : field.choices)
            if (ImGui::Selectable(std::string(choice.name).c_str(), choice.value == v)) value = choice.value, changed = true;
          ImGui::EndCombo();
        }
        break;
      }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(field.description).c_str());
    if (changed && !settings::check_value(field, value)) field.set(values, value);
  }
}

void draw_scene_panel(UiContext& ui, UiRequests& requests) {
  scene::Scene& scene = *ui.scene;
  if (ui.world) {
    for (std::size_t i = 0; i < ui.world->instances().size(); ++i) {
      const auto& instance = ui.world->instances()[i];
      const auto& clips = instance.model->character.clips;
      if (clips.empty()) continue;
      const std::string label = "clip of character " + std::to_string(i);
      const int current = std::clamp(instance.clip, 0, int(clips.size()) - 1);
      if (ImGui::BeginCombo(label.c_str(), clips[current].name.c_str())) {
        for (int c = 0; c < int(clips.size()); ++c)
          if (ImGui::Selectable((std::to_string(c) + ": " + clips[c].name).c_str(), c == current) && c != current &&
              instance.scene_character < scene.characters.size()) {
            scene.characters[instance.scene_character].clip = scene::ClipRef{std::in_place_type<int>, c};
            requests.reload = true;
          }
        ImGui::EndCombo();
      }
    }
  }
  scene::Environment& environment = scene.environment;
  bool edited = false;
  edited |= ImGui::SliderFloat("env intensity", &environment.intensity, 0.0f, 4.0f);
  edited |= ImGui::SliderFloat("env rotation", &environment.rotation_degrees, -180.0f, 180.0f);
  if (environment.type == scene::Environment::Type::sky) {
    edited |= ImGui::SliderFloat("sun elevation", &environment.sun.elevation_degrees, -10.0f, 90.0f);
    edited |= ImGui::SliderFloat("sun azimuth", &environment.sun.azimuth_degrees, -180.0f, 180.0f);
    edited |= ImGui::SliderFloat("sun size", &environment.sun.angular_radius_degrees, 0.25f, 20.0f);
  }
  // Environment edits reload the world (its SH projection), on release, not per drag step.
  static bool pending = false;
  if (edited) pending = true;
  if (pending && !ImGui::IsAnyItemActive()) requests.reload = true, pending = false;
  if (ui.adaptive) ImGui::Checkbox("adaptive internal resolution", ui.adaptive);
  ImGui::InputText("##open", ui.open_path);
  ImGui::SameLine();
  if (ImGui::Button("Open")) requests.open = *ui.open_path;
  ImGui::InputText("##save", ui.save_path);
  ImGui::SameLine();
  if (ImGui::Button("Save scene")) requests.save = *ui.save_path;
}

// The heat map's ramp, as upsample_composite.comp's heat_color (t = count / proxies).
ImVec4 heat_color(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  auto band = [t](float center) { return std::clamp(1.5f - std::abs(4.0f * t - center), 0.0f, 1.0f); };
  return {band(3.0f), band(2.0f), band(1.0f), 1.0f};
}

// What the chosen view shows, and the heat map's legend (0 .. all proxies of the frame).
void draw_view_legend(UiContext& ui) {
  const ViewerState& state = ui.core.state();
  const settings::RenderSettings& render = state.settings;
  const bool receiver_views = render.method != settings::ShadingMethod::vertex;
  const bool tiles = render.method == settings::ShadingMethod::ambient_occlusion ||
                     (render.method == settings::ShadingMethod::image_space && render.splat == settings::SplatMethod::compute);
  const View view = state.view;
  if (view == View::final || view == View::albedo || view == View::normals) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({8, display.y - 100}, ImGuiCond_Always, {0.0f, 1.0f});
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("view legend", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("view: %s", std::string(view_name(view)).c_str());
  if ((view == View::direct || view == View::indirect || view == View::occlusion) && !receiver_views) {
    ImGui::TextUnformatted("not for the vertex method: the final frame is shown");
  } else if (view == View::occlusion) {
    ImGui::TextUnformatted("black: sphere of directions fully occluded, white: unoccluded");
  } else if (view == View::heat_map && !tiles) {
    ImGui::TextUnformatted("needs the tile lists of splat=compute (image method) or method=ao: the final frame is shown");
  } else if (view == View::heat_map) {
    const std::size_t proxies = ui.hud.proxies;
    ImGui::Text("proxies kept per %dx%d-pixel tile (shadow eta %.3g), of %zu", 8 * render.receiver_scale,
                8 * render.receiver_scale, ui.hud.shadow_eta, proxies);
    ImDrawList& list = *ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    constexpr int kSteps = 64;
    constexpr float kWidth = 256.0f, kHeight = 14.0f;
    for (int i = 0; i < kSteps; ++i) {
      const float x0 = origin.x + kWidth * float(i) / kSteps, x1 = origin.x + kWidth * float(i + 1) / kSteps;
      list.AddRectFilled({x0, origin.y}, {x1 + 0.5f, origin.y + kHeight},
                         ImGui::GetColorU32(heat_color((float(i) + 0.5f) / kSteps)));
    }
    ImGui::Dummy({kWidth, kHeight});
    ImGui::Text("left: 0, right: %zu (every proxy); tiles that keep none are untinted", proxies);
  }
  ImGui::End();
}

void draw_help() {
  ImGui::SetNextWindowPos({300, 60}, ImGuiCond_FirstUseEver);
  ImGui::Begin("Keys (F1)");
  for (const auto& row : kKeyMap) ImGui::Text("%-32s %s", row[0], row[1]);
  ImGui::TextUnformatted("Files dropped on the window open: scene .json, .glb/.gltf, .hdr/.exr");
  ImGui::End();
}

}  // namespace

UiRequests draw_ui(UiContext& ui) {
  UiRequests requests;
  ViewerState& state = ui.core.state();
  if (ui.state) draw_overlays(ui.core.camera(), ui.world, *ui.state, state.toggles, ui.hud.shadow_eta);
  if (state.toggles.hud) draw_hud(ui, requests);
  draw_playback(ui, requests);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({display.x - kSettingsWidth - 8, 8}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize({kSettingsWidth, std::max(display.y - 16, 100.0f)}, ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::SetNextWindowCollapsed(display.x < 800.0f, ImGuiCond_FirstUseEver);  // small windows: the frame first
  ImGui::Begin("Settings");
  if (ImGui::CollapsingHeader("render", ImGuiTreeNodeFlags_DefaultOpen)) draw_settings(ui);
  if (ImGui::CollapsingHeader("scene", ImGuiTreeNodeFlags_DefaultOpen) && ui.scene) draw_scene_panel(ui, requests);
  if (ImGui::CollapsingHeader("view", ImGuiTreeNodeFlags_DefaultOpen)) {
    int view = int(state.view);
    for (int v = 0; v < kViewCount; ++v) {
      if (ImGui::RadioButton(std::string(view_name(View(v))).c_str(), &view, v)) state.view = View(v);
      if (v % 2 == 0 && v + 1 < kViewCount) ImGui::SameLine();
    }
  }
  if (ImGui::CollapsingHeader("overlays")) {
    ImGui::Checkbox("proxies (O)", &state.toggles.proxies);
    ImGui::Checkbox("skeleton (B)", &state.toggles.bones);
    ImGui::Checkbox("grid (G)", &state.toggles.grid);
    ImGui::Checkbox("wireframe (W, x-ray)", &state.toggles.wireframe);
    ImGui::Checkbox("influence shells (eta r)", &state.toggles.shells);
    // Selecting a joint highlights its spheres (the bones that carry proxies, per model).
    const std::string none = "(no joint selected)";
    if (ui.world && ImGui::BeginCombo("joint", state.toggles.selected_bone.empty() ? none.c_str() : state.toggles.selected_bone.c_str())) {
      if (ImGui::Selectable(none.c_str(), state.toggles.selected_bone.empty())) state.toggles.selected_bone.clear();
      std::vector<std::string> bones;
      for (const auto& model : ui.world->models())
        for (const auto& sphere : model->rig.spheres)
          if (std::find(bones.begin(), bones.end(), sphere.bone) == bones.end()) bones.push_back(sphere.bone);
      for (const std::string& bone : bones)
        if (ImGui::Selectable(bone.c_str(), bone == state.toggles.selected_bone)) {
          state.toggles.selected_bone = bone;
          state.toggles.proxies = true;
        }
      ImGui::EndCombo();
    }
  }
  ImGui::End();
  if (!ui.hud.loading.empty() || !state.message.empty() || !state.notice.empty()) {
    ImGui::SetNextWindowPos({display.x * 0.5f, 8}, ImGuiCond_Always, {0.5f, 0.0f});
    ImGui::Begin("status", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::PushTextWrapPos(std::max(display.x * 0.6f, 200.0f));
    if (!ui.hud.loading.empty()) ImGui::TextUnformatted(ui.hud.loading.c_str());
    if (!state.notice.empty()) ImGui::TextUnformatted(state.notice.c_str());
    if (!state.message.empty()) {
      ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", state.message.c_str());
      if (ImGui::SmallButton("dismiss")) state.message.clear();
    }
    ImGui::PopTextWrapPos();
    ImGui::End();
  }
  if (state.toggles.help) draw_help();
  draw_view_legend(ui);
  return requests;
}

}  // namespace proxygi::view

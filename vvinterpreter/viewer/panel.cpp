#include "viewer/panel.hpp"

#include <imgui.h>
#include <imgui_internal.h>  // the window's content extent (see content_changed_size)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace vvi {

namespace {

constexpr float panel_margin = 10;  // between the panel and the window's edges

// Whether the panel's content this frame needs another size than the
// content of the frame before. Dear ImGui sizes an auto-resizing window from
// the frame before's content, so on such a frame the window has the old
// size: grown content would be cut off at the bottom (or the right).
bool content_changed_size() {
  ImGuiWindow* w = ImGui::GetCurrentWindow();
  ImVec2 extent(std::max(w->DC.CursorMaxPos.x, w->DC.IdealMaxPos.x) - w->DC.CursorStartPos.x,
                std::max(w->DC.CursorMaxPos.y, w->DC.IdealMaxPos.y) - w->DC.CursorStartPos.y);
  ImGuiStorage* kept = ImGui::GetStateStorage();
  ImGuiID x = ImGui::GetID("##content width"), y = ImGui::GetID("##content height");
  bool changed = std::abs(kept->GetFloat(x, -1) - extent.x) >= 0.5f || std::abs(kept->GetFloat(y, -1) - extent.y) >= 0.5f;
  kept->SetFloat(x, extent.x);
  kept->SetFloat(y, extent.y);
  return changed;
}

// Save checkpoint (the next free vv_checkpoint_NNN.ckpt), and Resume...:
// a popup naming the file to go on from, the last one saved or any the
// user types. Beside Step, so the panel grows by no row.
void draw_checkpoints(const panel_state& s, panel_actions& a) {
  static char file[512] = "";
  static std::string offered;
  if (s.last_checkpoint != offered) {
    offered = s.last_checkpoint;
    std::snprintf(file, sizeof file, "%s", offered.c_str());
  }
  if (ImGui::Button("Save checkpoint")) a.add(command::of(command::checkpoint));
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("save the model's whole state, to go on from it later");
  ImGui::SameLine();
  if (ImGui::Button("Resume...")) ImGui::OpenPopup("Resume");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("go on from a checkpoint: the last one saved, or a file you name");
  if (!ImGui::BeginPopup("Resume")) return;
  ImGui::SetNextItemWidth(260);
  ImGui::InputText("checkpoint file", file, sizeof file);
  bool none = !file[0];
  if (none) ImGui::BeginDisabled();
  if (ImGui::Button("Resume")) {
    a.add(command::with_path(command::resume, file));
    ImGui::CloseCurrentPopup();
  }
  if (none) ImGui::EndDisabled();
  ImGui::EndPopup();
}

// The panel, once; `changed_size`: its content needs another size than
// the window had.
panel_actions draw_panel_once(const panel_state& s, bool& changed_size) {
  panel_actions a;
  changed_size = false;
  ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(panel_margin, panel_margin), ImGuiCond_FirstUseEver);
  // Never taller than the window: what does not fit scrolls.
  ImGui::SetNextWindowSizeConstraints(ImVec2(300, 0), ImVec2(520, std::max(100.0f, display.y - 2 * panel_margin)));
  bool open = ImGui::Begin("vv", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  a.panel_collapsed = !open;
  a.panel_right = ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
  if (!open) {
    ImGui::End();
    return a;
  }
  ImGui::TextUnformatted(s.model.c_str());
  ImGui::TextDisabled("%s", s.status.c_str());
  ImGui::Separator();
  auto button = [&a](const char* label, command::kind_t k) {
    if (ImGui::Button(label)) a.add(command::of(k));
  };
  if (!s.running.empty()) {
    ImGui::TextColored(ImVec4(0.8f, 0.45f, 0.0f, 1), "%s", s.running.c_str());
    button("Stop (Esc)", command::stop);
    ImGui::SameLine();
    ImGui::TextDisabled("restarts the model");
    ImGui::Separator();
  }
  bool disabled = !s.has_model || s.busy;
  if (disabled) ImGui::BeginDisabled();
  button("Step", command::step);
  ImGui::SameLine();
  button(("Run " + std::to_string(s.run_steps)).c_str(), command::run);
  ImGui::SameLine();
  if (s.animating) {
    button("Stop", command::stop);
  } else {
    if (!s.can_animate) ImGui::BeginDisabled();
    button("Animate", command::animate);
    if (!s.can_animate) ImGui::EndDisabled();
  }
  ImGui::SameLine();
  draw_checkpoints(s, a);
  button("Rewind", command::rewind);
  ImGui::SameLine();
  button("End", command::end);
  ImGui::SameLine();
  button("Reread files", command::reread);
  ImGui::SameLine();
  draw_record(s, a);
  if (disabled) ImGui::EndDisabled();
  button("Recompile", command::recompile);
  ImGui::SameLine();
  button("Fit view", command::fit);
  ImGui::SameLine();
  button("Screenshot", command::screenshot);
  ImGui::SameLine();
  if (disabled) ImGui::BeginDisabled();
  button("Save session", command::save_session);
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("write what was done to the model, for --replay");
  if (disabled) ImGui::EndDisabled();
  bool replay = s.replay;
  if (ImGui::Checkbox("After a reload or restart, run again to the step", &replay))
    a.add(command::switched(command::replay, "", replay));
  ImGui::Separator();
  ImGui::Text("step %u", s.steps);
  if (s.steps > 0) ImGui::Text("last step: %.2f ms", s.last_step_ms);
  for (const auto& [name, count] : s.meshes) ImGui::Text("mesh %s: %zu vertices", name.c_str(), count);
  for (const std::string& r : s.recording) ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "recording %s", r.c_str());
  if (!s.message.empty()) ImGui::TextDisabled("%s", s.message.c_str());
  if (!s.error.empty()) {
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.85f, 0.15f, 0.1f, 1));
    ImGui::TextWrapped("%s", s.error.c_str());
    ImGui::PopStyleColor();
  }
  if (!s.warnings.empty() && ImGui::CollapsingHeader("Compiler warnings")) ImGui::TextWrapped("%s", s.warnings.c_str());
  draw_inspector(s, a);
  draw_actions(s, a);
  draw_parameters(s, a);
  draw_plots(s);
  draw_display(s, a);
  ImGui::Separator();
  ImGui::TextDisabled("drag: rotate   right-drag: pan   wheel: zoom");
  ImGui::TextDisabled("space: step  a: animate  w: rewind  f: fit  s: screenshot");
  ImGui::TextDisabled("shift+click: the model's pick block on a vertex");
  ImGui::TextDisabled("ctrl+click: pick a vertex  esc: stop  ctrl+q: quit");
  changed_size = content_changed_size();
  ImGui::End();
  return a;
}

}  // namespace

panel_actions draw_panel(const panel_state& s) {
  bool changed_size = false;
  panel_actions a = draw_panel_once(s, changed_size);
  if (!changed_size) return a;
  // Lay the frame out again, now that the window knows its content: nothing
  // has been drawn yet. The second pass sees the same input without new
  // events (no click happens twice); the actions are the first pass's.
  ImGui::EndFrame();
  ImGui::NewFrame();
  panel_actions again = draw_panel_once(s, changed_size);
  a.panel_right = again.panel_right;
  a.panel_collapsed = again.panel_collapsed;
  return a;
}

}  // namespace vvi

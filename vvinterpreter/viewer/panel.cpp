#include "viewer/panel.hpp"

#include <imgui.h>

namespace vvi {

panel_actions draw_panel(const panel_state& s) {
  panel_actions a;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(300, 0), ImVec2(520, 2000));
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
  if (!s.running.empty()) {
    ImGui::TextColored(ImVec4(0.8f, 0.45f, 0.0f, 1), "%s", s.running.c_str());
    a.stop = ImGui::Button("Stop (Esc)");
    ImGui::SameLine();
    ImGui::TextDisabled("restarts the model");
    ImGui::Separator();
  }
  bool disabled = !s.has_model || s.busy;
  if (disabled) ImGui::BeginDisabled();
  a.step = ImGui::Button("Step");
  ImGui::SameLine();
  a.run = ImGui::Button(("Run " + std::to_string(s.run_steps)).c_str());
  ImGui::SameLine();
  if (s.animating) {
    a.stop = ImGui::Button("Stop");
  } else {
    if (!s.can_animate) ImGui::BeginDisabled();
    a.animate = ImGui::Button("Animate");
    if (!s.can_animate) ImGui::EndDisabled();
  }
  a.rewind = ImGui::Button("Rewind");
  ImGui::SameLine();
  a.end = ImGui::Button("End");
  ImGui::SameLine();
  a.reread = ImGui::Button("Reread files");
  if (disabled) ImGui::EndDisabled();
  a.recompile = ImGui::Button("Recompile");
  ImGui::SameLine();
  a.fit = ImGui::Button("Fit view");
  ImGui::SameLine();
  a.screenshot = ImGui::Button("Screenshot");
  bool replay = s.replay;
  if (ImGui::Checkbox("After a reload or restart, run again to the step", &replay)) a.toggle_replay = true;
  ImGui::Separator();
  ImGui::Text("step %u", s.steps);
  if (s.steps > 0) ImGui::Text("last step: %.2f ms", s.last_step_ms);
  for (const auto& [name, count] : s.meshes) ImGui::Text("mesh %s: %zu vertices", name.c_str(), count);
  if (!s.message.empty()) ImGui::TextDisabled("%s", s.message.c_str());
  if (!s.error.empty()) {
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.85f, 0.15f, 0.1f, 1));
    ImGui::TextWrapped("%s", s.error.c_str());
    ImGui::PopStyleColor();
  }
  if (!s.warnings.empty() && ImGui::CollapsingHeader("Compiler warnings")) ImGui::TextWrapped("%s", s.warnings.c_str());
  draw_parameters(s, a);
  draw_plots(s);
  draw_display(s, a);
  draw_inspector(s, a);
  ImGui::Separator();
  ImGui::TextDisabled("drag: rotate   right-drag: pan   wheel: zoom");
  ImGui::TextDisabled("space: step  a: animate  w: rewind  f: fit  s: screenshot");
  ImGui::TextDisabled("ctrl+click: pick a vertex  esc: stop  ctrl+q: quit");
  ImGui::End();
  return a;
}

}  // namespace vvi

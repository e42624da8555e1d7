// The panel's sections for looking into a model: the picked vertex, its
// actions, its parameters, its plots, and how it is drawn.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <cstdlib>

#include "viewer/panel.hpp"

namespace vvi {

namespace {

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  for (int digits = 1; digits <= 17; ++digits) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", digits, v);
    if (std::strtod(shorter, nullptr) == v) return shorter;
  }
  return buf;
}

// One parameter as a row of the table: its name; a slider over its range
// (no text on it: the grab would cover it), or a checkbox; and the value
// in a field of its own, where an exact value can be typed (Enter).
void parameter_row(const parameter_view& p, panel_actions& a) {
  ImGui::PushID(p.name.c_str());
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(p.name.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s %s, line %d", p.type.c_str(), p.name.c_str(), p.line);
  ImGui::TableNextColumn();
  ImGui::SetNextItemWidth(-FLT_MIN);
  const ImGuiSliderFlags slider = ImGuiSliderFlags_NoInput;  // typing goes to the value's field
  const ImGuiInputTextFlags on_enter = ImGuiInputTextFlags_EnterReturnsTrue;
  if (p.type == "bool") {
    bool on = p.number != 0;
    if (ImGui::Checkbox("##on", &on)) a.add(command::named(command::set, p.name, on ? "true" : "false"));
  } else if (p.type == "int" || p.type == "unsigned") {
    int v = static_cast<int>(p.number);
    bool changed = p.has_range && ImGui::SliderInt("##slider", &v, int(p.lo), int(p.hi), "", slider);
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(-FLT_MIN);
    changed |= ImGui::InputInt("##value", &v, 0, 0, on_enter);
    if (changed) a.add(command::named(command::set, p.name, std::to_string(v)));
  } else {
    double v = p.number;
    bool changed = p.has_range && ImGui::SliderScalar("##slider", ImGuiDataType_Double, &v, &p.lo, &p.hi, "", slider);
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(-FLT_MIN);
    changed |= ImGui::InputDouble("##value", &v, 0, 0, "%.6g", on_enter);
    if (changed) a.add(command::named(command::set, p.name, number_text(p.type == "float" ? double(float(v)) : v)));
  }
  ImGui::PopID();
}

}  // namespace

// A button per action, its key in brackets, as many to a line as fit.
void draw_actions(const panel_state& s, panel_actions& a) {
  if (s.actions.empty() || !ImGui::CollapsingHeader("Actions", ImGuiTreeNodeFlags_DefaultOpen)) return;
  bool disabled = !s.has_model || s.busy;
  if (disabled) ImGui::BeginDisabled();
  const float line_width = 300;  // the panel's narrowest
  const ImGuiStyle& style = ImGui::GetStyle();
  float used = 0;
  for (std::size_t i = 0; i < s.actions.size(); ++i) {
    const action_view& v = s.actions[i];
    std::string label = v.name + (v.key ? std::string(" (") + static_cast<char>(v.key) + ")" : "");
    float width = ImGui::CalcTextSize(label.c_str()).x + 2 * style.FramePadding.x;
    if (i > 0 && used + style.ItemSpacing.x + width <= line_width) {
      ImGui::SameLine();
      used += style.ItemSpacing.x + width;
    } else {
      used = width;
    }
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::Button(label.c_str())) a.add(command::named(command::action, v.name));
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
      ImGui::SetTooltip("action \"%s\", line %d", v.name.c_str(), v.line);
    ImGui::PopID();
  }
  if (disabled) ImGui::EndDisabled();
}

void draw_parameters(const panel_state& s, panel_actions& a) {
  if (s.parameters.empty() || !ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) return;
  bool disabled = !s.has_model || s.busy;
  if (disabled) ImGui::BeginDisabled();
  if (ImGui::BeginTable("##parameters", 3, ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("slider", ImGuiTableColumnFlags_WidthFixed, 170);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthFixed, 90);
    for (const parameter_view& p : s.parameters) parameter_row(p, a);
    ImGui::EndTable();
  }
  bool rewind = s.rewind_on_change;
  if (ImGui::Checkbox("Rewind on change (run again to this step)", &rewind))
    a.add(command::switched(command::rewind_on_change, "", rewind));
  if (ImGui::Button("Save to file")) a.add(command::of(command::save_params));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("write these values into the parameters' lines of the .vvp");
  if (disabled) ImGui::EndDisabled();
}

void draw_plots(const panel_state& s) {
  if (s.plots.empty() || !ImGui::CollapsingHeader("Plots", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (const plot_view& p : s.plots) {
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%s = %.6g (step %u)", p.name.c_str(), p.last, p.last_step);
    ImGui::PlotLines(("##" + p.name).c_str(), p.values.data(), int(p.values.size()), 0, overlay, FLT_MAX, FLT_MAX,
                     ImVec2(300, 70));
    ImGui::TextDisabled("steps %u to %u", p.first_step, p.last_step);
  }
}

void draw_display(const panel_state& s, panel_actions& a) {
  if (!ImGui::CollapsingHeader("Display")) return;
  // Each box is a `show WHAT on|off`.
  auto toggle = [&a](const char* label, const char* what, bool on) {
    if (ImGui::Checkbox(label, &on)) a.add(command::switched(command::show, what, on));
  };
  const display_style& style = s.style;
  toggle("faces", "faces", style.faces);
  ImGui::SameLine();
  toggle("edges", "edges", style.edges);
  ImGui::SameLine();
  toggle("points", "points", style.points);
  toggle("flat shading", "flat", style.flat);
  ImGui::SameLine();
  toggle("back faces", "back-faces", style.back_faces);
  toggle("hide edges when they fill the picture", "auto-hide-edges", style.auto_hide_edges);
  toggle("fit the view while the model grows", "auto-fit", s.auto_fit);
  const char* shown = s.color_by.empty() ? "(plain)" : s.color_by.c_str();
  if (ImGui::BeginCombo("colour by", shown)) {
    if (ImGui::Selectable("(plain)", s.color_by.empty())) a.add(command::named(command::color_by, ""));
    for (const std::string& f : s.numeric_fields)
      if (ImGui::Selectable(f.c_str(), f == s.color_by)) a.add(command::named(command::color_by, f));
    ImGui::EndCombo();
  }
  if (s.has_values) ImGui::Text("%s: %.6g (dark) to %.6g (light)", s.color_by.c_str(), s.value_min, s.value_max);
  const mesh_counts& c = s.counts;
  ImGui::Text("V %zu  E %zu  F %zu", c.vertices, c.edges, c.faces);
  if (c.boundary_edges || c.non_manifold_edges)
    ImGui::Text("boundary edges %zu  non-manifold edges %zu", c.boundary_edges, c.non_manifold_edges);
  if (!s.file_objects.empty()) {
    ImGui::TextDisabled("files reread when saved:");
    for (const std::string& f : s.file_objects) ImGui::TextDisabled("  %s", f.c_str());
  }
}

// Record: a time series while you step (the command record K FILE): the
// meshes, the pictures, or both, every K steps; the names' {step} is the
// step. Its settings are in a popup, so the panel grows by nothing; the
// fields keep what was typed for the whole session.
void draw_record(const panel_state& s, panel_actions& a) {
  static int every = 1;
  static bool meshes = true, pictures = true;
  static char mesh_file[256] = "vv_mesh_{step}.vtp";
  static char picture_file[256] = "vv_frame_{step}.png";
  if (!s.recording.empty()) {
    if (ImGui::Button("Stop recording")) a.add(command::record_off());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("writes the state it stops at too, and puts a movie in place");
    return;
  }
  if (ImGui::Button("Record...")) ImGui::OpenPopup("Record");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("write meshes and pictures (or a movie) every K steps");
  if (!ImGui::BeginPopup("Record")) return;
  ImGui::SetNextItemWidth(100);
  if (ImGui::InputInt("every K steps", &every)) every = std::max(every, 1);
  ImGui::Checkbox("mesh   ", &meshes);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(260);
  ImGui::InputText("##mesh file", mesh_file, sizeof mesh_file);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip(".vtp (listed in a .pvd for ParaView), .vvm .obj .off .ply .stl");
  ImGui::Checkbox("picture", &pictures);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(260);
  ImGui::InputText("##picture file", picture_file, sizeof picture_file);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip(".png a picture a step, .mp4 a movie (ffmpeg)");
  ImGui::TextDisabled("{step} in a name is the step; written now, then after every step that is a multiple of K");
  if (!meshes && !pictures) ImGui::BeginDisabled();
  if (ImGui::Button("Start recording")) {
    if (meshes) a.add(command::recording(static_cast<unsigned long>(every), mesh_file));
    if (pictures) a.add(command::recording(static_cast<unsigned long>(every), picture_file));
    ImGui::CloseCurrentPopup();
  }
  if (!meshes && !pictures) ImGui::EndDisabled();
  ImGui::EndPopup();
}

void draw_inspector(const panel_state& s, panel_actions& a) {
  if (s.picked.empty()) return;
  // A new pick opens the section, also after the user folded it.
  ImGuiStorage* kept = ImGui::GetStateStorage();
  ImGuiID shown = ImGui::GetID("##label shown");
  if (kept->GetInt(shown, 0) != int(s.picked_label)) ImGui::SetNextItemOpen(true);
  kept->SetInt(shown, int(s.picked_label));
  std::string first_line = s.picked.substr(0, s.picked.find('\n'));
  if (!ImGui::CollapsingHeader(("Inspect: " + first_line + "###inspect").c_str(), ImGuiTreeNodeFlags_DefaultOpen))
    return;
  // The colours it has in the picture.
  auto swatch = [](const char* id, const rgb& c, const char* what) {
    ImGui::ColorButton(id, ImVec4(c[0], c[1], c[2], 1), ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
    ImGui::SameLine(0, 4);
    ImGui::TextUnformatted(what);
  };
  swatch("##picked", pick_colours::picked, "picked");
  ImGui::SameLine();
  swatch("##neighbours", pick_colours::neighbour, "neighbours");
  ImGui::SameLine();
  if (ImGui::SmallButton("Clear")) a.add(command::labelled(command::inspect, 0));
  // A vertex with many neighbours has a long description: it scrolls in a
  // box of its own, so the sections below stay within reach.
  constexpr int most_lines = 14;
  int lines = int(std::count(s.picked.begin(), s.picked.end(), '\n')) + 1;
  ImVec2 text = ImGui::CalcTextSize(s.picked.c_str());
  const ImGuiStyle& style = ImGui::GetStyle();
  float height = std::min(lines, most_lines) * ImGui::GetTextLineHeight() + 2 * style.WindowPadding.y;
  float width = text.x + 2 * style.WindowPadding.x + (lines > most_lines ? style.ScrollbarSize : 0);
  ImGui::BeginChild("##picked", ImVec2(std::min(width, 490.0f), height), true);
  ImGui::TextUnformatted(s.picked.c_str());
  ImGui::EndChild();
}

}  // namespace vvi

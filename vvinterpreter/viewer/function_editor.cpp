#include "viewer/function_editor.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace vvi {

namespace {

bool is_function_file(const std::string& path) {
  return path.size() > 5 && path.compare(path.size() - 5, 5, ".func") == 0;
}

constexpr float canvas_width = 320, canvas_height = 200, grab_radius = 7;

}  // namespace

bool function_editor::open(const std::string& path, std::string& error) {
  try {
    auto f = std::make_unique<util::Function>(path);
    points_ = f->points();
    file_ = std::move(f);
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
  path_ = path;
  dirty_ = false;
  dragging_ = -1;
  // The box of the points with a margin; it stays put while editing so that
  // a dragged point does not run away from the cursor.
  x0_ = x1_ = points_.front().pos.x();
  y0_ = y1_ = points_.front().pos.y();
  for (const auto& p : points_) {
    x0_ = std::min(x0_, p.pos.x()), x1_ = std::max(x1_, p.pos.x());
    y0_ = std::min(y0_, p.pos.y()), y1_ = std::max(y1_, p.pos.y());
  }
  double dy = std::max(y1_ - y0_, 1e-6), dx = std::max(x1_ - x0_, 1e-6);
  y0_ -= 0.25 * dy, y1_ += 0.25 * dy, x0_ -= 0.05 * dx, x1_ += 0.05 * dx;
  return true;
}

void function_editor::draw(const std::vector<std::string>& files, std::string& said, std::string& error) {
  std::vector<std::string> functions;
  for (const std::string& f : files)
    if (is_function_file(f)) functions.push_back(f);
  if (functions.empty()) return;
  // A window of its own, folded until opened, in the bottom right corner
  // (the panel is on the left, the colour bar higher up on the right).
  ImVec2 screen = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(screen.x - 10, screen.y - 10), ImGuiCond_FirstUseEver, ImVec2(1, 1));
  ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
  bool open_window = ImGui::Begin("Function editor", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  if (open_window) draw_open(functions, said, error);
  ImGui::End();
}

void function_editor::draw_open(const std::vector<std::string>& functions, std::string& said, std::string& error) {
  if (path_.empty() || std::find(functions.begin(), functions.end(), path_) == functions.end()) {
    if (!open(functions.front(), error)) return;
  }
  if (ImGui::BeginCombo("file", path_.c_str())) {
    for (const std::string& f : functions)
      if (ImGui::Selectable(f.c_str(), f == path_)) open(f, error);
    ImGui::EndCombo();
  }
  edit_on_canvas();
  if (!dirty_) ImGui::BeginDisabled();
  if (ImGui::Button("Save")) save(said, error);
  ImGui::SameLine();
  if (ImGui::Button("Revert")) open(path_, error);
  if (!dirty_) ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextDisabled("drag: move  double-click: add  right-click: remove");
}

void function_editor::edit_on_canvas() {
  ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("canvas", ImVec2(canvas_width, canvas_height),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  auto to_screen = [&](double x, double y) {
    return ImVec2(origin.x + float((x - x0_) / (x1_ - x0_)) * canvas_width,
                  origin.y + float((y1_ - y) / (y1_ - y0_)) * canvas_height);
  };
  ImVec2 mouse = ImGui::GetIO().MousePos;
  double mx = x0_ + (mouse.x - origin.x) / canvas_width * (x1_ - x0_);
  double my = y1_ - (mouse.y - origin.y) / canvas_height * (y1_ - y0_);
  int under = -1;  // the control point under the cursor
  for (std::size_t i = 0; i < points_.size(); ++i) {
    ImVec2 p = to_screen(points_[i].pos.x(), points_[i].pos.y());
    if (std::hypot(p.x - mouse.x, p.y - mouse.y) <= grab_radius) under = int(i);
  }
  bool hovered = ImGui::IsItemHovered();
  std::size_t n = points_.size();
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) dragging_ = under;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging_ = -1;
  if (dragging_ >= 0) {
    // x stays between the neighbours (a function's x never decreases); the
    // end points keep their x, which is the domain.
    std::size_t i = std::size_t(dragging_);
    double x = i == 0 || i + 1 == n ? points_[i].pos.x()
                                     : std::clamp(mx, points_[i - 1].pos.x(), points_[i + 1].pos.x());
    points_[i].pos = util::Point<double>(x, my, 0);
    dirty_ = true;
  } else if (hovered && under < 0 && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && mx > points_.front().pos.x() &&
             mx < points_.back().pos.x()) {
    auto at = std::upper_bound(points_.begin(), points_.end(), mx,
                               [](double x, const util::Function::ControlPoint& p) { return x < p.pos.x(); });
    points_.insert(at, util::Function::ControlPoint{util::Point<double>(mx, my, 0), 1});
    dirty_ = true;
  } else if (hovered && under > 0 && std::size_t(under) + 1 < n && n > 4 &&
             ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
    points_.erase(points_.begin() + under);  // a function needs 4 points; the ends stay
    dirty_ = true;
  }

  ImDrawList* d = ImGui::GetWindowDrawList();
  d->AddRectFilled(origin, ImVec2(origin.x + canvas_width, origin.y + canvas_height), IM_COL32(250, 250, 252, 255));
  util::Function preview;
  try {
    preview.setPoints(points_);
  } catch (const std::exception&) {
    return;  // cannot happen: edits keep x in order
  }
  for (std::size_t i = 0; i + 1 < points_.size(); ++i)  // the control polygon
    d->AddLine(to_screen(points_[i].pos.x(), points_[i].pos.y()),
               to_screen(points_[i + 1].pos.x(), points_[i + 1].pos.y()), IM_COL32(180, 180, 190, 255));
  ImVec2 last;
  const int samples = 160;
  double a = points_.front().pos.x(), b = points_.back().pos.x();
  for (int s = 0; s <= samples; ++s) {  // the function itself
    double x = a + (b - a) * s / samples;
    ImVec2 p = to_screen(x, preview(x));
    if (s > 0) d->AddLine(last, p, IM_COL32(30, 60, 160, 255), 2);
    last = p;
  }
  for (std::size_t i = 0; i < points_.size(); ++i)
    d->AddCircleFilled(to_screen(points_[i].pos.x(), points_[i].pos.y()), 4,
                       int(i) == under || int(i) == dragging_ ? IM_COL32(220, 40, 30, 255) : IM_COL32(40, 40, 50, 255));
}

void function_editor::save(std::string& said, std::string& error) {
  try {
    file_->setPoints(points_);
    file_->write(path_);
  } catch (const std::exception& e) {
    error = e.what();
    return;
  }
  dirty_ = false;
  said = "wrote " + path_;
}

}  // namespace vvi

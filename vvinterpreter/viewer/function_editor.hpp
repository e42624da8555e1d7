// The function editor: the VLAB function files (.func) a model reads, drawn
// as their curves with their control points, which the user drags, adds
// (double-click) and removes (right-click). Save writes the file, and the
// viewer's file watch then has the model reread it, keeping the step.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <util/function.hpp>

namespace vvi {

class function_editor {
 public:
  //! Draws the editor (a panel section) for the model's .func files;
  //! `said` gets what was done ("wrote growth.func"), `error` what failed.
  void draw(const std::vector<std::string>& files, std::string& said, std::string& error);

 private:
  //! Loads the file into the editor; false (error set) when it does not read.
  bool open(const std::string& path, std::string& error);
  void draw_open(const std::vector<std::string>& functions, std::string& said, std::string& error);
  void edit_on_canvas();
  void save(std::string& said, std::string& error);

  std::string path_;
  std::unique_ptr<util::Function> file_;  // as last read or saved
  std::vector<util::Function::ControlPoint> points_;  // as being edited
  double x0_ = 0, x1_ = 1, y0_ = 0, y1_ = 1;          // the canvas shows this box
  int dragging_ = -1;
  bool dirty_ = false;
};

}  // namespace vvi

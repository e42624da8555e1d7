// What batch mode and the viewer share: building and loading a model, the
// view that shows it, and its default drawing.
#pragma once

#include <memory>
#include <string>

#include "camera.hpp"
#include "model_build.hpp"
#include "options.hpp"
#include "session.hpp"

namespace vvi {

class mesh_drawing;

struct loaded_model {
  build_result build;
  std::unique_ptr<session> model;  // null when building or loading failed
  std::string error;               // one line, when it failed
};

build_settings settings_for(const options& o, bool force = false);
//! Builds (or finds) and loads the model; does not run start.
loaded_model load_model(const options& o, bool force = false);

//! The box the view must show: the proxy's view volume when the program set
//! one, else the drawing's bounds, else the unit cube.
box view_box(session* model, const mesh_drawing* drawing);

//! The longest face orbit drawn or exported: --max-face, else the
//! program's proxy.max_face (0: no limit).
std::size_t max_face_of(const options& o, session& model);

//! Fills drawing from the chosen global mesh; "" or the error.
std::string update_drawing(session& model, const std::string& mesh_name, std::size_t max_face,
                           mesh_drawing& drawing);

}  // namespace vvi

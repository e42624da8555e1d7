// The interactive viewer: a GLFW window (OpenGL compatibility profile) with
// the model, a control panel, mouse and key controls, continuous
// modelling (recompile and reload when a source file changes) and --script.
#pragma once

#include "options.hpp"

namespace vvi {

//! Runs until the window closes; the exit status.
int run_viewer(const options& o);

}  // namespace vvi

// The interactive viewer: a GLFW window (OpenGL compatibility profile) with
// the model, a control panel, mouse and key controls, continuous
// modelling (recompile and reload when a source file changes) and --script.
// Everything that drives the model goes through its model controller
// (control/model_controller.hpp).
//
// The window runs in a child process of a small supervisor
// (viewer/supervised_viewer.cpp): when the model crashes, the supervisor
// starts the window again from the state record it last sent, with the
// crash on the panel.
#pragma once

#include "app/options.hpp"
#include "control/state_record.hpp"

namespace vvi {

//! The viewer under its supervisor: runs until the window closes; the exit
//! status.
int run_viewer(const options& o);

//! One viewer process's window, from a fresh start or a restart's record;
//! the exit status (viewer_restart_code: start me again).
int run_viewer_window(const options& o, const state_record& from);

}  // namespace vvi

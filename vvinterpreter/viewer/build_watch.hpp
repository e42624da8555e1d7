// Continuous modelling: the model's source files and the files its file
// objects read are watched; a saved source is a `reload`, a saved file of
// a file object a `reread` (an event of the model: the log keeps it). They
// are looked at when a save is told (file_events), and every quarter of a
// second in any case.
#pragma once

#include <string>
#include <vector>

#include "compile/model_build.hpp"
#include "viewer/file_events.hpp"
#include "viewer/file_watch.hpp"

namespace vvi {

class model_controller;

class build_watch {
 public:
  explicit build_watch(std::string model) : model_(std::move(model)) {}

  //! A build starts: what its sources are now (a save during the build is
  //! a change after it).
  void build_started();
  //! The build's sources are watched from the state they had when it started.
  void build_finished(const build_result& b);
  //! The files the model's file objects read, as the job just done left
  //! them: watched from now (before the next job, so a save while it runs
  //! is a change).
  void model_files(const std::vector<std::string>& files);
  //! Looks at the files (when a save was told, else at most every 0.25 s)
  //! and gives the controller what their changes ask for.
  void check(double now, model_controller& c);
  //! How long until check() looks again (the window sleeps until then).
  double seconds_until_look(double now) const;
  //! Called from another thread when a watched file is saved (to wake the
  //! window's loop).
  wake_signal& saved() { return events_.saved(); }

 private:
  void listen();  // the events of every watched file

  std::string model_;
  file_watch sources_, objects_;
  std::vector<file_watch::stamp> before_build_;
  std::vector<std::string> objects_watched_;
  file_events events_;
  static constexpr double period_ = 0.25;
  double last_check_ = 0;
};

}  // namespace vvi

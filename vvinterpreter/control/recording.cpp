// The model controller's time series (control/recording.hpp).
#include "control/recording.hpp"

#include <algorithm>

#include "control/model_controller.hpp"

namespace vvi {

std::string recording_refused(const command& c) {
  const std::string head = "record " + c.path + ": ";
  series_file kind = series_file_of(c.path);
  if (kind == series_file::unknown)
    return head + "a recorded file is a mesh (.vtp .vvm .obj .off .ply .stl), a picture (.png) or a movie (.mp4)";
  if (kind == series_file::movie && has_step_mark(c.path))
    return head + "a movie is one file: leave {step} out of its name";
  if (kind != series_file::movie && !has_step_mark(c.path))
    return head + "the name has no {step}, so each file would replace the one before; write it as " +
           with_step_mark(c.path);
  return "";
}

void model_controller::record(const command& c) {
  if (!c.on) {
    if (std::string e = stop_recording(true, true); !e.empty()) error(e, e);
    return;
  }
  std::string e = recording_refused(c);
  if (e.empty() && !runner_.model()) e = "record " + c.path + ": no model is loaded";
  if (!e.empty()) return error(e, e);
  // The same file again starts its series again.
  auto same = std::find_if(recording_.begin(), recording_.end(),
                           [&c](const recorded_series& s) { return s.pattern == c.path; });
  if (same != recording_.end()) {
    if (same->kind == series_file::movie) view_.end_movie(same->pattern, false);
    recording_.erase(same);
  }
  recorded_series s;
  s.every = c.number;
  s.pattern = c.path;
  s.digits = c.digits ? c.digits : default_step_digits;
  s.kind = series_file_of(c.path);
  if (vv::io::extension_of(c.path) == ".vtp") s.collection.emplace(vv::pvd_path_for(c.path));
  recording_.push_back(std::move(s));
  if (std::string failed = write_series(recording_.back()); !failed.empty()) recording_failed(failed);
}

// The files of one series for the state the model is in now: "" or the error.
std::string model_controller::write_series(recorded_series& s) {
  unsigned long step = facts_.steps;
  s.changed = false;
  if (s.kind == series_file::mesh) {
    std::string name = name_at_step(s.pattern, step, s.digits);
    if (std::string e = runner_.export_to(name); !e.empty()) return e;
    view_.wrote(name);
    if (!s.collection) return "";
    try {
      s.collection->add(step, name);
    } catch (const std::exception& x) {
      return x.what();
    }
    if (s.collection->entries().size() == 1) view_.wrote(s.collection->path());
    return "";
  }
  std::string name = s.kind == series_file::movie ? s.pattern : name_at_step(s.pattern, step, s.digits);
  return view_.record_picture(name, step);
}

// After a change of the model: the series whose step it is now.
void model_controller::changed(const model_change& c) {
  view_.model_changed(c);
  for (recorded_series& s : recording_) s.changed = true;
  if (c.kind == model_change::changed || !runner_.model()) return;
  for (std::size_t i = 0; i < recording_.size(); ++i)
    if (facts_.steps % recording_[i].every == 0)
      if (std::string e = write_series(recording_[i]); !e.empty()) return recording_failed(e);
}

// Ends every series; write_last: with the state the model is in now (when
// it changed since); keep_movies: movies are put in place, else dropped.
std::string model_controller::stop_recording(bool write_last, bool keep_movies) {
  std::vector<recorded_series> ending = std::move(recording_);
  recording_.clear();
  std::string first_error;
  for (recorded_series& s : ending) {
    std::string e;
    if (write_last && s.changed && runner_.model()) e = write_series(s);
    if (s.kind == series_file::movie) {
      std::string ended = view_.end_movie(s.pattern, e.empty() && keep_movies);
      if (e.empty()) e = ended;
    }
    if (first_error.empty()) first_error = e;
  }
  return first_error;
}

// A file of a series could not be written: the error, and the recording
// ends (its movies are dropped: they would miss frames).
void model_controller::recording_failed(const std::string& e) {
  stop_recording(false, false);
  error(e, e);
}

std::vector<std::string> model_controller::recorded_files() const {
  std::vector<std::string> files;
  for (const recorded_series& s : recording_)
    files.push_back(s.pattern + " every " + std::to_string(s.every) + (s.every == 1 ? " step" : " steps"));
  return files;
}

}  // namespace vvi

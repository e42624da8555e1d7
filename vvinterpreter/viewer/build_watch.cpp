#include "viewer/build_watch.hpp"

#include "control/model_controller.hpp"

namespace vvi {

void build_watch::build_started() {
  std::vector<std::string> known = sources_.paths();
  if (known.empty()) known.push_back(model_);
  before_build_ = file_watch::stamps_of(known);
}

void build_watch::build_finished(const build_result& b) {
  if (b.sources.empty()) return;
  sources_.watch(b.sources, before_build_);
  listen();
}

void build_watch::model_files(const std::vector<std::string>& files) {
  if (files == objects_watched_) return;
  objects_watched_ = files;
  objects_.watch(files);
  listen();
}

void build_watch::listen() {
  std::vector<std::string> all = sources_.paths();
  all.insert(all.end(), objects_watched_.begin(), objects_watched_.end());
  events_.watch(all);
}

void build_watch::check(double now, model_controller& c) {
  // A save told during a build is looked at when the build has ended.
  bool told = !c.building() && events_.take();
  if (!told && now - last_check_ < period_) return;
  last_check_ = now;
  if (!c.building() && sources_.changed()) c.submit(command::of(command::reload));
  // A file a file object reads was saved: reread it, keeping the step.
  if (objects_.changed() && c.facts().loaded) c.submit(command::of(command::reread));
}

double build_watch::seconds_until_look(double now) const {
  if (events_.pending()) return 0;
  return last_check_ + period_ > now ? last_check_ + period_ - now : 0;
}

}  // namespace vvi

#include "experiment/sweep_progress.hpp"

#include <cmath>

namespace vvi {

std::string time_left_text(double seconds) {
  long s = std::lround(std::ceil(seconds));
  if (s < 60) return "about " + std::to_string(s) + " s";
  long minutes = (s + 30) / 60;
  if (minutes < 60) return "about " + std::to_string(minutes) + " min";
  return "about " + std::to_string(minutes / 60) + " h " + std::to_string(minutes % 60) + " min";
}

sweep_progress::sweep_progress(std::size_t total, std::FILE* to, bool rewrite)
    : total_(total), to_(to), rewrite_(rewrite) {}

std::string sweep_progress::state() const {
  std::size_t ended = done_ + failed_, remaining = total_ - ended;
  std::string text = std::to_string(done_) + " done, " + std::to_string(failed_) + " failed, " +
                     std::to_string(remaining) + " remaining";
  if (remaining == 0 || ended == 0) return text;
  // The pace so far, runs at a time included.
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return text + ", " + time_left_text(elapsed / static_cast<double>(ended) * static_cast<double>(remaining)) + " left";
}

void sweep_progress::ended(bool failed, const std::string& what) {
  ++(failed ? failed_ : done_);
  if (rewrite_) {
    tick();
  } else {
    std::fprintf(to_, "%s %s: %s\n", what.c_str(), failed ? "failed" : "finished", state().c_str());
    std::fflush(to_);
  }
}

void sweep_progress::tick() {
  if (!rewrite_) return;
  // \033[K clears what a longer line before left.
  std::fprintf(to_, "\rruns: %s\033[K", state().c_str());
  std::fflush(to_);
}

void sweep_progress::finish() {
  if (rewrite_ && total_ > 0) std::fprintf(to_, "\n");
  std::fflush(to_);
}

}  // namespace vvi

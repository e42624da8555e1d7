#include "runner/report_reader.hpp"

#include <algorithm>
#include <cstdlib>

#include "runner/report_words.hpp"

namespace vvi {

namespace words = report_words;

void report_reader::feed(const char* data, std::size_t n) {
  pending_.append(data, n);
  std::size_t at;
  while ((at = pending_.find('\n')) != std::string::npos) {
    line(pending_.substr(0, at));
    pending_.erase(0, at + 1);
  }
}

void report_reader::line(const std::string& l) {
  std::size_t space = l.find(' ');
  std::string key = l.substr(0, space), rest = space == std::string::npos ? "" : l.substr(space + 1);
  if (key == words::begin || key == words::activity) {
    // "WHAT STEP"
    std::size_t last = rest.rfind(' ');
    child_activity a;
    a.what = rest.substr(0, last == std::string::npos ? rest.size() : last);
    if (last != std::string::npos) a.step = static_cast<unsigned>(std::strtoul(rest.c_str() + last + 1, nullptr, 10));
    end_.activity = a;
    if (key == words::begin) busy_since = clock_type::now(), ++activity_number, timed_ = true;
  } else if (key == words::thread) {
    activity_thread = static_cast<pid_t>(std::strtol(rest.c_str(), nullptr, 10));
  } else if (key == words::done) {
    end_.activity = child_activity();
    timed_ = false;
  } else if (key == words::crash) {
    end_.crash.signal = rest;
    filling_ = &end_.crash;
  } else if (key == words::sample) {  // "WHY NUMBER"
    std::size_t space_at = rest.find(' ');
    end_.sample = stack_sample();
    end_.sample.why = rest.substr(0, space_at);
    sample_number_ = space_at == std::string::npos ? -1 : std::atoi(rest.c_str() + space_at + 1);
    filling_ = &end_.sample;
  } else if (key == words::exception) {
    end_.crash.exception = rest;
  } else if (key == words::pc) {
    if (filling_) filling_->pc = std::strtoull(rest.c_str(), nullptr, 16);
  } else if (key == words::frame) {
    if (filling_) filling_->frames.push_back(std::strtoull(rest.c_str(), nullptr, 16));
  } else if (key == words::map) {
    if (filling_) filling_->maps.push_back(rest);
  } else if (key == words::module) {
    std::size_t tab = rest.find('\t');
    if (tab != std::string::npos) end_.modules[rest.substr(0, tab)] = rest.substr(tab + 1);
  } else if (key == words::writing_in) {
    auto& folders = end_.writing_folders;
    if (std::find(folders.begin(), folders.end(), rest) == folders.end()) folders.push_back(rest);
  } else if (key == words::writing) {
    std::size_t tab = rest.find('\t');
    if (tab != std::string::npos) end_.writing.emplace_back(rest.substr(tab + 1), rest.substr(0, tab));
  } else if (key == words::written) {
    auto& w = end_.writing;
    w.erase(std::remove_if(w.begin(), w.end(), [&](const auto& p) { return p.second == rest; }), w.end());
  } else if (key == words::end) {
    // The answer to the request last made (or exit's own report).
    if (filling_ == &end_.sample && (end_.sample.why == words::exit_call || sample_number_ == sample_asked))
      sample_arrived = true;
    filling_ = nullptr;
  } else if (s_.on_line) {
    s_.on_line(l);
  }
}

}  // namespace vvi

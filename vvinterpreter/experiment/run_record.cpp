#include "experiment/run_record.hpp"

#include <cctype>
#include <sys/stat.h>

#include <vv/io/files.hpp>

#include "experiment/sweep_folder.hpp"

namespace vvi {

namespace {

const char* const finished_marker = "/finished";
const char* const failed_marker = "/failed";
const char* const finished_name = "finished";
const char* const failed_name = "failed";

bool exists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// A one-line field: line breaks would split it.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

// "PATH:DIGITS: " at the start of text: the length of PATH:DIGITS, or 0.
std::size_t place_length(const std::string& text) {
  std::size_t colon = text.find(": ");
  if (colon == std::string::npos) return 0;
  std::size_t digits = text.rfind(':', colon - 1);
  if (digits == std::string::npos || digits == 0 || digits + 1 == colon) return 0;
  for (std::size_t i = digits + 1; i < colon; ++i)
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) return 0;
  return colon;
}

}  // namespace

run_state state_of_run(const std::string& folder) {
  if (exists(folder + finished_marker)) return run_state::finished;
  if (exists(folder + failed_marker)) return run_state::failed;
  return run_state::unfinished;
}

std::string mark_finished(const std::string& folder) { return write_in_folder(folder, finished_name, "finished\n"); }

std::string mark_failed(const std::string& folder, const run_failure& f) {
  return write_in_folder(folder, failed_name, "line: " + one_line(f.line) + "\nreason: " + one_line(f.reason) + "\n");
}

run_failure read_failure(const std::string& folder) {
  run_failure f;
  std::string text = vv::io::read_file(folder + failed_marker).value_or("");
  for (std::size_t from = 0; from < text.size();) {
    std::size_t end = text.find('\n', from);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(from, end - from);
    if (line.rfind("line: ", 0) == 0) f.line = line.substr(6);
    if (line.rfind("reason: ", 0) == 0) f.reason = line.substr(8);
    from = end + 1;
  }
  return f;
}

run_failure failure_from_output(const std::string& error_output, const std::string& how_it_ended,
                                const std::string& shown_as_from, const std::string& shown_as) {
  const std::string prefix = "vvinterpreter: ";
  std::string last;
  for (std::size_t from = 0; from < error_output.size();) {
    std::size_t end = error_output.find('\n', from);
    if (end == std::string::npos) end = error_output.size();
    if (error_output.compare(from, prefix.size(), prefix) == 0)
      last = error_output.substr(from + prefix.size(), end - from - prefix.size());
    from = end + 1;
  }
  run_failure f;
  if (last.empty()) {
    f.reason = how_it_ended;
    return f;
  }
  std::size_t place = place_length(last);
  f.reason = place ? last.substr(place + 2) : last;
  f.line = last.substr(0, place);
  if (!shown_as_from.empty() && f.line.rfind(shown_as_from + ":", 0) == 0)
    f.line = shown_as + f.line.substr(shown_as_from.size());
  return f;
}

}  // namespace vvi

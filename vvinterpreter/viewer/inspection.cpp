#include "viewer/inspection.hpp"

#include <sstream>

#include "runner/model_runner.hpp"

namespace vvi {

void inspection::update(const vv_geometry& g) {
  positions_.assign(g.positions, g.positions ? g.positions + 3 * g.vertex_count : g.positions);
  labels_.assign(g.labels, g.labels ? g.labels + g.vertex_count : g.labels);
  counts_ = count_mesh(g);
  numeric_fields_.clear();
  std::string list = g.numeric_fields ? g.numeric_fields : "";
  for (std::size_t at = 0; at < list.size();) {
    std::size_t comma = list.find(", ", at);
    if (comma == std::string::npos) comma = list.size();
    numeric_fields_.push_back(list.substr(at, comma - at));
    at = comma + 2;
  }
}

long inspection::index_of(unsigned label) const {
  for (std::size_t i = 0; i < labels_.size(); ++i)
    if (labels_[i] == label) return static_cast<long>(i);
  return -1;
}

unsigned inspection::label_of(long index) const {
  return index < 0 || std::size_t(index) >= labels_.size() ? 0 : labels_[std::size_t(index)];
}

std::string inspection::describe(const model_runner& runner) {
  if (!picked_label_) return "";
  std::string e = runner.describe_vertex(picked_label_, text_);
  if (!e.empty()) {
    clear();
    return e;
  }
  picked_index_ = index_of(picked_label_);
  // The neighbourhood line: "  neighbourhood (N, rotation order...): 3 [4] 5".
  neighbours_.clear();
  std::size_t at = text_.find("  neighbourhood (");
  if (at == std::string::npos) return "";
  std::size_t colon = text_.find("): ", at), end = text_.find('\n', at);
  std::istringstream words(text_.substr(colon + 3, end - colon - 3));
  for (std::string w; words >> w;) {
    if (w.front() == '[') w = w.substr(1, w.size() - 2);
    long i = w.find_first_not_of("0123456789") == std::string::npos ? index_of(unsigned(std::stoul(w))) : -1;
    if (i >= 0) neighbours_.push_back(std::uint32_t(i));
  }
  return "";
}

}  // namespace vvi

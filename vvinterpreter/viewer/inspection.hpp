// What the viewer keeps of the drawn model to look into it between steps:
// where each vertex is and its label (for picking), the counts, the
// numeric properties (for colouring), and the picked vertex with its
// neighbours (for highlighting).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <model/abi.hpp>

#include "runner/mesh_counts.hpp"

namespace vvi {

class model_runner;

class inspection {
 public:
  //! The geometry just drawn.
  void update(const vv_geometry& g);

  const std::vector<double>& positions() const { return positions_; }
  const mesh_counts& counts() const { return counts_; }
  const std::vector<std::string>& numeric_fields() const { return numeric_fields_; }

  //! The label of the vertex at this index of the drawing (-1: 0, none).
  unsigned label_of(long index) const;
  //! Picks by label (`pick LABEL`, Ctrl+click); described by describe().
  void pick_label(unsigned label) { picked_label_ = label; }
  void clear() { picked_label_ = 0, text_.clear(), picked_index_ = -1, neighbours_.clear(); }
  unsigned picked_label() const { return picked_label_; }

  //! Describes the picked vertex again (after a step it may have changed):
  //! "" or the error, which also clears the pick.
  std::string describe(const model_runner& runner);
  const std::string& text() const { return text_; }
  //! Drawing indices of the picked vertex and of its neighbours.
  long picked_index() const { return picked_index_; }
  const std::vector<std::uint32_t>& neighbours() const { return neighbours_; }

 private:
  long index_of(unsigned label) const;

  std::vector<double> positions_;
  std::vector<std::uint32_t> labels_;
  mesh_counts counts_;
  std::vector<std::string> numeric_fields_;
  unsigned picked_label_ = 0;
  long picked_index_ = -1;
  std::vector<std::uint32_t> neighbours_;
  std::string text_;
};

}  // namespace vvi

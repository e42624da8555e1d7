// The state of the C library's generators, which programs written for vv
// 1.1 draw from (rand, random, drand48, ...): saved and restored with a
// model's state (model/state.hpp), so that a resumed run draws the numbers
// the uninterrupted one would have.
//
// rand() and random() share one table. The C library says where a table's
// position is only when it switches away from it (initstate, setstate
// write it into the table's first word), so the save switches to a spare
// table for a moment, copies the model's, and switches back; the restore
// copies the saved table in while the spare one is current. The table
// stays the C library's own: nothing of it belongs to a model that may be
// unloaded. drand48's state is its 48-bit number (seed48 gives it back and
// sets it; the multiplier and increment are the default ones unless a
// program calls lcong48, which is not saved).
#pragma once

#include <stdlib.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "state_stream.hpp"

namespace vv::model {

namespace c_random_detail {

#ifdef __GLIBC__
// The table's bytes for the type in its first word: the type word, then
// 0, 7, 15, 31 or 63 numbers.
inline std::size_t table_bytes(const char* table) {
  std::int32_t word;
  std::memcpy(&word, table, 4);
  static const std::size_t degree[] = {0, 7, 15, 31, 63};
  const int type = static_cast<int>(static_cast<std::uint32_t>(word) % 5u);
  return 4 * (1 + degree[type]);
}
#endif

}  // namespace c_random_detail

inline void save_c_random(state_writer& w) {
#ifdef __GLIBC__
  alignas(std::int32_t) char spare[128];
  char* table = initstate(1, spare, sizeof spare);  // the model's table, with its position written in
  w.text(std::string(table, c_random_detail::table_bytes(table)));
  setstate(table);
#else
  w.text("");
#endif
  unsigned short any[3] = {0, 0, 0};
  unsigned short x[3];
  std::memcpy(x, seed48(any), sizeof x);
  seed48(x);
  for (unsigned short part : x) w.u32(part);
}

inline void restore_c_random(state_reader& r) {
  const std::string saved = r.text("the C library's random table");
#ifdef __GLIBC__
  if (!saved.empty()) {
    alignas(std::int32_t) char spare[128];
    char* table = initstate(1, spare, sizeof spare);
    if (saved.size() != c_random_detail::table_bytes(table) || saved.size() != c_random_detail::table_bytes(saved.data())) {
      setstate(table);
      throw state_error("the C library's random table has another size than the saved one");
    }
    std::memcpy(table, saved.data(), saved.size());
    setstate(table);
  }
#endif
  unsigned short x[3];
  for (unsigned short& part : x) part = static_cast<unsigned short>(r.u32("drand48's state"));
  seed48(x);
}

}  // namespace vv::model

// The state of the C library's generators, which programs written for vv
// 1.1 draw from (rand, random, drand48, ...): saved and restored with a
// model's state (model/state.hpp), so that a resumed run draws the numbers
// the uninterrupted one would have. Compiled once, in vv_formats
// (formats/model_state.cpp), as the other parts of a state that do not
// depend on the model's types (model/state_parts.hpp).
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

#include "state_stream.hpp"

#ifndef VV_FORMATS_API
#define VV_FORMATS_API __attribute__((visibility("default")))
#endif

namespace vv::model {

VV_FORMATS_API void save_c_random(state_writer& w);
//! Throws state_error when the saved table does not fit the C library's.
VV_FORMATS_API void restore_c_random(state_reader& r);

}  // namespace vv::model

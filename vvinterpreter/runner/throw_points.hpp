// Where a model's exception was thrown. An exception the library or the
// C++ library throws without a source location (std::out_of_range from
// .at(), std::bad_alloc, a `throw 42`) reaches the host as a message only:
// the stack where it was thrown is gone by then. The host takes every
// throw on its way (it defines __cxa_throw, which the model's and the C++
// library's throws call) and keeps the stack of the last one while a
// block runs; the plugin's catch (vv::model::guarded, model/guarded.hpp) asks for it through
// vv_host_throw_frames, and the session names the innermost .vvp line.
#pragma once

#include <cstddef>

namespace vvi::throw_points {

//! On: this thread keeps the stack of each exception thrown, from now (a
//! model's block runs); off: it keeps none and forgets the last.
void keep(bool on);

}  // namespace vvi::throw_points

extern "C" {
//! The return addresses where this thread last threw while keeping (at
//! most max into frames); 0 when there is none. Exported by the
//! interpreter to the plugins it loads.
std::size_t vv_host_throw_frames(void** frames, std::size_t max);
}

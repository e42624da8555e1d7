// The parts of a model's state (model/state.hpp) that do not depend on the
// model's types: the proxy's settings and plots, the model's random
// generator, the warnings said once. Compiled once, in vv_formats
// (formats/model_state.cpp), not in every model.
#pragma once

#include <cstddef>
#include <random>
#include <set>
#include <string>

#include "file_object.hpp"
#include "proxy.hpp"
#include "state_stream.hpp"

#ifndef VV_FORMATS_API
#define VV_FORMATS_API __attribute__((visibility("default")))
#endif

namespace vv::model {

//! The proxy; the file objects in its lists by their index in `files` (the
//! program's globals, null where a global is no file object), whose
//! objects are made anew when a model loads. Throws state_error for a
//! file object that is no global.
VV_FORMATS_API void save_proxy(state_writer& w, const vv::proxy& p, const file_object* const* files, std::size_t n);
VV_FORMATS_API void restore_proxy(state_reader& r, vv::proxy& p, const file_object* const* files, std::size_t n);

//! A generator by its text form, which the standard makes exact.
VV_FORMATS_API void save_engine(state_writer& w, const std::mt19937_64& e);
VV_FORMATS_API void restore_engine(state_reader& r, std::mt19937_64& e);

VV_FORMATS_API void save_texts(state_writer& w, const std::set<std::string>& texts);
VV_FORMATS_API void restore_texts(state_reader& r, std::set<std::string>& texts);

}  // namespace vv::model

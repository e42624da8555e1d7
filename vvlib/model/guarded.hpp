// Exceptions never cross the plugin ABI (model/abi.hpp): every entry point
// runs the program's code through guarded(), which returns NULL or the
// message, kept in the model's exchange until the next call.
#pragma once

#include <cxxabi.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <typeinfo>
#include <vector>

#include <vv/error.hpp>

#include "abi.hpp"

namespace vv::model {

//! What a model keeps between calls for its host: the last error, and the
//! data the pointers it returned point into.
struct exchange {
  std::string last_error;
  std::vector<void*> error_frames;  //!< vv::error::frames() of the last error
  std::vector<double> positions;
  std::vector<std::uint32_t> face_offsets, face_vertices;
  std::vector<std::uint32_t> line_offsets, line_vertices;
  std::vector<std::uint32_t> labels;
  std::vector<double> values;
  std::string numeric_fields, text;
  std::shared_ptr<void> union_mesh;  //!< the last union_geometry's mesh
  std::vector<char> was_symmetric;   //!< per global mesh, at the last check
  std::string state;                 //!< the last save_state's bytes
};

//! The message of the exception being handled, kept in x (called from a
//! catch block). One function for every entry point: each guarded() call
//! then compiles to a try and a call, not to five handlers of its own.
inline const char* keep_current_exception(exchange& x) noexcept {
  try {
    throw;  // a rethrow: the host's record of where it was thrown stays
  } catch (const vv::error& e) {
    x.last_error = e.what();
    x.error_frames = e.frames();
    return x.last_error.c_str();
  } catch (const std::exception& e) {
    x.last_error = e.what();
  } catch (const std::string& text) {
    x.last_error = "an exception of type std::string: " + text;
  } catch (const char* text) {
    x.last_error = std::string("an exception of type const char*: ") + (text ? text : "(null)");
  } catch (...) {
    const std::type_info* type = abi::__cxa_current_exception_type();
    int status = 0;
    char* name = type ? abi::__cxa_demangle(type->name(), nullptr, nullptr, &status) : nullptr;
    x.last_error = std::string("an exception of type ") + (name ? name : type ? type->name() : "unknown");
    std::free(name);
  }
  if (vv_host_throw_frames) {
    x.error_frames.resize(48);
    x.error_frames.resize(vv_host_throw_frames(x.error_frames.data(), x.error_frames.size()));
  }
  return x.last_error.c_str();
}

//! Runs fn, turning any exception into the returned message (or NULL). An
//! exception that is not a vv::error keeps where it was thrown, when the
//! host knows (its stack is gone once caught): the host names its .vvp line.
template <class Fn>
const char* guarded(exchange& x, Fn&& fn) noexcept {
  x.error_frames.clear();
  try {
    fn();
    return nullptr;
  } catch (...) {
    return keep_current_exception(x);
  }
}

//! A message that is the host's mistake, not the program's (no line to
//! look for).
inline const char* refuse(exchange& x, std::string message) noexcept {
  x.error_frames.clear();
  x.last_error = std::move(message);
  return x.last_error.c_str();
}

}  // namespace vv::model

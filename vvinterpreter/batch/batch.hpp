// Batch mode: start, N steps, export, screenshot, close — no display.
#pragma once

#include "app/options.hpp"

namespace vvi {

//! Runs a model headless; the exit status (0, or 1 with a one-line reason
//! on standard error).
int run_batch(const options& o);
//! --compile-only.
int run_compile_only(const options& o);

}  // namespace vvi

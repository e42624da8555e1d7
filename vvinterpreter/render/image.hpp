// PNG files of rendered frames.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vvi {

//! Writes RGBA pixels (top row first) as a PNG, atomically; "" or the error.
std::string write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba);

}  // namespace vvi

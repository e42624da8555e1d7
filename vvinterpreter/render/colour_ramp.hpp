// The colours of "colour by a property": a ramp from dark violet through
// blue and green to yellow, ordered in lightness so that higher values read
// as lighter also in grey, and told apart by people with red-green colour
// blindness.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace vvi {

using rgb = std::array<float, 3>;

//! t in [0, 1] (clamped); a value that is not a number is grey.
inline rgb colour_ramp(double t) {
  static const rgb stops[] = {{0.267f, 0.005f, 0.329f},
                              {0.230f, 0.322f, 0.546f},
                              {0.128f, 0.567f, 0.551f},
                              {0.370f, 0.789f, 0.383f},
                              {0.993f, 0.906f, 0.144f}};
  if (std::isnan(t)) return {0.6f, 0.6f, 0.6f};
  double x = std::clamp(t, 0.0, 1.0) * 4;
  int i = std::min(static_cast<int>(x), 3);
  float f = static_cast<float>(x - i);
  rgb out;
  for (int c = 0; c < 3; ++c) out[c] = stops[i][c] * (1 - f) + stops[i + 1][c] * f;
  return out;
}

}  // namespace vvi

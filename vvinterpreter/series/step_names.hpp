// The file names of a time series (--every K, the viewer's Record): a
// name with {step} in it is a pattern, and each file of the series is the
// pattern with the step number in place of {step}, zero-padded to a width
// (batch: the width of the last step, so the names sort in step order).
#pragma once

#include <string>

namespace vvi {

inline constexpr const char* step_mark = "{step}";

//! Whether a name is a pattern (holds {step}).
bool has_step_mark(const std::string& name);
//! The pattern with every {step} replaced by `step`, zero-padded to `digits`.
std::string name_at_step(const std::string& pattern, unsigned long step, unsigned digits);
//! The number of digits of `step` (1 for 0).
unsigned digits_of(unsigned long step);
//! The same name with "-{step}" before its extension (what to write instead
//! of a name without {step}).
std::string with_step_mark(const std::string& name);

//! What a recorded file is, by its extension.
enum class series_file { mesh, picture, movie, unknown };
series_file series_file_of(const std::string& name);

}  // namespace vvi

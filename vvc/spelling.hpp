// Misspelt vv words: how far a name is from each vv word, and which word a
// name most likely misspells. Where the parser asks: parser_spelling.cpp.
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

#include "keywords.hpp"

namespace vvc {

//! The Damerau-Levenshtein distance of a and b (optimal string alignment):
//! inserting, deleting or replacing a character, or swapping two neighbours,
//! each count one edit. Anything above `limit` is reported as limit + 1,
//! and so is any distance to a b of 20 characters or more (no vv word is
//! near that long).
std::size_t edit_distance(std::string_view a, std::string_view b, std::size_t limit);

//! The most edits a misspelling of `word` is taken to be: 1 for a word of
//! up to four letters (any short name is two edits from `is` or `add`), 2
//! for a longer one.
std::size_t misspelling_edits(std::string_view word);

//! The vv word that `name` most likely misspells among those `fits`
//! accepts: the nearest within misspelling_edits, the first in the keyword
//! table on a tie; nullptr when none is near, or when name is itself a
//! word of vv or of C++.
const vv_word* misspelt_vv_word(std::string_view name, const std::function<bool(const vv_word&)>& fits);

//! A keyword of C++ (up to C++20, alternative tokens included).
bool is_cxx_keyword(std::string_view w);

}  // namespace vvc

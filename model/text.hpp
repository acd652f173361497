// Text helpers shared by every layer that writes messages (model/validate,
// formats/, reports/). The lowest layer: depends on nothing of cemv.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace cemv::model {

// A user-supplied text as a message shows it: in single quotes, every byte
// outside printable ASCII escaped as \xHH (a message must never carry control
// characters or broken UTF-8 to the terminal), shortened after max_chars.
std::string in_quotes(std::string_view s, std::size_t max_chars = 48);
// The same escaping without the quotes, for texts we did not write.
std::string printable(std::string_view s);

// Number of UTF-8 code points (continuation bytes not counted).
std::size_t utf8_length(std::string_view s);

// Levenshtein distance, letters compared case-insensitively.
std::size_t edit_distance(std::string_view a, std::string_view b);
// " (did you mean 'x'?)" when one candidate is a plausible typo of `word`
// (or `word` a truncation of it), else "".
// One rule for every file format and check: letters compare case-
// insensitively; the distance allowed grows with the candidate's length (1 up
// to 3 letters, 2 up to 8, else 3); ties go to the first candidate.
std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& candidates);
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

// Shortest decimal text that reads back as the same float (e.g. 0.1f -> "0.1").
std::string float_text(float v);

}  // namespace cemv::model

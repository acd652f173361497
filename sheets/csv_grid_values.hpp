// The values of the attributes of a vendor's C&E sheet (docs/csv.md
// "Attributes"), read from their cells: voting, SIL, setpoints and the side
// that trips, tag lists, deletion words. Internal to formats/; each function
// reads one cell text and says nothing of where it is.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::formats::grid {

// A cause's voting (6.3.1, 3.4): XooN (`2oo3`, `2 out of 3`, `2/3`) or a
// function word (`AND`, `OR`). `tags` is N, or 0 for a word (as many as the
// rows of its group).
struct Voting {
  int votes = 1;
  int tags = 1;
  std::optional<model::CauseFunction> word;  // AND, OR
};
// nullopt when the text is no voting; `problem` then says why.
std::optional<Voting> parse_voting(std::string_view text, std::string& problem);
// The cause function of a voting over `tags` tags: 1oo1 normal, 1ooN OR, NooN
// AND, 2oo3 2oo3; nullopt for what the Safety Matrix cannot express (2oo4).
std::optional<model::CauseFunction> function_of(const Voting& v, int tags);

// SIL 0-4 (`2`, `SIL 2`, `SIL2`; `-`, `n/a`, `none` are 0). nullopt otherwise.
std::optional<int> parse_sil(std::string_view text);

// A setpoint: a number (`45`, `0.8`, `0,8`, `-5`), optionally after a
// comparison that says the trip side (`> 45`, `<= 0.8`) or before a side word
// (`45 HH`) or other text (`45 barg`, in `rest`). nullopt when the text does
// not start with a number (a switch state, `N/A`).
struct Setpoint {
  double value = 0;
  std::optional<model::LimitType> side;
  std::string rest;
};
std::optional<Setpoint> parse_setpoint(std::string_view text);

// The side a trip-side cell names: H, HH, HI, HIGH, MAX, >; L, LL, LO, LOW, MIN, <.
std::optional<model::LimitType> parse_trip_side(std::string_view text);

// The side a description names with its words: high (high, hi, hh, max, over,
// above) or low (low, lo, ll, min, under, below). nullopt when it names none;
// `both` is set when it names both (then nothing can be said).
std::optional<model::LimitType> side_of_words(std::string_view text, bool& both);

// The tags of a tag cell: one, or several separated by `,`, `;`, `/` or line
// breaks; `PT-101A/B/C` is PT-101A, PT-101B and PT-101C (a short part after
// `/` replaces as many characters at the end of the first tag).
std::vector<std::string> split_tags(std::string_view text);

// A cell that says "nothing here": `-`, an en or em dash, `n/a`, `na`, `none`.
bool nil_value(std::string_view text);

// Whether text holds one of the words, whole, in any letter case.
bool has_word(std::string_view text, const std::vector<std::string>& words);

}  // namespace cemv::formats::grid

// Inside the symbolic monitor (monitor.cpp): the command inputs of an
// encoding that an `issued(...)` pattern (ast.hpp CommandPattern) stands for.
#pragma once

#include <vector>

#include "encoder/encode.hpp"
#include "properties/ast.hpp"

namespace cemv::properties::monitor_commands {

// Whether a command input of the encoding matches a pattern: empty fields
// match anything, `on` only for soft bypass.
bool matches(const encoder::CommandInput& ci, const CommandPattern& p);

// The concrete commands a pattern can match that name a target of the cone
// (or the target the pattern fixes).
std::vector<model::Command> candidate_commands(const encoder::Encoding& enc, const CommandPattern& p);

// A fresh, unconstrained input for a command the encoding has none for
// (one the configuration always refuses, or one acting outside the cone).
void add_free_command(encoder::Encoding& enc, const model::Command& c);

}  // namespace cemv::properties::monitor_commands

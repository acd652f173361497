// Files the checker writes beside its results. A counterexample or witness
// is written as a `cemv-scenario/1` file by the format's one writer
// (formats/scenario_writer.hpp, checked_at_end): its constant stretches
// folded into steps, its last step expecting the values of the property's
// signals at the violation, so `cemv simulate` on the file passes exactly
// when the runtime reproduces the run.
#pragma once

#include <filesystem>
#include <string>

namespace cemv::checker {

// Writes `text` to a temporary file beside `path` and renames it into place,
// so an interrupted run leaves the old file or none, never half of one.
// Throws std::runtime_error naming the file when a write fails.
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace cemv::checker

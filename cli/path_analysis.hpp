// How `cemv response` and `cemv defeats` run their analysis of the SIF paths:
// the progress line (paths done / total, the running ones; cli/progress.hpp)
// fed by the analysis' hooks, and what the analysis throws. An
// std::invalid_argument (the input asks for what the matrix does not have)
// passes on once the line is erased; anything else is cemv's fault: said on
// standard error, and no result (the command's exit 4).
#pragma once

#include <cstddef>
#include <exception>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include "checker/prover.hpp"
#include "cli/progress.hpp"

namespace cemv::cli {

template <class Options, class Analyse>
auto run_path_analysis(const std::string& command, Options& o, bool quiet, Analyse analyse)
    -> std::optional<decltype(analyse())> {
  Progress progress(command, 0, "paths", !quiet && Progress::terminal(), std::cerr);
  o.on_plan = [&](std::size_t paths) { progress.phase(command, paths, "paths"); };
  o.on_start = [&](const std::string& key) { progress.started(key); };
  o.on_done = [&](const std::string& key) { progress.finished(key); };
  try {
    auto result = analyse();
    progress.stop();
    return result;
  } catch (const std::invalid_argument&) {
    progress.stop();
    throw;
  } catch (const std::exception& e) {
    progress.stop();
    const bool refuted = dynamic_cast<const checker::InternalError*>(&e) != nullptr;
    std::cerr << "internal error: " << (refuted ? "" : "the checker failed: ") << e.what()
              << "\n(a bug in cemv: please report it with the matrix)\n";
    return std::nullopt;
  }
}

}  // namespace cemv::cli

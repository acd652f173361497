// The progress line of long commands (`check`, `testgen`, `evidence`,
// `response`) on a terminal: items done / total, elapsed time, the current item, redrawn in
// place on standard error about twice a second. Only when standard error is a
// terminal and the command is not --quiet: in a pipe, a CI log or a file
// nothing is written, so machine-readable output and the files cemv writes
// never see it (they are byte-identical with or without a terminal). The line
// is erased before the command prints its results.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

namespace cemv::cli {

class Progress {
 public:
  // `what`: "check", "testgen", ...; `unit`: "properties", "objectives".
  // `enabled` false: every call does nothing (no thread, no output).
  Progress(std::string what, std::size_t total, std::string unit, bool enabled, std::ostream& out);
  ~Progress();  // erases the line
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void started(const std::string& item);              // now running
  void finished(const std::string& item);             // done (counts one)
  void phase(const std::string& what, std::size_t total, std::string unit);  // a new count from 0
  void stop();                                        // erase the line now (idempotent)

  // The line as drawn (without the terminal's control characters); public for tests.
  static std::string line(const std::string& what, std::size_t done, std::size_t total, const std::string& unit,
                          double seconds, const std::vector<std::string>& running, std::size_t width);

  // Whether standard error is a terminal the line may be drawn on (not TERM=dumb).
  static bool terminal();

 private:
  void draw_locked();
  std::string what_, unit_;
  std::size_t total_, done_ = 0;
  bool enabled_, stopped_ = false;
  std::ostream& out_;
  std::vector<std::string> running_;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  std::condition_variable cv_;
  std::thread ticker_;
};

}  // namespace cemv::cli

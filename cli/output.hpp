// The one output path of the command line: every byte a command writes to
// standard output or to a file goes through Output, so that no write failure
// is ever silent (the coreutils convention: a write error is always an error).
//
//  - Every write, the final flush and the close are checked. A failure throws
//    OutputError, whose message names the destination; the CLI prints it and
//    exits 2.
//  - Writing to a closed pipe (`cemv check ... | head -1`) throws ClosedPipe;
//    the CLI ends quietly (no message), as a process killed by SIGPIPE would.
//  - A file is written to a temporary file in the same folder and renamed over
//    the destination by commit(): an interrupted or failed run leaves the
//    previous file or no file, never half of one (rename(2) is atomic within a
//    file system, which the same folder guarantees).
//  - "-" means standard output.
//
// Destinations are checked before the work starts with check_writable() /
// check_writable_directory(), so an unwritable path fails in milliseconds
// instead of after a long run.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace cemv::cli {

// A destination could not be written. what() = "DESTINATION: reason".
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The reader of standard output went away (EPIPE). Not an error to report.
class ClosedPipe : public std::exception {
 public:
  const char* what() const noexcept override { return "standard output is a closed pipe"; }
};

// How messages name standard output.
inline constexpr std::string_view kStdoutName = "<stdout>";

// Throws OutputError unless `path` can be created or replaced: its folder
// exists and accepts a new file (tested by creating and removing a temporary
// file there), and the path is not a folder. "-" (standard output) always passes.
void check_writable(const std::string& path);

// Creates `dir` (and missing parents) if needed and throws OutputError unless
// files can be created in it.
void check_writable_directory(const std::string& dir);

// One destination, written in pieces and completed by commit(). Destroying an
// Output that was not committed removes its temporary file and leaves the
// destination untouched.
class Output {
 public:
  explicit Output(const std::string& path);  // "-" = standard output
  ~Output();
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  void write(std::string_view text);
  // Flushes and closes; for a file, syncs it and renames it over the destination.
  void commit();

  const std::string& name() const { return name_; }  // the path, or "<stdout>"
  bool is_stdout() const { return fd_ == 1; }

 private:
  [[noreturn]] void fail(const std::string& what, int err);

  std::string path_;
  std::string name_;
  std::string temp_path_;
  int fd_ = -1;
  bool committed_ = false;
};

// Writes `text` to `path` ("-" = standard output) completely, or throws.
void write_output(const std::string& path, std::string_view text);

}  // namespace cemv::cli

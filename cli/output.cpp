// See output.hpp. Plain POSIX file descriptors rather than iostreams: every
// write(2), fsync(2), close(2) and rename(2) returns its own error, which is
// what lets each failure name its cause.
#include "cli/output.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace cemv::cli {

namespace {

namespace fs = std::filesystem;

std::string reason(int err) { return std::strerror(err); }

std::string folder_of(const std::string& path) {
  fs::path p(path);
  fs::path dir = p.parent_path();
  return dir.empty() ? std::string(".") : dir.string();
}

// A temporary file next to `path` (same folder, hence same file system, so the
// final rename is atomic). Returns its descriptor and fills `temp`, or -1 with errno.
int make_temp_next_to(const std::string& path, std::string& temp) {
  fs::path p(path);
  std::string pattern =
      (fs::path(folder_of(path)) / ("." + p.filename().string() + ".cemv-XXXXXX")).string();
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  int fd = ::mkstemp(buf.data());
  if (fd >= 0) temp.assign(buf.data());
  return fd;
}

// The permissions a new file would get (0666 minus the umask), read once
// before any thread starts so that no thread ever sees the umask changed.
mode_t new_file_mode() {
  static const mode_t mode = [] {
    mode_t mask = ::umask(022);
    ::umask(mask);
    return static_cast<mode_t>(0666 & ~mask);
  }();
  return mode;
}
const mode_t kInitMode = new_file_mode();

bool is_special_file(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

}  // namespace

void check_writable(const std::string& path) {
  if (path == "-") return;
  if (path.empty()) throw OutputError("an output path is empty");
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw OutputError(path + ": cannot write: it is a folder");
  if (is_special_file(path)) {
    int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) throw OutputError(path + ": cannot write: " + reason(errno));
    ::close(fd);
    return;
  }
  std::string temp;
  int fd = make_temp_next_to(path, temp);
  if (fd < 0) throw OutputError(path + ": cannot write: " + reason(errno));
  ::close(fd);
  ::unlink(temp.c_str());
}

void check_writable_directory(const std::string& dir) {
  if (dir.empty()) throw OutputError("an output folder is empty");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw OutputError(dir + ": cannot write into it: it is not a folder");
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir + ": cannot create the folder: " + ec.message());
  check_writable((fs::path(dir) / "probe").string());
}

Output::Output(const std::string& path) : path_(path) {
  if (path == "-") {
    name_ = std::string(kStdoutName);
    // Report a closed pipe as EPIPE from write(2) instead of dying by the
    // signal, so a file being written at the same time is not left behind.
    std::signal(SIGPIPE, SIG_IGN);
    fd_ = 1;
    return;
  }
  name_ = path;
  (void)kInitMode;
  if (is_special_file(path)) {
    // A device or FIFO (/dev/null, /dev/stdout): nothing to rename over.
    fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) fail("cannot open", errno);
    return;
  }
  fd_ = make_temp_next_to(path, temp_path_);
  if (fd_ < 0) fail("cannot create a file in its folder", errno);
  struct stat st {};
  mode_t mode = ::stat(path.c_str(), &st) == 0 ? (st.st_mode & 07777) : new_file_mode();
  if (::fchmod(fd_, mode) != 0) fail("cannot set permissions", errno);
}

Output::~Output() {
  if (committed_ || fd_ < 0) return;
  if (fd_ != 1) ::close(fd_);
  if (!temp_path_.empty()) ::unlink(temp_path_.c_str());
}

void Output::fail(const std::string& what, int err) {
  if (err == EPIPE && fd_ == 1) throw ClosedPipe();
  throw OutputError(name_ + ": " + what + ": " + reason(err));
}

void Output::write(std::string_view text) {
  if (committed_) throw OutputError(name_ + ": internal error: write after commit");
  while (!text.empty()) {
    ssize_t n = ::write(fd_, text.data(), text.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot write", errno);
    }
    text.remove_prefix(static_cast<std::size_t>(n));
  }
}

void Output::commit() {
  if (committed_) return;
  if (fd_ == 1) {
    // Nothing is buffered (write(2) above); a regular file behind stdout may
    // still report a deferred error at sync.
    if (::fsync(1) != 0 && errno != EINVAL && errno != EROFS && errno != ENOTSUP)
      fail("cannot flush", errno);
    committed_ = true;
    return;
  }
  if (temp_path_.empty()) {  // device or FIFO
    int rc = ::close(fd_);
    fd_ = -1;
    if (rc != 0) fail("cannot close", errno);
    committed_ = true;
    return;
  }
  if (::fsync(fd_) != 0) fail("cannot flush", errno);
  int rc = ::close(fd_);
  fd_ = -1;
  if (rc != 0) {
    int err = errno;
    ::unlink(temp_path_.c_str());
    fail("cannot close", err);
  }
  if (::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    int err = errno;
    ::unlink(temp_path_.c_str());
    fail("cannot replace the file", err);
  }
  committed_ = true;
}

void write_output(const std::string& path, std::string_view text) {
  Output out(path);
  out.write(text);
  out.commit();
}

}  // namespace cemv::cli

#include "cli/progress.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <sys/ioctl.h>
#include <unistd.h>

namespace cemv::cli {

namespace {

std::size_t terminal_width() {
  winsize w{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col >= 20) return w.ws_col;
  return 80;
}

}  // namespace

bool Progress::terminal() {
  const char* term = std::getenv("TERM");
  return isatty(STDERR_FILENO) && !(term && std::strcmp(term, "dumb") == 0);
}

Progress::Progress(std::string what, std::size_t total, std::string unit, bool enabled, std::ostream& out)
    : what_(std::move(what)), unit_(std::move(unit)), total_(total), enabled_(enabled), out_(out) {
  if (!enabled_) return;
  ticker_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopped_) {
      draw_locked();
      cv_.wait_for(lock, std::chrono::milliseconds(500));
    }
  });
}

Progress::~Progress() { stop(); }

void Progress::stop() {
  if (!enabled_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_) return;
    stopped_ = true;
    out_ << "\r\033[K" << std::flush;
  }
  cv_.notify_all();
  if (ticker_.joinable()) ticker_.join();
}

void Progress::started(const std::string& item) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  running_.push_back(item);
  draw_locked();
}

void Progress::finished(const std::string& item) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (auto it = std::find(running_.begin(), running_.end(), item); it != running_.end()) running_.erase(it);
  ++done_;
  draw_locked();
}

void Progress::phase(const std::string& what, std::size_t total, std::string unit) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  what_ = what;
  total_ = total;
  unit_ = std::move(unit);
  done_ = 0;
  running_.clear();
  draw_locked();
}

void Progress::draw_locked() {
  if (stopped_) return;
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  out_ << "\r\033[K" << line(what_, done_, total_, unit_, s, running_, terminal_width() - 1) << std::flush;
}

std::string Progress::line(const std::string& what, std::size_t done, std::size_t total, const std::string& unit,
                           double seconds, const std::vector<std::string>& running, std::size_t width) {
  char t[32];
  long whole = static_cast<long>(seconds);
  std::snprintf(t, sizeof t, "%ld:%02ld", whole / 60, whole % 60);
  std::string s = what + ": " + std::to_string(done) + "/" + std::to_string(total) + " " + unit + ", " + t;
  if (!running.empty()) {
    s += ", now: " + running.front();
    if (running.size() > 1) s += " (+" + std::to_string(running.size() - 1) + ")";
  }
  if (s.size() > width) s = s.substr(0, width > 3 ? width - 3 : 0) + "...";
  return s;
}

}  // namespace cemv::cli

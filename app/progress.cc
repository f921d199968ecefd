#include "app/progress.h"

#include <unistd.h>

#include <cstdio>

namespace ivv {

ProgressLine::ProgressLine(std::string label, std::size_t already_done)
    : label_(std::move(label)), start_done_(already_done), tty_(isatty(STDERR_FILENO) == 1) {}

namespace {
std::string duration(double s) {
  char buf[32];
  if (s < 120)
    std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 7200)
    std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
  else
    std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  return buf;
}
}  // namespace

void ProgressLine::update(std::size_t done, std::size_t total) {
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0) return;
  const double since_last = std::chrono::duration<double>(now - last_).count();
  if (done < total && since_last < (tty_ ? 0.2 : 5.0)) return;
  // a batch of rows delivered at once reports the same count once per row: print it once
  if (done == printed_done_) return;
  printed_done_ = done;
  last_ = now;
  const double rate = (done - start_done_) / elapsed;
  const std::string eta = rate > 0 ? duration((total - done) / rate) : "?";
  const double pct = total ? 100.0 * done / total : 100.0;
  if (tty_) {
    constexpr int width = 30;
    const int filled = static_cast<int>(width * pct / 100);
    std::fprintf(stderr, "\r%s [%s%s] %zu/%zu (%.1f%%) %.3g points/s, ETA %s   ", label_.c_str(),
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), done,
                 total, pct, rate, eta.c_str());
    drawn_ = true;
  } else {
    std::fprintf(stderr, "%s: %zu/%zu points (%.1f%%), %.3g points/s, ETA %s\n", label_.c_str(),
                 done, total, pct, rate, eta.c_str());
  }
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace ivv

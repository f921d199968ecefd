// Progress of a long run on stderr: points done, rate, ETA. Silent for the first second. On a
// terminal one line redrawn with \r (at most 5 times a second); otherwise (a log file, CI) one
// line every 5 seconds.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace ivv {

class ProgressLine {
 public:
  // `already_done` points were done before this run started (a resumed sweep): the rate
  // counts only this run's points.
  ProgressLine(std::string label, std::size_t already_done);
  void update(std::size_t done, std::size_t total);
  // Ends the redrawn line (if one was drawn).
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::string label_;
  std::size_t start_done_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_{};
  bool tty_;
  bool drawn_ = false;
  std::size_t printed_done_ = static_cast<std::size_t>(-1);  // the count last printed
};

}  // namespace ivv

// A progress bar on stderr for long CPU runs (bakes, the path-traced reference):
// "\rbake [###########             ]  45%  1134 of 2503 points  0.4 s, 0.5 s left" on a terminal,
// nothing otherwise.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace lg::cli {

class ProgressLine {
 public:
  // `label` starts the line ("bake"), `unit` names what is counted ("points").
  ProgressLine(std::string label, std::string unit, uint64_t total);
  void update(uint64_t done) const;
  void finish() const;  // ends the line, when one was shown
  double seconds() const;

 private:
  std::string label_, unit_;
  uint64_t total_;
  bool shown_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace lg::cli

#include "cli/progress_line.h"

#include <unistd.h>

#include <cstdio>

namespace lg::cli {

ProgressLine::ProgressLine(std::string label, std::string unit, uint64_t total)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total), shown_(isatty(STDERR_FILENO)) {}

void ProgressLine::update(uint64_t done) const {
  if (!shown_ || total_ == 0) return;
  constexpr int width = 24;
  const int filled = int(width * done / total_);
  const double elapsed = seconds(), left = done > 0 ? elapsed * double(total_ - done) / double(done) : 0.0;
  std::fprintf(stderr, "\r%s [%.*s%*s] %3d%%  %llu of %llu %s  %.1f s, %.1f s left ", label_.c_str(), filled,
               "########################", width - filled, "", int(100 * done / total_),
               static_cast<unsigned long long>(done), static_cast<unsigned long long>(total_), unit_.c_str(), elapsed,
               left);
}

void ProgressLine::finish() const {
  if (shown_ && total_ > 0) std::fputc('\n', stderr);
}

double ProgressLine::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace lg::cli

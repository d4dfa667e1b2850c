#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace tetblend::cli {

namespace {
constexpr int kBarWidth = 30;  // characters between the brackets
}  // namespace

bool progressEnabled(bool quiet) { return !quiet && isatty(STDERR_FILENO) == 1; }

ProgressBar::ProgressBar(std::string label, std::size_t total, bool quiet)
    : label_(std::move(label)),
      total_(std::max<std::size_t>(total, 1)),
      enabled_(progressEnabled(quiet)) {
  std::lock_guard<std::mutex> lock(mutex_);
  draw();
}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::advance(std::size_t steps) {
  std::lock_guard<std::mutex> lock(mutex_);
  done_ = std::min(total_, done_ + steps);
  draw();
}

void ProgressBar::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (enabled_) std::fputc('\n', stderr);
}

void ProgressBar::draw() {
  if (!enabled_ || finished_) return;
  const int filled = static_cast<int>(kBarWidth * done_ / total_);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(kBarWidth - filled), '.');
  std::fprintf(stderr, "\r%s [%s] %zu/%zu", label_.c_str(), bar.c_str(), done_, total_);
  std::fflush(stderr);
}

}  // namespace tetblend::cli

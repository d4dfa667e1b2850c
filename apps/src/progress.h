#pragma once
// A terminal progress bar for long steps of the command line. It draws on
// stderr only when stderr is a terminal and the user did not ask for --quiet,
// so logs and pipes stay clean.

#include <cstddef>
#include <mutex>
#include <string>

namespace tetblend::cli {

/// Thread-safe progress bar "label [#####.....] done/total" redrawn in place.
class ProgressBar {
 public:
  /// `total` steps to go; `quiet` (or a non-terminal stderr) silences it.
  ProgressBar(std::string label, std::size_t total, bool quiet);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Marks `steps` more steps done and redraws.
  void advance(std::size_t steps = 1);
  /// Ends the line (called by the destructor if not before).
  void finish();

 private:
  void draw();

  std::string label_;
  std::size_t total_;
  std::size_t done_ = 0;
  bool enabled_;
  bool finished_ = false;
  std::mutex mutex_;
};

/// True when progress output is wanted: stderr is a terminal and not quiet.
bool progressEnabled(bool quiet);

}  // namespace tetblend::cli

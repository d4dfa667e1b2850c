#pragma once
// Helpers shared by the subcommands of the tetblend command line: argument
// parsing of weight lists, output naming, thread limits and the option every
// subcommand has (--quiet).

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

namespace tetblend::cli {

/// Parses one finite number (surrounding blanks allowed); `what` names the
/// option in the InputError thrown otherwise.
double parseFiniteNumber(const std::string& text, const std::string& what);

/// Parses a comma-separated list of finite numbers ("0.5,-0.2,1"); `what`
/// names the option in the InputError thrown for an empty list or a bad
/// number.
std::vector<double> parseWeights(const std::string& text, const std::string& what);

/// Parses semicolon-separated weight vectors ("0,0;1,0;0,1").
std::vector<std::vector<double>> parseWeightKeys(const std::string& text, const std::string& what);

/// Checks that `weights` has one entry per example; InputError otherwise.
void requireWeightCount(const std::vector<double>& weights, std::size_t exampleCount,
                        const std::string& what);

/// `path` with its extension replaced by `extension` (".vtp").
std::string withExtension(const std::string& path, const std::string& extension);

/// Lower-case extension of `path` including the dot (".vtu"), or "".
std::string extensionOf(const std::string& path);

/// Creates directory `dir` (and parents) if missing; InputError on failure.
void ensureDirectory(const std::string& dir);

/// Adds --quiet (silences progress bars) to `command`.
void addQuietOption(CLI::App& command, bool& quiet);

/// Largest thread count accepted from --threads or a batch spec's "threads":
/// far above the cores of any machine this runs on, low enough that the
/// per-worker state of a run cannot exhaust memory.
constexpr int kMaxThreads = 1024;

/// Adds --threads (0 = all cores, at most kMaxThreads) to `command`.
void addThreadsOption(CLI::App& command, int& threads);

/// Limits TBB's parallelism to `threads` (0 = no limit) while alive.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  std::shared_ptr<void> control_;
};

/// Number of worker threads to use for `threads` (0 = hardware concurrency).
int resolveThreads(int threads);

/// Refuses, before any work, to write `outputs` that would lose data: an
/// output that is the same file (device and inode) as one of `inputs`, or
/// that exists and is not a regular file (a symbolic link, a directory, a
/// FIFO, a socket or a device). InputError naming the output (and the input).
void checkOutputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);

/// The error line for a std::bad_alloc that escaped a subcommand; `args` is
/// the command line without the program name. Names the subcommand and the
/// arguments that are existing files other than -o/--output.
std::string outOfMemoryMessage(const std::vector<std::string>& args);

/// Prints "tetblend: warning: <line>" on stderr (always, --quiet or not).
void printWarning(const std::string& line);

/// Prints "tetblend: <line>" on stderr unless `quiet`.
void printNote(const std::string& line, bool quiet);

}  // namespace tetblend::cli

#pragma once
// The batch command's resume record and output-directory lock (cmd_batch.cpp
// explains the resume rule): the journal of finished jobs, their
// fingerprints, the flock that keeps one run per output directory, and the
// clean-up of a killed run's temporaries.

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "batch_spec.h"

namespace tetblend::cli {

constexpr const char* kLockName = ".tetblend-batch.lock";
constexpr const char* kJournalName = ".tetblend-batch.journal";

/// Holds an exclusive, non-blocking flock on <dir>/.tetblend-batch.lock for
/// its lifetime; InputError naming `dir` when another process holds it.
class OutputDirLock {
 public:
  explicit OutputDirLock(const std::string& dir);
  ~OutputDirLock();
  OutputDirLock(const OutputDirLock&) = delete;
  OutputDirLock& operator=(const OutputDirLock&) = delete;

 private:
  int fd_ = -1;
};

/// FNV-1a 64 of the bytes of the file at `path`.
std::uint64_t fileHash(const std::string& path);

/// A job's fingerprint: FNV-1a 64 (hex) of the model file's hash, the job's
/// method, weights, consistency, nonlinear, surface formats, surface_only,
/// quality arrays (equal choices, however written, give equal keys;
/// InputError for a spec.qualityArrays that does not parse) and compression.
std::string fingerprint(const BatchSpec& spec, const BatchJob& job, std::uint64_t modelHash);

/// The last journal line of each job name; lines that do not parse (one cut
/// by a kill, a foreign file) mark nothing done.
std::map<std::string, nlohmann::json> readJournal(const std::string& path);

/// Removes from `dir` the temporaries of writeFileAtomically
/// (.<name>.<digits>.tmp) whose <name> is one of `outputs`' file names; only
/// a killed run leaves them, and the caller holds the directory's lock.
void removeStaleTemporaries(const std::string& dir, const std::vector<std::string>& outputs);

/// Syncs each of `files`, then `dir` (the renames into it): a worker rank's
/// job files are on disk before rank 0 journals them.
void syncOutputs(const std::vector<std::string>& files, const std::string& dir);

/// Writes `text` to `path` atomically (writeFileAtomically).
void writeText(const std::string& path, const std::string& text);

/// The journal of finished jobs, open for appending.
class Journal {
 public:
  /// Rewrites <dir>/.tetblend-batch.journal with `kept` (one line each).
  Journal(const std::string& dir, const std::vector<nlohmann::json>& kept);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  /// Syncs `record["files"]` and the directory, then appends `record` as one
  /// line and syncs the journal. Thread-safe.
  void append(const nlohmann::json& record);

 private:
  std::string dir_;
  std::string path_;
  std::mutex mutex_;
  int fd_ = -1;
};

}  // namespace tetblend::cli

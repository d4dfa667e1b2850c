#include "batch_journal.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "quality_arrays.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/atomic_file.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string hex64(std::uint64_t v) {
  std::ostringstream s;
  s << std::hex << v;
  return s.str();
}

/// fsync of a file or directory: its data, or the renames into it, on disk.
void syncPath(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(path + ": cannot open to sync (" + std::strerror(errno) + ")");
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw InputError(path + ": cannot sync (" + std::strerror(err) + ")");
}

}  // namespace

OutputDirLock::OutputDirLock(const std::string& dir) {
  const std::string path = (fs::path(dir) / kLockName).string();
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0) {
    throw InputError(path + ": cannot open the lock file (" + std::strerror(errno) + ")");
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    if (err == EWOULDBLOCK) {
      throw InputError(dir +
                       ": another 'tetblend batch' is running on this output directory (it "
                       "holds " +
                       path + "); wait for it to end or choose another output_dir");
    }
    throw InputError(path + ": cannot lock (" + std::strerror(err) + ")");
  }
}

OutputDirLock::~OutputDirLock() { ::close(fd_); }

std::uint64_t fileHash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  return fnv1a64(bytes.data(), bytes.size());
}

std::string fingerprint(const BatchSpec& spec, const BatchJob& job, std::uint64_t modelHash) {
  std::string key = "model=" + hex64(modelHash) + ";method=" + job.method +
                    ";weights=" + job.weights.dump() + ";consistency=" + spec.consistency +
                    ";nonlinear=" + (spec.nonlinear ? "1" : "0") + ";formats=";
  for (const std::string& f : spec.surfaceFormats) key += f + ",";
  // Options at their defaults add nothing, so journals written before they
  // existed stay valid.
  if (spec.surfaceOnly) key += ";surface_only";
  const QualityArrays arrays = parseQualityArrays(spec.qualityArrays, "quality_arrays");
  if (!arrays.all) key += ";quality_arrays=" + qualityArraysText(arrays);
  // The level does not matter without a compressor.
  const VtkCompression& c = spec.compression;
  const std::string compression =
      vtkCompressorName(c.compressor) +
      (c.compressor == VtkCompressor::none ? "" : "/" + std::to_string(c.level));
  const VtkCompression& d = kBlendOutputCompression;
  if (compression != vtkCompressorName(d.compressor) + "/" + std::to_string(d.level))
    key += ";compression=" + compression;
  return hex64(fnv1a64(reinterpret_cast<const unsigned char*>(key.data()), key.size()));
}

std::map<std::string, json> readJournal(const std::string& path) {
  std::map<std::string, json> records;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    try {
      json r = json::parse(line);
      if (r.is_object() && r.contains("name") && r["name"].is_string() &&
          r.contains("fingerprint") && r["fingerprint"].is_string()) {
        const std::string name = r["name"].get<std::string>();
        records[name] = std::move(r);
      }
    } catch (const json::exception&) {
    }
  }
  return records;
}

void removeStaleTemporaries(const std::string& dir, const std::vector<std::string>& outputs) {
  std::set<std::string> names;
  for (const std::string& o : outputs) names.insert(fs::path(o).filename().string());
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    if (n.size() < 7 || n[0] != '.' || n.compare(n.size() - 4, 4, ".tmp") != 0) continue;
    const std::string stem = n.substr(1, n.size() - 5);  // <name>.<digits>
    const std::size_t dot = stem.rfind('.');
    if (dot == std::string::npos || dot + 1 == stem.size()) continue;
    const bool digits = std::all_of(stem.begin() + static_cast<std::ptrdiff_t>(dot) + 1, stem.end(),
                                    [](char c) { return c >= '0' && c <= '9'; });
    if (digits && names.count(stem.substr(0, dot)) && !e.is_directory(ec))
      stale.push_back(e.path());
  }
  for (const fs::path& p : stale) fs::remove(p, ec);
}

void syncOutputs(const std::vector<std::string>& files, const std::string& dir) {
  for (const std::string& f : files) syncPath(f);
  syncPath(dir);
}

void writeText(const std::string& path, const std::string& text) {
  writeFileAtomically(path, [&](const std::string& temp) {
    std::ofstream out(temp);
    out << text;
    if (!out.flush()) throw InputError(path + ": cannot write");
  });
}

Journal::Journal(const std::string& dir, const std::vector<json>& kept)
    : dir_(dir), path_((fs::path(dir) / kJournalName).string()) {
  std::string text;
  for (const json& r : kept) text += r.dump() + "\n";
  writeText(path_, text);
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | O_NOFOLLOW);
  if (fd_ < 0) throw InputError(path_ + ": cannot open (" + std::strerror(errno) + ")");
  if (::fsync(fd_) != 0) {
    const int err = errno;
    ::close(fd_);
    throw InputError(path_ + ": cannot sync (" + std::strerror(err) + ")");
  }
}

Journal::~Journal() { ::close(fd_); }

void Journal::append(const json& record) {
  for (const json& f : record["files"]) syncPath(f.get<std::string>());
  syncPath(dir_);
  const std::string line = record.dump() + "\n";
  std::lock_guard<std::mutex> lock(mutex_);
  for (std::size_t done = 0; done < line.size();) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw InputError(path_ + ": cannot append (" + std::strerror(errno) + ")");
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd_) != 0) throw InputError(path_ + ": cannot sync (" + std::strerror(errno) + ")");
}

}  // namespace tetblend::cli

// tetblend batch: many blends of one model from a JSON spec (batch_spec.h),
// in parallel, with a summary table and a .pvd of the results.
//
// Resume rule: the journal (<output_dir>/.tetblend-batch.journal, one JSON
// line per finished job: name, fingerprint, files, quality) is the
// done-marker. A job's line is appended and fsync'd right after its files are
// renamed into place and synced, so a run killed at any point keeps the jobs
// it finished. A job is skipped when its last journal line has the same
// fingerprint (FNV-1a 64 of the model file's bytes, the job's method,
// weights, consistency, nonlinear and surface formats) and all its output
// files still exist. Editing a job, or re-preparing the model, reruns it. At
// start the journal is rewritten with only the lines still valid (dropping a
// line cut by a kill) and the atomic writer's temporaries of killed runs
// (.<output name>.<digits>.tmp) are removed.
//
// summary.json: {"spec": the spec's file name, "model", "jobs": [{"name",
// "method", "weights", "status" (done|failed), "fingerprint",
// "skipped_this_run", "files", "seconds", "quality" (done jobs: the
// qualityColumns), "error" (failed jobs)}]}; every path in it is relative to
// the spec's folder, whatever the working directory. summary.csv has one row
// per job: name, method, status, weights, the quality columns, seconds, error.
//
// One run per output directory: a run holds an exclusive flock on
// <output_dir>/.tetblend-batch.lock (released by the kernel when the process
// ends, even by kill -9); a second run on the same directory is refused.
//
// Concurrency: the blends take turns behind a mutex (each is parallel over
// tets inside); the quality figures and the compressed output files of
// different jobs are made concurrently by the job workers. The stitch is
// documented and tested safe for concurrent use, but blends running
// concurrently measured no faster (bench_batch, README: Benchmarks).
//
// Under an MPI launcher (mpirun, srun; built with MPI, batch_mpi.h) the jobs
// are shared among the ranks: rank 0 alone takes the lock, reads and writes
// the journal, decides what a re-run skips, and writes the summaries and the
// .pvd; it hands out the pending jobs one at a time to whichever rank (or
// one of its own job workers) asks next. Every rank reads the model once;
// the other ranks write only the files of the jobs they are given (each job
// is handed out once, so no two ranks write one file) and send each job's
// outcome back to rank 0, which journals it as its own.

#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include "batch_job_weights.h"
#include "batch_journal.h"
#include "batch_mpi.h"
#include "batch_spec.h"
#include "blend_options.h"
#include "blend_output.h"
#include "cli_common.h"
#include "commands.h"
#include "progress.h"
#include "quality_arrays.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/atomic_file.h"
#include "tetblend/meshing/pvd_collection.h"
#include "tetblend/pipeline/blended_shape.h"
#include "tetblend/pipeline/format_number.h"
#include "tetblend/pipeline/make_blender.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct BatchArgs {
  std::string spec;
  int threads = -1;          // -1: take the spec's value
  std::string compression;   // "": take the spec's value
  int compressionLevel = 0;  // 0: take the spec's value
  bool quiet = false;
  bool coordinatorOnly = false;  // under MPI: rank 0 blends nothing itself
};

struct JobOutcome {
  bool done = false;
  bool skipped = false;
  std::string error;
  std::vector<std::string> files;
  // Done jobs: the quality columns (a skipped job's from its journal line).
  json quality = json::object();
  double seconds = 0.0;
};

/// One CSV field per RFC 4180: in double quotes, inner quotes doubled, when it
/// holds a comma, a quote, CR or LF; as is otherwise.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

/// `path` relative to the spec's folder, so that summary.json reads the same
/// from any working directory.
std::string fromSpecFolder(const BatchSpec& spec, const std::string& path) {
  const fs::path folder = fs::absolute(spec.specPath).parent_path().lexically_normal();
  return fs::absolute(path).lexically_normal().lexically_relative(folder).string();
}

void writeSummaries(const BatchSpec& spec, const std::vector<std::string>& fingerprints,
                    const std::vector<JobOutcome>& outcomes) {
  json summary{{"spec", fromSpecFolder(spec, spec.specPath)},
               {"model", fromSpecFolder(spec, spec.modelPath)},
               {"jobs", json::array()}};
  std::ostringstream csv;
  csv << "name,method,status,weights";
  for (const auto& c : qualityColumns(QualitySummary{})) csv << "," << c.first;
  csv << ",seconds,error\n";
  for (std::size_t i = 0; i < spec.jobs.size(); ++i) {
    const BatchJob& job = spec.jobs[i];
    const JobOutcome& o = outcomes[i];
    json files = json::array();
    for (const std::string& f : o.files) files.push_back(fromSpecFolder(spec, f));
    json entry{{"name", job.name},
               {"method", job.method},
               {"weights", job.weights},
               {"status", o.done ? "done" : "failed"},
               {"fingerprint", fingerprints[i]},
               {"skipped_this_run", o.skipped},
               {"files", files},
               {"seconds", o.seconds}};
    const json& quality = o.quality;
    if (o.done) entry["quality"] = quality;
    if (!o.done) entry["error"] = o.error;
    summary["jobs"].push_back(entry);

    csv << csvField(job.name) << "," << csvField(job.method) << "," << (o.done ? "done" : "failed")
        << "," << csvField(jobWeightsText(job));
    for (const auto& c : qualityColumns(QualitySummary{})) {
      csv << ",";
      if (o.done && quality.contains(c.first) && quality[c.first].is_number())
        csv << formatNumber(quality[c.first].get<double>());
    }
    csv << "," << formatNumber(o.seconds) << "," << csvField(o.error) << "\n";
  }
  writeText((fs::path(spec.outputDir) / "summary.json").string(), summary.dump(2) + "\n");
  writeText((fs::path(spec.outputDir) / "summary.csv").string(), csv.str());
}

// The first line of a run: how many jobs run, how many a re-run skips and
// why, and where every output goes (output_dir may point anywhere).
std::string runNote(const BatchSpec& spec, std::size_t pending) {
  const std::size_t skipped = spec.jobs.size() - pending;
  std::string line = "batch: " + std::to_string(pending) + " of " +
                     std::to_string(spec.jobs.size()) + " jobs to run";
  if (skipped > 0) {
    line += " (" + std::to_string(skipped) +
            " done by an earlier run: same model file, method, weights and options, files "
            "present)";
  }
  return line + ", writing into " + fs::absolute(spec.outputDir).lexically_normal().string();
}

/// What every rank needs to run jobs: the spec and its parsed options (the
/// model is read after rank 0 has checked the outputs).
struct BatchSetup {
  BatchSpec spec;
  std::vector<std::string> formats;
  bool consistency = true;
  QualityArrays arrays;
  std::string extension;
  ModelData model;
  int threads = 0;  // --threads or the spec's

  std::vector<std::string> jobFiles(std::size_t i) const {
    return blendOutputFiles((fs::path(spec.outputDir) / (spec.jobs[i].name + extension)).string(),
                            formats);
  }
};

BatchSetup readSetup(const BatchArgs& a) {
  BatchSetup s;
  s.spec = readBatchSpec(a.spec);
  // One name per method for the blender, the fingerprint and the summary:
  // an alias ("dqs") becomes the name it stands for ("dq").
  for (BatchJob& job : s.spec.jobs) job.method = canonicalMethodName(job.method);
  if (!a.compression.empty() || a.compressionLevel != 0) {
    s.spec.compression = parseVtkCompression(
        a.compression.empty() ? vtkCompressorName(s.spec.compression.compressor) : a.compression,
        a.compressionLevel != 0 ? a.compressionLevel : s.spec.compression.level, "--compression");
  }
  s.formats = parseSurfaceFormats(s.spec.surfaceFormats);
  s.consistency = parseOnOff(s.spec.consistency, a.spec + ": \"consistency\"");
  const std::string arraysWhere = a.spec + ": \"quality_arrays\"";
  s.arrays = parseQualityArrays(s.spec.qualityArrays, arraysWhere);
  if (s.spec.surfaceOnly && !s.arrays.all && !s.arrays.names.empty()) {
    throw InputError(arraysWhere +
                     " names arrays, but \"surface_only\" writes no .vtu to hold them");
  }
  s.extension = s.spec.surfaceOnly ? ".vtp" : ".vtu";
  s.threads = a.threads >= 0 ? a.threads : s.spec.threads;
  return s;
}

/// The blender of the pending jobs' methods (made once per process) and the
/// running of one job: blend, write its files, its quality columns.
class JobRunner {
 public:
  JobRunner(const BatchSetup& setup, const std::vector<std::size_t>& pendingJobs)
      : setup_(setup),
        limit_(setup.threads),
        figures_(qualityFigures(setup.arrays, !setup.spec.surfaceOnly)),
        restData_(modelRestData(setup.model)) {
    const BatchSpec& spec = setup.spec;
    std::vector<BlendMethod> methods;
    for (std::size_t i : pendingJobs) {
      const std::string& name = spec.jobs[i].method;
      if (methodError_.count(name)) continue;
      try {
        const BlendMethod m = parseMethod(name);
        methodError_[name] = "";
        if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
      } catch (const Error& e) {
        methodError_[name] = e.what();
      }
    }
    for (BlendMethod m : methods) {
      try {
        if (!blender_) {
          blender_ = std::make_unique<ShapeBlender>(
              makeBlender(setup.model, {m}, setup.consistency, spec.nonlinear,
                          figures_.targetResidual));
        } else {
          blender_->prepare(m);
        }
      } catch (const DomainError& e) {
        methodError_[blendMethodName(m)] = e.what();
      }
    }
  }

  /// Runs job i into `o` (whose files are set): done, error, quality,
  /// seconds. Thread-safe; the blends take turns.
  void run(std::size_t i, JobOutcome& o) {
    const BatchJob& job = setup_.spec.jobs[i];
    const auto start = std::chrono::steady_clock::now();
    try {
      const std::vector<double> weights =
          jobWeights(job, setup_.model.exampleSources, setup_.spec.modelPath);
      if (!methodError_.at(job.method).empty()) throw InputError(methodError_.at(job.method));
      BlendedShape shape;
      {
        std::lock_guard<std::mutex> lock(blendMutex_);
        shape = blendShape(*blender_, setup_.model, restData_, weights, parseMethod(job.method),
                           figures_);
      }
      writeBlendResult(o.files.front(), setup_.model, shape.vertices,
                       selectQualityArrays(shape.cellData, setup_.arrays, "\"quality_arrays\""),
                       setup_.formats, setup_.spec.compression);
      o.quality = json::object();
      for (const auto& c : qualityColumns(shape.quality)) o.quality[c.first] = c.second;
      o.done = true;
    } catch (const std::exception& e) {
      o.error = e.what();
    }
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

 private:
  const BatchSetup& setup_;
  ThreadLimit limit_;
  QualityFigures figures_;  // only those whose arrays are written
  RestTetData restData_;    // the rest's inverse edge matrices, once for every job
  std::map<std::string, std::string> methodError_;  // method name -> why it cannot run
  std::unique_ptr<ShapeBlender> blender_;
  std::mutex blendMutex_;
};

/// A job's outcome as sent by a worker rank; the quality figures travel as
/// their bit patterns, so rank 0 writes exactly what a local job gives (NaN
/// included).
std::string encodeOutcome(std::size_t i, const JobOutcome& o) {
  json bits = json::object();
  for (const auto& [name, value] : o.quality.items()) {
    const double v = value.get<double>();
    std::uint64_t b = 0;
    std::memcpy(&b, &v, sizeof b);
    bits[name] = b;
  }
  return json{{"job", i},
              {"done", o.done},
              {"error", o.error},
              {"seconds", o.seconds},
              {"quality_bits", bits}}
      .dump();
}

/// Decodes encodeOutcome into outcomes[job] (files kept); returns the job.
std::size_t decodeOutcome(const std::string& text, std::vector<JobOutcome>& outcomes) {
  const json m = json::parse(text);
  const auto i = m.at("job").get<std::size_t>();
  JobOutcome& o = outcomes.at(i);
  o.done = m.at("done").get<bool>();
  o.error = m.at("error").get<std::string>();
  o.seconds = m.at("seconds").get<double>();
  o.quality = json::object();
  for (const auto& [name, value] : m.at("quality_bits").items()) {
    const auto b = value.get<std::uint64_t>();
    double v = 0;
    std::memcpy(&v, &b, sizeof v);
    o.quality[name] = v;
  }
  return i;
}

/// FNV-1a 64 of the spec's and the model's file hashes: what every rank must
/// read alike for the job indices to mean the same jobs.
std::uint64_t inputsHash(const BatchSpec& spec, std::uint64_t modelHash) {
  const std::uint64_t h[2] = {fileHash(spec.specPath), modelHash};
  return fnv1a64(reinterpret_cast<const unsigned char*>(h), sizeof h);
}

/// A rank other than 0: reads the spec and the model, waits for rank 0's
/// start, then blends and writes the jobs it is handed until there are none.
/// It writes nothing else and prints nothing; what goes wrong goes to rank 0.
void runWorkerRank(const BatchArgs& a, BatchWorld& world) {
  std::string setupError;
  BatchSetup setup;
  std::uint64_t inputs = 0;
  try {
    setup = readSetup(a);
    setup.model = readModelFile(setup.spec.modelPath);
    inputs = inputsHash(setup.spec, fileHash(setup.spec.modelPath));
  } catch (const std::exception& e) {
    setupError = e.what();
  }
  std::vector<std::int64_t> pending;
  std::uint64_t rank0Inputs = 0;
  if (!world.awaitStart(rank0Inputs, pending)) return;  // rank 0 failed and says why
  if (pending.empty()) return world.bye("");
  if (!setupError.empty()) return world.bye(setupError);
  if (inputs != rank0Inputs) {
    return world.bye("its spec " + a.spec + " or model " + setup.spec.modelPath +
                     " has other bytes than rank 0's");
  }
  std::unique_ptr<JobRunner> runner;
  try {
    runner = std::make_unique<JobRunner>(setup,
                                         std::vector<std::size_t>(pending.begin(), pending.end()));
  } catch (const std::exception& e) {
    return world.bye(e.what());
  }
  const auto worker = [&] {
    std::string outcome;
    for (std::int64_t i = world.requestJob(outcome); i >= 0; i = world.requestJob(outcome)) {
      const auto job = static_cast<std::size_t>(i);
      JobOutcome o;
      o.files = setup.jobFiles(job);
      runner->run(job, o);
      if (o.done) {
        try {
          syncOutputs(o.files, setup.spec.outputDir);
        } catch (const std::exception& e) {
          o.done = false;
          o.error = e.what();
        }
      }
      outcome = encodeOutcome(job, o);
    }
  };
  const int workers = world.threadsMayTalk() ? std::min<int>(resolveThreads(setup.threads),
                                                             static_cast<int>(pending.size()))
                                             : 1;
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  world.bye("");
}

/// Until started, a rank 0 that fails tells the other ranks there is no run.
struct StartGuard {
  BatchWorld* world;
  bool started = false;
  ~StartGuard() {
    if (world != nullptr && !started) world->start(false, 0, {});
  }
};

void runBatch(const BatchArgs& a) {
  const std::unique_ptr<BatchWorld> world = joinBatchWorld();
  if (world && world->rank() != 0) return runWorkerRank(a, *world);
  StartGuard guard{world.get()};

  BatchSetup setup = readSetup(a);
  const BatchSpec& spec = setup.spec;
  const std::string& extension = setup.extension;
  std::vector<std::string> outputs;
  for (const char* name : {"summary.json", "summary.csv", "batch.pvd", kLockName, kJournalName})
    outputs.push_back((fs::path(spec.outputDir) / name).string());
  for (std::size_t i = 0; i < spec.jobs.size(); ++i) {
    for (const std::string& f : setup.jobFiles(i)) outputs.push_back(f);
  }
  checkOutputs(outputs, {a.spec, spec.modelPath});
  setup.model = readModelFile(spec.modelPath);
  const std::uint64_t modelHash = fileHash(spec.modelPath);
  ensureDirectory(spec.outputDir);
  const OutputDirLock lock(spec.outputDir);
  removeStaleTemporaries(spec.outputDir, outputs);
  const std::string summaryPath = (fs::path(spec.outputDir) / "summary.json").string();
  const std::map<std::string, json> previous =
      readJournal((fs::path(spec.outputDir) / kJournalName).string());
  std::vector<json> kept;  // journal lines of the jobs skipped this run

  const std::size_t n = spec.jobs.size();
  std::vector<std::string> fingerprints(n);
  std::vector<JobOutcome> outcomes(n);
  std::vector<std::size_t> pendingJobs;
  for (std::size_t i = 0; i < n; ++i) {
    const BatchJob& job = spec.jobs[i];
    fingerprints[i] = fingerprint(spec, job, modelHash);
    outcomes[i].files = setup.jobFiles(i);
    const auto record = previous.find(job.name);
    bool skip = record != previous.end() &&
                record->second["fingerprint"].get<std::string>() == fingerprints[i];
    for (const std::string& f : outcomes[i].files) skip = skip && fs::exists(f);
    if (skip) {
      outcomes[i].quality = record->second.value("quality", json::object());
      kept.push_back(record->second);
      outcomes[i].done = outcomes[i].skipped = true;
    } else {
      pendingJobs.push_back(i);
    }
  }

  // On stdout: stderr stays the one error line of a failing batch.
  if (!a.quiet) std::cout << "tetblend: " << runNote(spec, pendingJobs.size()) << std::endl;

  Journal journal(spec.outputDir, kept);
  if (world) {
    world->start(true, inputsHash(spec, modelHash),
                 std::vector<std::int64_t>(pendingJobs.begin(), pendingJobs.end()));
    guard.started = true;
  }
  if (!pendingJobs.empty() || world) {
    try {
      const int workers =
          std::min<int>(resolveThreads(setup.threads), static_cast<int>(pendingJobs.size()));
      const int localWorkers = world && a.coordinatorOnly ? 0 : workers;
      std::unique_ptr<JobRunner> runner;
      if (localWorkers > 0) runner = std::make_unique<JobRunner>(setup, pendingJobs);
      std::vector<std::size_t> perRank(world ? static_cast<std::size_t>(world->size()) : 1);
      std::mutex perRankMutex;
      ProgressBar progress("batch", pendingJobs.size(), a.quiet);
      std::atomic<std::size_t> next{0};
      const auto takeJob = [&]() -> std::int64_t {
        const std::size_t t = next++;
        return t < pendingJobs.size() ? static_cast<std::int64_t>(pendingJobs[t]) : -1;
      };
      // The journal line of a finished job, written here only (rank 0).
      const auto record = [&](std::size_t i, int rank) {
        {
          std::lock_guard<std::mutex> lock(perRankMutex);
          ++perRank[static_cast<std::size_t>(rank)];
        }
        JobOutcome& o = outcomes[i];
        if (o.done) {
          try {
            journal.append({{"name", spec.jobs[i].name},
                            {"fingerprint", fingerprints[i]},
                            {"files", o.files},
                            {"quality", o.quality}});
          } catch (const std::exception& e) {
            o.done = false;
            o.error = e.what();
          }
        }
        progress.advance();
      };
      const auto worker = [&] {
        for (std::int64_t t = takeJob(); t >= 0; t = takeJob()) {
          const auto i = static_cast<std::size_t>(t);
          runner->run(i, outcomes[i]);
          record(i, 0);
        }
      };
      std::vector<std::thread> pool;
      if (!world) {
        for (int w = 1; w < workers; ++w) pool.emplace_back(worker);
        worker();
      } else {
        // This thread serves the other ranks; `localWorkers` threads blend here.
        for (int w = 0; w < localWorkers; ++w) pool.emplace_back(worker);
        world->serve(
            takeJob,
            [&](int rank, const std::string& text) {
              std::size_t i = 0;
              try {
                i = decodeOutcome(text, outcomes);
              } catch (const std::exception& e) {
                world->abort("batch: rank " + std::to_string(rank) + " sent a bad outcome (" +
                             e.what() + ")");
              }
              record(i, rank);
            },
            [&](int rank, const std::string& reason) {
              std::cerr << "tetblend: warning: batch: rank " << rank
                        << " cannot run jobs (the other ranks run them): " << reason << std::endl;
            });
      }
      for (std::thread& t : pool) t.join();
      if (next < pendingJobs.size()) {  // no other rank could take them: do them here
        if (!runner) runner = std::make_unique<JobRunner>(setup, pendingJobs);
        worker();
      }
      if (world && !a.quiet) {
        std::cout << "tetblend: batch: jobs run per rank:";
        for (std::size_t r = 0; r < perRank.size(); ++r)
          std::cout << (r ? ", " : " ") << r << ": " << perRank[r];
        std::cout << std::endl;
      }
    } catch (const std::exception& e) {
      if (world) world->abort(e.what());  // the other ranks wait for work
      throw;
    }
  }

  writeSummaries(spec, fingerprints, outcomes);
  std::vector<PvdDataSet> sets;
  int failed = 0;
  std::string firstError;
  for (std::size_t i = 0; i < n; ++i) {
    if (outcomes[i].done) {
      sets.push_back({static_cast<double>(i), spec.jobs[i].name + extension, 0});
    } else if (failed++ == 0) {
      firstError = "job '" + spec.jobs[i].name + "': " + outcomes[i].error;
    }
  }
  if (!sets.empty()) writePvdCollection((fs::path(spec.outputDir) / "batch.pvd").string(), sets);
  if (failed > 0) {
    throw InputError("batch: " + std::to_string(failed) + " of " + std::to_string(n) +
                     " jobs failed (first: " + firstError + "); see " + summaryPath);
  }
}

}  // namespace

void registerBatch(CLI::App& root) {
  auto args = std::make_shared<BatchArgs>();
  CLI::App* cmd = root.add_subcommand(
      "batch",
      "Run the blend jobs of a JSON spec over one model, in parallel. Writes <output_dir>/<job>"
      ".vtu and .vtp per job (only the .vtp with \"surface_only\"), batch.pvd (all finished "
      "jobs, time = job index), summary.json (paths relative to the spec's folder) and "
      "summary.csv (quality figures per job). A failing job is reported and the others go on; "
      "the exit code is non-zero if any failed. The first line on stdout says how many jobs run, "
      "how many a re-run skips and why, and the output folder. A second run on the same output_dir "
      "while one "
      "is running is refused. Re-running (also after a kill) skips jobs that the journal "
      "<output_dir>/.tetblend-batch.journal records as done with the same fingerprint (model "
      "bytes, method, weights, options) whose files exist. "
      "Under mpirun or srun (when built with MPI) the jobs are shared among the ranks, handed "
      "out one at a time; rank 0 writes the journal, the summaries and the .pvd. "
      "Spec: {\"model\", \"output_dir\" (default <spec>_out), \"method\" (default kaji), "
      "\"consistency\" (on), \"nonlinear\" (false), \"surface_formats\" ([]), \"surface_only\" "
      "(false), \"quality_arrays\" (\"all\"; \"none\" or names, as --quality-arrays of blend), "
      "\"compression\" (\"lz4\"; \"zlib\" or \"none\"), \"compression_level\" (5; 1..9), "
      "\"threads\" (0), "
      "\"jobs\": [{\"name\", \"weights\": [one per example] or {\"example name or 1-based "
      "index\": weight, ...} (the others 0), \"method\"}]}; paths relative to the spec.");
  cmd->add_option("SPEC", args->spec, "batch spec (.json)")->required();
  cmd->add_option("--threads", args->threads,
                  "job workers and TBB threads; 0 = all cores; default: the spec's \"threads\"")
      ->check(CLI::Range(0, kMaxThreads));
  cmd->add_option("--compression", args->compression,
                  "compressor of the .vtu/.vtp data: lz4, zlib or none; default: the spec's "
                  "\"compression\"");
  cmd->add_option("--compression-level", args->compressionLevel,
                  "1 (fastest) .. 9 (smallest); default: the spec's \"compression_level\"")
      ->check(CLI::Range(kMinCompressionLevel, kMaxCompressionLevel));
  cmd->add_flag("--coordinator-only", args->coordinatorOnly,
                "under mpirun/srun: rank 0 hands out the jobs and writes the journal and "
                "summaries but blends none itself (for a rank 0 on a login or head node); "
                "ignored without MPI");
  addQuietOption(*cmd, args->quiet);
  cmd->callback([args] { runBatch(*args); });
}

}  // namespace tetblend::cli

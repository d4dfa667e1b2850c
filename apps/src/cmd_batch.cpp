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

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include "batch_journal.h"
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
};

struct JobOutcome {
  bool done = false;
  bool skipped = false;
  std::string error;
  std::vector<std::string> files;
  QualitySummary quality;
  json previousQuality;  // for skipped jobs
  double seconds = 0.0;
};

std::vector<double> jobWeights(const BatchJob& job, std::size_t exampleCount) {
  if (!job.weights.is_array()) throw InputError("\"weights\" must be an array of numbers");
  std::vector<double> w;
  for (const json& x : job.weights) {
    if (!x.is_number()) throw InputError("\"weights\" must be an array of numbers");
    w.push_back(x.get<double>());
  }
  requireWeightCount(w, exampleCount, "\"weights\"");
  return w;
}

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
    json quality = o.previousQuality;
    if (o.done && !o.skipped) {
      quality = json::object();
      for (const auto& c : qualityColumns(o.quality)) quality[c.first] = c.second;
    }
    if (o.done) entry["quality"] = quality;
    if (!o.done) entry["error"] = o.error;
    summary["jobs"].push_back(entry);

    std::string weights;
    if (job.weights.is_array())
      for (const json& x : job.weights) weights += (weights.empty() ? "" : " ") + x.dump();
    csv << csvField(job.name) << "," << csvField(job.method) << "," << (o.done ? "done" : "failed")
        << "," << csvField(weights);
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

void runBatch(const BatchArgs& a) {
  BatchSpec spec = readBatchSpec(a.spec);
  if (!a.compression.empty() || a.compressionLevel != 0) {
    spec.compression = parseVtkCompression(
        a.compression.empty() ? vtkCompressorName(spec.compression.compressor) : a.compression,
        a.compressionLevel != 0 ? a.compressionLevel : spec.compression.level, "--compression");
  }
  const std::vector<std::string> formats = parseSurfaceFormats(spec.surfaceFormats);
  const bool consistency = parseOnOff(spec.consistency, a.spec + ": \"consistency\"");
  const std::string arraysWhere = a.spec + ": \"quality_arrays\"";
  const QualityArrays arrays = parseQualityArrays(spec.qualityArrays, arraysWhere);
  if (spec.surfaceOnly && !arrays.all && !arrays.names.empty()) {
    throw InputError(arraysWhere +
                     " names arrays, but \"surface_only\" writes no .vtu to hold them");
  }
  std::vector<std::string> outputs;
  for (const char* name : {"summary.json", "summary.csv", "batch.pvd", kLockName, kJournalName})
    outputs.push_back((fs::path(spec.outputDir) / name).string());
  const std::string extension = spec.surfaceOnly ? ".vtp" : ".vtu";
  for (const BatchJob& job : spec.jobs) {
    for (const std::string& f :
         blendOutputFiles((fs::path(spec.outputDir) / (job.name + extension)).string(), formats))
      outputs.push_back(f);
  }
  checkOutputs(outputs, {a.spec, spec.modelPath});
  const ModelData model = readModelFile(spec.modelPath);
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
    const std::string primary = (fs::path(spec.outputDir) / (job.name + extension)).string();
    outcomes[i].files = blendOutputFiles(primary, formats);
    const auto record = previous.find(job.name);
    bool skip = record != previous.end() &&
                record->second["fingerprint"].get<std::string>() == fingerprints[i];
    for (const std::string& f : outcomes[i].files) skip = skip && fs::exists(f);
    if (skip) {
      outcomes[i].previousQuality = record->second.value("quality", json::object());
      kept.push_back(record->second);
      outcomes[i].done = outcomes[i].skipped = true;
    } else {
      pendingJobs.push_back(i);
    }
  }

  // On stdout: stderr stays the one error line of a failing batch.
  if (!a.quiet) std::cout << "tetblend: " << runNote(spec, pendingJobs.size()) << std::endl;

  Journal journal(spec.outputDir, kept);
  if (!pendingJobs.empty()) {
    std::map<std::string, std::string> methodError;  // method name -> why it cannot run
    std::vector<BlendMethod> methods;
    for (std::size_t i : pendingJobs) {
      const std::string& name = spec.jobs[i].method;
      if (methodError.count(name)) continue;
      try {
        const BlendMethod m = parseMethod(name);
        methodError[name] = "";
        if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
      } catch (const Error& e) {
        methodError[name] = e.what();
      }
    }
    const ThreadLimit limit(a.threads >= 0 ? a.threads : spec.threads);
    const QualityFigures figures = qualityFigures(arrays, !spec.surfaceOnly);
    std::unique_ptr<ShapeBlender> blender;
    for (BlendMethod m : methods) {
      try {
        if (!blender) {
          blender = std::make_unique<ShapeBlender>(
              makeBlender(model, {m}, consistency, spec.nonlinear, figures.targetResidual));
        } else {
          blender->prepare(m);
        }
      } catch (const DomainError& e) {
        methodError[blendMethodName(m)] = e.what();
      }
    }

    const RestTetData restData = restTetData(model.rest);
    ProgressBar progress("batch", pendingJobs.size(), a.quiet);
    std::mutex blendMutex;
    std::atomic<std::size_t> next{0};
    const auto worker = [&] {
      for (std::size_t t = next++; t < pendingJobs.size(); t = next++) {
        const std::size_t i = pendingJobs[t];
        const BatchJob& job = spec.jobs[i];
        JobOutcome& o = outcomes[i];
        const auto start = std::chrono::steady_clock::now();
        try {
          const std::vector<double> weights = jobWeights(job, model.examples.size());
          if (!methodError.at(job.method).empty()) throw InputError(methodError.at(job.method));
          BlendedShape shape;
          {
            std::lock_guard<std::mutex> lock(blendMutex);
            shape =
                blendShape(*blender, model, restData, weights, parseMethod(job.method), figures);
          }
          writeBlendResult(o.files.front(), model, shape.vertices,
                           selectQualityArrays(shape.cellData, arrays, "\"quality_arrays\""),
                           formats, spec.compression);
          o.quality = shape.quality;
          json quality = json::object();
          for (const auto& c : qualityColumns(o.quality)) quality[c.first] = c.second;
          journal.append({{"name", job.name},
                          {"fingerprint", fingerprints[i]},
                          {"files", o.files},
                          {"quality", quality}});
          o.done = true;
        } catch (const std::exception& e) {
          o.error = e.what();
        }
        o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        progress.advance();
      }
    };
    const int workers = std::min<int>(resolveThreads(a.threads >= 0 ? a.threads : spec.threads),
                                      static_cast<int>(pendingJobs.size()));
    std::vector<std::thread> pool;
    for (int w = 1; w < workers; ++w) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
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
      "Spec: {\"model\", \"output_dir\" (default <spec>_out), \"method\" (default kaji), "
      "\"consistency\" (on), \"nonlinear\" (false), \"surface_formats\" ([]), \"surface_only\" "
      "(false), \"quality_arrays\" (\"all\"; \"none\" or names, as --quality-arrays of blend), "
      "\"compression\" (\"lz4\"; \"zlib\" or \"none\"), \"compression_level\" (5; 1..9), "
      "\"threads\" (0), "
      "\"jobs\": [{\"name\", \"weights\": [..], \"method\"}]}; paths relative to the spec.");
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
  addQuietOption(*cmd, args->quiet);
  cmd->callback([args] { runBatch(*args); });
}

}  // namespace tetblend::cli

#pragma once
// The JSON job list of `tetblend batch`:
//   {
//     "model": "bar.tbm",            model file, relative to the spec's folder
//     "output_dir": "bar_batch",     default: <spec name without .json>_out
//     "method": "kaji",              default method of the jobs (default kaji)
//     "consistency": "on",           rotation consistency, on|off (default on)
//     "nonlinear": false,            nonlinear stitch (default false)
//     "surface_formats": ["obj"],    extra surface files (default none)
//     "surface_only": false,         write <name>.vtp alone, no .vtu (default false)
//     "quality_arrays": "all",       .vtu cell arrays: "all", "none", "a,b" or
//                                    ["a", "b"] (default all; quality_arrays.h)
//     "compression": "lz4",          compressor of the .vtu/.vtp: lz4, zlib or none
//                                    (default lz4)
//     "compression_level": 5,        1 (fastest) .. 9 (smallest) (default 5)
//     "threads": 0,                  job workers, 0 = all cores, at most 1024 (default 0)
//     "jobs": [ {"name": "half", "weights": [0.5, 0], "method": "dq"},
//               {"name": "some", "weights": {"frame012": 0.5, "3": 0.25}}, ... ]
//   }
// A job's "name" (letters, digits, '-', '_', '.'; unique) names its output
// files <output_dir>/<name>.vtu and .vtp (only .vtp when surface_only);
// "method" overrides the default. "weights" is an array of one number per
// example, or an object of some examples' weights keyed by the example's
// name or 1-based index (batch_job_weights.h; the others get 0).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "blend_compression.h"

namespace tetblend::cli {

/// One job as written in the spec. Its fields are checked when it runs, so a
/// bad job fails alone; only its name is checked when the spec is read.
struct BatchJob {
  std::string name;
  nlohmann::json weights;  ///< as written; checked by jobWeights (batch_job_weights.h)
  std::string method;      ///< resolved: the job's or the spec's default
};

/// A read batch spec with every path resolved against the spec's folder.
struct BatchSpec {
  std::string specPath;
  std::string modelPath;
  std::string outputDir;
  std::string consistency = "on";
  bool nonlinear = false;
  std::vector<std::string> surfaceFormats;
  bool surfaceOnly = false;
  std::string qualityArrays = "all";  ///< the text of --quality-arrays; "a,b" for ["a", "b"]
  VtkCompression compression = kBlendOutputCompression;
  int threads = 0;
  std::vector<BatchJob> jobs;
};

/// Reads `path`. InputError (naming the file and the entry) for unreadable
/// JSON, a missing model or jobs entry, a quality_arrays neither a string nor
/// an array of strings, an unknown compression or a level outside 1..9, a
/// job without a valid name, or two jobs with one name.
BatchSpec readBatchSpec(const std::string& path);

}  // namespace tetblend::cli

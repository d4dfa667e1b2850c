#include "batch_spec.h"

#include <filesystem>
#include <fstream>
#include <set>

#include "cli_common.h"
#include "tetblend/core/error.h"

namespace tetblend::cli {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool validName(const std::string& name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'))
      return false;
  return true;
}

std::string resolve(const fs::path& base, const std::string& p) {
  const fs::path path(p);
  return (path.is_absolute() ? path : base / path).lexically_normal().string();
}

// "quality_arrays" as the text of --quality-arrays: a string as is, an array
// of names joined by commas ([] = "none"). The names are checked when the
// batch runs (parseQualityArrays).
std::string qualityArraysText(const json& value, const std::string& where) {
  if (value.is_string()) return value.get<std::string>();
  if (!value.is_array()) {
    throw InputError(where + " is " + value.dump() +
                     ": give \"all\", \"none\" or the names of the arrays");
  }
  if (value.empty()) return "none";
  std::string text;
  for (const json& name : value) {
    if (!name.is_string()) throw InputError(where + " lists " + name.dump() + ": not a name");
    text += (text.empty() ? "" : ",") + name.get<std::string>();
  }
  return text;
}

}  // namespace

BatchSpec readBatchSpec(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the batch spec");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {
    throw InputError(path + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  const fs::path base = fs::path(path).parent_path();
  BatchSpec spec;
  spec.specPath = path;
  try {
    if (!j.is_object() || !j.contains("model") || !j["model"].is_string()) {
      throw InputError(path + ": needs \"model\": the model file made by 'tetblend prepare'");
    }
    spec.modelPath = resolve(base, j["model"].get<std::string>());
    spec.outputDir = resolve(base, j.value("output_dir", fs::path(path).stem().string() + "_out"));
    spec.consistency = j.value("consistency", std::string("on"));
    spec.nonlinear = j.value("nonlinear", false);
    spec.surfaceFormats = j.value("surface_formats", std::vector<std::string>{});
    spec.surfaceOnly = j.value("surface_only", false);
    spec.qualityArrays =
        qualityArraysText(j.value("quality_arrays", json("all")), path + ": \"quality_arrays\"");
    const json level = j.value("compression_level", json(kBlendOutputCompression.level));
    if (!level.is_number_integer()) {
      throw InputError(path + ": \"compression_level\" is " + level.dump() +
                       ": give a whole number " + std::to_string(kMinCompressionLevel) + ".." +
                       std::to_string(kMaxCompressionLevel));
    }
    spec.compression = parseVtkCompression(
        j.value("compression", vtkCompressorName(kBlendOutputCompression.compressor)),
        level.get<int>(), path + ": \"compression\"");
    const json threads = j.value("threads", json(0));
    if (!threads.is_number_integer() || threads.get<double>() < 0 ||
        threads.get<double>() > kMaxThreads) {
      throw InputError(path + ": \"threads\" is " + threads.dump() + ": give a whole number 0.." +
                       std::to_string(kMaxThreads) + " (0 = all cores)");
    }
    spec.threads = threads.get<int>();
    const std::string method = j.value("method", std::string("kaji"));
    if (!j.contains("jobs") || !j["jobs"].is_array() || j["jobs"].empty()) {
      throw InputError(path + ": needs a non-empty \"jobs\" array");
    }
    std::set<std::string> names;
    for (std::size_t i = 0; i < j["jobs"].size(); ++i) {
      const json& job = j["jobs"][i];
      const std::string where = path + ": jobs[" + std::to_string(i) + "]";
      if (!job.is_object() || !job.contains("name") || !job["name"].is_string() ||
          !validName(job["name"].get<std::string>())) {
        throw InputError(where + " needs a \"name\" of letters, digits, '-', '_' or '.'");
      }
      BatchJob b{job["name"].get<std::string>(), job.value("weights", json()),
                 job.value("method", method)};
      if (!names.insert(b.name).second) {
        throw InputError(where + ": the name '" + b.name + "' is used by an earlier job");
      }
      spec.jobs.push_back(std::move(b));
    }
  } catch (const json::exception& e) {
    throw InputError(path + ": bad entry (" + std::string(e.what()) + ")");
  }
  return spec;
}

}  // namespace tetblend::cli

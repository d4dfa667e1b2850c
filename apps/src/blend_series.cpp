#include "blend_series.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "blend_output.h"
#include "cli_common.h"
#include "progress.h"
#include "quality_arrays.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/atomic_file.h"
#include "tetblend/meshing/pvd_collection.h"
#include "tetblend/pipeline/blended_shape.h"
#include "tetblend/pipeline/format_number.h"
#include "tetblend/pipeline/make_blender.h"

namespace tetblend::cli {

namespace fs = std::filesystem;

void blendSeries(const ModelData& model, const BlendSettings& settings,
                 const std::vector<SeriesItem>& items, const std::string& dir,
                 const std::string& collection, const std::vector<std::string>& inputs,
                 bool quiet) {
  if (items.empty()) throw InputError("nothing to blend: the series is empty");
  const BlendMethod method = parseMethod(settings.method);
  const std::vector<std::string> formats = parseSurfaceFormats(settings.surfaceFormats);
  const QualityArrays arrays = parseQualityArrays(settings.qualityArrays, "--quality-arrays");
  const VtkCompression compression =
      parseVtkCompression(settings.compression, settings.compressionLevel, "--compression");
  for (const SeriesItem& item : items)
    requireWeightCount(item.weights, model.examples.size(), "weights of " + item.name);
  std::vector<std::string> outputs = {(fs::path(dir) / (collection + ".pvd")).string(),
                                      (fs::path(dir) / "weights.csv").string()};
  for (const SeriesItem& item : items) {
    for (const std::string& f :
         blendOutputFiles((fs::path(dir) / (item.name + ".vtu")).string(), formats))
      outputs.push_back(f);
  }
  checkOutputs(outputs, inputs);
  ensureDirectory(dir);
  const QualityFigures figures = qualityFigures(arrays, true);
  const ShapeBlender blender =
      makeBlender(model, {method}, parseOnOff(settings.consistency, "--consistency"),
                  settings.nonlinear, figures.targetResidual);
  const RestTetData restData = modelRestData(model);
  ProgressBar progress("blend", items.size(), quiet);
  std::vector<PvdDataSet> sets;
  std::ostringstream csv;
  csv << "name,time";
  for (std::size_t k = 0; k < model.examples.size(); ++k) csv << ",w" << k + 1;
  csv << "\n";
  std::size_t shapesWithInverted = 0;
  int mostInverted = 0;
  std::string worst;
  for (const SeriesItem& item : items) {
    const BlendedShape shape = blendShape(blender, model, restData, item.weights, method, figures);
    if (shape.quality.invertedCount > 0) ++shapesWithInverted;
    if (shape.quality.invertedCount > mostInverted) {
      mostInverted = shape.quality.invertedCount;
      worst = item.name;
    }
    writeBlendResult((fs::path(dir) / (item.name + ".vtu")).string(), model, shape.vertices,
                     selectQualityArrays(shape.cellData, arrays, "--quality-arrays"), formats,
                     compression);
    sets.push_back({item.time, item.name + ".vtu", 0});
    csv << item.name << "," << formatNumber(item.time);
    for (double w : item.weights) csv << "," << formatNumber(w);
    csv << "\n";
    progress.advance();
  }
  writePvdCollection((fs::path(dir) / (collection + ".pvd")).string(), sets);
  const std::string csvPath = (fs::path(dir) / "weights.csv").string();
  writeFileAtomically(csvPath, [&](const std::string& temp) {
    std::ofstream out(temp);
    out << csv.str();
    if (!out.flush()) throw InputError(csvPath + ": cannot write");
  });
  progress.finish();
  if (shapesWithInverted > 0) {
    printWarning(dir + ": " + std::to_string(shapesWithInverted) + " of " +
                 std::to_string(items.size()) + " shapes have inverted tets (most: " + worst +
                 ", " + std::to_string(mostInverted) + " of " +
                 std::to_string(model.rest.tets.rows()) + " tets; cell array 'inverted')");
  }
}

}  // namespace tetblend::cli

#pragma once
// Choosing the per-tet quality arrays a blend writes to its .vtu
// (--quality-arrays, a batch spec's "quality_arrays"): all of them, none, or
// a named subset of blendCellArrayNames().

#include <string>
#include <vector>

#include "tetblend/blending/quality.h"
#include "tetblend/meshing/mesh_data_arrays.h"

namespace tetblend::cli {

/// Which cell arrays go into a blend's .vtu.
struct QualityArrays {
  bool all = true;                 ///< every array the blend makes (the default)
  std::vector<std::string> names;  ///< when !all: exactly these; empty = none
};

/// Parses "all", "none" or a comma-separated list of names from
/// blendCellArrayNames() ("volume_ratio,inverted"); the names are kept in
/// that list's order, each once. InputError naming `what`, the bad value and
/// the valid names.
QualityArrays parseQualityArrays(const std::string& text, const std::string& what);

/// "all", "none" or the names joined by commas: equal choices give equal text.
std::string qualityArraysText(const QualityArrays& choice);

/// The per-tet figures a blend computes for `choice` beyond volume ratio and
/// inversion: those whose array is written, none when no .vtu is
/// (`writesVtu` false: a surface output).
QualityFigures qualityFigures(const QualityArrays& choice, bool writesVtu);

/// The arrays of `cellData` that `choice` keeps, in cellData's order.
/// InputError naming `where` when a named array is not among them (the
/// target_residual of vertex-linear, which has no per-tet targets; excluded
/// for a model without excluded tets).
std::vector<NamedArray> selectQualityArrays(const std::vector<NamedArray>& cellData,
                                            const QualityArrays& choice, const std::string& where);

}  // namespace tetblend::cli

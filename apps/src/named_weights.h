#pragma once
// Weights given by example rather than one per example: `--weight
// frame012=0.5 --weight 3=0.25` on the command line, {"frame012": 0.5,
// "3": 0.25} as a batch job's "weights". An example is named by
//   - its source as the model records it (ModelData::exampleSources: the
//     path given to prepare, e.g. "poses/frame012.obj"),
//   - that source's file stem, without folder and extension ("frame012"),
//   - or its 1-based index, as `tetblend inspect` counts the examples ("3").
// A whole-source match wins over a stem match. A key of digits that is an
// index and also names another example is refused as ambiguous. Examples
// not named get weight 0.

#include <cstddef>
#include <string>
#include <vector>

namespace tetblend::cli {

/// One example's weight as written.
struct ExampleWeight {
  std::string example;  ///< the example's source, stem or 1-based index
  double weight = 0.0;  ///< finite
  std::string where;    ///< the entry as written, to start its errors ("--weight a=0.5")
};

/// Parses "NAME_OR_INDEX=VALUE" (split at the last '=', so a name may hold
/// one); VALUE is a finite real. InputError starting with `where` otherwise.
ExampleWeight parseExampleWeight(const std::string& text, const std::string& where);

/// The 0-based index of the example `key` names (see the file comment) among
/// the examples recorded as `sources`. InputError starting with `where` for
/// an unknown name (listing a few names and, when `modelPath` is not empty,
/// how `tetblend inspect` lists them all), a name of several examples (use
/// the index), an index out of range (the valid range), or an index that
/// also names another example.
std::size_t findExample(const std::string& key, const std::vector<std::string>& sources,
                        const std::string& where, const std::string& modelPath);

/// One weight per example of `sources`: the weights of `entries`, 0 for the
/// examples they do not name. InputError as findExample, and for an example
/// named twice (by any two of its source, stem and index).
std::vector<double> exampleWeights(const std::vector<ExampleWeight>& entries,
                                   const std::vector<std::string>& sources,
                                   const std::string& modelPath);

}  // namespace tetblend::cli

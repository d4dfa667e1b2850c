#include "quality_arrays.h"

#include <algorithm>
#include <set>

#include "tetblend/core/error.h"
#include "tetblend/pipeline/blended_shape.h"

namespace tetblend::cli {

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ",") + n;
  return text;
}

}  // namespace

QualityArrays parseQualityArrays(const std::string& text, const std::string& what) {
  if (text == "all") return {};
  if (text == "none") return {false, {}};
  const std::vector<std::string>& known = blendCellArrayNames();
  const std::string use = "; use all, none or a comma-separated list of " + join(known);
  if (text.empty()) throw InputError(what + ": empty" + use);
  std::set<std::string> asked;
  std::size_t start = 0;
  for (;;) {  // every comma-separated field, the empty last one of "a," included
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, comma - start);
    if (name.empty()) throw InputError(what + ": an empty array name in '" + text + "'" + use);
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw InputError(what + ": unknown quality array '" + name + "'" + use);
    }
    asked.insert(name);
    if (comma == text.size()) break;
    start = comma + 1;
  }
  QualityArrays choice{false, {}};
  for (const std::string& n : known)
    if (asked.count(n)) choice.names.push_back(n);
  return choice;
}

std::string qualityArraysText(const QualityArrays& choice) {
  if (choice.all) return "all";
  return choice.names.empty() ? "none" : join(choice.names);
}

QualityFigures qualityFigures(const QualityArrays& choice, bool writesVtu) {
  const auto wanted = [&](const std::string& name) {
    return writesVtu && (choice.all || std::find(choice.names.begin(), choice.names.end(), name) !=
                                           choice.names.end());
  };
  return {wanted("distortion"), wanted("rotation_angle"), wanted("target_residual")};
}

std::vector<NamedArray> selectQualityArrays(const std::vector<NamedArray>& cellData,
                                            const QualityArrays& choice, const std::string& where) {
  if (choice.all) return cellData;
  const auto chosen = [&](const std::string& name) {
    return std::find(choice.names.begin(), choice.names.end(), name) != choice.names.end();
  };
  std::vector<NamedArray> kept;
  for (const NamedArray& a : cellData)
    if (chosen(a.name)) kept.push_back(a);
  for (const std::string& name : choice.names) {
    const auto found = std::find_if(cellData.begin(), cellData.end(),
                                    [&](const NamedArray& a) { return a.name == name; });
    if (found == cellData.end()) {
      throw InputError(where + ": this blend has no quality array '" + name + "'" +
                       (name == "target_residual" ? " (vertex-linear has no per-tet targets)"
                        : name == "excluded"      ? " (the model has no excluded tets)"
                                                  : ""));
    }
  }
  return kept;
}

}  // namespace tetblend::cli

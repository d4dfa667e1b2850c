#include "quality_arrays.h"

#include <algorithm>
#include <set>
#include <sstream>

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
  std::set<std::string> asked;
  std::istringstream in(text);
  std::string name;
  bool any = false;
  while (std::getline(in, name, ',')) {
    any = true;
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw InputError(what + ": unknown quality array '" + name + "'; use all, none or " +
                       "a comma-separated list of " + join(known));
    }
    asked.insert(name);
  }
  if (!any || text.back() == ',') {
    throw InputError(what + ": '" + text + "' names no array; use all, none or a " +
                     "comma-separated list of " + join(known));
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

#include "tetblend/meshing/pvd_collection.h"

#include <cmath>
#include <filesystem>

#include "tetblend/core/error.h"
#include "text_parsing.h"

namespace tetblend {
namespace {

std::string escapeXml(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

void writePvdCollection(const std::string& path, const std::vector<PvdDataSet>& dataSets) {
  namespace fs = std::filesystem;
  if (dataSets.empty()) throw InputError(path + ": no data sets to collect");
  const fs::path directory = fs::absolute(fs::path(path)).parent_path();
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (std::size_t i = 0; i < dataSets.size(); ++i) {
    const PvdDataSet& d = dataSets[i];
    const std::string entry = path + ": data set " + std::to_string(i);
    if (d.file.empty()) throw InputError(entry + " has an empty file name");
    if (!std::isfinite(d.time)) throw InputError(entry + " has a non-finite time");
    if (d.part < 0) throw InputError(entry + " has negative part " + std::to_string(d.part));
    fs::path file(d.file);
    if (file.is_absolute()) file = file.lexically_relative(directory);
    if (file.empty()) {
      throw InputError(entry + ": '" + d.file + "' cannot be expressed relative to " +
                       directory.string());
    }
    out += "    <DataSet timestep=\"";
    detail::appendDouble(out, d.time);
    out += "\" group=\"\" part=\"";
    detail::appendInteger(out, d.part);
    out += "\" file=\"" + escapeXml(file.generic_string()) + "\"/>\n";
  }
  out += "  </Collection>\n</VTKFile>\n";
  detail::writeBytesAtomically(path, out);
}

}  // namespace tetblend

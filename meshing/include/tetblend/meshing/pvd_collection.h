#pragma once
// ParaView .pvd collections (time series and multi-part data sets). VTK 9.1
// has no writer for them (vtkPVDReader lives in ParaView), so the XML is
// written here.

#include <string>
#include <vector>

namespace tetblend {

/// One entry of a .pvd collection: the data set `file` shown at `time`
/// (any finite value; ParaView sorts by it) as part `part` (0 unless several
/// files make up one time step).
struct PvdDataSet {
  double time = 0.0;
  std::string file;
  int part = 0;
};

/// Writes the collection `dataSets` to `path` (a .pvd file), atomically.
/// Relative `file` paths are taken relative to the directory of `path` and
/// written as given; absolute ones are rewritten relative to that directory,
/// so the collection can be moved together with its files. Files are not
/// required to exist yet. Times are written in shortest exact decimal form.
/// Throws InputError for an empty list, an empty file name, a non-finite
/// time, a negative part, or an I/O failure (the old file is then kept).
void writePvdCollection(const std::string& path, const std::vector<PvdDataSet>& dataSets);

}  // namespace tetblend

#pragma once
// Named per-point and per-cell data arrays attached to a mesh when it is
// written for ParaView (.vtu/.vtp).

#include <string>
#include <vector>

namespace tetblend {

/// One data array: `values` holds count * components numbers, element-major
/// (the components of element 0, then of element 1, ...). `name` must be
/// non-empty, without whitespace, and unique among the arrays of its kind
/// (ParaView shows it as is, e.g. "volume_ratio", "displacement").
struct NamedArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

/// The arrays written with a mesh: pointData has one tuple per vertex (in
/// vertex order), cellData one tuple per cell (triangle or tet, in order).
struct MeshDataArrays {
  std::vector<NamedArray> pointData;
  std::vector<NamedArray> cellData;
};

}  // namespace tetblend

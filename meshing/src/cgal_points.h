#pragma once
// Private to meshing's CGAL translation units (see meshing/CMakeLists.txt):
// their kernel, and a row of a position matrix as its point.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "tetblend/core/mesh_types.h"

namespace tetblend {
namespace detail {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/// Row `i` of `positions` (#V by 3) as a CGAL point.
inline Kernel::Point_3 pointAt(const Vertices& positions, int i) {
  return Kernel::Point_3(positions(i, 0), positions(i, 1), positions(i, 2));
}

}  // namespace detail
}  // namespace tetblend

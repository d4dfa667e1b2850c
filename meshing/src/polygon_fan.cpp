#include "polygon_fan.h"

namespace tetblend::detail {

Triangles fanTriangles(const PolygonFaces& faces) {
  Eigen::Index count = 0;
  for (std::size_t f = 0; f + 1 < faces.start.size(); ++f) {
    count += static_cast<Eigen::Index>(faces.start[f + 1] - faces.start[f]) - 2;
  }
  Triangles triangles(count, 3);
  Eigen::Index row = 0;
  for (std::size_t f = 0; f + 1 < faces.start.size(); ++f) {
    const std::size_t first = faces.start[f];
    for (std::size_t i = first + 1; i + 1 < faces.start[f + 1]; ++i) {
      triangles.row(row++) << faces.corners[first], faces.corners[i], faces.corners[i + 1];
    }
  }
  return triangles;
}

}  // namespace tetblend::detail

#include "spatial_order.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace tetblend {
namespace {

constexpr int kMortonBits = 21;  // per axis: 63 bits of a 64-bit code

// The bits of x (< 2^21) spread to every third bit.
std::uint64_t spreadBits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

}  // namespace

TetMesh inSpatialOrder(const TetMesh& mesh, int surfaceVertexCount) {
  const Eigen::Index tetCount = mesh.tets.rows();
  if (tetCount == 0) return mesh;
  const Eigen::RowVector3d low = mesh.vertices.colwise().minCoeff();
  const double extent = (mesh.vertices.colwise().maxCoeff() - low).maxCoeff();
  const double scale = extent > 0.0 ? ((1 << kMortonBits) - 1) / extent : 0.0;
  std::vector<std::uint64_t> code(static_cast<std::size_t>(tetCount));
  for (Eigen::Index t = 0; t < tetCount; ++t) {
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k) centroid += mesh.vertices.row(mesh.tets(t, k));
    const Eigen::RowVector3d cell = (centroid / 4 - low) * scale;
    std::uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis) {
      key |= spreadBits(static_cast<std::uint64_t>(cell(axis))) << axis;
    }
    code[static_cast<std::size_t>(t)] = key;
  }
  std::vector<int> order(static_cast<std::size_t>(tetCount));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return code[static_cast<std::size_t>(a)] < code[static_cast<std::size_t>(b)];
  });

  const auto vertexCount = static_cast<std::size_t>(mesh.vertices.rows());
  std::vector<int> newIndex(vertexCount, -1);
  for (int v = 0; v < surfaceVertexCount; ++v) newIndex[static_cast<std::size_t>(v)] = v;
  int next = surfaceVertexCount;
  TetMesh result;
  result.tets.resize(tetCount, 4);
  for (Eigen::Index i = 0; i < tetCount; ++i) {
    for (int k = 0; k < 4; ++k) {
      int& index = newIndex[static_cast<std::size_t>(mesh.tets(order[static_cast<std::size_t>(i)], k))];
      if (index < 0) index = next++;
      result.tets(i, k) = index;
    }
  }
  for (std::size_t v = 0; v < vertexCount; ++v) {
    if (newIndex[v] < 0) newIndex[v] = next++;
  }
  result.vertices.resize(mesh.vertices.rows(), 3);
  for (std::size_t v = 0; v < vertexCount; ++v) {
    result.vertices.row(newIndex[v]) = mesh.vertices.row(static_cast<Eigen::Index>(v));
  }
  return result;
}

}  // namespace tetblend

#include "tet_elements.h"

#include <string>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "tetblend/core/batch_kernels.h"
#include "tetblend/core/error.h"
#include "tetblend/core/polar.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {

namespace {

// The element of the tet with edge matrix `edges` (positive determinant).
TetElement elementOf(const Eigen::Matrix3d& edges) {
  const Eigen::Matrix3d inverse = edges.inverse();  // rows: gradients of λ1..λ3
  TetElement element;
  element.volume = edges.determinant() / 6.0;
  element.gradients.rightCols<3>() = inverse.transpose();
  element.gradients.col(0) = -inverse.transpose().rowwise().sum();
  return element;
}

}  // namespace

std::vector<TetElement> buildTetElements(const TetMesh& mesh) {
  const Eigen::Index vertexCount = mesh.vertices.rows();
  std::vector<TetElement> elements(static_cast<size_t>(mesh.tets.rows()));
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const Eigen::RowVector4i tet = mesh.tets.row(t);
    if (tet.minCoeff() < 0 || tet.maxCoeff() >= vertexCount) {
      throw InputError("tet " + std::to_string(t) + " has a vertex index outside [0, " +
                       std::to_string(vertexCount) + ")");
    }
    const Eigen::Matrix3d edges = tetEdgeMatrix(mesh.vertices, tet);
    const double volume = edges.determinant() / 6.0;
    if (!(volume > 0.0)) {
      throw InputError("rest tet " + std::to_string(t) + " has signed volume " +
                       std::to_string(volume) +
                       "; the rest mesh must be positively oriented and non-degenerate");
    }
    elements[static_cast<size_t>(t)] = elementOf(edges);
  }
  return elements;
}

std::vector<TetElement> thickenedTetElements(const TetMesh& mesh,
                                             const std::vector<TetElement>& elements,
                                             double minSingularRatio) {
  std::vector<TetElement> thickened = elements;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const Eigen::Matrix3d edges = tetEdgeMatrix(mesh.vertices, mesh.tets.row(t));
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(edges, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d sigma = svd.singularValues();  // descending
    const double least = minSingularRatio * sigma(0);
    if (sigma(2) >= least) continue;
    // det U det V = +1 since det D > 0, so the thickened D stays positive.
    thickened[static_cast<size_t>(t)] =
        elementOf(svd.matrixU() * sigma.cwiseMax(least).asDiagonal() * svd.matrixV().transpose());
  }
  return thickened;
}

Eigen::Matrix3d closestRotation(const Eigen::Matrix3d& f) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  const Eigen::Matrix3d v = svd.matrixV();
  if ((u * v.transpose()).determinant() < 0.0) u.col(2) *= -1.0;
  return u * v.transpose();
}

namespace {

// The rotation closest to F: for det F > 0 the polar factor by core's
// Newton iteration (~3× cheaper than an SVD), else, or if it does not
// converge, closestRotation's SVD (reflection removed).
Eigen::Matrix3d fastClosestRotation(const Eigen::Matrix3d& f) {
  if (f.allFinite() && f.determinant() > 0.0) {
    try {
      return polarDecompose(f).rotation;
    } catch (const NumericalError&) {
      // falls through to the SVD, defined for every f
    }
  }
  return closestRotation(f);
}

}  // namespace

void closestRotations(const Eigen::Matrix3d* f, Eigen::Matrix3d* out, std::size_t n) {
  std::vector<std::size_t> positive;
  std::vector<Eigen::Matrix3d> in;
  for (std::size_t i = 0; i < n; ++i) {
    if (f[i].allFinite() && f[i].determinant() > 0.0) {
      positive.push_back(i);
      in.push_back(f[i]);
    } else {
      out[i] = closestRotation(f[i]);
    }
  }
  std::vector<Eigen::Matrix3d> rotations(in.size());
  try {
    polarRotationBatch(in.data(), rotations.data(), in.size());
  } catch (const NumericalError&) {
    for (std::size_t k = 0; k < in.size(); ++k) rotations[k] = fastClosestRotation(in[k]);
  }
  for (std::size_t k = 0; k < positive.size(); ++k) out[positive[k]] = rotations[k];
}

}  // namespace tetblend

#include "tetblend/meshing/compatible_tets.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#ifdef TETBLEND_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include "tet_elements.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/tet_boundary.h"
#include "untangle.h"

namespace tetblend {

using SparseMatrix = Eigen::SparseMatrix<double>;
using RotationField = std::vector<Eigen::Matrix3d>;

struct CompatibleTetBuilder::Impl {
  TetMesh rest;
  int surfaceCount = 0;
  int interiorCount = 0;
  CompatibleTetOptions options;
  std::vector<TetElement> elements;
  Triangles surfaceTriangles;  // boundary of rest, indices < surfaceCount
  SparseMatrix interiorBlock;  // K_II
  SparseMatrix couplingBlock;  // K_IB
  // K_II is factored once per rest mesh: CHOLMOD's supernodal LL^T when
  // tetblend is built with CHOLMOD (BLAS-3 on the dense supernodes, many times
  // faster than the simplicial factor at 10^5-10^6 tets), else Eigen's
  // SimplicialLDLT. Solves are sequential (Eigen's CHOLMOD wrapper keeps one
  // cholmod_common).
#ifdef TETBLEND_HAVE_CHOLMOD
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> solver;
#else
  Eigen::SimplicialLDLT<SparseMatrix> solver;
#endif
  double diagonal = 0.0;
  std::vector<int> vertexTetStart;  // CSR: tets of vertex v are
  std::vector<int> vertexTets;      // vertexTets[vertexTetStart[v] .. vertexTetStart[v+1])

  // Interior vertices within `rings` tet-rings of the given tets.
  std::vector<int> interiorRegion(const std::vector<int>& seedTets, int rings) const {
    std::vector<char> inRegion(rest.vertices.rows(), 0);
    std::vector<int> frontier;
    for (int t : seedTets) {
      for (int a = 0; a < 4; ++a) {
        const int v = rest.tets(t, a);
        if (!inRegion[static_cast<size_t>(v)]) frontier.push_back(v);
        inRegion[static_cast<size_t>(v)] = 1;
      }
    }
    for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
      std::vector<int> next;
      for (int v : frontier) {
        for (int k = vertexTetStart[static_cast<size_t>(v)];
             k < vertexTetStart[static_cast<size_t>(v) + 1]; ++k) {
          for (int a = 0; a < 4; ++a) {
            const int w = rest.tets(vertexTets[static_cast<size_t>(k)], a);
            if (!inRegion[static_cast<size_t>(w)]) next.push_back(w);
            inRegion[static_cast<size_t>(w)] = 1;
          }
        }
      }
      frontier = std::move(next);
    }
    std::vector<int> region;
    for (int v = surfaceCount; v < static_cast<int>(inRegion.size()); ++v) {
      if (inRegion[static_cast<size_t>(v)]) region.push_back(v);
    }
    return region;
  }

  // Step 3: untangle growing neighbourhoods of the inverted tets until none
  // is left or the whole interior was free. Returns the rounds performed.
  // Keeps the attempt with the fewest inverted tets.
  int untangleInverted(Vertices& positions) const {
    int rounds = 0;
    std::vector<int> inverted = invertedTets(positions, rest.tets);
    Vertices current = positions;
    for (int rings = options.untangleRings; !inverted.empty(); rings *= 2) {
      const std::vector<int> region = interiorRegion(inverted, rings);
      if (!region.empty()) {
        rounds += untangle(rest.tets, elements, region, options.untangleRounds,
                           options.untangleIterationsPerRound, current)
                      .rounds;
      }
      std::vector<int> now = invertedTets(current, rest.tets);
      if (now.size() < inverted.size()) {
        positions = current;
        inverted = std::move(now);
      }
      if (static_cast<int>(region.size()) == interiorCount) break;
    }
    return rounds;
  }

  // Interior positions X_I = K_II^{-1} (rhs - K_IB X_B), all as #rows by k.
  Eigen::MatrixXd solveInterior(const Eigen::MatrixXd& rhs, const Eigen::MatrixXd& boundary) const {
    return solver.solve(rhs - couplingBlock * boundary);
  }

  // Σ_t vol_t R_t g_a over the tets, restricted to interior vertices a
  // (the right-hand side of the ARAP global step).
  Eigen::MatrixXd arapRhs(const RotationField& rotations) const {
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(interiorCount, 3);
    for (Eigen::Index t = 0; t < rest.tets.rows(); ++t) {
      const TetElement& element = elements[static_cast<size_t>(t)];
      for (int a = 0; a < 4; ++a) {
        const int v = rest.tets(t, a) - surfaceCount;
        if (v < 0) continue;
        rhs.row(v) += element.volume *
                      (rotations[static_cast<size_t>(t)] * element.gradients.col(a)).transpose();
      }
    }
    return rhs;
  }

  // Local step: the rotation closest to each tet's deformation gradient.
  RotationField localRotations(const Vertices& positions, double* energy) const {
    RotationField rotations(elements.size());
    double sum = 0.0;
    double volume = 0.0;
    for (Eigen::Index t = 0; t < rest.tets.rows(); ++t) {
      const TetElement& element = elements[static_cast<size_t>(t)];
      const Eigen::Matrix3d f = deformationGradient(positions, rest.tets.row(t), element);
      rotations[static_cast<size_t>(t)] = closestRotation(f);
      sum += element.volume * (f - rotations[static_cast<size_t>(t)]).squaredNorm();
      volume += element.volume;
    }
    if (energy) *energy = sum / volume;
    return rotations;
  }

  // Rotations propagated from the boundary: each surface triangle's rotation
  // (closest rotation to the map of its frame (e1, e2, unit normal)) is
  // averaged at its corners, extended harmonically to the interior (the same
  // factorisation, 9 right-hand sides), averaged over each tet's corners and
  // projected back to SO(3).
  RotationField propagatedRotations(const Vertices& example) const {
    Eigen::MatrixXd boundary = Eigen::MatrixXd::Zero(surfaceCount, 9);
    for (Eigen::Index f = 0; f < surfaceTriangles.rows(); ++f) {
      auto frame = [&](const Vertices& positions) {
        const Eigen::Vector3d a = positions.row(surfaceTriangles(f, 0));
        Eigen::Matrix3d m;
        m.col(0) = Eigen::Vector3d(positions.row(surfaceTriangles(f, 1))) - a;
        m.col(1) = Eigen::Vector3d(positions.row(surfaceTriangles(f, 2))) - a;
        m.col(2) = m.col(0).cross(m.col(1)).normalized();
        return m;
      };
      const Eigen::Matrix3d restFrame = frame(rest.vertices);
      const double area = 0.5 * restFrame.col(0).cross(restFrame.col(1)).norm();
      const Eigen::Matrix3d rotation = closestRotation(frame(example) * restFrame.inverse());
      const Eigen::Map<const Eigen::Matrix<double, 1, 9>> flat(rotation.data());
      for (int k = 0; k < 3; ++k) boundary.row(surfaceTriangles(f, k)) += area * flat;
    }
    const Eigen::MatrixXd interior =
        solveInterior(Eigen::MatrixXd::Zero(interiorCount, 9), boundary);
    RotationField rotations(elements.size());
    for (Eigen::Index t = 0; t < rest.tets.rows(); ++t) {
      Eigen::Matrix<double, 1, 9> sum = Eigen::Matrix<double, 1, 9>::Zero();
      for (int a = 0; a < 4; ++a) {
        const int v = rest.tets(t, a);
        if (v < surfaceCount) {
          sum += boundary.row(v);
        } else {
          sum += interior.row(v - surfaceCount);
        }
      }
      rotations[static_cast<size_t>(t)] = closestRotation(Eigen::Map<Eigen::Matrix3d>(sum.data()));
    }
    return rotations;
  }

  Vertices assemble(const Vertices& example, const Eigen::MatrixXd& interior) const {
    Vertices positions(surfaceCount + interiorCount, 3);
    positions.topRows(surfaceCount) = example;
    positions.bottomRows(interiorCount) = interior;
    return positions;
  }
};

CompatibleTetBuilder::CompatibleTetBuilder(const TetMesh& rest, int surfaceVertexCount,
                                           const CompatibleTetOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  const int vertexCount = static_cast<int>(rest.vertices.rows());
  if (surfaceVertexCount < 1 || surfaceVertexCount > vertexCount) {
    throw InputError("CompatibleTetBuilder: surface vertex count " +
                     std::to_string(surfaceVertexCount) + " is outside [1, " +
                     std::to_string(vertexCount) + "]");
  }
  m.rest = rest;
  m.surfaceCount = surfaceVertexCount;
  m.interiorCount = vertexCount - surfaceVertexCount;
  m.options = options;
  m.elements = buildTetElements(rest);
  m.diagonal = boundingBoxDiagonal(rest.vertices);
  m.surfaceTriangles = boundarySurface(rest).triangles;
  if (m.surfaceTriangles.size() > 0 && m.surfaceTriangles.maxCoeff() >= surfaceVertexCount) {
    throw InputError(
        "CompatibleTetBuilder: vertex " + std::to_string(m.surfaceTriangles.maxCoeff()) +
        " lies on the boundary but is not among the first " + std::to_string(surfaceVertexCount) +
        " (surface) vertices; reorder with reorderBoundaryFirst");
  }
  m.vertexTetStart.assign(static_cast<size_t>(vertexCount) + 1, 0);
  for (Eigen::Index t = 0; t < rest.tets.rows(); ++t) {
    for (int a = 0; a < 4; ++a) ++m.vertexTetStart[static_cast<size_t>(rest.tets(t, a)) + 1];
  }
  for (size_t v = 0; v < static_cast<size_t>(vertexCount); ++v) {
    m.vertexTetStart[v + 1] += m.vertexTetStart[v];
  }
  m.vertexTets.resize(static_cast<size_t>(m.vertexTetStart.back()));
  {
    std::vector<int> fill(m.vertexTetStart.begin(), m.vertexTetStart.end() - 1);
    for (Eigen::Index t = 0; t < rest.tets.rows(); ++t) {
      for (int a = 0; a < 4; ++a) {
        m.vertexTets[static_cast<size_t>(fill[static_cast<size_t>(rest.tets(t, a))]++)] =
            static_cast<int>(t);
      }
    }
  }
  // P1 stiffness K = Σ_t vol_t G_t^T G_t, split into interior and coupling.
  std::vector<Eigen::Triplet<double>> interior;
  std::vector<Eigen::Triplet<double>> coupling;
  interior.reserve(16 * m.elements.size());
  for (Eigen::Index t = 0; t < rest.tets.rows(); ++t) {
    const TetElement& element = m.elements[static_cast<size_t>(t)];
    const Eigen::Matrix4d local =
        element.volume * element.gradients.transpose() * element.gradients;
    for (int a = 0; a < 4; ++a) {
      const int row = rest.tets(t, a) - surfaceVertexCount;
      if (row < 0) continue;
      for (int b = 0; b < 4; ++b) {
        const int column = rest.tets(t, b);
        if (column >= surfaceVertexCount) {
          interior.emplace_back(row, column - surfaceVertexCount, local(a, b));
        } else {
          coupling.emplace_back(row, column, local(a, b));
        }
      }
    }
  }
  m.interiorBlock.resize(m.interiorCount, m.interiorCount);
  m.interiorBlock.setFromTriplets(interior.begin(), interior.end());
  m.couplingBlock.resize(m.interiorCount, m.surfaceCount);
  m.couplingBlock.setFromTriplets(coupling.begin(), coupling.end());
  if (m.interiorCount > 0) {
    m.solver.compute(m.interiorBlock);
    if (m.solver.info() != Eigen::Success) {
      throw NumericalError(
          "CompatibleTetBuilder: Cholesky factorisation of the interior stiffness block failed "
          "(an interior vertex used by no tet?)");
    }
  }
}

CompatibleTetBuilder::~CompatibleTetBuilder() = default;
CompatibleTetBuilder::CompatibleTetBuilder(CompatibleTetBuilder&&) noexcept = default;
CompatibleTetBuilder& CompatibleTetBuilder::operator=(CompatibleTetBuilder&&) noexcept = default;

int CompatibleTetBuilder::surfaceVertexCount() const { return impl_->surfaceCount; }
const TetMesh& CompatibleTetBuilder::restMesh() const { return impl_->rest; }

Vertices CompatibleTetBuilder::harmonicExtension(const Vertices& exampleSurface) const {
  const Impl& m = *impl_;
  if (exampleSurface.rows() != m.surfaceCount || !exampleSurface.allFinite()) {
    throw InputError("CompatibleTetBuilder: the example surface has " +
                     std::to_string(exampleSurface.rows()) + " vertices (need " +
                     std::to_string(m.surfaceCount) + ", all finite)");
  }
  if (m.interiorCount == 0) return exampleSurface;
  const Eigen::MatrixXd boundary = exampleSurface;
  return m.assemble(exampleSurface,
                    m.solveInterior(Eigen::MatrixXd::Zero(m.interiorCount, 3), boundary));
}

CompatibleTetResult CompatibleTetBuilder::place(const Vertices& exampleSurface) const {
  const Impl& m = *impl_;
  CompatibleTetResult result;
  result.vertices = harmonicExtension(exampleSurface);
  result.harmonicInvertedCount =
      static_cast<int>(invertedTets(result.vertices, m.rest.tets).size());
  if (m.interiorCount > 0) {
    const Eigen::MatrixXd boundary = exampleSurface;
    // Keep the candidate with the fewest inverted tets, then the lowest ARAP
    // energy: ARAP can fold strongly compressed regions that harmonic kept
    // valid, and an affine example is already optimal as harmonic.
    Vertices best;
    std::pair<size_t, double> bestKey(SIZE_MAX, INFINITY);
    auto consider = [&](const Vertices& candidate, double energy) {
      const std::pair<size_t, double> key(invertedTets(candidate, m.rest.tets).size(), energy);
      if (key < bestKey) {
        best = candidate;
        bestKey = key;
      }
    };
    double energy = 0.0;
    RotationField rotations = m.localRotations(result.vertices, &energy);
    consider(result.vertices, energy);
    Vertices current = result.vertices;
    if (m.options.propagateRotations) {
      Vertices propagated =
          m.assemble(exampleSurface,
                     m.solveInterior(m.arapRhs(m.propagatedRotations(exampleSurface)), boundary));
      double propagatedEnergy = 0.0;
      RotationField propagatedRotations = m.localRotations(propagated, &propagatedEnergy);
      consider(propagated, propagatedEnergy);
      if (propagatedEnergy < energy) {  // warm start from the better of the two
        current = std::move(propagated);
        rotations = std::move(propagatedRotations);
      }
    }
    const double tolerance = m.options.arapRelativeTolerance * m.diagonal;
    for (int iteration = 0; iteration < m.options.arapIterations; ++iteration) {
      const Eigen::MatrixXd interior = m.solveInterior(m.arapRhs(rotations), boundary);
      const double moved =
          (interior - current.bottomRows(m.interiorCount)).rowwise().norm().maxCoeff();
      current.bottomRows(m.interiorCount) = interior;
      ++result.arapIterations;
      rotations = m.localRotations(current, &energy);
      consider(current, energy);
      if (moved <= tolerance) break;
    }
    result.vertices = std::move(best);
    if (m.options.untangle) result.untangleRounds = m.untangleInverted(result.vertices);
  }
  m.localRotations(result.vertices, &result.arapEnergy);
  result.invertedTets = invertedTets(result.vertices, m.rest.tets);
  for (int t : result.invertedTets) {
    result.invertedVolumes.push_back(tetSignedVolume(result.vertices, m.rest.tets.row(t)));
  }
  result.minVolumeRatio = INFINITY;
  for (Eigen::Index t = 0; t < m.rest.tets.rows(); ++t) {
    result.minVolumeRatio = std::min(
        result.minVolumeRatio,
        deformationGradient(result.vertices, m.rest.tets.row(t), m.elements[static_cast<size_t>(t)])
            .determinant());
  }
  return result;
}

std::vector<int> invertedTets(const Vertices& vertices, const Tets& tets) {
  std::vector<int> result;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    if (!(tetSignedVolume(vertices, tets.row(t)) > 0.0)) result.push_back(static_cast<int>(t));
  }
  return result;
}

}  // namespace tetblend

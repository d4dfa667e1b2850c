#include "tetblend/blending/stitch_solver.h"

#include <Eigen/LU>
#include <functional>
#include <sstream>
#include <vector>

#include "stitch_solver_impl.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {
namespace {

using stitch_detail::Clock;
using stitch_detail::secondsSince;

}  // namespace

StitchWorkspace::StitchWorkspace() : impl_(std::make_unique<Impl>()) {}
StitchWorkspace::~StitchWorkspace() = default;
StitchWorkspace::StitchWorkspace(StitchWorkspace&&) noexcept = default;
StitchWorkspace& StitchWorkspace::operator=(StitchWorkspace&&) noexcept = default;

StitchSolver::StitchSolver(const TetMesh& rest, const StitchOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  stitch_detail::SparseMatrix matrix;
  matrix = m.reducedNormalMatrix(m.setUp(rest));  // the rest data is freed after
  std::vector<int>().swap(m.reducedIndex);        // only needed to build the matrix
#ifdef TETBLEND_HAVE_CHOLMOD
  if (options.backend == StitchBackend::kCholmodSupernodal && matrix.rows() > 0) {
    m.backend = StitchBackend::kCholmodSupernodal;
    m.factorCholmod(matrix);
    return;
  }
#else
  (void)options;
#endif
  m.backend = StitchBackend::kEigenSimplicialLdlt;
  m.factor(m.ldlt, matrix);
}

StitchSolver::StitchSolver(const TetMesh& rest, StitchFactorData factor)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.setUp(rest);  // the same InputError as a factoring solver's for a bad rest tet
  std::vector<int>().swap(m.reducedIndex);
#ifdef TETBLEND_HAVE_CHOLMOD
  m.backend = StitchBackend::kCholmodSupernodal;
  m.adoptFactor(std::make_unique<stitch_detail::SupernodalFactor>(
      std::move(factor), static_cast<int>(m.freeVertices.size())));
#else
  (void)factor;
  throw InputError("stitch: a stored factor needs CHOLMOD, which this build of tetblend lacks");
#endif
}

StitchSolver::~StitchSolver() = default;
StitchSolver::StitchSolver(StitchSolver&&) noexcept = default;
StitchSolver& StitchSolver::operator=(StitchSolver&&) noexcept = default;

int StitchSolver::vertexCount() const { return static_cast<int>(impl_->component.size()); }
int StitchSolver::tetCount() const { return static_cast<int>(impl_->rest.tets.rows()); }
int StitchSolver::componentCount() const { return static_cast<int>(impl_->componentSize.size()); }
const std::vector<int>& StitchSolver::vertexComponent() const { return impl_->component; }
RestTetData StitchSolver::restData() const { return restTetData(impl_->rest); }
const Tets& StitchSolver::tets() const { return impl_->rest.tets; }
const TetMesh& StitchSolver::rest() const { return impl_->rest; }
StitchBackend StitchSolver::backend() const { return impl_->backend; }

double StitchSolver::factorNonzeros() const {
#ifdef TETBLEND_HAVE_CHOLMOD
  if (impl_->supernodal) return impl_->supernodal->nonzeros();
#endif
  return static_cast<double>(impl_->ldlt.matrixL().nestedExpression().nonZeros());
}

StitchFactorData StitchSolver::factorData() const {
#ifdef TETBLEND_HAVE_CHOLMOD
  if (impl_->supernodal) return impl_->supernodal->data();
#endif
  throw InputError("stitch: only the CHOLMOD supernodal factor can be stored");
}

double StitchSolver::memoryBytes() const {
  const Impl& m = *impl_;
  const auto ints = [](const auto& v) { return static_cast<double>(sizeof(int) * v.size()); };
  double bytes = static_cast<double>(sizeof(double) * m.rest.vertices.size() +
                                     sizeof(int) * m.rest.tets.size()) +
                 ints(m.component) + ints(m.componentSize) + ints(m.reducedIndex) +
                 ints(m.freeVertices) + ints(m.chunkTet) + ints(m.chunkRow) + ints(m.cornerRow) +
                 ints(m.vertexRowStart) + ints(m.vertexRows);
#ifdef TETBLEND_HAVE_CHOLMOD
  if (m.supernodal) {
    return bytes + m.supernodal->bytes() + ints(m.factorRow) + ints(m.factorVertex);
  }
#endif
  // SimplicialLDLT: L's values and row indices, its column starts, D and the
  // two permutations.
  const auto n = static_cast<double>(m.freeVertices.size());
  const double nonzeros = static_cast<double>(m.ldlt.matrixL().nestedExpression().nonZeros());
  return bytes + nonzeros * (sizeof(double) + sizeof(int)) + n * (sizeof(double) + 3 * sizeof(int));
}

Centroids StitchSolver::componentCentroids(const Vertices& vertices) const {
  if (vertices.rows() != vertexCount()) {
    std::ostringstream message;
    message << "stitch: " << vertices.rows() << " vertices given, the rest mesh has "
            << vertexCount();
    throw InputError(message.str());
  }
  // Sums of differences from each component's first vertex, which are exact
  // or nearly so however far the mesh lies from the origin: a plain sum of
  // coordinates of size M rounds to about sqrt(#V) ulps of M (a hand 10^6
  // of its size away: 13 ulps, 1.6e-9 of its diagonal).
  Centroids first(componentCount(), 3);
  std::vector<char> seen(static_cast<std::size_t>(componentCount()), 0);
  Centroids sums = Centroids::Zero(componentCount(), 3);
  for (int v = 0; v < vertexCount(); ++v) {
    const int c = impl_->component[v];
    if (!seen[static_cast<std::size_t>(c)]) {
      seen[static_cast<std::size_t>(c)] = 1;
      first.row(c) = vertices.row(v);
    }
    sums.row(c) += vertices.row(v) - first.row(c);
  }
  Centroids centroids(componentCount(), 3);
  for (int c = 0; c < componentCount(); ++c) {
    centroids.row(c) = first.row(c) + sums.row(c) / impl_->componentSize[c];
  }
  return centroids;
}

Vertices StitchSolver::solve(const std::vector<Eigen::Matrix3d>& targets,
                             const Centroids& centroids) const {
  Vertices result;
  solveInto(targets, centroids, result);
  return result;
}

void StitchSolver::solveInto(const std::vector<Eigen::Matrix3d>& targets,
                             const Centroids& centroids, Vertices& result,
                             StitchTimings* timings) const {
  StitchWorkspace workspace;
  solveInto(targets, centroids, result, workspace, timings);
}

void StitchSolver::solveInto(const std::vector<Eigen::Matrix3d>& targets,
                             const Centroids& centroids, Vertices& result,
                             StitchWorkspace& workspace, StitchTimings* timings) const {
  if (static_cast<int>(targets.size()) != tetCount()) {
    std::ostringstream message;
    message << "stitch: got " << targets.size() << " target maps for a mesh with " << tetCount()
            << " tets";
    throw InputError(message.str());
  }
  solveImpl([&](int begin, int, Eigen::Matrix3d*) { return targets.data() + begin; }, centroids,
            result, workspace, timings);
}

void StitchSolver::solveInto(const TargetRangeFunction& targets, const Centroids& centroids,
                             Vertices& result, StitchWorkspace& workspace,
                             StitchTimings* timings) const {
  solveImpl(
      [&](int begin, int end, Eigen::Matrix3d* scratch) {
        targets(begin, end, scratch);
        return static_cast<const Eigen::Matrix3d*>(scratch);
      },
      centroids, result, workspace, timings);
}

template <typename Targets>
void StitchSolver::solveImpl(const Targets& targets, const Centroids& centroids, Vertices& result,
                             StitchWorkspace& workspace, StitchTimings* timings) const {
  const Impl& m = *impl_;
  StitchWorkspace::Impl& w = *workspace.impl_;
  if (centroids.rows() != componentCount()) {
    std::ostringstream message;
    message << "stitch: got " << centroids.rows() << " centroids for a mesh with "
            << componentCount() << " components";
    throw InputError(message.str());
  }
  auto start = Clock::now();
  const auto freeCount = static_cast<Eigen::Index>(m.freeVertices.size());
  result.setZero(vertexCount(), 3);
  w.values.resize(freeCount, 3);
  std::pair<double, double> threadSeconds{0.0, 0.0};
#ifdef TETBLEND_HAVE_CHOLMOD
  if (m.backend == StitchBackend::kCholmodSupernodal) {
    threadSeconds = m.assembleRhs(targets, m.factorRow, w.chunkSums, w.values);
  }
#endif
  if (m.backend == StitchBackend::kEigenSimplicialLdlt) {
    threadSeconds = m.assembleRhs(targets, {}, w.chunkSums, w.values);
  }
  if (timings != nullptr) {
    // The pass's wall time, split in the ratio of the thread time spent
    // producing the maps to the thread time of the whole pass.
    const double wall = secondsSince(start);
    const double share =
        threadSeconds.second > 0.0 ? threadSeconds.first / threadSeconds.second : 0.0;
    timings->targetSeconds = wall * share;
    timings->rhsSeconds = wall - timings->targetSeconds;
  }
  start = Clock::now();
#ifdef TETBLEND_HAVE_CHOLMOD
  if (m.backend == StitchBackend::kCholmodSupernodal) {
    m.supernodal->solve(w.values, w.workspace);
    for (Eigen::Index k = 0; k < freeCount; ++k) result.row(m.factorVertex[k]) = w.values.row(k);
  }
#endif
  if (m.backend == StitchBackend::kEigenSimplicialLdlt) {
    w.solution = m.ldlt.solve(w.values);
    for (Eigen::Index r = 0; r < freeCount; ++r) result.row(m.freeVertices[r]) = w.solution.row(r);
  }
  // x − (its centroid) + (the centroid asked for): the small relative
  // position first, so that a far centroid is rounded once.
  const Centroids solvedCentroids = componentCentroids(result);
  for (int v = 0; v < vertexCount(); ++v) {
    const int c = m.component[v];
    result.row(v) = (result.row(v) - solvedCentroids.row(c)) + centroids.row(c);
  }
  if (timings != nullptr) timings->solveSeconds = secondsSince(start);
}

Eigen::Matrix3d StitchSolver::gradient(const Vertices& x, int tet) const {
  const Eigen::RowVector4i corners = impl_->rest.tets.row(tet);
  return tetEdgeMatrix(x, corners) * tetEdgeMatrix(impl_->rest.vertices, corners).inverse();
}

double StitchSolver::energy(const Vertices& x, const std::vector<Eigen::Matrix3d>& targets) const {
  double sum = 0.0;
  for (int j = 0; j < tetCount(); ++j) {
    const Eigen::RowVector4i corners = impl_->rest.tets.row(j);
    const Eigen::Matrix3d edges = tetEdgeMatrix(impl_->rest.vertices, corners);
    const double volume = edges.determinant() / 6.0;
    sum += volume * (tetEdgeMatrix(x, corners) * edges.inverse() - targets[j]).squaredNorm();
  }
  return sum;
}

}  // namespace tetblend

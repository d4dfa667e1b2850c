#include "untangle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "tetblend/core/openmp_teams.h"
#include "untangle_tet_energy.h"
#include "vertex_block_ordering.h"
#ifdef TETBLEND_HAVE_CHOLMOD
#include "supernodal_values_ahead.h"
#endif

namespace tetblend {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

constexpr double kArmijo = 1e-4;
constexpr int kMaxHalvings = 40;
// Gradient-norm stop of one round, relative to the gradient at its start.
constexpr double kRelativeGradientTolerance = 1e-3;
// Active tets per TBB task (~0.2 µs of work each for the energy, a few µs
// for the Hessian).
constexpr size_t kTetGrain = 1024;
// Free vertices per TBB task of the gradient and Hessian gathers (~20
// corners each).
constexpr size_t kVertexGrain = 1024;
// An untangling attempt gives up after UntangleEffort::stallRounds rounds in
// a row that neither raised the smallest det F (by
// UntangleEffort::minDetProgress) nor lowered the count of inverted tets.
// It also gives up once ε falls below this fraction of |min det F| with tets
// still inverted: the barrier then holds them inverted while the energy
// grows like 1/ε (on the hard-pose corpus, successful attempts kept ε above
// |min det F|; stuck ones went on to ε = 1e-5 at 10^5 times the energy).
// 0.01 stopped some attempts that a later, larger region would have started
// from a better state: knot1's 720° twist then kept 8 tets.
constexpr double kHopelessEpsilon = 0.001;
// The first ε, relative to |min det F| at the start (at most
// UntangleEffort::largestStartEpsilon, 1 by default: the paper's start): a start that is nearly
// valid (a repair after a split, a larger region after a smaller one) keeps its valid tets, where ε
// = 1 lets the whole region relax first (on knot1's 720° twist, 1 inverted tet became 25 that way).
constexpr double kStartEpsilonPerDet = 2.0;
// Diagonal shift of the Newton matrix relative to its largest diagonal entry:
// the projected Hessian is only semi-definite. Raised ×100 while the
// factorisation fails.
constexpr double kRelativeShift = 1e-10;
constexpr int kShiftAttempts = 6;
// Flops of a simplicial factorisation (Σ_j |L_*j|²) from which NewtonSolver
// takes CHOLMOD's supernodal one. Measured on the Newton matrices of the
// hard-pose benchmark and the 48-frame bear rehearsal (3 k to 7 k unknowns,
// 2e7 to 3e8 flops, one core): the simplicial factorisation was faster up to
// about 1e8 flops, even at 1e8, and twice as slow at 2.7e8.
constexpr double kSupernodalFlops = 1.5e8;
// A round keeps the last round's factor of the Newton matrix when that
// round's first step agreed with the factor's quadratic model
// (newtonModelAgrees): its actual decrease was within [kModelAgreement,
// 2 - kModelAgreement] times the predicted one. For a quadratic energy of
// Hessian H and a factor of c H the ratio is 2 - 1/c, so the factor is kept
// while c lies in [5/9, 5]. ε shrinks by 5-10 % a round and the positions
// move little, so the matrix of a few rounds back is often still a good
// model. Measured 2026-12-03 over the README's five prepare sets: 269 ->
// 162 s, no clean frame with excluded tets, 46 232 -> 46 375 excluded;
// with 0.5, 171 s and 46 778; keeping it after any full step (0), 175 s
// and one clean frame with excluded tets.
constexpr double kModelAgreement = 0.2;
// Refocusing (FreeRegionAround): once the inverted tets number at most
// 1 / kRefocusFall of those at the last focus, the free region is narrowed
// to the caller's rings around them if that frees at most 1 / kRefocusShrink
// of the vertices, and ε goes on from where it was. A region's last tets
// often need tens of rounds at 5 % less ε each (a lion gallop frame: 19
// tets to 1 in 16 rounds, that 1 in 54 more, all on 711 free vertices).
// Measured 2026-11-29 over the README's sets (The untangler): the same
// clean frames with tets (8) and excluded tets within 0.2 % (41 850 ->
// 41 909, summed over frames), 401 -> 342 s; the corpus's counts the same,
// its embedding 33.5 -> 29.8 s.
constexpr int kRefocusFall = 4;
constexpr std::size_t kRefocusShrink = 2;

class UntangleEnergy {
 public:
  UntangleEnergy(const Tets& tets, const std::vector<TetElement>& elements,
                 std::vector<int> freeVertices, const Vertices& positions)
      : tets_(tets),
        elements_(elements),
        freeVertices_(std::move(freeVertices)),
        variable_(static_cast<size_t>(positions.rows()), -1),
        positions_(positions) {
    for (size_t i = 0; i < freeVertices_.size(); ++i) {
      variable_[static_cast<size_t>(freeVertices_[i])] = static_cast<int>(i);
    }
    for (Eigen::Index t = 0; t < tets.rows(); ++t) {
      for (int a = 0; a < 4; ++a) {
        if (variable_[static_cast<size_t>(tets(t, a))] >= 0) {
          active_.push_back(static_cast<int>(t));
          break;
        }
      }
    }
    for (int t : active_) totalVolume_ += elements[static_cast<size_t>(t)].volume;
    tetEnergy_.resize(active_.size());
    tetGradient_.resize(active_.size());
    // Each free vertex's (active tet, corner) pairs in ascending tet order.
    cornerStart_.assign(freeVertices_.size() + 1, 0);
    for (int t : active_) {
      for (int a = 0; a < 4; ++a) {
        const int v = variable_[static_cast<size_t>(tets(t, a))];
        if (v >= 0) ++cornerStart_[static_cast<size_t>(v) + 1];
      }
    }
    for (size_t v = 0; v < freeVertices_.size(); ++v) cornerStart_[v + 1] += cornerStart_[v];
    corners_.resize(static_cast<size_t>(cornerStart_.back()));
    std::vector<int> next(cornerStart_.begin(), cornerStart_.end() - 1);
    for (size_t i = 0; i < active_.size(); ++i) {
      for (int a = 0; a < 4; ++a) {
        const int v = variable_[static_cast<size_t>(tets(active_[i], a))];
        if (v >= 0) corners_[static_cast<size_t>(next[static_cast<size_t>(v)]++)] = {i, a};
      }
    }
    buildNewtonPattern();
  }

  Eigen::VectorXd freeVariables() const {
    Eigen::VectorXd x(3 * static_cast<Eigen::Index>(freeVertices_.size()));
    for (size_t i = 0; i < freeVertices_.size(); ++i) {
      x.segment<3>(3 * static_cast<Eigen::Index>(i)) = positions_.row(freeVertices_[i]);
    }
    return x;
  }

  void setFreeVariables(const Eigen::VectorXd& x) {
    for (size_t i = 0; i < freeVertices_.size(); ++i) {
      positions_.row(freeVertices_[i]) = x.segment<3>(3 * static_cast<Eigen::Index>(i)).transpose();
    }
  }

  // Energy at x; the gradient (same size as x) when `gradient` is non-null.
  // The tets are evaluated in parallel into per-tet slots, then summed in tet
  // order and gathered per free vertex in tet order: the same result for any
  // thread count.
  double evaluate(const Eigen::VectorXd& x, double epsilon, Eigen::VectorXd* gradient) {
    setFreeVariables(x);
    const bool wantGradient = gradient != nullptr;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, active_.size(), kTetGrain),
                      [&](const tbb::blocked_range<size_t>& range) {
                        for (size_t i = range.begin(); i != range.end(); ++i) {
                          evaluateTet(i, epsilon, wantGradient);
                        }
                      });
    double energy = 0.0;
    for (double e : tetEnergy_) energy += e;
    if (!wantGradient) return energy;
    gradient->resize(x.size());
    forEachFreeVertex([&](size_t v) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int k = cornerStart_[v]; k < cornerStart_[v + 1]; ++k) {
        const Corner& c = corners_[static_cast<size_t>(k)];
        sum += tetGradient_[c.activeTet].col(c.corner);
      }
      gradient->segment<3>(3 * static_cast<Eigen::Index>(v)) = sum;
    });
    return energy;
  }

  // The Hessian of the energy at the current positions with every tet's
  // part projected to positive semi-definite (projected Newton), as the lower
  // triangle of the 3#free by 3#free matrix on the pattern of
  // buildNewtonPattern.
  // Gathered per free vertex column in tet order: deterministic.
  SparseMatrix& projectedHessian(double epsilon) {
    tetHessian_.resize(active_.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, active_.size(), kTetGrain),
                      [&](const tbb::blocked_range<size_t>& range) {
                        for (size_t i = range.begin(); i != range.end(); ++i) {
                          const int t = active_[i];
                          const TetElement& element = elements_[static_cast<size_t>(t)];
                          const Eigen::Matrix3d f =
                              deformationGradient(positions_, tets_.row(t), element);
                          tetHessian_[i] = (element.volume / totalVolume_) *
                                           untangleCornerHessian(f, element.gradients, epsilon,
                                                                 /*projected=*/true);
                        }
                      });
    double* values = hessian_.valuePtr();
    std::fill(values, values + hessian_.nonZeros(), 0.0);
    forEachFreeVertex([&](size_t column) {
      for (int k = cornerStart_[column]; k < cornerStart_[column + 1]; ++k) {
        const Corner& c = corners_[static_cast<size_t>(k)];
        const Matrix12d& tetHessian = tetHessian_[c.activeTet];
        for (int q = 0; q < 4; ++q) {
          const int position = blockPosition_[static_cast<size_t>(k)][static_cast<size_t>(q)];
          if (position < 0) continue;
          for (int l = 0; l < 3; ++l) {
            double* target = values +
                             hessian_.outerIndexPtr()[3 * column + static_cast<size_t>(l)] +
                             3 * position;
            for (int r = 0; r < 3; ++r) target[r] += tetHessian(3 * q + r, 3 * c.corner + l);
          }
        }
      }
    });
    return hessian_;
  }

  // The smallest det F over the active tets and how many have det F <= 0.
  std::pair<double, int> determinants() const {
    double smallest = std::numeric_limits<double>::infinity();
    int inverted = 0;
    for (int t : active_) {
      const double det = determinant(t);
      smallest = std::min(smallest, det);
      if (!(det > 0.0)) ++inverted;
    }
    return {smallest, inverted};
  }

  // The active tets with det F <= 0.
  std::vector<int> invertedTets() const {
    std::vector<int> inverted;
    for (int t : active_) {
      if (!(determinant(t) > 0.0)) inverted.push_back(t);
    }
    return inverted;
  }

  std::size_t freeCount() const { return freeVertices_.size(); }
  const Vertices& positions() const { return positions_; }

 private:
  double determinant(int t) const {
    return deformationGradient(positions_, tets_.row(t), elements_[static_cast<size_t>(t)])
        .determinant();
  }

  template <typename Body>
  void forEachFreeVertex(const Body& body) const {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, freeVertices_.size(), kVertexGrain),
                      [&](const tbb::blocked_range<size_t>& range) {
                        for (size_t v = range.begin(); v != range.end(); ++v) body(v);
                      });
  }

  // Energy of active tet i into tetEnergy_[i]; with `wantGradient`, its
  // derivative with respect to each corner into tetGradient_[i] (3 by 4).
  void evaluateTet(size_t i, double epsilon, bool wantGradient) {
    const int t = active_[i];
    const TetElement& element = elements_[static_cast<size_t>(t)];
    const Eigen::Matrix3d f = deformationGradient(positions_, tets_.row(t), element);
    const double weight = element.volume / totalVolume_;
    Eigen::Matrix3d dEdF;
    tetEnergy_[i] = weight * untangleTetEnergy(f, epsilon, wantGradient ? &dEdF : nullptr);
    if (wantGradient) tetGradient_[i] = weight * dEdF * element.gradients;
  }

  // The pattern of the Newton matrix: a 3 by 3 block (r, c) with r >= c for
  // every pair of free vertices sharing an active tet, the rows of each
  // column block sorted (blockRows_ from blockStart_[c]). Only the lower
  // triangle is read by the factorisations (the upper entries of diagonal
  // blocks are stored and ignored), so the upper blocks are left out: half
  // the assembly.
  void buildNewtonPattern() {
    const size_t count = freeVertices_.size();
    blockStart_.assign(count + 1, 0);
    std::vector<std::vector<int>> rows(count);
    for (size_t c = 0; c < count; ++c) {
      for (int k = cornerStart_[c]; k < cornerStart_[c + 1]; ++k) {
        const int t = active_[corners_[static_cast<size_t>(k)].activeTet];
        for (int q = 0; q < 4; ++q) {
          const int row = variable_[static_cast<size_t>(tets_(t, q))];
          if (row >= static_cast<int>(c)) rows[c].push_back(row);
        }
      }
      std::sort(rows[c].begin(), rows[c].end());
      rows[c].erase(std::unique(rows[c].begin(), rows[c].end()), rows[c].end());
      blockStart_[c + 1] = blockStart_[c] + static_cast<int>(rows[c].size());
    }
    blockRows_.reserve(static_cast<size_t>(blockStart_.back()));
    for (const std::vector<int>& list : rows)
      blockRows_.insert(blockRows_.end(), list.begin(), list.end());
    const Eigen::Index size = 3 * static_cast<Eigen::Index>(count);
    hessian_.resize(size, size);
    Eigen::VectorXi perColumn(size);
    for (size_t c = 0; c < count; ++c) {
      perColumn.segment<3>(3 * static_cast<Eigen::Index>(c))
          .setConstant(3 * (blockStart_[c + 1] - blockStart_[c]));
    }
    hessian_.reserve(perColumn);
    for (size_t c = 0; c < count; ++c) {
      for (int l = 0; l < 3; ++l) {
        const Eigen::Index column = 3 * static_cast<Eigen::Index>(c) + l;
        for (int k = blockStart_[c]; k < blockStart_[c + 1]; ++k) {
          for (int r = 0; r < 3; ++r)
            hessian_.insert(3 * blockRows_[static_cast<size_t>(k)] + r, column) = 0.0;
        }
      }
    }
    hessian_.makeCompressed();
    blockPosition_.resize(corners_.size());
    for (size_t c = 0; c < count; ++c) {
      const auto first = blockRows_.begin() + blockStart_[c];
      const auto last = blockRows_.begin() + blockStart_[c + 1];
      for (int k = cornerStart_[c]; k < cornerStart_[c + 1]; ++k) {
        const int t = active_[corners_[static_cast<size_t>(k)].activeTet];
        for (int q = 0; q < 4; ++q) {
          const int row = variable_[static_cast<size_t>(tets_(t, q))];
          blockPosition_[static_cast<size_t>(k)][static_cast<size_t>(q)] =
              row < static_cast<int>(c)
                  ? -1
                  : static_cast<int>(std::lower_bound(first, last, row) - first);
        }
      }
    }
  }

  struct Corner {
    size_t activeTet;  // index into active_
    int corner;        // 0..3
  };

  const Tets& tets_;
  const std::vector<TetElement>& elements_;
  std::vector<int> freeVertices_;
  std::vector<int> variable_;  // per vertex: its index in freeVertices_, or -1
  Vertices positions_;
  std::vector<int> active_;
  std::vector<double> tetEnergy_;                         // per active tet
  std::vector<Eigen::Matrix<double, 3, 4>> tetGradient_;  // per active tet
  std::vector<Matrix12d> tetHessian_;                     // per active tet, on demand
  std::vector<int> cornerStart_;                          // per free vertex: its range in corners_
  std::vector<Corner> corners_;
  std::vector<int> blockStart_;  // per free vertex: its range in blockRows_
  std::vector<int> blockRows_;
  // Per corner record (as corners_): for each corner q of its tet, the
  // position of q's free vertex among its column's block rows, or -1.
  std::vector<std::array<int, 4>> blockPosition_;
  SparseMatrix hessian_;
  double totalVolume_ = 0.0;
};

// Eigen's simplicial LLᵀ, ordered on the free vertices' graph
// (vertex_block_ordering.h), with the cost of its numeric factorisation,
// Σ_j |L_*j|² flops over the columns of L (George & Liu 1981), from the
// column counts of its symbolic analysis.
class SimplicialSolver
    : public Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, VertexBlockAmdOrdering> {
 public:
  double factorisationFlops() const {
    const int* start = m_matrix.outerIndexPtr();
    double flops = 0.0;
    for (Eigen::Index j = 0; j < m_matrix.cols(); ++j) {
      const double count = start[j + 1] - start[j];
      flops += count * count;
    }
    return flops;
  }
};

// Sparse Cholesky factorisation of the Newton matrix, its pattern analysed on
// the first factorisation (the pattern is fixed per attempt): Eigen's
// simplicial LLᵀ, or CHOLMOD's supernodal LLᵀ (BLAS-3 on dense supernodes)
// when the simplicial one would take more than kSupernodalFlops and tetblend
// has CHOLMOD. Most attempts free a few hundred vertices, where CHOLMOD's
// OpenMP and BLAS thread teams cost more than the factorisation: with
// CHOLMOD for every size the 48-frame homer rehearsal spent 42 s of its 83 s
// in the kernel (threads waiting), with the simplicial factorisation 1 s of
// 64 s.
class NewtonSolver {
 public:
  bool factorize(const SparseMatrix& matrix) {
    if (!analysed_) {
      simplicialSolver_ = std::make_unique<SimplicialSolver>();
      simplicialSolver_->analyzePattern(matrix);
#ifdef TETBLEND_HAVE_CHOLMOD
      supernodal_ = simplicialSolver_->factorisationFlops() >= kSupernodalFlops;
      if (supernodal_) {
        simplicialSolver_.reset();  // its analysis holds the storage of L
        supernodalSolver_.analyzePattern(matrix);
      }
#endif
      analysed_ = true;
    }
#ifdef TETBLEND_HAVE_CHOLMOD
    if (supernodal_) {
      useOpenMpTeams(false);  // placements run beside it
      supernodalSolver_.factorize(matrix);
      return supernodalSolver_.info() == Eigen::Success;
    }
#endif
    simplicialSolver_->factorize(matrix);
    return simplicialSolver_->info() == Eigen::Success;
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& rightHandSide) const {
#ifdef TETBLEND_HAVE_CHOLMOD
    if (supernodal_) return supernodalSolver_.solve(rightHandSide);
#endif
    return simplicialSolver_->solve(rightHandSide);
  }

 private:
  bool analysed_ = false;
  std::unique_ptr<SimplicialSolver> simplicialSolver_;  // null when supernodal
#ifdef TETBLEND_HAVE_CHOLMOD
  SupernodalLLTValuesAhead<SparseMatrix> supernodalSolver_;
  bool supernodal_ = false;
#endif
};

// Factors the projected Hessian at the current positions, shifted by
// kRelativeShift of its largest diagonal entry, the shift raised ×100 while
// the factorisation fails (at most kShiftAttempts times). False if it never
// succeeds.
bool factorNewtonMatrix(UntangleEnergy& energy, double epsilon, NewtonSolver& solver) {
  SparseMatrix& hessian = energy.projectedHessian(epsilon);
  double shift = kRelativeShift * hessian.diagonal().maxCoeff();
  hessian.diagonal().array() += shift;
  bool factored = solver.factorize(hessian);
  for (int attempt = 1; attempt < kShiftAttempts && !factored; ++attempt) {
    hessian.diagonal().array() += 99.0 * shift;  // the shift ×100
    shift *= 100.0;
    factored = solver.factorize(hessian);
  }
  return factored;
}

// Energies at the start and at the end of one minimisation.
struct EnergyChange {
  double before;
  double after;
  // The first step was taken at full length and decreased the energy as
  // the factored matrix's quadratic model predicted (newtonModelAgrees).
  bool modelAgreed = false;
};

// Projected Newton with Armijo backtracking (Nocedal & Wright Alg. 3.1 with
// the Hessian made positive definite per element): at most maxIterations
// steps, until the gradient falls below kRelativeGradientTolerance of its
// start. With `refactor` the Newton matrix is assembled and factored at the
// first step, else the solver's factor of an earlier round is used
// (kModelAgreement); later steps solve with that factor (the chord method: a positive
// definite matrix still gives a descent direction, and the line search
// keeps the decrease). Measured 2026-12-03 over the README's five prepare
// sets (clean examples take 2 steps a round): 316 -> 253 s, the one clean
// frame that kept a tet (the harsh open lion's frame 14) embeds, and 0.7 %
// more excluded tets (45 916 -> 46 232, in 3 of 48 models); a single step a
// round instead took 269 s and excluded 5 % more.
EnergyChange minimiseNewton(UntangleEnergy& energy, double epsilon, int maxIterations,
                            NewtonSolver& solver, Eigen::VectorXd& x, bool refactor) {
  bool modelAgreed = false;
  Eigen::VectorXd gradient;
  double value = energy.evaluate(x, epsilon, &gradient);
  const double before = value;
  const double startNorm = gradient.norm();
  for (int iteration = 0; iteration < maxIterations; ++iteration) {
    if (gradient.norm() <= kRelativeGradientTolerance * startNorm) break;
    if (iteration == 0 && refactor && !factorNewtonMatrix(energy, epsilon, solver)) break;
    const Eigen::VectorXd direction = -solver.solve(gradient);
    const double slope = gradient.dot(direction);
    if (!(slope < 0.0)) break;
    double step = 1.0;
    Eigen::VectorXd trial;
    Eigen::VectorXd trialGradient;
    double trialValue = value;
    bool accepted = false;
    for (int halving = 0; halving < kMaxHalvings; ++halving, step *= 0.5) {
      trial = x + step * direction;
      trialValue = energy.evaluate(trial, epsilon, &trialGradient);
      if (std::isfinite(trialValue) && trialValue <= value + kArmijo * step * slope) {
        accepted = true;
        break;
      }
    }
    if (!accepted) break;
    if (iteration == 0) modelAgreed = step == 1.0 && newtonModelAgrees(slope, value, trialValue);
    x = trial;
    gradient = trialGradient;
    value = trialValue;
  }
  energy.setFreeVariables(x);
  return {before, value, modelAgreed};
}

}  // namespace

bool newtonModelAgrees(double slope, double before, double after) {
  const double predicted = -0.5 * slope;
  const double actual = before - after;
  return actual >= kModelAgreement * predicted && actual <= (2.0 - kModelAgreement) * predicted;
}

UntangleOutcome untangle(const Tets& tets, const std::vector<TetElement>& elements,
                         const std::vector<int>& freeVertices, const UntangleEffort& effort,
                         Vertices& positions, const FreeRegionAround& regionAround) {
  auto energy = std::make_unique<UntangleEnergy>(tets, elements, freeVertices, positions);
  auto solver = std::make_unique<NewtonSolver>();
  UntangleOutcome outcome;
  auto [minDet, inverted] = energy->determinants();
  Eigen::VectorXd x = energy->freeVariables();
  // ε schedule of the paper (Alg. 1): start at the scale of the unit
  // Jacobian, then shrink according to the energy decrease of each round.
  double epsilon = std::min(effort.largestStartEpsilon, kStartEpsilonPerDet * std::abs(minDet));
  double bestMinDet = minDet;
  int fewestInverted = inverted;
  const int startInverted = inverted;
  int stagnant = 0;
  int focusInverted = inverted;
  // The attempt returns the best state it reached (fewest inverted tets, then
  // the largest min det F), not its last: as ε shrinks a region can lose
  // what it gained (bench_meshing's 10 k elbow: 94 tets inverted at best,
  // 100 at the end). Over the README's sets of The untangler, 2 % fewer
  // excluded tets.
  std::pair<int, double> bestState(inverted, -minDet);
  Vertices best = positions;
  bool refactor = true;  // the first round factors the Newton matrix; see kModelAgreement
  int risingRounds = 0;  // rounds in a row ending with more inverted tets than the last
  int lastInverted = inverted;
  int notBelowStart = 0;  // rounds in a row ending with no fewer inverted tets than the start
  while (minDet <= 0.0 && outcome.rounds < effort.maxRounds && stagnant < effort.stallRounds &&
         epsilon >= -kHopelessEpsilon * minDet &&
         (effort.roundsToFallBelowStart == 0 || notBelowStart < effort.roundsToFallBelowStart) &&
         (effort.risingRoundsToGiveUp == 0 || risingRounds < effort.risingRoundsToGiveUp)) {
    const EnergyChange change =
        minimiseNewton(*energy, epsilon, effort.iterationsPerRound, *solver, x, refactor);
    refactor = !change.modelAgreed;
    ++outcome.rounds;
    std::tie(minDet, inverted) = energy->determinants();
    if (minDet > bestMinDet + effort.minDetProgress * std::abs(bestMinDet) ||
        inverted < fewestInverted) {
      stagnant = 0;
    } else {
      ++stagnant;
    }
    bestMinDet = std::max(bestMinDet, minDet);
    if (std::make_pair(inverted, -minDet) < bestState) {
      bestState = {inverted, -minDet};
      best = energy->positions();
    }
    fewestInverted = std::min(fewestInverted, inverted);
    notBelowStart = inverted >= startInverted ? notBelowStart + 1 : 0;
    const bool fellBelowStart = fewestInverted < startInverted;  // in some round so far
    risingRounds = !fellBelowStart && inverted > lastInverted ? risingRounds + 1 : 0;
    lastInverted = inverted;
    const double sigma = std::max(1.0 - change.after / change.before, effort.smallestDecrease);
    const double mu =
        (1.0 - sigma) * 0.5 * (minDet + std::sqrt(epsilon * epsilon + minDet * minDet));
    epsilon = minDet < mu ? 2.0 * std::sqrt(mu * (mu - minDet)) : 1e-13;
    if (regionAround && inverted > 0 && kRefocusFall * inverted <= focusInverted) {
      std::vector<int> region = regionAround(energy->invertedTets());
      if (kRefocusShrink * region.size() <= energy->freeCount()) {
        energy = std::make_unique<UntangleEnergy>(tets, elements, std::move(region),
                                                  energy->positions());
        solver = std::make_unique<NewtonSolver>();
        refactor = true;
        x = energy->freeVariables();
      }
      focusInverted = inverted;
    }
  }
  outcome.minDet = -bestState.second;
  positions = std::move(best);
  return outcome;
}

}  // namespace tetblend

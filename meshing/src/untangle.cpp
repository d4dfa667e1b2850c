#include "untangle.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "tetblend/core/lane_math.h"

namespace tetblend {
namespace {

constexpr double kVolumeWeight = 0.5;  // θ: weight of the volume term (paper's choice in 3D)
constexpr int kLbfgsMemory = 10;
constexpr double kArmijo = 1e-4;
constexpr int kMaxHalvings = 40;
// Gradient-norm stop of one round, relative to the gradient at its start.
constexpr double kRelativeGradientTolerance = 1e-3;
// Active tets per TBB task (~0.2 µs of work each).
constexpr size_t kTetGrain = 1024;
// Free vertices per TBB task of the gradient gather (~20 corners each).
constexpr size_t kVertexGrain = 1024;
// An untangling attempt gives up when this many rounds in a row did not
// raise the smallest det F: the free region is too small (or the example
// cannot be embedded), and a larger region or refinement is the remedy.
constexpr int kStagnantRounds = 8;

class UntangleEnergy {
 public:
  UntangleEnergy(const Tets& tets, const std::vector<TetElement>& elements,
                 const std::vector<int>& freeVertices, const Vertices& positions)
      : tets_(tets),
        elements_(elements),
        freeVertices_(freeVertices),
        variable_(static_cast<size_t>(positions.rows()), -1),
        positions_(positions) {
    for (size_t i = 0; i < freeVertices.size(); ++i) {
      variable_[static_cast<size_t>(freeVertices[i])] = static_cast<int>(i);
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
    cornerStart_.assign(freeVertices.size() + 1, 0);
    for (int t : active_) {
      for (int a = 0; a < 4; ++a) {
        const int v = variable_[static_cast<size_t>(tets(t, a))];
        if (v >= 0) ++cornerStart_[static_cast<size_t>(v) + 1];
      }
    }
    for (size_t v = 0; v < freeVertices.size(); ++v) cornerStart_[v + 1] += cornerStart_[v];
    corners_.resize(static_cast<size_t>(cornerStart_.back()));
    std::vector<int> next(cornerStart_.begin(), cornerStart_.end() - 1);
    for (size_t i = 0; i < active_.size(); ++i) {
      for (int a = 0; a < 4; ++a) {
        const int v = variable_[static_cast<size_t>(tets(active_[i], a))];
        if (v >= 0) corners_[static_cast<size_t>(next[static_cast<size_t>(v)]++)] = {i, a};
      }
    }
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
    tbb::parallel_for(tbb::blocked_range<size_t>(0, freeVertices_.size(), kVertexGrain),
                      [&](const tbb::blocked_range<size_t>& range) {
                        for (size_t v = range.begin(); v != range.end(); ++v) {
                          Eigen::Vector3d sum = Eigen::Vector3d::Zero();
                          for (int k = cornerStart_[v]; k < cornerStart_[v + 1]; ++k) {
                            const Corner& c = corners_[static_cast<size_t>(k)];
                            sum += tetGradient_[c.activeTet].col(c.corner);
                          }
                          gradient->segment<3>(3 * static_cast<Eigen::Index>(v)) = sum;
                        }
                      });
    return energy;
  }

  double minDet() const {
    double result = std::numeric_limits<double>::infinity();
    for (int t : active_) {
      result = std::min(
          result, deformationGradient(positions_, tets_.row(t), elements_[static_cast<size_t>(t)])
                      .determinant());
    }
    return result;
  }

  const Vertices& positions() const { return positions_; }

 private:
  // Energy of active tet i into tetEnergy_[i]; with `wantGradient`, its
  // derivative with respect to each corner into tetGradient_[i] (3 by 4).
  void evaluateTet(size_t i, double epsilon, bool wantGradient) {
    const int t = active_[i];
    const Eigen::RowVector4i tet = tets_.row(t);
    const TetElement& element = elements_[static_cast<size_t>(t)];
    const Eigen::Matrix3d f = deformationGradient(positions_, tet, element);
    const double j = f.determinant();
    const double root = std::sqrt(epsilon * epsilon + j * j);
    // χ = (J + root) / 2, written for J <= 0 as ε² / (2 (root − J)): the sum
    // cancels catastrophically there (to 0 once ε² < ulp(J²)).
    const double chi = j > 0.0 ? 0.5 * (j + root) : 0.5 * epsilon * epsilon / (root - j);
    const double dChi = chi / root;
    const double frobenius = f.squaredNorm();
    const double chiPow = chi >= std::numeric_limits<double>::min()
                              ? lane_math::inverseCbrtSquaredLane(chi)
                              : std::pow(chi, -2.0 / 3.0);
    const double weight = element.volume / totalVolume_;
    tetEnergy_[i] =
        weight * ((1 - kVolumeWeight) * frobenius * chiPow + kVolumeWeight * (j * j + 1) / chi);
    if (!wantGradient) return;
    const double dEdJ = (1 - kVolumeWeight) * frobenius * (-2.0 / 3.0) * chiPow / chi * dChi +
                        kVolumeWeight * (2 * j / chi - (j * j + 1) * dChi / (chi * chi));
    Eigen::Matrix3d cofactor;
    cofactor.col(0) = f.col(1).cross(f.col(2));
    cofactor.col(1) = f.col(2).cross(f.col(0));
    cofactor.col(2) = f.col(0).cross(f.col(1));
    const Eigen::Matrix3d dEdF = weight * (2 * (1 - kVolumeWeight) * chiPow * f + dEdJ * cofactor);
    tetGradient_[i] = dEdF * element.gradients;
  }

  struct Corner {
    size_t activeTet;  // index into active_
    int corner;        // 0..3
  };

  const Tets& tets_;
  const std::vector<TetElement>& elements_;
  const std::vector<int>& freeVertices_;
  std::vector<int> variable_;  // per vertex: its index in freeVertices_, or -1
  Vertices positions_;
  std::vector<int> active_;
  std::vector<double> tetEnergy_;                         // per active tet
  std::vector<Eigen::Matrix<double, 3, 4>> tetGradient_;  // per active tet
  std::vector<int> cornerStart_;  // per free vertex: its range in corners_
  std::vector<Corner> corners_;
  double totalVolume_ = 0.0;
};

// L-BFGS with Armijo backtracking (Nocedal & Wright Alg. 7.4/7.5).
void minimiseLbfgs(UntangleEnergy& energy, double epsilon, int maxIterations, Eigen::VectorXd& x) {
  Eigen::VectorXd gradient;
  double value = energy.evaluate(x, epsilon, &gradient);
  const double startNorm = gradient.norm();
  std::deque<Eigen::VectorXd> sHistory;
  std::deque<Eigen::VectorXd> yHistory;
  for (int iteration = 0; iteration < maxIterations; ++iteration) {
    if (gradient.norm() <= kRelativeGradientTolerance * startNorm) break;
    // Two-loop recursion.
    Eigen::VectorXd q = gradient;
    std::vector<double> alpha(sHistory.size());
    for (int i = static_cast<int>(sHistory.size()) - 1; i >= 0; --i) {
      alpha[i] = sHistory[i].dot(q) / yHistory[i].dot(sHistory[i]);
      q -= alpha[i] * yHistory[i];
    }
    if (!sHistory.empty()) {
      q *= sHistory.back().dot(yHistory.back()) / yHistory.back().squaredNorm();
    } else {
      q /= std::max(gradient.norm(), 1.0);
    }
    for (size_t i = 0; i < sHistory.size(); ++i) {
      const double beta = yHistory[i].dot(q) / yHistory[i].dot(sHistory[i]);
      q += (alpha[i] - beta) * sHistory[i];
    }
    Eigen::VectorXd direction = -q;
    double slope = gradient.dot(direction);
    if (slope >= 0.0) {  // not a descent direction: restart from steepest descent
      sHistory.clear();
      yHistory.clear();
      direction = -gradient / std::max(gradient.norm(), 1.0);
      slope = gradient.dot(direction);
    }
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
    Eigen::VectorXd s = trial - x;
    Eigen::VectorXd y = trialGradient - gradient;
    if (s.dot(y) > 1e-300) {
      sHistory.push_back(std::move(s));
      yHistory.push_back(std::move(y));
      if (static_cast<int>(sHistory.size()) > kLbfgsMemory) {
        sHistory.pop_front();
        yHistory.pop_front();
      }
    }
    x = trial;
    gradient = trialGradient;
    value = trialValue;
  }
  energy.setFreeVariables(x);
}

}  // namespace

UntangleOutcome untangle(const Tets& tets, const std::vector<TetElement>& elements,
                         const std::vector<int>& freeVertices, int maxRounds,
                         int iterationsPerRound, Vertices& positions) {
  UntangleEnergy energy(tets, elements, freeVertices, positions);
  UntangleOutcome outcome;
  outcome.minDet = energy.minDet();
  Eigen::VectorXd x = energy.freeVariables();
  // ε schedule of the paper (Alg. 1): start at the scale of the unit
  // Jacobian, then shrink according to the energy decrease of each round.
  double epsilon = 1.0;
  double bestMinDet = outcome.minDet;
  int stagnant = 0;
  while (outcome.minDet <= 0.0 && outcome.rounds < maxRounds && stagnant < kStagnantRounds) {
    const double before = energy.evaluate(x, epsilon, nullptr);
    minimiseLbfgs(energy, epsilon, iterationsPerRound, x);
    const double after = energy.evaluate(x, epsilon, nullptr);
    ++outcome.rounds;
    outcome.minDet = energy.minDet();
    if (outcome.minDet > bestMinDet) {
      bestMinDet = outcome.minDet;
      stagnant = 0;
    } else {
      ++stagnant;
    }
    const double sigma = std::max(1.0 - after / before, 0.1);
    const double minDet = outcome.minDet;
    const double mu =
        (1.0 - sigma) * 0.5 * (minDet + std::sqrt(epsilon * epsilon + minDet * minDet));
    epsilon = minDet < mu ? 2.0 * std::sqrt(mu * (mu - minDet)) : 1e-13;
  }
  positions = energy.positions();
  return outcome;
}

}  // namespace tetblend

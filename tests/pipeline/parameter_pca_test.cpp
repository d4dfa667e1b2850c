// The PCA of an example set in weight space (pipeline/parameter_pca.h).

#include "tetblend/pipeline/parameter_pca.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "test_seed.h"

namespace tetblend {
namespace {

constexpr unsigned kDefaultSeed = 20240611;
// sigma and the covariance's eigen-residual come from a self-adjoint
// eigensolve of the 4x4 Gram matrix of centred vectors in [-1, 1]^12
// (entries O(10)): a few hundred ulps of the O(1) sigmas.
constexpr double kEigenTolerance = 1e-12;
// The mean weights 1/(n+1) times a 12x3 basis of entries <= 1 against the
// oracle's row mean: a few roundings per entry, ~1e-15 each.
constexpr double kMeanReconstruction = 1e-14;

TEST(ParameterPca, WeightStepsReproduceThePrincipalDirections) {
  // Oracle: build the PCA of random vectors directly (covariance of the n+1
  // shapes in parameter space) and compare with the weight-space answer.
  const unsigned seed = test_seed::seedFor("ParameterPca", kDefaultSeed);
  std::srand(static_cast<unsigned>(seed));
  const int n = 3, dim = 12;
  std::vector<Eigen::VectorXd> p;
  for (int k = 0; k < n; ++k) p.push_back(Eigen::VectorXd::Random(dim));
  const ParameterPca pca = parameterPca(p);
  ASSERT_EQ(pca.steps.size(), static_cast<std::size_t>(n));
  Eigen::MatrixXd shapes = Eigen::MatrixXd::Zero(dim, n + 1);
  for (int k = 0; k < n; ++k) shapes.col(k + 1) = p[k];
  const Eigen::VectorXd mean = shapes.rowwise().mean();
  const Eigen::MatrixXd centred = shapes.colwise() - mean;
  const Eigen::MatrixXd cov = centred * centred.transpose() / (n + 1);
  Eigen::MatrixXd basis(dim, n);
  for (int k = 0; k < n; ++k) basis.col(k) = p[k];
  for (std::size_t i = 0; i < pca.steps.size(); ++i) {
    const Eigen::VectorXd d = basis * pca.steps[i];  // +1 sigma in parameter space
    EXPECT_NEAR(d.norm(), pca.sigmas[i], kEigenTolerance);
    // d is an eigenvector of the covariance with eigenvalue sigma^2.
    EXPECT_LT((cov * d - pca.sigmas[i] * pca.sigmas[i] * d).norm(), kEigenTolerance);
  }
  EXPECT_LT((basis * pca.meanWeights - mean).norm(), kMeanReconstruction);
}

}  // namespace
}  // namespace tetblend

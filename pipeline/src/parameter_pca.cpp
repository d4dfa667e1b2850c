#include "tetblend/pipeline/parameter_pca.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "tetblend/blending/rotation_consistency.h"
#include "tetblend/blending/tet_adjacency.h"
#include "tetblend/blending/tet_maps.h"
#include "tetblend/core/error.h"
#include "tetblend/core/polar.h"
#include "tetblend/pipeline/make_blender.h"

namespace tetblend {

namespace {
// Relative variance below which a principal component is round-off: the
// parameters carry ~1e-16 relative error, so their variances ~1e-32; 1e-12
// leaves a wide margin while keeping any real component.
constexpr double kRelativeVarianceFloor = 1e-12;
}  // namespace

Eigen::VectorXd kajiParameterVector(const TetMesh& rest, const Vertices& example, bool consistent) {
  const RestTetData restData = restTetData(rest);
  const std::vector<Eigen::Matrix3d> gradients = deformationGradients(rest, restData, example, 0);
  const auto count = static_cast<int>(gradients.size());
  std::vector<Eigen::Matrix3d> rotations(gradients.size());
  std::vector<Eigen::Matrix3d> stretchLogs(gradients.size());
  for (int j = 0; j < count; ++j) {
    const PolarLogDecomposition p = polarDecomposeLog(gradients[static_cast<std::size_t>(j)]);
    rotations[static_cast<std::size_t>(j)] = p.rotation;
    stretchLogs[static_cast<std::size_t>(j)] = p.stretchLog;
  }
  const TetAdjacency adjacency = buildTetAdjacency(rest.tets);
  const std::vector<Eigen::Vector3d> omegas =
      rotationLogs(rotations, adjacency, tetComponents(adjacency), consistent);
  const double r2 = std::sqrt(2.0);
  Eigen::VectorXd out(9 * count);
  for (int j = 0; j < count; ++j) {
    const auto u = static_cast<std::size_t>(j);
    const double s = std::sqrt(restData.volumes[u]);
    const Eigen::Matrix3d& y = stretchLogs[u];
    out.segment<9>(9 * j) << r2 * omegas[u], y(0, 0), y(1, 1), y(2, 2), r2 * y(0, 1), r2 * y(0, 2),
        r2 * y(1, 2);
    out.segment<9>(9 * j) *= s;
  }
  return out;
}

ParameterPca parameterPca(const std::vector<Eigen::VectorXd>& exampleParameters) {
  const auto n = static_cast<Eigen::Index>(exampleParameters.size());
  if (n < 1) throw InputError("principal components need at least one example");
  const Eigen::Index dim = exampleParameters.front().size();
  Eigen::MatrixXd shapes = Eigen::MatrixXd::Zero(dim, n + 1);  // column 0: the rest
  for (Eigen::Index k = 0; k < n; ++k) {
    if (exampleParameters[static_cast<std::size_t>(k)].size() != dim) {
      throw InputError("principal components: parameter vectors of different lengths");
    }
    shapes.col(k + 1) = exampleParameters[static_cast<std::size_t>(k)];
  }
  const Eigen::VectorXd mean = shapes.rowwise().mean();
  shapes.colwise() -= mean;
  const Eigen::MatrixXd gram = shapes.transpose() * shapes;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
  ParameterPca pca;
  pca.meanWeights = Eigen::VectorXd::Constant(n, 1.0 / static_cast<double>(n + 1));
  const double largest = eig.eigenvalues().maxCoeff();
  for (Eigen::Index i = n; i >= 0; --i) {  // eigenvalues ascend: walk down
    const double lambda = eig.eigenvalues()(i);
    if (!(largest > 0.0) || lambda <= kRelativeVarianceFloor * largest) continue;
    pca.sigmas.push_back(std::sqrt(lambda / static_cast<double>(n + 1)));
    pca.steps.push_back(eig.eigenvectors().col(i).tail(n) / std::sqrt(static_cast<double>(n + 1)));
  }
  return pca;
}

ParameterPca modelPca(const ModelData& model, bool consistent) {
  const TetMesh stitched = stitchedMesh(model);
  std::vector<Eigen::VectorXd> params;
  for (const Vertices& example : model.examples) {
    params.push_back(kajiParameterVector(stitched, example, consistent));
  }
  return parameterPca(params);
}

}  // namespace tetblend

#pragma once
// Principal-component variations of an example set in Kaji–Ochiai's
// parameter space (§3, eq. (2)–(3); §6.2 "variations of shapes").
//
// Why that space: V = R^3 x so(3) x sym(3) is a Euclidean vector space in
// which phi is defined everywhere and Blend is the linear combination
// sum_k w_k psi(A_k) (§5), so a mean and principal components of the
// examples' parameters are meaningful shapes; in the matrix space they are
// not (the mean of two rotations is not a rotation).
//
// Each shape s (rest s_0 = 0, example k s_k) is the vector of its per-tet
// (X_j, Y_j) = (log R_j, log S_j) of the deformation gradients, with the
// volume-weighted Frobenius inner product <s, t> = sum_j vol_j (tr(X_j^T X'_j)
// + tr(Y_j^T Y'_j)) (translations are fixed by the stitch, not by tets).
// Because the blended parameters are linear in the weights, every point
// mean + t sigma_i d_i of the principal plane is a weight vector: with the
// Gram matrix G = U Lambda U^T of the n+1 centred shapes, the mean is
// w = 1/(n+1) (every shape equally) and one standard deviation along
// component i is the weight step U[1..n, i] / sqrt(n+1).

#include <Eigen/Core>
#include <vector>

#include "tetblend/core/mesh_types.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend {

/// Principal components of the rest and its examples, as weight vectors.
struct ParameterPca {
  Eigen::VectorXd meanWeights;         ///< n weights of the mean shape (all 1/(n+1))
  std::vector<Eigen::VectorXd> steps;  ///< per component, the weight step of +1 sigma
  std::vector<double> sigmas;          ///< per component, the standard deviation
                                       ///< (population, over the n+1 shapes; units of
                                       ///< the parameters times sqrt(volume))
};

/// Per-tet Kaji–Ochiai parameters of `example` against `rest` as one vector
/// (#T * 9 numbers: sqrt(2) omega, the diagonal of log S, sqrt(2) times its
/// upper off-diagonal, each scaled by sqrt(vol_j) so that the Euclidean dot
/// product is the inner product of the file comment). Rotation logarithms
/// are made consistent across neighbouring tets when `consistent` is true.
Eigen::VectorXd kajiParameterVector(const TetMesh& rest, const Vertices& example, bool consistent);

/// PCA of the rest (the zero vector) and the examples' parameter vectors
/// (n >= 1 vectors of one length). Components with a variance below
/// 1e-12 times the largest are dropped (they are round-off).
ParameterPca parameterPca(const std::vector<Eigen::VectorXd>& exampleParameters);

/// The PCA of a model: parameterPca of its examples' kajiParameterVector over
/// stitchedMesh(model) (excluded tets have no parameters).
ParameterPca modelPca(const ModelData& model, bool consistent);

}  // namespace tetblend

#include "tetblend/core/so3.h"

#include <Eigen/LU>

#include <cmath>
#include <sstream>

#include "tetblend/core/error.h"

namespace tetblend {

Eigen::Vector3d so3LogChecked(const Eigen::Matrix3d& r, double tolerance) {
  const double orthoError = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  const double det = r.determinant();
  // Negated comparisons: a NaN defect (non-finite R) is refused too.
  if (!(orthoError <= tolerance && std::abs(det - 1.0) <= tolerance)) {
    std::ostringstream msg;
    msg << "so3LogChecked: the matrix is not a rotation (|R^T R - I| = " << orthoError
        << ", det R = " << det << ", tolerance " << tolerance
        << "); give an orthonormal matrix with determinant +1";
    throw DomainError(msg.str());
  }
  return so3Log(r);
}

}  // namespace tetblend

// The handle deformer (pipeline/handle_deformer.h).

#include "tetblend/pipeline/handle_deformer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tetblend/core/constants.h"
#include "tetblend/core/dual_quaternion_blend.h"
#include "tetblend/core/error.h"
#include "tetblend/core/kaji_ochiai.h"

namespace tetblend {
namespace {

// Round-off of one DLB and one point transform of unit-scale values.
constexpr double kTolerance = 1e-12;

Handle turnAboutZ(const std::string& name, double angle) {
  Handle h;
  h.name = name;
  h.params.rotationLog = Eigen::Vector3d(0, 0, angle);
  return h;
}

// Regression: dqs aligned the antipodes with handle 0 while core's dlb
// aligns them with the handle of largest weight. Handles at 0, +170 and
// -170 degrees about z: +170 and -170 are 20 degrees apart, but both
// quaternions lie on handle 0's side, so aligning with handle 0 cancels them
// into (nearly) no turn; aligning with the heaviest (+170) turns the point
// by about 168 degrees, between the two heavy handles.
TEST(HandleDeformer, DqsIsCoreDlbWithTheHeaviestHandleAsSignReference) {
  const std::vector<Handle> handles = {turnAboutZ("still", 0.0),
                                       turnAboutZ("left", 170.0 * kPi / 180.0),
                                       turnAboutZ("right", -170.0 * kPi / 180.0)};
  Vertices point(1, 3);
  point << 1.0, 0.0, 0.0;
  Eigen::MatrixXd weights(1, 3);
  weights << 0.1, 0.45, 0.45;
  const Vertices moved = deformByHandles(point, handles, weights, HandleBlend::kDqs);

  std::vector<DualQuaternion> dqs;
  for (const Handle& h : handles) dqs.push_back(DualQuaternion::fromRigid(phi(h.params)));
  const Eigen::Vector3d expected = dlb(dqs, {0.1, 0.45, 0.45}).transformPoint(point.row(0));
  EXPECT_LT((moved.row(0).transpose() - expected).norm(), kTolerance);
  const double angle = std::atan2(moved(0, 1), moved(0, 0));
  EXPECT_GT(std::abs(angle), 160.0 * kPi / 180.0) << "turned by " << angle << " rad";
}

// The dual quaternion deformer is named as the blend method (dq), and
// "dqs", its earlier name, is the alias every method name takes.
TEST(HandleDeformer, DqIsNamedAsTheBlendMethodWithTheAliasDqs) {
  EXPECT_EQ(parseHandleBlend("dq"), HandleBlend::kDqs);
  EXPECT_EQ(parseHandleBlend("dqs"), HandleBlend::kDqs);
  EXPECT_EQ(parseHandleBlend("lbs"), HandleBlend::kLbs);
  EXPECT_EQ(parseHandleBlend("kaji"), HandleBlend::kKaji);
  EXPECT_EQ(parseHandleBlend("kaji-frechet"), HandleBlend::kKajiFrechet);
  EXPECT_THROW(parseHandleBlend("dib"), InputError);
  EXPECT_EQ(handleBlendNames(), "lbs, dq, kaji, kaji-frechet (dqs = dq)");
}

}  // namespace
}  // namespace tetblend

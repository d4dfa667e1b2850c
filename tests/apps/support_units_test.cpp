// Unit tests of the command line's own numerics: the weight splines of
// animate. (The model file, weight sampling and PCA tests live in
// tests/pipeline.)

#include <gtest/gtest.h>

#include "tetblend/core/error.h"
#include "weight_spline.h"

namespace tetblend::cli {
namespace {

// Spline frames at keys and the Catmull-Rom midpoint are a few products and
// sums of small integers and fractions like 9/16: a few ulps of values <= 2.
constexpr double kSplineTolerance = 1e-15;

TEST(WeightSpline, InterpolatingSplinesHitTheKeysAndBSplineTheEnds) {
  const std::vector<std::vector<double>> keys{{0, 0}, {1, 0}, {0, 1}, {2, 2}};
  // 7 frames over 3 segments: frames 0, 2, 4, 6 sit on the keys.
  for (SplineKind kind : {SplineKind::kLinear, SplineKind::kCatmullRom}) {
    const auto f = splineFrames(keys, 7, kind);
    ASSERT_EQ(f.size(), 7u);
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 2; ++c) EXPECT_NEAR(f[2 * k][c], keys[k][c], kSplineTolerance);
  }
  const auto b = splineFrames(keys, 11, SplineKind::kBSpline);
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(b.front()[c], keys.front()[c], kSplineTolerance);
    EXPECT_NEAR(b.back()[c], keys.back()[c], kSplineTolerance);
  }
  // Catmull–Rom midpoint of the inner segment: (-p0 + 9 p1 + 9 p2 - p3) / 16.
  const auto m = splineFrames(keys, 7, SplineKind::kCatmullRom)[3];
  EXPECT_NEAR(m[0], (-0 + 9 * 1 + 9 * 0 - 2) / 16.0, kSplineTolerance);
  EXPECT_NEAR(m[1], (-0 + 9 * 0 + 9 * 1 - 2) / 16.0, kSplineTolerance);
  EXPECT_THROW(parseSplineKind("cubic"), InputError);
}

}  // namespace
}  // namespace tetblend::cli

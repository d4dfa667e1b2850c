#include "weight_spline.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "tetblend/core/error.h"

namespace tetblend::cli {

namespace {

using Key = std::vector<double>;

const Key& clampedKey(const std::vector<Key>& keys, long i) {
  const long last = static_cast<long>(keys.size()) - 1;
  return keys[static_cast<std::size_t>(std::clamp(i, 0L, last))];
}

Key combine(const std::array<const Key*, 4>& p, const std::array<double, 4>& c) {
  Key out(p[0]->size(), 0.0);
  for (std::size_t j = 0; j < out.size(); ++j)
    for (int i = 0; i < 4; ++i)
      out[j] += c[static_cast<std::size_t>(i)] * (*p[static_cast<std::size_t>(i)])[j];
  return out;
}

// Uniform Catmull–Rom basis at local parameter u in [0, 1] over p1..p2.
std::array<double, 4> catmullRomBasis(double u) {
  const double u2 = u * u, u3 = u2 * u;
  return {0.5 * (-u3 + 2 * u2 - u), 0.5 * (3 * u3 - 5 * u2 + 2), 0.5 * (-3 * u3 + 4 * u2 + u),
          0.5 * (u3 - u2)};
}

// Uniform cubic B-spline basis at local parameter u in [0, 1].
std::array<double, 4> bSplineBasis(double u) {
  const double u2 = u * u, u3 = u2 * u;
  return {(1 - 3 * u + 3 * u2 - u3) / 6, (4 - 6 * u2 + 3 * u3) / 6,
          (1 + 3 * u + 3 * u2 - 3 * u3) / 6, u3 / 6};
}

}  // namespace

SplineKind parseSplineKind(const std::string& name) {
  if (name == "linear") return SplineKind::kLinear;
  if (name == "catmull-rom") return SplineKind::kCatmullRom;
  if (name == "bspline") return SplineKind::kBSpline;
  throw InputError("unknown spline '" + name + "'; use linear, catmull-rom or bspline");
}

std::vector<Key> splineFrames(const std::vector<Key>& keys, int frames, SplineKind kind) {
  if (keys.empty()) throw InputError("--keys: give at least one key weight vector");
  if (frames < 1) throw InputError("--frames must be >= 1, got " + std::to_string(frames));
  for (const Key& k : keys)
    if (k.size() != keys.front().size())
      throw InputError("--keys: every key needs " + std::to_string(keys.front().size()) +
                       " weights, one has " + std::to_string(k.size()));
  std::vector<Key> out;
  const long m = static_cast<long>(keys.size());
  // B-spline: control points with both end keys tripled, segments 0..m.
  const long segments = kind == SplineKind::kBSpline ? m + 1 : m - 1;
  for (int f = 0; f < frames; ++f) {
    if (m == 1) {
      out.push_back(keys.front());
      continue;
    }
    const double s = frames == 1 ? 0.0 : static_cast<double>(f) * segments / (frames - 1);
    const long seg = std::min(static_cast<long>(std::floor(s)), segments - 1);
    const double u = s - static_cast<double>(seg);
    if (kind == SplineKind::kLinear) {
      out.push_back(
          combine({&keys[seg], &keys[seg], &keys[seg + 1], &keys[seg + 1]}, {1 - u, 0.0, u, 0.0}));
    } else if (kind == SplineKind::kCatmullRom) {
      out.push_back(combine(
          {&clampedKey(keys, seg - 1), &keys[seg], &keys[seg + 1], &clampedKey(keys, seg + 2)},
          catmullRomBasis(u)));
    } else {
      // Control point i of the tripled sequence is key clamp(i - 2).
      out.push_back(combine({&clampedKey(keys, seg - 2), &clampedKey(keys, seg - 1),
                             &clampedKey(keys, seg), &clampedKey(keys, seg + 1)},
                            bSplineBasis(u)));
    }
  }
  return out;
}

}  // namespace tetblend::cli

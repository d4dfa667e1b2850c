#pragma once
// Shared fixtures of the blending tests: the seed of the random tests and
// small procedural examples.

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

#include "test_seed.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend::testing {

/// Seed of the random tests: TETBLEND_SEED if set, else a fixed default.
/// Printed with the running test's name, so a failure can be replayed.
inline unsigned testSeed() { return test_seed::seedOfCurrentTest(20240611u); }

/// A smooth non-affine deformation of `v` with amplitude `amplitude` (units
/// of v): small enough on a unit-scale mesh to keep every tet positive.
inline Vertices smoothWarp(const Vertices& v, double amplitude, std::mt19937& rng) {
  std::uniform_real_distribution<double> phase(0.0, 6.283185307179586);
  const double a = phase(rng), b = phase(rng), c = phase(rng);
  Vertices out = v;
  for (Eigen::Index i = 0; i < v.rows(); ++i) {
    const double x = v(i, 0), y = v(i, 1), z = v(i, 2);
    out(i, 0) += amplitude * std::sin(1.3 * y + a) * std::cos(0.7 * z);
    out(i, 1) += amplitude * std::sin(1.1 * z + b) * std::cos(0.9 * x);
    out(i, 2) += amplitude * std::sin(0.8 * x + c) * std::cos(1.2 * y);
  }
  return out;
}

/// A rest tet mesh and its examples.
struct BarExamples {
  TetMesh rest;
  std::vector<Vertices> examples;
};

/// A 1 x 1 x 3 box bar (2 x 2 x `layers` cubes of 6 tets) and two examples:
/// twisted by `twist` radians about its long axis, and bent by 60 degrees.
inline BarExamples twistedAndBentBar(int layers, double twist) {
  BarExamples f;
  f.rest = boxTetMesh(2, 2, layers, Eigen::Vector3d(1.0, 1.0, 3.0));
  const Eigen::Vector3d base(0.0, 0.0, -1.5);
  f.examples.push_back(twistAboutAxis(f.rest.vertices, base, Eigen::Vector3d::UnitZ(), twist, 3.0));
  f.examples.push_back(bendAboutAxis(f.rest.vertices, base, Eigen::Vector3d::UnitZ(),
                                     Eigen::Vector3d::UnitX(), kPi / 3.0, 3.0));
  return f;
}

}  // namespace tetblend::testing

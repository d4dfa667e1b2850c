#pragma once
// Private helpers for the wording of surface problem messages.

#include <string>

#include "tetblend/core/mesh_types.h"

namespace tetblend {
namespace detail {

/// "(a, b, c)": the vertex indices of face f.
std::string faceText(const Triangles& triangles, Eigen::Index f);

/// A double with up to 10 significant digits ("nan", "inf" as printed by C++).
std::string numberText(double x);

}  // namespace detail
}  // namespace tetblend

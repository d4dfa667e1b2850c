#pragma once
// Mathematical constants shared by the library, its tests and its benchmarks.

namespace tetblend {

/// π, rounded to the nearest double (C++17 has no std::numbers::pi; M_PI is
/// POSIX, not standard C++).
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace tetblend

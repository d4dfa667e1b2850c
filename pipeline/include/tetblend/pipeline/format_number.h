#pragma once
// Numbers in messages, file names and tables.

#include <string>

namespace tetblend {

/// `value` in shortest round-trip form ("0.5", "1e-08", "nan").
std::string formatNumber(double value);

}  // namespace tetblend

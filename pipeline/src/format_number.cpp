#include "tetblend/pipeline/format_number.h"

#include <charconv>

namespace tetblend {

std::string formatNumber(double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc() ? std::string(buffer, end) : std::string("nan");
}

}  // namespace tetblend

#pragma once
// Internal helpers shared by the hand-written format readers and writers:
// loading a file, walking its lines and tokens, parsing numbers with
// from_chars, and raising InputError messages of the form
// "<file>:<line>: <what is wrong>: <what to do>".

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

namespace tetblend::detail {

/// The whole content of `path`; InputError if it is missing or unreadable.
std::string readFileBytes(const std::string& path);

/// Throws InputError "<path>:<line>: <message>".
[[noreturn]] void throwAtLine(const std::string& path, std::size_t line,
                              const std::string& message);

/// Lower-case extension of `path` including the dot (".obj"), or "".
std::string lowerExtension(const std::string& path);

/// Walks a text buffer line by line, splitting each line into whitespace
/// separated tokens; everything from `comment` to the end of the line is
/// dropped, and lines left without tokens are skipped.
class TextLines {
 public:
  explicit TextLines(std::string_view text, char comment = '#');
  /// Moves to the next line with tokens; false at the end of the text.
  bool next();
  /// 1-based number of the current line in the file.
  std::size_t lineNumber() const { return lineNumber_; }
  const std::vector<std::string_view>& tokens() const { return tokens_; }
  /// Byte offset just past the current line (where binary data may start).
  std::size_t endOffset() const { return position_; }

 private:
  std::string_view text_;
  char comment_;
  std::size_t position_ = 0;
  std::size_t lineNumber_ = 0;
  std::vector<std::string_view> tokens_;
};

/// The tokens of a text one after the other across lines (Medit style), with
/// the line of each token.
class TextTokens {
 public:
  explicit TextTokens(std::string_view text, char comment = '#') : lines_(text, comment) {}
  /// Next token into `token`; false at the end of the text.
  bool next(std::string_view& token);
  /// Line of the token last returned (or of the last line at the end).
  std::size_t lineNumber() const { return lines_.lineNumber(); }

 private:
  TextLines lines_;
  std::size_t index_ = 0;
  bool started_ = false;
};

/// A description as a string: strings as they are, callables by calling them,
/// so hot loops build their error messages only when they fail.
template <typename What>
std::string describe(const What& what) {
  if constexpr (std::is_invocable_v<const What&>) {
    return std::string(what());
  } else {
    return std::string(what);
  }
}

/// from_chars over the whole token (a leading '+' is allowed); false if the
/// token is not entirely a number or out of range. "nan"/"inf" parse.
bool tryParseDouble(std::string_view token, double& value);
bool tryParseInteger(std::string_view token, long long& value);

/// InputError for a token that is not a number (`integer`: what was expected).
[[noreturn]] void throwBadNumber(std::string_view token, const std::string& path, std::size_t line,
                                 const std::string& what, bool integer);

/// InputError "index <value> out of range <base>..<base+count-1>".
[[noreturn]] void throwIndexOutOfRange(long long value, long long base, int count,
                                       const std::string& path, std::size_t line,
                                       const std::string& element);

/// Parses a whole token as a double ("nan"/"inf" parse, finiteness is checked
/// separately); InputError naming `what` (string or callable) and the token.
template <typename What>
double parseDouble(std::string_view token, const std::string& path, std::size_t line,
                   const What& what) {
  double value = 0.0;
  if (!tryParseDouble(token, value)) throwBadNumber(token, path, line, describe(what), false);
  return value;
}

/// Parses a whole token as an integer; InputError naming `what` otherwise.
template <typename What>
long long parseInteger(std::string_view token, const std::string& path, std::size_t line,
                       const What& what) {
  long long value = 0;
  if (!tryParseInteger(token, value)) throwBadNumber(token, path, line, describe(what), true);
  return value;
}

/// Parses a non-negative element count that fits in an int.
int parseCount(std::string_view token, const std::string& path, std::size_t line,
               const std::string& what);

/// Rows to allocate before reading `count` elements of at least `bytesEach`
/// bytes each from the `available` bytes left after the header: `count`, or
/// only as many as those bytes can hold. A wrong count (2^31 - 1 in a small
/// file) then allocates nothing big, and the reader fails where the data ends,
/// naming the file and line. Fill the rows through growRows.
Eigen::Index rowsToAllocate(long long count, std::size_t bytesEach, std::size_t available);

/// Makes row `row` of `matrix`, which is being filled with `count` rows,
/// writable: the allocation doubles as rows are actually read, up to `count`,
/// so memory follows the data even if a rowsToAllocate bound were too small.
template <typename Matrix>
void growRows(Matrix& matrix, Eigen::Index row, Eigen::Index count) {
  if (row < matrix.rows()) return;
  constexpr Eigen::Index kMinGrowth = 1024;  // rows; avoids many small reallocations
  matrix.conservativeResize(
      std::min(count, std::max(row + 1, std::max(2 * matrix.rows(), kMinGrowth))), Eigen::NoChange);
}

/// `token` for an error message: at most kMaxQuotedBytes of it (then "..."),
/// bytes outside printable ASCII and backslashes written as \xNN, so that a
/// binary or hostile file cannot put control sequences or megabytes on the
/// terminal.
std::string printableToken(std::string_view token);

/// printableToken(token) in single quotes.
std::string quoteToken(std::string_view token);

/// Parses tokens[first..first+3) as the position of vertex `vertex`
/// (0-based), refusing missing values and NaN/Inf.
Eigen::RowVector3d parseVertex(const std::vector<std::string_view>& tokens, std::size_t first,
                               const std::string& path, std::size_t line, int vertex);

/// Throws InputError if `position` of vertex `vertex` (0-based) is not finite.
void checkFiniteVertex(const Eigen::RowVector3d& position, const std::string& path,
                       const std::string& where, int vertex);

/// Converts a file index `value` with numbering starting at `base` into a
/// 0-based index, refusing values outside base..base+count-1; `element`
/// (string or callable) names the element in the message.
template <typename Element>
int checkedIndex(long long value, long long base, int count, const std::string& path,
                 std::size_t line, const Element& element) {
  if (value < base || value >= base + count) {
    throwIndexOutOfRange(value, base, count, path, line, describe(element));
  }
  return static_cast<int>(value - base);
}

/// Appends the shortest decimal form of `value` that reads back exactly.
void appendDouble(std::string& out, double value);

/// Appends `value` in decimal.
void appendInteger(std::string& out, long long value);

/// Writes `bytes` to `tempPath` (binary); InputError naming `target` on failure.
void writeFileBytes(const std::string& tempPath, const std::string& bytes,
                    const std::string& target);

/// Writes `bytes` to `path` atomically (writeFileAtomically).
void writeBytesAtomically(const std::string& path, const std::string& bytes);

}  // namespace tetblend::detail

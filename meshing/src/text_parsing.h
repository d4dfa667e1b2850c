#pragma once
// Internal helpers shared by the hand-written format readers and writers:
// loading a file, walking its lines and tokens, parsing numbers with
// from_chars, and raising InputError messages of the form
// "<file>:<line>: <what is wrong>: <what to do>".

#include <cstddef>
#include <string>
#include <string_view>
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

/// Parses a whole token as a double ("nan"/"inf" parse, finiteness is checked
/// separately); InputError naming `what` and the token otherwise.
double parseDouble(std::string_view token, const std::string& path, std::size_t line,
                   const std::string& what);

/// Parses a whole token as an integer; InputError naming `what` otherwise.
long long parseInteger(std::string_view token, const std::string& path, std::size_t line,
                       const std::string& what);

/// Parses a non-negative element count that fits in an int.
int parseCount(std::string_view token, const std::string& path, std::size_t line,
               const std::string& what);

/// Parses tokens[first..first+3) as the position of vertex `vertex`
/// (0-based), refusing missing values and NaN/Inf.
Eigen::RowVector3d parseVertex(const std::vector<std::string_view>& tokens, std::size_t first,
                               const std::string& path, std::size_t line, int vertex);

/// Throws InputError if `position` of vertex `vertex` (0-based) is not finite.
void checkFiniteVertex(const Eigen::RowVector3d& position, const std::string& path,
                       const std::string& where, int vertex);

/// Converts a file index `value` with numbering starting at `base` into a
/// 0-based index, refusing values outside base..base+count-1.
int checkedIndex(long long value, long long base, int count, const std::string& path,
                 std::size_t line, const std::string& element);

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

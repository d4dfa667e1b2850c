#pragma once
// Atomic file output: write beside the target, then rename over it, so a
// reader never sees a half-written file and a failed write loses nothing.

#include <functional>
#include <string>

namespace tetblend {

/// Calls `write(tempPath)` to produce the file at a temporary path in the same
/// directory as `path`, then renames it to `path`. If `write` throws or the
/// rename fails, the temporary file is removed, `path` is left untouched and
/// the error propagates (as InputError naming `path` for I/O failures).
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tempPath)>& write);

} // namespace tetblend

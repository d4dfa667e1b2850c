#pragma once
// Atomic file output: write beside the target, then rename over it, so a
// reader never sees a half-written file and a failed write loses nothing.

#include <functional>
#include <string>

namespace tetblend {

/// Why `path` must not be replaced by an output, or "" when it is missing or a
/// regular file: "is a directory, not a file", "is a symbolic link (...)",
/// "is a FIFO (named pipe), not a regular file", "is a device, ..." or
/// "is a socket, ...". Checks the path itself, not what a link points to.
std::string nonRegularOutputReason(const std::string& path);

/// Calls `write(tempPath)` to produce the file at a temporary path in the same
/// directory as `path`, then renames it to `path`. If `write` throws or the
/// rename fails, the temporary file is removed, `path` is left untouched and
/// the error propagates (as InputError naming `path` for I/O failures).
/// Refuses (InputError, before `write` runs) a `path` that exists and is not
/// a regular file (nonRegularOutputReason).
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tempPath)>& write);

}  // namespace tetblend

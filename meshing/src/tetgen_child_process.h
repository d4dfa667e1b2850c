#pragma once
// Private helper of tetgen_mesher.cpp: runs TetGen 1.5 in a forked child
// process, so that TetGen's failure path cannot take the caller down.
//
// Why: Debian's TetGen 1.5.0 throws its error code from terminatetetgen()
// after freeing the mesh, and the tetgenmesh destructor then frees it again
// while the exception unwinds: any TetGen error (tiny features, facets too
// close, ...) aborts the process. In the child, TetGen runs on a thread with
// no exception handler above it, so a thrown code reaches std::terminate
// before any destructor runs; the terminate handler reports the code and
// leaves with _exit. A crash of the child (any signal) is reported as such.

#include <tetgen.h>

#include <string>

#include "tetblend/core/mesh_types.h"

namespace tetblend {
namespace detail {

/// How the TetGen child ended.
enum class TetGenChildStatus {
  kOk,           ///< TetGen returned; points and tets are filled.
  kTetGenError,  ///< TetGen threw its error code (`code`, tetgen.h's list).
  kSignal,       ///< the child died of signal `code` (e.g. SIGABRT, SIGSEGV).
  kBrokenChild,  ///< fork/pipe failed, or the child's report was incomplete;
                 ///< `detail` says which.
  kTimedOut,     ///< the child had not finished by the time limit and was killed.
};

/// Outcome of runTetGenInChild.
struct TetGenChildResult {
  TetGenChildStatus status = TetGenChildStatus::kBrokenChild;
  int code = 0;
  std::string detail;
  Vertices points;  ///< #P by 3, TetGen's output points (kOk only).
  Tets tets;        ///< #T by 4, TetGen's output tets, as TetGen gave them.
  int corners = 0;  ///< TetGen's numberofcorners (4 expected).
};

/// Runs ::tetrahedralize(switches, in, out) in a forked child and returns its
/// output through a pipe. The child never runs atexit handlers nor flushes
/// the parent's inherited stdio buffers (it discards them and leaves with
/// _exit). With `silence` the child's stdout and stderr go to /dev/null;
/// otherwise TetGen's own report is flushed to the inherited stdout. A child
/// still running `timeLimitSeconds` after the fork is killed (SIGKILL) and
/// reaped; 0 means no limit.
TetGenChildResult runTetGenInChild(const std::string& switches, tetgenio& in, bool silence,
                                   double timeLimitSeconds = 0.0);

}  // namespace detail
}  // namespace tetblend

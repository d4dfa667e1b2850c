#pragma once
// OpenBLAS (Debian 12's libopenblas0-pthread, which CHOLMOD's supernodal
// factorisations and solves call) keeps a team of worker threads that spin
// in sched_yield for a while after every threaded call. Where tetblend places
// several examples at once, one per core, that team only steals the cores:
// 16 skinned frames of the 135 k-tet armadillo took 71 s (32 s of it system
// time, sched_yield) with OpenBLAS's default team and 51 s with
// OPENBLAS_NUM_THREADS=1. One large factorisation that nothing runs beside
// is the exception: 1 M tets, 6.5 s of embedding with the team, 7.2 s
// without. These scopes switch the team at run time (the environment
// variable is read only when OpenBLAS loads), without starting a team that a
// fork stopped (blas_threads.cpp); with another BLAS they do nothing.

namespace tetblend {

/// While at least one SerialBlas lives (in any thread), OpenBLAS runs every
/// call on the calling thread alone; the last one to go gives OpenBLAS back
/// the thread count it had when the first came.
class SerialBlas {
 public:
  SerialBlas();
  ~SerialBlas();
  SerialBlas(const SerialBlas&) = delete;
  SerialBlas& operator=(const SerialBlas&) = delete;
};

/// While one lives, OpenBLAS has its own thread count again, inside
/// SerialBlas scopes too: for one large factorisation that nothing else runs
/// beside.
class ParallelBlas {
 public:
  ParallelBlas();
  ~ParallelBlas();
  ParallelBlas(const ParallelBlas&) = delete;
  ParallelBlas& operator=(const ParallelBlas&) = delete;
};

/// The threads OpenBLAS runs its calls on now (openblas_get_num_threads), or
/// 0 when the BLAS loaded is not OpenBLAS.
int openBlasThreads();

}  // namespace tetblend

#pragma once
// Fresh memory is faulted in one page at a time, on first write; in a
// virtual machine every fault is an exit to the host. CHOLMOD's supernodal
// factorisation writes its factor's values (L->x, 536 MiB for bench_meshing's
// 1 M-tet interior) supernode by supernode, and perf showed about 1 s of that
// factorisation's 2 s in the kernel's page clearing while OpenBLAS's second
// thread spun beside it. Linux (5.14 on) faults a whole range in for writing
// from one call, madvise(MADV_POPULATE_WRITE), without reading or writing
// the data, so another thread may write the range meanwhile. Memory the
// guest has not used for a few seconds is slow to fault in here (1 GB from
// one thread in 1.6-2.4 s, from two in 0.4-1.6 s; memory freed a moment
// before, 0.3 s). bench_meshing's 1 M row, three interleaved pairs (scratch
// timers): the interior's factorisation 2.81, 2.23, 2.88 s, and 2.01, 1.90,
// 1.74 s with its values faulted in ahead on a second thread (536 MiB in
// 0.51-0.78 s beside it); the embedding 5.40, 4.87, 5.49 -> 4.84, 4.48,
// 4.10 s.

#include <cstddef>
#include <thread>

namespace tetblend {

/// While one lives, a thread of its own faults in the pages of
/// [data, data + bytes) for writing, in ascending order, without touching
/// the data; the destructor waits for it. Nothing happens for less than
/// kPagesAheadMinimumBytes, or where the kernel cannot (before Linux 5.14,
/// other systems).
class PagesFaultedAhead {
 public:
  PagesFaultedAhead(void* data, std::size_t bytes);
  ~PagesFaultedAhead();
  PagesFaultedAhead(const PagesFaultedAhead&) = delete;
  PagesFaultedAhead& operator=(const PagesFaultedAhead&) = delete;

 private:
  std::thread thread_;
};

/// Below this nothing is faulted ahead: the faults cost a few tens of
/// milliseconds at most, and the small factorisations (the untangler's, by
/// the thousand) run beside other examples' placements, which a thread of
/// its own would take a core from. Not tuned.
inline constexpr std::size_t kPagesAheadMinimumBytes = std::size_t{16} << 20;

}  // namespace tetblend

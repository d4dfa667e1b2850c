#pragma once
// CHOLMOD (SuiteSparse 5.12, Debian 12) runs parts of its supernodal
// factorisation in OpenMP teams of a fixed size (CHOLMOD_OMP_NUM_THREADS,
// 4), however many cores there are and however many factorisations run at
// once, for any matrix of more than 128 columns. With two examples placed at
// once on two cores, their teams' waiting threads then took most of a large
// prepare's time in the kernel: a 104 k vertex armadillo with 4 frames, 121 s
// wall and 73 s system time, against 77 s and 24 s with OMP_DYNAMIC=true,
// which lets OpenMP shrink a team (same model bit for bit). libgomp sizes a
// dynamic team by the cores less the 15-minute load average, not by the
// cores free now: on two cores a team of 2 when the machine has been idle,
// of 1 after a quarter of an hour of work. After a region, a team's threads
// also spin before they sleep: bench_meshing's hard 10 k row, whose
// factorisations are small, embedded in 181-205 ms with teams and 175-177 ms
// without.

namespace tetblend {

/// Sets how CHOLMOD's OpenMP regions run on the calling thread from now on:
/// with `team`, in a dynamic team (what OMP_DYNAMIC=true does,
/// omp_set_dynamic); without, on the calling thread alone (no active
/// level, omp_set_max_active_levels(0)). Call before a CHOLMOD
/// factorisation; a no-op in a build without OpenMP.
void useOpenMpTeams(bool team);

}  // namespace tetblend

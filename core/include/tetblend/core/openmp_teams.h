#pragma once
// CHOLMOD (SuiteSparse 5.12, Debian 12) runs parts of its supernodal
// factorisation in OpenMP teams of a fixed size (CHOLMOD_OMP_NUM_THREADS,
// 4), however many cores there are and however many factorisations run at
// once. With two examples placed at once on two cores, their teams' waiting
// threads then took most of a large prepare's time in the kernel: a 104 k
// vertex armadillo with 4 frames, 121 s wall and 73 s system time, against
// 77 s and 24 s with OMP_DYNAMIC=true, which lets OpenMP shrink a team to
// the cores that are free (same model bit for bit).

namespace tetblend {

/// Lets OpenMP give the calling thread's later parallel regions (CHOLMOD's)
/// fewer threads than they ask for when the cores are busy: what
/// OMP_DYNAMIC=true does, for this thread (omp_set_dynamic). Call before a
/// CHOLMOD factorisation; a no-op in a build without OpenMP.
void letOpenMpShrinkTeams();

}  // namespace tetblend

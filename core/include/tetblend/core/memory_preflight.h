#pragma once
// Memory checks before a sparse Cholesky factorisation (issue 11). Under an
// address-space limit (ulimit -v, 128-512 MiB) a factorisation used to hang:
// OpenBLAS maps one work buffer per thread on its first level-3 call and, when
// that mapping fails, retries forever, while the caller waits for the thread.
// So the factorisations first check that their memory can be had at all.

#include <cstddef>
#include <string>

namespace tetblend {

/// Work buffer OpenBLAS maps per thread for level-3 BLAS (Debian 12's
/// libopenblas0-pthread, which setup.sh installs: 128 MiB, seen as the
/// 134,225,920-byte mmap of the hanging thread).
constexpr std::size_t kBlasBufferBytesPerThread = std::size_t{128} << 20;

/// Threads the BLAS runs level-3 calls on: OPENBLAS_NUM_THREADS when set to a
/// positive number, else the hardware threads (OpenBLAS's default).
int blasThreadCount();

/// Bytes the BLAS maps for a factorisation: one buffer per BLAS thread.
std::size_t blasWorkspaceBytes();

/// Throws ResourceError when `bytes` (a factor and blasWorkspaceBytes)
/// cannot be allocated now; it allocates and frees them untouched, so no
/// memory is used. The message: "not enough memory for <what>: it needs
/// about N MB ...; <remedy>". Without a limit, under overcommit, it passes;
/// then the kernel, not a hang, ends an overrun.
void requireAllocatable(std::size_t bytes, const std::string& what);

}  // namespace tetblend

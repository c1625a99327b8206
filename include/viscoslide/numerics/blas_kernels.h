// SPDX-License-Identifier: LGPL-2.1-or-later
// The BLAS kernels that MUMPS and LAPACK run on.
#ifndef viscoslide_blas_kernels_h
#define viscoslide_blas_kernels_h

namespace viscoslide
{
  // OpenBLAS chooses its kernels for the CPU as it loads, before main(). A
  // release that does not know the CPU (Debian bookworm's 0.3.21 on Intel's
  // Sapphire Rapids) falls back to its Prescott (SSE3) kernels, with which
  // the Fig. 9b curve took 93 s instead of 78 s (doc/benchmark.md). If that
  // happened on a CPU with AVX2, this sets OPENBLAS_CORETYPE to the newest
  // kernels the CPU runs and executes the program again with `argv`; it
  // returns if OPENBLAS_CORETYPE is set already (the user's choice), if the
  // BLAS is not OpenBLAS or knew the CPU, or if the execution fails. To be
  // called first in main(), before MPI is initialized. Under valgrind, set
  // OPENBLAS_CORETYPE: the program executed again would run outside it.
  void
  use_native_blas_kernels(char *argv[]);
} // namespace viscoslide

#endif

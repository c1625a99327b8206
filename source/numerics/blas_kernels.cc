// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/numerics/blas_kernels.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

namespace viscoslide
{
  void
  use_native_blas_kernels(char *argv[])
  {
    if (std::getenv("OPENBLAS_CORETYPE") != nullptr)
      return;
    // Absent unless the BLAS the system's alternatives name is OpenBLAS.
    const auto corename = reinterpret_cast<char *(*)()>(
      dlsym(RTLD_DEFAULT, "openblas_get_corename"));
    if (corename == nullptr || std::strcmp(corename(), "Prescott") != 0)
      return;
    const char *type = __builtin_cpu_supports("avx512f") ? "SkylakeX"
                       : __builtin_cpu_supports("avx2")  ? "Haswell"
                                                         : nullptr;
    if (type == nullptr)
      return;
    setenv("OPENBLAS_CORETYPE", type, 1);
    execv("/proc/self/exe", argv);
  }
} // namespace viscoslide

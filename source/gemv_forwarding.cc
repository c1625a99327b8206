// MUMPS's forward and backward substitutions multiply the fronts by the
// right-hand side through dgemm, also when there is a single right-hand
// side. OpenBLAS before 0.3.27 (Debian bookworm ships 0.3.21) packs the
// whole front into a buffer before such a product, and in a
// back-substitution that packing, not the arithmetic, was half of the
// time (doc/benchmark.md). A matrix-vector product needs no packing, so
// this executable's dgemm hands the one-column products to dgemv and all
// others to the BLAS it shadows. It is found first because the executable
// exports it (CMakeLists.txt). The forwarding of dtrsm to dtrsv, tried in
// the same way, gained nothing measurable.
#include <dlfcn.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>

extern "C"
{
  void
  dgemv_(const char   *trans,
         const int    *m,
         const int    *n,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *x,
         const int    *incx,
         const double *beta,
         double       *y,
         const int    *incy,
         std::size_t   trans_length);

  using Dgemm = void(const char *,
                     const char *,
                     const int *,
                     const int *,
                     const int *,
                     const double *,
                     const double *,
                     const int *,
                     const double *,
                     const int *,
                     const double *,
                     double *,
                     const int *,
                     std::size_t,
                     std::size_t);

  // C = alpha op(A) op(B) + beta C, op(A) m x k, op(B) k x n.
  void
  dgemm_(const char   *transa,
         const char   *transb,
         const int    *m,
         const int    *n,
         const int    *k,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *b,
         const int    *ldb,
         const double *beta,
         double       *c,
         const int    *ldc,
         std::size_t   transa_length,
         std::size_t   transb_length)
  {
    if (*n == 1)
      {
        const auto is_n = [](const char *t) { return *t == 'N' || *t == 'n'; };
        // op(B) is one column: stride 1 in B, or a row of B^T.
        const int incb = is_n(transb) ? 1 : *ldb;
        const int one  = 1;
        if (is_n(transa))
          dgemv_("N", m, k, alpha, a, lda, b, &incb, beta, c, &one, 1);
        else
          dgemv_("T", k, m, alpha, a, lda, b, &incb, beta, c, &one, 1);
        return;
      }
    static Dgemm *const blas =
      reinterpret_cast<Dgemm *>(dlsym(RTLD_NEXT, "dgemm_"));
    if (blas == nullptr)
      {
        std::fputs("viscoslide: no BLAS dgemm found behind its own\n", stderr);
        std::abort();
      }
    blas(transa,
         transb,
         m,
         n,
         k,
         alpha,
         a,
         lda,
         b,
         ldb,
         beta,
         c,
         ldc,
         transa_length,
         transb_length);
  }
}

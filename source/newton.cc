#include <viscoslide/newton.h>

#include <cmath>

namespace viscoslide
{
  int
  newton(const NewtonProblem &p,
         const unsigned int   max_iterations,
         const bool           line_search,
         const bool           verbose,
         ConditionalOStream  &out)
  {
    p.assemble(true);
    double residual = p.residual_norm();
    for (unsigned int it = 0; it <= max_iterations; ++it)
      {
        if (!std::isfinite(residual))
          {
            out << "      Newton: residual is " << residual << " at iteration "
                << it << "\n";
            return -1;
          }
        const double tolerance = p.tolerance();
        if (verbose)
          out << "      Newton " << it << ": residual " << residual
              << " (tolerance " << tolerance << ")" << std::endl;
        if (residual <= tolerance)
          return it;
        if (it == max_iterations)
          break;

        p.compute_update();
        if (!std::isfinite(p.update_norm()))
          {
            out << "      Newton: linear solve gave a non-finite update at "
                   "iteration "
                << it << "\n";
            return -1;
          }

        // Accept the first step that reduces the residual, else give up
        // (the caller cuts the step).
        p.remember_iterate();
        double alpha   = 1.;
        bool   reduced = false;
        for (unsigned int k = 0; k < (line_search ? 8 : 1); ++k)
          {
            p.step(alpha);
            p.assemble(false);
            const double r = p.residual_norm();
            if (std::isfinite(r) &&
                (r < (1. - 1e-4 * alpha) * residual || !line_search))
              {
                reduced = true;
                break;
              }
            alpha *= 0.5;
          }
        if (verbose)
          out << "        line search: alpha = " << alpha << std::endl;
        if (!reduced)
          return -1;
        p.assemble(true);
        residual = p.residual_norm();
      }
    return -1;
  }
} // namespace viscoslide

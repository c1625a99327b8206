// SPDX-License-Identifier: LGPL-2.1-or-later
// FFTW plans that are fast and give the same digits in every run. A plan
// measured by FFTW (FFTW_MEASURE) is chosen by timing, so that two runs
// could take two algorithms and differ in the last digits; an estimated
// one (FFTW_ESTIMATE) depends on the sizes only, but costs the 3D window's
// transforms some 15 % (doc/boundary_element.md, FFT plans). So the first
// plan of a size is measured once and kept as FFTW wisdom in a file, under
// a lock, and every later plan of that size, in this run or another, is
// that plan. Where the file cannot be kept, plans are estimated.
#ifndef viscoslide_numerics_fft_plans_h
#define viscoslide_numerics_fft_plans_h

#include <fftw3.h>

#include <functional>
#include <string>

namespace viscoslide
{
  // The file of the kept wisdom: $VISCOSLIDE_FFTW_WISDOM, else
  // $XDG_CACHE_HOME/viscoslide/fftw_wisdom, else
  // $HOME/.cache/viscoslide/fftw_wisdom; empty where none can be named.
  std::string
  fft_wisdom_file();

  // The plan `make(flags)` makes, with the flags and the wisdom above.
  // `make` must not rely on the arrays' contents: a measured plan
  // overwrites them.
  fftw_plan
  make_fft_plan(const std::function<fftw_plan(unsigned int flags)> &make);
} // namespace viscoslide

#endif

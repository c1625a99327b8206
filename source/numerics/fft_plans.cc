// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/numerics/fft_plans.h>

#include <cstdlib>
#include <filesystem>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace viscoslide
{
  namespace
  {
    // An exclusive lock on `path`, held while the object lives; invalid
    // (fd -1) where the file cannot be opened.
    struct FileLock
    {
      explicit FileLock(const std::string &path)
        : fd(::open(path.c_str(), O_RDWR | O_CREAT, 0644))
      {
        if (fd >= 0 && ::flock(fd, LOCK_EX) != 0)
          {
            ::close(fd);
            fd = -1;
          }
      }
      ~FileLock()
      {
        if (fd >= 0)
          ::close(fd); // releases the lock
      }
      FileLock(const FileLock &) = delete;
      FileLock     &
      operator=(const FileLock &) = delete;
      int fd;
    };
  } // namespace


  std::string
  fft_wisdom_file()
  {
    if (const char *given = std::getenv("VISCOSLIDE_FFTW_WISDOM"))
      return given;
    std::filesystem::path cache;
    if (const char *xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
      cache = xdg;
    else if (const char *home = std::getenv("HOME"); home && *home)
      cache = std::filesystem::path(home) / ".cache";
    else
      return "";
    return (cache / "viscoslide" / "fftw_wisdom").string();
  }


  fftw_plan
  make_fft_plan(const std::function<fftw_plan(unsigned int flags)> &make)
  {
    const std::string file = fft_wisdom_file();
    std::error_code   error;
    if (file.empty())
      return make(FFTW_ESTIMATE);
    const std::filesystem::path folder =
      std::filesystem::path(file).parent_path();
    if (!folder.empty())
      std::filesystem::create_directories(folder, error);
    if (error)
      return make(FFTW_ESTIMATE);
    // Under the lock, so that two runs that first meet a size at once
    // (ctest -j, a study's groups) keep one plan for it.
    const FileLock lock(file + ".lock");
    if (lock.fd < 0)
      return make(FFTW_ESTIMATE);
    fftw_import_wisdom_from_filename(file.c_str()); // none yet: no wisdom
    const fftw_plan plan = make(FFTW_MEASURE);
    // Written beside and renamed, so that no reader sees half a file.
    const std::string written = file + "." + std::to_string(::getpid());
    if (fftw_export_wisdom_to_filename(written.c_str()))
      std::filesystem::rename(written, file, error);
    if (error)
      std::filesystem::remove(written, error);
    return plan;
  }
} // namespace viscoslide

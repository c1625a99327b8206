// SPDX-License-Identifier: LGPL-2.1-or-later
#include <viscoslide/driver/case_lock.h>

#include <sys/file.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>

namespace viscoslide
{
  CaseLock::CaseLock(const std::string &file, const double patience)
  {
    fd = ::open(file.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (fd < 0)
      throw std::runtime_error("cannot create the lock file '" + file +
                               "': " + std::strerror(errno));
    for (int tries = std::max(1, static_cast<int>(patience * 10));;)
      {
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0)
          return;
        const int error = errno;
        if (error == EWOULDBLOCK && --tries > 0)
          {
            ::usleep(100000);
            continue;
          }
        ::close(fd);
        fd = -1;
        if (error != EWOULDBLOCK)
          throw std::runtime_error("cannot lock '" + file +
                                   "': " + std::strerror(error));
        return;
      }
  }


  CaseLock::~CaseLock()
  {
    if (fd >= 0)
      ::close(fd);
  }
} // namespace viscoslide

#include <viscoslide/case_lock.h>

#include <sys/file.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>

namespace viscoslide
{
  CaseLock::CaseLock(const std::string &file)
  {
    fd = ::open(file.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (fd < 0)
      throw std::runtime_error("cannot create the lock file '" + file +
                               "': " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
      {
        const int error = errno;
        ::close(fd);
        fd = -1;
        if (error != EWOULDBLOCK)
          throw std::runtime_error("cannot lock '" + file +
                                   "': " + std::strerror(error));
      }
  }


  CaseLock::~CaseLock()
  {
    if (fd >= 0)
      ::close(fd);
  }
} // namespace viscoslide

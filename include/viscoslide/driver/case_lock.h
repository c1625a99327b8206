// SPDX-License-Identifier: LGPL-2.1-or-later
// A lock on one run's folder, so that two invocations (or two groups of
// processes of one invocation) never run the same case at once.
#ifndef viscoslide_case_lock_h
#define viscoslide_case_lock_h

#include <string>

namespace viscoslide
{
  // An advisory lock (flock) on `file`, taken without waiting. The system
  // releases it when the process ends, also when the process is killed,
  // so a lock never outlives its run. The file stays, empty.
  class CaseLock
  {
  public:
    // Tries for `patience` seconds (a killed run's processes may take a
    // moment to end). Throws if the file cannot be created.
    explicit CaseLock(const std::string &file, double patience = 0);
    ~CaseLock();
    CaseLock(const CaseLock &) = delete;
    CaseLock &
    operator=(const CaseLock &) = delete;

    // False: another process holds the lock.
    bool
    held() const
    {
      return fd >= 0;
    }

  private:
    int fd = -1;
  };
} // namespace viscoslide

#endif

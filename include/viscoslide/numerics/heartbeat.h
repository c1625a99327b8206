// SPDX-License-Identifier: LGPL-2.1-or-later
// A line at least every 10 s while one solve runs long (a large 3D mesh
// spends minutes in one Newton step, a GMRES solve in its iterations), so
// that a user sees it progress.
#ifndef viscoslide_heartbeat_h
#define viscoslide_heartbeat_h

#include <chrono>
#include <condition_variable>
#include <functional>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>

namespace viscoslide
{
  class Heartbeat
  {
  public:
    // Whether 10 s have passed since the last line (or the start).
    bool
    due()
    {
      const auto now = std::chrono::steady_clock::now();
      if (now - last < std::chrono::seconds(10))
        return false;
      last = now;
      return true;
    }

    // Since the start.
    double
    seconds() const
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
        .count();
    }

  private:
    std::chrono::steady_clock::time_point start =
                                            std::chrono::steady_clock::now(),
                                          last = start;
  };


  // The same for a call that cannot report itself (a MUMPS factorization):
  // while this object lives, a thread prints line(seconds so far) to
  // std::cout every 10 s, if `active`.
  class HeartbeatWhile
  {
  public:
    HeartbeatWhile(const bool                                 active,
                   std::function<std::string(double seconds)> line)
    {
      if (active)
        watcher = std::thread([this, line = std::move(line)]() {
          const auto                   start = std::chrono::steady_clock::now();
          std::unique_lock<std::mutex> lock(mutex);
          while (!wake.wait_for(lock, std::chrono::seconds(10), [this]() {
            return done;
          }))
            std::cout << line(std::chrono::duration<double>(
                                std::chrono::steady_clock::now() - start)
                                .count())
                      << std::endl;
        });
    }

    ~HeartbeatWhile()
    {
      if (!watcher.joinable())
        return;
      {
        std::lock_guard<std::mutex> lock(mutex);
        done = true;
      }
      wake.notify_one();
      watcher.join();
    }

  private:
    std::mutex              mutex;
    std::condition_variable wake;
    bool                    done = false;
    std::thread             watcher;
  };
} // namespace viscoslide

#endif

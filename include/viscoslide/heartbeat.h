// A line at least every 10 s while one solve runs long (a large 3D mesh
// spends minutes in one Newton step, a GMRES solve in its iterations), so
// that a user sees it progress.
#ifndef viscoslide_heartbeat_h
#define viscoslide_heartbeat_h

#include <chrono>

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
} // namespace viscoslide

#endif

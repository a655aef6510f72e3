// A pool of threads made and joined by the caller's call (the library starts no thread that
// outlives a call): the jobs 0 … count − 1 taken in order by whichever thread is free. Sweeps run
// their rows on it, snapshot suites their cases.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stop_token>

namespace tasks {

struct PoolRun {
  int threads = 0;           ///< threads used: min(jobs, count), at least 1
  bool interrupted = false;  ///< `cancelled` said stop before every job was taken
};

/// Runs `job(i, stop)` for each i on `jobs` threads (0: one per core). A job returns false when
/// it stopped on request (its thread then takes no more). `cancelled` (may be empty) is asked
/// every 50 ms, and a true stops the pool (the stop token says so to the running jobs);
/// `progress` (may be empty) is told the jobs finished, from the calling thread.
PoolRun runJobs(std::size_t count, int jobs,
                const std::function<bool(std::size_t, std::stop_token)>& job,
                const std::function<bool()>& cancelled = {},
                const std::function<void(std::int64_t)>& progress = {});

}  // namespace tasks

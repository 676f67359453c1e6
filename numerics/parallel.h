// One parallel loop for independent pieces of work (a diagnosis' fits and predictions, the
// homogenisation's realisations and a ball's film speeds): OpenMP threads, dynamic schedule —
// unless already inside a parallel region, where nested regions stay serial.
#pragma once

#include <omp.h>

#include <atomic>
#include <cstddef>
#include <exception>

namespace tribo::numerics {

// body(k) for every k < n on `threads` threads (0: as many as OpenMP offers). An exception must
// not leave an OpenMP region (the runtime terminates the program): the first one a body throws is
// kept and rethrown here after the loop, and the bodies not yet started are skipped — their work
// would be lost with the loop's result.
template <class Body>
void parallel_for(std::size_t n, const Body& body, int threads = 0) {
  std::exception_ptr failure;
  std::atomic<bool> failed{false};
#pragma omp parallel for schedule(dynamic) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (std::size_t k = 0; k < n; ++k) {
    if (failed) continue;
    try {
      body(k);
    } catch (...) {
#pragma omp critical(tribo_parallel_for_failure)
      if (!failure) failure = std::current_exception();
      failed = true;
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace tribo::numerics

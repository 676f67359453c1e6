// One parallel loop for the diagnosis' independent pieces of work (the plans of a prediction, the
// starts and candidates of the fits): OpenMP threads, dynamic schedule — unless already inside a
// parallel region, where nested regions stay serial.
#pragma once

#include <cstddef>
#include <exception>

namespace tribo::gap {

// body(k) for every k < n. An exception must not leave an OpenMP region (the runtime terminates
// the program): the first one a body throws is kept and rethrown here after the loop.
template <class Body>
void parallel_for(std::size_t n, const Body& body) {
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic)
  for (std::size_t k = 0; k < n; ++k) {
    try {
      body(k);
    } catch (...) {
#pragma omp critical(tribo_gap_parallel_for_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace tribo::gap

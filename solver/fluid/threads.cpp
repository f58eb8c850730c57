// Thread count of the OpenMP loops and of FFTW (threads.hpp).
#include "fluid/threads.hpp"

#if defined(_OPENMP)
#include <fftw3.h>
#include <omp.h>
#endif

namespace ibms {

#if defined(_OPENMP)
namespace {
bool fftw_threads_ready() {
  static const bool ready = fftw_init_threads() != 0;
  return ready;
}
}  // namespace

int set_thread_count(int n) {
  const int count = n > 0 ? n : omp_get_num_procs();
  omp_set_num_threads(count);
  if (fftw_threads_ready()) fftw_plan_with_nthreads(count);
  return count;
}

int thread_count() { return omp_get_max_threads(); }
void prepare_fft_threads() {
  if (fftw_threads_ready()) fftw_plan_with_nthreads(thread_count());
}
bool built_with_openmp() { return true; }
#else
int set_thread_count(int) { return 1; }
int thread_count() { return 1; }
bool built_with_openmp() { return false; }
void prepare_fft_threads() {}
#endif

}  // namespace ibms

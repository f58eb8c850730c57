// Thread count of the OpenMP loops and of FFTW (threads.hpp).
#include "fluid/threads.hpp"

#include <sched.h>

#include <algorithm>
#include <cstddef>

#if defined(_OPENMP)
#include <fftw3.h>
#include <omp.h>
#endif

namespace ibms {

#if defined(_OPENMP)
namespace {
// FFTW's parallel loop over a plan's jobs: the jobs are fixed when the plan is made, the threads
// that run them are those of the loops now.
extern "C" void run_fft_jobs(void* (*work)(char*), char* job_data, std::size_t job_size, int jobs, void*) {
  const int threads = std::min(jobs, omp_get_max_threads());
#pragma omp parallel for schedule(static) num_threads(threads) if(!omp_in_parallel())
  for (int k = 0; k < jobs; ++k) work(job_data + job_size * static_cast<std::size_t>(k));
}

bool fftw_threads_ready() {
  static const bool ready = [] {
    if (fftw_init_threads() == 0) return false;
    fftw_threads_set_callback(run_fft_jobs, nullptr);
    return true;
  }();
  return ready;
}

int run_threads = 0;  // the count set by set_thread_count; 0: OpenMP's default
}  // namespace

void set_loop_threads(int n) { omp_set_num_threads(std::max(1, n)); }

int set_thread_count(int n) {
  run_threads = n > 0 ? n : available_cores();
  omp_set_num_threads(run_threads);
  if (fftw_threads_ready()) fftw_plan_with_nthreads(run_threads);
  return run_threads;
}

int thread_count() { return run_threads > 0 ? run_threads : omp_get_max_threads(); }
int loop_threads() { return omp_get_max_threads(); }
void prepare_fft_threads() {
  if (fftw_threads_ready()) fftw_plan_with_nthreads(thread_count());
}
bool built_with_openmp() { return true; }
#else
void set_loop_threads(int) {}
int set_thread_count(int) { return 1; }
int thread_count() { return 1; }
int loop_threads() { return 1; }
bool built_with_openmp() { return false; }
void prepare_fft_threads() {}
#endif

int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

ThreadGovernor::ThreadGovernor(int full_count) : full_(full_count), current_(1), running_(1) {}

int ThreadGovernor::after_step(double seconds) {
  running_ = next_count(seconds);
  return running_;
}

int ThreadGovernor::next_count(double seconds) {
  if (!active()) return current_;
  if (running_ == 1) ++steps_at_one_;
  const int other = current_ == 1 ? full_ : 1;
  switch (phase_) {
    case Phase::hold:
      // A load that arrives while the run holds its count shows as a run of slow steps: measure
      // again at once instead of waiting out the interval.
      slow_steps_ = seconds > surge * mean_current_ ? slow_steps_ + 1 : 0;
      if (slow_steps_ >= surge_steps) left_ = 1;
      [[fallthrough]];
    case Phase::warmup:  // the first steps plan and fill caches
      if (--left_ > 0) break;
      slow_steps_ = 0;
      phase_ = Phase::measure;
      left_ = window;
      sum_ = 0.0;
      break;
    case Phase::measure:
      sum_ += seconds;
      if (--left_ > 0) break;
      mean_current_ = sum_ / window;
      phase_ = Phase::probe;
      left_ = window;
      sum_ = 0.0;
      return other;  // the probe runs at the other count
    case Phase::probe: {
      sum_ += seconds;
      if (--left_ > 0) return other;
      const double ratio = sum_ / window / mean_current_;  // the other count's time per step over this one's
      if (ratio < gain) {
        current_ = other;
        mean_current_ *= ratio;
        interval_ = first_interval;
      } else {
        const double paid_for = window * ratio / probe_share;
        interval_ = static_cast<int>(std::min<double>(last_interval, std::max<double>(2 * interval_, paid_for)));
      }
      phase_ = Phase::hold;
      left_ = interval_;
      break;
    }
  }
  return current_;
}

}  // namespace ibms

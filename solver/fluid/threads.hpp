// Threads. With IBMS_OPENMP (the default build) the cell loops of the
// fluid operators and solver run as OpenMP static loops over grid rows, the FFTW transforms use
// FFTW's OpenMP threads, and the bodies' per-body loops (interpolation, the inner-fluid term) run
// body by body (for_each_body); every loop writes each cell or body from one thread and does no
// reduction, so the result does not depend on the thread count (test_threads). Without OpenMP
// everything is serial.
#pragma once

#include <cstddef>
#include <exception>

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace ibms {

// Sets the threads of later parallel loops and of FFTW plans made afterwards (a SpectralSolver
// plans in its constructor); n <= 0: one per processor. Returns the count now in force (1 without
// OpenMP).
int set_thread_count(int n);
int thread_count();
// The threads the next parallel loop will have (1 without OpenMP).
int loop_threads();
bool built_with_openmp();
// Makes FFTW plan with thread_count() threads from now on (called before planning). A plan's jobs
// run on as many threads as the loops have when it executes (at most its planned count), so
// set_loop_threads governs the FFTs too, with the same result.
void prepare_fft_threads();
// The threads of the loops and of the FFTs' jobs from the next step on, without replanning.
void set_loop_threads(int n);
// The cores this process may run on (its CPU affinity), the default thread count.
int available_cores();

// Chooses, while a run goes, between its thread count and one thread by the wall time of its
// steps. On a busy machine a thread of a parallel loop waits at every barrier for the one the
// scheduler has put aside, and two threads can take several times as long per step as one
// (docs/design.md §9). The governor starts on one thread (a probe of one thread costs an idle
// machine less than a probe of all threads costs a busy one), measures the mean wall time of
// `window` steps at the count in force and of `window` steps at the other count, and keeps the
// other one only when it takes at most `gain` of the time. The next comparison comes after
// `interval` steps: first_interval after a change; while the choice holds, twice the last interval
// and at least what keeps the probes to `probe_share` of the time (a probe that took r times as
// long per step needs window r / probe_share steps between probes), at most last_interval. The
// A run of `surge_steps` steps each more than `surge` times the mean last measured (a load that
// arrived) starts the next comparison at once. The result does not depend on the count
// (test_threads), so the choice changes the wall time only.
class ThreadGovernor {
 public:
  explicit ThreadGovernor(int full_count);  // full_count <= 1: never changes anything
  bool active() const { return full_ > 1; }
  int count() const { return current_; }  // the count chosen (the first step's: 1 when active)
  // The wall time of the step just taken; returns the thread count for the next step.
  int after_step(double seconds);
  long steps_at_one() const { return steps_at_one_; }

  static constexpr int warmup = 2, window = 4, first_interval = 16, last_interval = 8192;
  static constexpr int surge_steps = 3;
  static constexpr double gain = 0.9, probe_share = 0.05, surge = 2.0;

 private:
  enum class Phase { warmup, hold, measure, probe };
  int next_count(double seconds);
  int full_, current_, running_;  // the run's count, the count chosen, the count of the last step
  Phase phase_ = Phase::warmup;
  int left_ = warmup, interval_ = first_interval;
  double sum_ = 0.0, mean_current_ = 0.0;
  int slow_steps_ = 0;
  long steps_at_one_ = 0;
};

}  // namespace ibms

// Runs the callables a and b side by side on two threads (one after the other without OpenMP).
#if defined(_OPENMP)
#define IBMS_PARALLEL_PAIR(a, b)          \
  _Pragma("omp parallel sections num_threads(2)") \
  {                                        \
    _Pragma("omp section") a();            \
    _Pragma("omp section") b();            \
  }
#else
#define IBMS_PARALLEL_PAIR(a, b) \
  {                              \
    a();                         \
    b();                         \
  }
#endif

// One OpenMP static loop over the following for statement (rows of a field); nothing without OpenMP.
// Inside a parallel region (a section of IBMS_PARALLEL_PAIR) the loop runs on the calling thread.
#if defined(_OPENMP)
#define IBMS_PARALLEL_ROWS _Pragma("omp parallel for schedule(static) if(!omp_in_parallel())")
#else
#define IBMS_PARALLEL_ROWS
#endif

namespace ibms {

// Runs f(b) for b = 0 .. n - 1 over the loop threads, each b on one thread (dynamic chunks: bodies
// differ in size). When f(b) writes only body b's data the result does not depend on the thread
// count. An exception from f is rethrown after the loop, that of the lowest b (the one a serial
// loop would have met first); inside a parallel region, or with one thread, a plain loop.
template <class F>
void for_each_body(std::size_t n, F&& f) {
#if defined(_OPENMP)
  if (n > 1 && loop_threads() > 1 && !omp_in_parallel()) {
    std::exception_ptr error;
    long first_failed = -1;
#pragma omp parallel for schedule(dynamic, 4)
    for (long b = 0; b < static_cast<long>(n); ++b) {
      try {
        f(static_cast<std::size_t>(b));
      } catch (...) {
#pragma omp critical(ibms_for_each_body)
        if (first_failed < 0 || b < first_failed) {
          first_failed = b;
          error = std::current_exception();
        }
      }
    }
    if (error) std::rethrow_exception(error);
    return;
  }
#endif
  for (std::size_t b = 0; b < n; ++b) f(b);
}

}  // namespace ibms

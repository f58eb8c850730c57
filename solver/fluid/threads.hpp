// Threads. With IBMS_OPENMP (the default build) the cell loops of the
// fluid operators and solver run as OpenMP static loops over grid rows and the FFTW transforms use
// FFTW's OpenMP threads; every loop writes each cell from one thread and does no reduction, so the
// result does not depend on the thread count (test_threads). Without OpenMP everything is serial.
#pragma once

namespace ibms {

// Sets the threads of later parallel loops and of FFTW plans made afterwards (a SpectralSolver
// plans in its constructor); n <= 0: one per processor. Returns the count now in force (1 without
// OpenMP).
int set_thread_count(int n);
int thread_count();
bool built_with_openmp();
// Makes FFTW plan with thread_count() threads from now on (called before planning).
void prepare_fft_threads();

}  // namespace ibms

// One OpenMP static loop over the following for statement (rows of a field); nothing without OpenMP.
#if defined(_OPENMP)
#define IBMS_PARALLEL_ROWS _Pragma("omp parallel for schedule(static)")
#else
#define IBMS_PARALLEL_ROWS
#endif

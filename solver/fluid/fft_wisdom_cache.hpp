// The FFTW wisdom cache: measured plans (FftPlanning::measure, fluid/spectral_solver.hpp) kept
// between runs on one machine, so that a run pays for measuring a transform size once, not at
// every start (about 1.3 s for the settling disk's grid on two threads), and so that two runs of a
// scene on one machine pick the same algorithms and give the same bits (docs/design.md §9).
//
// The file: IBMS_FFT_WISDOM if set ("off" disables the cache), else
// $XDG_CACHE_HOME/ibms/ (else $HOME/.cache/ibms/) fftw-wisdom-<FFTW version>-<host>.txt. One file
// holds every size, kind and thread count (FFTW keys its wisdom by the whole problem, threads
// included); it is per library version (FFTW refuses foreign wisdom anyway) and per host (the
// fastest algorithm is the machine's: a home folder shared by a cluster's nodes keeps one per node).
// Concurrent runs are safe: a run writes a file of its own beside the cache and renames it over the
// cache, so a reader sees one complete file; two runs that finish planning together keep the
// wisdom of the last, and the other's new sizes are measured again by a later run. A file FFTW
// cannot read is ignored (the run measures afresh and replaces it).
#pragma once
#include <string>

namespace ibms {

// The cache file this process uses; empty when the cache is off or no folder can be named.
std::string fft_wisdom_cache_path();
// Imports the cache into FFTW's planner. Returns false when there is none or FFTW refused it.
bool load_fft_wisdom_cache();
// Writes the planner's wisdom to the cache if it holds plans the cache did not (after planning).
// Returns false when nothing was written (nothing new, the cache off, or the folder not writable:
// the cache is an optimisation and its failure never stops a run).
bool save_fft_wisdom_cache();

}  // namespace ibms

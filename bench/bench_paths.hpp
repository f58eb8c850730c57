// Paths the benchmarks read from and write to, set by bench/CMakeLists.txt (defaults for a
// hand-built benchmark: the current directory and ./bench).
#pragma once

#ifndef IBMS_SOURCE_DIR
#define IBMS_SOURCE_DIR "."
#endif
#ifndef IBMS_BENCH_OUTPUT_DIR
#define IBMS_BENCH_OUTPUT_DIR "bench"
#endif

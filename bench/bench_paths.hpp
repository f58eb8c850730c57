// Paths the benchmarks read from and write to, set by bench/CMakeLists.txt (defaults for a
// hand-built benchmark: the current directory and ./bench).
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>

#ifndef IBMS_SOURCE_DIR
#define IBMS_SOURCE_DIR "."
#endif
#ifndef IBMS_BENCH_OUTPUT_DIR
#define IBMS_BENCH_OUTPUT_DIR "bench"
#endif

// A private scratch folder <tmp>/<prefix>_<pid> (concurrent benches do not collide), removed when
// it goes out of scope, also on an exception.
struct BenchScratch {
  std::filesystem::path path;
  explicit BenchScratch(const std::string& prefix)
      : path(std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~BenchScratch() { std::filesystem::remove_all(path); }
  BenchScratch(const BenchScratch&) = delete;
  BenchScratch& operator=(const BenchScratch&) = delete;
};

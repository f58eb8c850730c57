// The input format of the `ibms compare` fuzzer (fuzz_compare.cpp) and its corpus replay
// (test_fuzz_compare_corpus.cpp): an optional first line "#case NAME" (otherwise the case is the
// input's length modulo the number of cases), then the text of one or more CSV files separated by
// lines "#file" (a '#' line is a comment to the CSV reader, so a file parses alike without them).
// run_compare_input writes the files into a folder and runs compare_case on them, then reads each
// with the reference readers too (read_profile_table, reference_value): the claim under test is
// that every input gives a verdict (0 or 1) or an InputError of one line, nothing else.
#pragma once
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "app/compare.hpp"
#include "core/errors.hpp"
#include "metrics/csv_reader.hpp"
#include "metrics/profile.hpp"

namespace ibms::fuzz {

struct CompareInput {
  std::string case_name;
  std::vector<std::string> files;  // CSV texts
};

inline CompareInput split_compare_input(const std::string& text) {
  CompareInput input;
  std::size_t at = 0;
  const std::string case_marker = "#case ";
  if (text.compare(0, case_marker.size(), case_marker) == 0) {
    const std::size_t end = text.find('\n');
    input.case_name = text.substr(case_marker.size(), (end == std::string::npos ? text.size() : end) - case_marker.size());
    at = end == std::string::npos ? text.size() : end + 1;
  } else {
    const std::vector<std::string> names = compare_case_names();
    input.case_name = names[text.size() % names.size()];
  }
  const std::string separator = "#file\n";
  while (true) {
    const std::size_t next = text.find(separator, at);
    if (next == std::string::npos) {
      input.files.push_back(text.substr(at));
      break;
    }
    input.files.push_back(text.substr(at, next - at));
    at = next + separator.size();
  }
  return input;
}

// Every reader of `ibms compare` on the input's files, in `dir`; returns compare_case's result.
// Throws InputError for bad input (and whatever else escapes: a bug).
inline int run_compare_input(const CompareInput& input, const std::string& dir, const std::string& validation_dir) {
  std::vector<std::string> paths;
  for (std::size_t k = 0; k < input.files.size(); ++k) {
    paths.push_back(dir + "/file_" + std::to_string(k) + ".csv");
    std::ofstream(paths.back(), std::ios::binary) << input.files[k];
  }
  // The readers of the shipped references, on the input as if it were one: each either reads it
  // or refuses it with InputError.
  for (const std::string& path : paths) {
    try { read_profile_table(path); } catch (const InputError&) {}
    try { reference_value(path, "max_settling_speed"); } catch (const InputError&) {}
    try { reference_value(path, "drag_coefficient", "upper"); } catch (const InputError&) {}
  }
  return compare_case(input.case_name, paths, validation_dir);
}

}  // namespace ibms::fuzz

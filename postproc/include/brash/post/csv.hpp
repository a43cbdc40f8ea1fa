// Strict CSV scanning for run files: the run layer's scanner (brash/run/run_csv.hpp), named in brash::post for the
// postprocessor's readers (particle snapshots, particles/index.csv).
#pragma once
#include <string_view>
#include <vector>

#include <brash/run/run_csv.hpp>

namespace brash::post {

using run::CsvRecordFn;
using run::CsvScan;
using run::parse_finite;
using run::read_text_file;
using run::scan_csv;

// The whitespace-separated fields of one line of a LIGGGHTS output file (fix ave/time, dump custom); they view `line`.
inline std::vector<std::string_view> whitespace_fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

}  // namespace brash::post

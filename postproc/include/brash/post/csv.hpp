// Strict CSV scanning for run files: the run layer's scanner (brash/run/run_csv.hpp), named in brash::post for the
// postprocessor's readers (particle snapshots, particles/index.csv).
#pragma once
#include <brash/run/run_csv.hpp>

namespace brash::post {

using run::CsvRecordFn;
using run::CsvScan;
using run::parse_finite;
using run::read_text_file;
using run::scan_csv;

}  // namespace brash::post

// Strict CSV scanning for run files (hull_force.csv, particle snapshots, particles/index.csv), for the engines'
// runners and for brash-post.
// Every malformed record is a brash::InputError naming "file:line". A last line without a newline
// can be dropped (a run still being written) instead of parsed.
#pragma once
#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace brash::run {

struct CsvScan {
  std::size_t records = 0;    // records handed to the callback
  bool tail_dropped = false;  // an unterminated last line was skipped
  std::size_t tail_line = 0;  // its line number (1-based) when dropped
};

using CsvRecordFn = std::function<void(std::size_t line_no, std::span<const std::string_view> fields)>;

// Reads a whole file; InputError if it cannot be opened.
std::string read_text_file(const std::filesystem::path& path);

// The first non-blank line of a CSV text, split into trimmed fields, and its number (1-based); no fields when
// the text has no such line.
struct CsvHeader {
  std::vector<std::string> fields;
  std::size_t line = 0;
};
CsvHeader read_csv_header(std::string_view text);

// Checks the header (exact column names, whitespace/CR tolerated), then calls `on_record` for every
// non-blank line with exactly header.size() fields. `drop_unterminated_tail`: skip a last line that
// has no trailing newline (it may still be being written).
CsvScan scan_csv(const std::filesystem::path& path, std::string_view text,
                 std::span<const std::string_view> header, bool drop_unterminated_tail,
                 const CsvRecordFn& on_record);

// Parses a finite double (whole field, surrounding spaces allowed); InputError naming file, line, column.
double parse_finite(std::string_view field, const std::filesystem::path& path, std::size_t line_no,
                    std::string_view column);

}  // namespace brash::run

// hull_force.csv of the run layout (docs/case_format.md): the force of the ice on the hull, one row per output
// interval. The one writer and the one reader of that file, for every engine's runner and for brash-post.
//
// The header names the columns: t_s,fx_N,fy_N,fz_N are required (in any order), and any further named column
// (a force component such as a normal/tangential split, or one hull region) is read and written back as it is,
// after the four. Every number is written with 9 significant digits, so a record read and written again is the
// same file byte for byte.
#pragma once
#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace brash::run {

// The columns every hull-force record has, in the order they are written.
inline constexpr std::array<std::string_view, 4> kForceColumns{"t_s", "fx_N", "fy_N", "fz_N"};

// The hull force split (docs/physics.md, "The hull force split"; brash/core/hull_split.hpp): further columns of
// the record that LIGGGHTS and brash-ode write, in this order. The x component of the force of the ice on the hull
// by hull region (bow, parallel mid-body, stern: the first three) and by mechanism (the normal and tangential
// parts of each contact force: the last two); each set adds up to fx_N. A record without them has no split (an
// older run, YADE, a user's own deck): it is not recorded, never zero.
inline constexpr std::array<std::string_view, 5> kSplitColumns{"fx_bow_N", "fx_mid_N", "fx_stern_N", "fx_normal_N",
                                                                "fx_tangential_N"};

// One row of the hull-force record: the force of the ice on the hull, averaged over an output interval.
struct ForceRow {
  double t_s = 0, fx_N = 0, fy_N = 0, fz_N = 0;
};

// A record as read, or to be written: its rows and the values of its further columns.
struct ForceRecord {
  std::vector<ForceRow> rows;
  std::vector<std::string> extra_columns;  // names of the columns after the four, in file order
  std::vector<double> extra;               // row-major: extra[i * extra_columns.size() + k] of row i, column k
  bool tail_dropped = false;               // an unterminated last line was left out (a file still being written)

  double extra_value(std::size_t row, std::size_t column) const { return extra[row * extra_columns.size() + column]; }
  // Whether the record has every column of the split (kSplitColumns); the split's part k of row i is then
  // extra_value(i, split_column(k)).
  bool has_split() const;
  std::size_t split_column(std::size_t k) const;
  // Sets the split's columns (after any other further columns, none before them); `values` row-major, one
  // kSplitColumns.size() block per row.
  void set_split(const std::vector<double>& values);
};

// The file's text: the header and one line per row.
std::string hull_force_csv_text(const ForceRecord& record);

// Writes the record to `csv` atomically (brash::run::write_atomic); the number of rows.
std::size_t write_hull_force_csv(const std::filesystem::path& csv, const ForceRecord& record);
std::size_t write_hull_force_csv(const std::filesystem::path& csv, const std::vector<ForceRow>& rows);

// A number as the record holds it (rounded to what is written), so that what an engine decides on its rows in
// memory (the early stop) is what a reader of the file would decide.
double as_recorded(double value);

// Reads a record written by write_hull_force_csv or by another writer of the same columns. Strict: a header
// without one of the four columns (or with a name twice), a row with the wrong number of fields, a number that
// does not parse or is not finite, a time that does not increase throw brash::InputError naming the file and line. `drop_unterminated_tail`: a last line without a newline
// is left out (the file may still be being written, or its writer was killed) instead of read.
ForceRecord read_hull_force_csv(const std::filesystem::path& csv, bool drop_unterminated_tail);

}  // namespace brash::run

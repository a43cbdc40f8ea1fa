// The run record hull_force.csv (brash/run/force_record.hpp): one writer, one header-driven strict reader.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "brash/error.hpp"
#include "brash/run/force_record.hpp"

namespace fs = std::filesystem;
using brash::run::ForceRecord;
using brash::run::ForceRow;

namespace {

class ForceRecordFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("brash_force_record_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    csv_ = dir_ / "hull_force.csv";
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& text) const { std::ofstream(csv_, std::ios::binary) << text; }
  std::string slurp() const {
    std::ifstream in(csv_, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  // The message of the InputError that reading `text` throws ("" when none is thrown).
  std::string read_error(const std::string& text, bool drop_tail = false) const {
    write(text);
    try {
      brash::run::read_hull_force_csv(csv_, drop_tail);
    } catch (const brash::InputError& e) {
      return e.what();
    }
    return "";
  }
  std::string at(int line) const { return csv_.string() + ":" + std::to_string(line) + ":"; }

  fs::path dir_, csv_;
};

::testing::AssertionResult mentions(const std::string& message, const std::string& part) {
  if (message.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << message << "' does not mention '" << part << "'";
}

}  // namespace

// The format every engine's runner wrote before the record had one writer: 9 significant digits, no spaces.
TEST_F(ForceRecordFile, WritesTheHeaderAndNineSignificantDigits) {
  const std::vector<ForceRow> rows{{0.0, -1234.56789012, 0.1, 3e-12}, {0.005, 1e21, -0.0, 42}};
  EXPECT_EQ(brash::run::write_hull_force_csv(csv_, rows), 2u);
  EXPECT_EQ(slurp(), "t_s,fx_N,fy_N,fz_N\n0,-1234.56789,0.1,3e-12\n0.005,1e+21,-0,42\n");
}

TEST_F(ForceRecordFile, RoundTripIsByteIdentical) {
  std::vector<ForceRow> rows;
  for (int i = 0; i < 50; ++i) rows.push_back({0.001 * (i + 1), -1e5 / (i + 3), 17.0 / (i + 7), 1e-3 * i * i});
  brash::run::write_hull_force_csv(csv_, rows);
  const std::string first = slurp();
  const ForceRecord read = brash::run::read_hull_force_csv(csv_, false);
  ASSERT_EQ(read.rows.size(), rows.size());
  EXPECT_TRUE(read.extra_columns.empty());
  EXPECT_FALSE(read.tail_dropped);
  brash::run::write_hull_force_csv(csv_, read);
  EXPECT_EQ(slurp(), first);
  EXPECT_DOUBLE_EQ(read.rows[4].fx_N, brash::run::as_recorded(rows[4].fx_N));
}

// A further named column (a force component) is read, kept with its name and written back after the four.
TEST_F(ForceRecordFile, ExtraColumnsAreKept) {
  const std::string text = "t_s,fx_N,fy_N,fz_N,fn_N,ft_N\n0.1,1,2,3,4,5\n0.2,-1,-2,-3,-4,-5.5\n";
  write(text);
  const ForceRecord r = brash::run::read_hull_force_csv(csv_, false);
  ASSERT_EQ(r.extra_columns, (std::vector<std::string>{"fn_N", "ft_N"}));
  ASSERT_EQ(r.rows.size(), 2u);
  EXPECT_EQ(r.extra_value(0, 0), 4);
  EXPECT_EQ(r.extra_value(1, 1), -5.5);
  brash::run::write_hull_force_csv(csv_, r);
  EXPECT_EQ(slurp(), text);
}

// The header says which column is which: the four may come in any order, with others between them.
TEST_F(ForceRecordFile, ColumnsAreFoundByName) {
  write("fz_N, bow_fx_N ,t_s,fy_N,fx_N\n3,9,0.1,2,1\n");
  const ForceRecord r = brash::run::read_hull_force_csv(csv_, false);
  ASSERT_EQ(r.rows.size(), 1u);
  EXPECT_EQ(r.rows[0].t_s, 0.1);
  EXPECT_EQ(r.rows[0].fx_N, 1);
  EXPECT_EQ(r.rows[0].fy_N, 2);
  EXPECT_EQ(r.rows[0].fz_N, 3);
  ASSERT_EQ(r.extra_columns, std::vector<std::string>{"bow_fx_N"});
  EXPECT_EQ(r.extra_value(0, 0), 9);
}

TEST_F(ForceRecordFile, MalformedRowNamesFileAndLine) {
  const std::string header = "t_s,fx_N,fy_N,fz_N\n";
  std::string e = read_error(header + "0.1,1,2,3\n0.2,1,x,3\n");
  EXPECT_TRUE(mentions(e, at(3)));
  EXPECT_TRUE(mentions(e, "'fy_N'"));
  EXPECT_TRUE(mentions(e, "'x' is not a number"));
  e = read_error(header + "0.1,1,2,3\n0.2,1,2\n");
  EXPECT_TRUE(mentions(e, at(3)));
  EXPECT_TRUE(mentions(e, "3 fields, expected 4"));
  EXPECT_TRUE(mentions(read_error(header + "0.1,inf,2,3\n"), at(2)));
  e = read_error(header + "0.2,1,2,3\n0.1,1,2,3\n");
  EXPECT_TRUE(mentions(e, at(3)));
  EXPECT_TRUE(mentions(e, "does not increase"));
  EXPECT_TRUE(mentions(read_error("t_s,fx_N,fy_N,fz_N,fn_N\n0.1,1,2,3,n\n"), "'fn_N'"));
}

TEST_F(ForceRecordFile, MissingHeaderNamesFileAndLine) {
  std::string e = read_error("0.1,1,2,3\n0.2,1,2,3\n");
  EXPECT_TRUE(mentions(e, at(1)));
  EXPECT_TRUE(mentions(e, "expected 't_s,fx_N,fy_N,fz_N'"));
  EXPECT_TRUE(mentions(read_error("t_s,fx_N,fy_N\n0.1,1,2\n"), at(1)));            // a column missing
  EXPECT_TRUE(mentions(read_error("t_s,fx_N,fy_N,fz_N,fx_N\n0.1,1,2,3,4\n"), at(1)));  // one named twice
  e = read_error("");
  EXPECT_TRUE(mentions(e, at(1)));
  EXPECT_TRUE(mentions(e, "empty file"));
}

// A file still being written (or left by a killed writer) ends in a cut line: left out when asked, else an error.
TEST_F(ForceRecordFile, UnterminatedLastLine) {
  const std::string text = "t_s,fx_N,fy_N,fz_N\n0.1,1,2,3\n0.2,1,2";
  write(text);
  const ForceRecord r = brash::run::read_hull_force_csv(csv_, true);
  EXPECT_EQ(r.rows.size(), 1u);
  EXPECT_TRUE(r.tail_dropped);
  EXPECT_TRUE(mentions(read_error(text, false), at(3)));
}

TEST_F(ForceRecordFile, MissingFileIsNamed) {
  try {
    brash::run::read_hull_force_csv(dir_ / "none.csv", false);
    FAIL() << "no error for a missing file";
  } catch (const brash::InputError& e) {
    EXPECT_TRUE(mentions(e.what(), (dir_ / "none.csv").string()));
  }
}

// The hull force split's columns (kSplitColumns) go through the one writer and reader like any further column, and
// the record names them: has_split and split_column find each part by name, whatever the file's column order.
TEST_F(ForceRecordFile, SplitColumnsRoundTripAndAreFoundByName) {
  ForceRecord r;
  r.rows = {{0.01, -3.0, 0.5, -1.0}, {0.02, -5.0, 0.25, -2.0}};
  EXPECT_FALSE(r.has_split());
  r.set_split({-2.0, -0.5, -0.5, -1.25, -1.75, -4.0, -1.0, 0.0, -3.5, -1.5});
  ASSERT_TRUE(r.has_split());
  brash::run::write_hull_force_csv(csv_, r);
  EXPECT_EQ(slurp().substr(0, slurp().find('\n')),
            "t_s,fx_N,fy_N,fz_N,fx_bow_N,fx_mid_N,fx_stern_N,fx_normal_N,fx_tangential_N");
  const ForceRecord back = brash::run::read_hull_force_csv(csv_, false);
  ASSERT_TRUE(back.has_split());
  EXPECT_EQ(back.extra_value(1, back.split_column(0)), -4.0);
  EXPECT_EQ(back.extra_value(1, back.split_column(4)), -1.5);
  // another order of the columns: found by name
  write("t_s,fx_tangential_N,fx_N,fy_N,fz_N,fx_normal_N,fx_stern_N,fx_mid_N,fx_bow_N\n0.01,-1.75,-3,0.5,-1,-1.25,-0.5,-0.5,-2\n");
  const ForceRecord shuffled = brash::run::read_hull_force_csv(csv_, false);
  ASSERT_TRUE(shuffled.has_split());
  EXPECT_EQ(shuffled.extra_value(0, shuffled.split_column(0)), -2.0);     // bow
  EXPECT_EQ(shuffled.extra_value(0, shuffled.split_column(4)), -1.75);    // tangential
  // a record with part of the split has none
  write("t_s,fx_N,fy_N,fz_N,fx_bow_N,fx_mid_N\n0.01,-3,0.5,-1,-2,-1\n");
  EXPECT_FALSE(brash::run::read_hull_force_csv(csv_, false).has_split());
  // the split is set on a record without further columns, one block of five per row
  ForceRecord wrong;
  wrong.rows = r.rows;
  EXPECT_THROW(wrong.set_split({1.0, 2.0}), std::logic_error);
}

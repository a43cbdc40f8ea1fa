// Golden outputs of the case loader: the resolved case (dump_case_yaml(load_case(...))) of every case file in the
// repository, and the resolved case or the error message of a corpus of case texts (the bad inputs of
// tests/robustness/test_catalogue.cpp and test_case.cpp, a bad value for every key, and cases that set the optional
// keys). Any change of a message or of a resolved case shows here as a difference against tests/case/golden/.
//
// Paths are written with placeholders: {src} the repository, {dir} the folder of a corpus case, {data} the brash
// data folder (an empty one, with only hull_meshes/jbc_panamax_model.stl, so the default hull resolves the same
// everywhere).
// BRASH_GOLDEN_UPDATE=1 rewrites the golden files from the current loader instead of comparing (for an intended
// change of the output; review the difference before committing it).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "brash/case.hpp"
#include "brash/error.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRepo = fs::absolute(BRASH_SOURCE_DIR).lexically_normal();
const fs::path kGolden = kRepo / "tests/case/golden";

bool updating() {
  const char* u = std::getenv("BRASH_GOLDEN_UPDATE");
  return u != nullptr && std::string(u) == "1";
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  if (from.empty()) return s;
  for (auto pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size()))
    s.replace(pos, from.size(), to);
  return s;
}

// A fixed data folder and no $BRASH_HULL_DIR, so a relative hull name resolves the same on every machine.
class CaseGolden : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("brash_case_golden_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "data/hull_meshes");
    write_text(root_ / "data/hull_meshes/jbc_panamax_model.stl", "solid x\nendsolid x\n");
    ::setenv("BRASH_DATA_DIR", (root_ / "data").c_str(), 1);
    ::unsetenv("BRASH_HULL_DIR");
  }
  static void TearDownTestSuite() {
    ::unsetenv("BRASH_DATA_DIR");
    fs::remove_all(root_);
  }

  // The resolved case, or "error: <message>", with the paths replaced by their placeholders.
  static std::string outcome(const fs::path& case_file, const fs::path& case_dir) {
    std::string out;
    try {
      out = brash::dump_case_yaml(brash::load_case(case_file));
    } catch (const brash::InputError& e) {
      out = std::string("error: ") + e.what() + "\n";
    }
    out = replace_all(out, (root_ / "data").string(), "{data}");
    if (!case_dir.empty()) out = replace_all(out, case_dir.string(), "{dir}");
    return replace_all(out, kRepo.string(), "{src}");
  }

  static fs::path root_;
};
fs::path CaseGolden::root_;

// Whether a case file names absolute paths inside this checkout (a run's resolved case recorded here).
bool names_this_checkout(const fs::path& case_file) {
  return read_text(case_file).find(kRepo.string()) != std::string::npos;
}

// tests/case/golden/case_files.txt lists the case files (relative to the repository); the golden of
// a/b/case.yaml is case_files/a--b--case.yaml.
TEST_F(CaseGolden, EveryCaseFileResolvesAsBefore) {
  std::ifstream list(kGolden / "case_files.txt");
  ASSERT_TRUE(list) << "missing " << (kGolden / "case_files.txt");
  int checked = 0;
  for (std::string rel; std::getline(list, rel);) {
    if (rel.empty() || rel[0] == '#') continue;
    const fs::path golden = kGolden / "case_files" / replace_all(rel, "/", "--");
    const std::string got = outcome(kRepo / rel, {});
    if (updating())
      // a run's resolved case names the absolute paths of the machine that recorded it: its golden keeps them
      // literal, so that it reads the same in a checkout anywhere else
      write_text(golden, names_this_checkout(kRepo / rel) ? replace_all(got, "{src}", kRepo.string()) : got);
    else
      // a case file that names an absolute path (a run's resolved case) names it in its golden too: where that
      // path lies in this checkout, it reads as {src} on both sides
      EXPECT_EQ(got, replace_all(read_text(golden), kRepo.string(), "{src}"))
          << rel << " (golden: " << golden << ")";
    ++checked;
  }
  EXPECT_GT(checked, 40);
}

// A resolved case as its difference from `base` (another resolved case): "-line" for each line of base it lacks,
// "+line" for each line it has that base lacks, in the order of each text.
std::string difference(const std::string& dump, const std::string& base) {
  const auto lines = [](const std::string& t) {
    std::vector<std::string> out;
    std::istringstream in(t);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
  };
  const std::vector<std::string> a = lines(base), b = lines(dump);
  const auto missing_from = [](const std::vector<std::string>& from, const std::vector<std::string>& in, char sign) {
    std::string out;
    std::vector<bool> used(in.size(), false);
    for (const auto& l : from) {
      bool found = false;
      for (std::size_t k = 0; k < in.size() && !found; ++k)
        if (!used[k] && in[k] == l) found = used[k] = true;
      if (!found) out += sign + l + "\n";
    }
    return out;
  };
  return "resolved, unlike the minimal case:\n" + missing_from(a, b, '-') + missing_from(b, a, '+');
}

// tests/case/golden/case_texts.yaml: a list of {case: text, result}; each text is loaded as {dir}/case.yaml.
// The result is the error message, or the resolved case: in full for the first entry (the minimal case,
// "name: x"), as its difference from the first entry for the others (the files stay small; the first entry and
// the case files check the whole text and the order of the keys).
TEST_F(CaseGolden, EveryCaseTextGivesTheSameResultOrMessage) {
  const fs::path file = kGolden / "case_texts.yaml";
  YAML::Node entries = YAML::LoadFile(file.string());
  ASSERT_TRUE(entries.IsSequence());
  const fs::path dir = root_ / "case";
  YAML::Emitter updated;
  updated << YAML::BeginSeq;
  int errors = 0;
  std::vector<std::string> results;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::string text = entries[i]["case"].as<std::string>();
    fs::remove_all(dir);
    fs::create_directories(dir);
    write_text(dir / "case.yaml", text);
    std::string got = outcome(dir / "case.yaml", dir);
    if (i == 0) {
      ASSERT_EQ(text, "name: x\n") << "the first entry is the minimal case";
    }
    if (i > 0 && !got.starts_with("error: ")) got = difference(got, results.front());
    errors += got.starts_with("error: ") ? 1 : 0;
    results.push_back(got);
    if (!updating()) {
      EXPECT_EQ(got, entries[i]["result"].as<std::string>()) << "entry " << i << ":\n" << text;
      continue;
    }
    updated << YAML::BeginMap << YAML::Key << "case" << YAML::Value << YAML::DoubleQuoted << text;
    updated << YAML::Key << "result" << YAML::Value;
    if (got.starts_with("error: "))
      updated << YAML::DoubleQuoted << got;
    else
      updated << YAML::Literal << got;
    updated << YAML::EndMap;
  }
  updated << YAML::EndSeq;
  if (updating()) {
    write_text(file, "# Golden outputs of tests/case/test_case_golden.cpp (BRASH_GOLDEN_UPDATE=1 rewrites them)\n" +
                         std::string(updated.c_str()) + "\n");
    const YAML::Node back = YAML::LoadFile(file.string());  // the file must read back to what was written
    ASSERT_EQ(back.size(), entries.size());
    for (std::size_t i = 0; i < back.size(); ++i) {
      EXPECT_EQ(back[i]["case"].as<std::string>(), entries[i]["case"].as<std::string>()) << "entry " << i;
      EXPECT_EQ(back[i]["result"].as<std::string>(), results[i]) << "entry " << i;
    }
  }
  EXPECT_GT(errors, 100);
  EXPECT_GT(static_cast<int>(entries.size()) - errors, 10);
}

}  // namespace

// Tests of the case file's key reference (brash/case_keys.hpp): it lists every key the resolved case writes, each
// once, with its default and the values it accepts, and its defaults are the ones the loader fills in.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <string>

#include "brash/case.hpp"
#include "brash/case_keys.hpp"

namespace {

std::map<std::string, brash::CaseKeyInfo> reference_by_key() {
  std::map<std::string, brash::CaseKeyInfo> out;
  for (const auto& k : brash::case_key_reference()) {
    EXPECT_TRUE(out.emplace(k.key, k).second) << k.key << " listed twice";
    EXPECT_FALSE(k.doc.empty()) << k.key;
    EXPECT_FALSE(k.values.empty()) << k.key;
    EXPECT_FALSE(k.default_value.empty()) << k.key;
  }
  return out;
}

// Every key the resolved case writes (with every optional key set), dotted: "ice.seed".
void keys_of(const YAML::Node& n, const std::string& prefix, std::map<std::string, std::string>& out) {
  for (const auto& kv : n) {
    const std::string key = prefix.empty() ? kv.first.as<std::string>() : prefix + "." + kv.first.as<std::string>();
    if (kv.second.IsMap() && prefix.empty())
      keys_of(kv.second, key, out);
    else
      out[key] = kv.second.IsScalar() ? kv.second.Scalar() : "";
  }
}

}  // namespace

TEST(CaseKeys, TheReferenceListsEveryKeyOfTheResolvedCase) {
  const auto reference = reference_by_key();
  brash::Case c = brash::parse_case("name: x\nice: {settle: true}\nchannel: {ends: walls}\n"
                                    "fluid: {hull_flow: panel}\nhull: {band_m: [0.1, 0.1]}\n"
                                    "contact: {rolling_friction: 0.05}\n"
                                    "fsicr: {alpha_deg: 30, phi1_deg: 30, phi2_deg: 30, psi_deg: 30, L_par_m: 1, "
                                    "L_bow_m: 1, A_wf_m2: 1}\nspeedups: {farfield_beside_m: 0.3}\n"
                                    "references: {source: s, resistance_full_kN: {both: 1}, fsicr_R_CH_kN: 1, "
                                    "ratio_fsicr_to_sim: {both: 1}}\n",
                                    std::filesystem::temp_directory_path(), "mem");
  std::map<std::string, std::string> written;
  keys_of(YAML::Load(brash::dump_case_yaml(c)), "", written);
  for (const auto& [key, value] : written) EXPECT_TRUE(reference.contains(key)) << key << " is not in the reference";
  for (const auto& [key, info] : reference) EXPECT_TRUE(written.contains(key)) << key << " is not in the resolved case";
}

// A default given as a plain value is the one a case that leaves the key out resolves to.
TEST(CaseKeys, DefaultsAreTheLoadersDefaults) {
  const brash::Case c = brash::parse_case("name: x\n", std::filesystem::temp_directory_path(), "mem");
  std::map<std::string, std::string> written;
  keys_of(YAML::Load(brash::dump_case_yaml(c)), "", written);
  int compared = 0;
  for (const auto& [key, info] : reference_by_key()) {
    const auto it = written.find(key);
    if (it == written.end() || key == "hull.file" || key == "ice.packing_file" || key == "name") continue;
    if (key == "ice.diameter_sd_m" || key == "run.window_s") continue;  // defaults that follow other keys, in words
    EXPECT_EQ(YAML::Load(info.default_value).as<std::string>(), it->second) << key;
    ++compared;
  }
  EXPECT_GT(compared, 50);
  EXPECT_EQ(reference_by_key().at("ice.diameter_sd_m").default_value, "5 % of diameter_mean_m");
  EXPECT_EQ(reference_by_key().at("fluid.drag_coefficient").default_value, "0.44");
}

TEST(CaseKeys, MarkdownHasOneRowPerKeyBetweenTheMarkers) {
  const std::string md = brash::case_keys_markdown();
  EXPECT_TRUE(md.starts_with(brash::kCaseKeysBegin));
  EXPECT_TRUE(md.ends_with(std::string(brash::kCaseKeysEnd) + "\n"));
  EXPECT_NE(md.find("| `ice.porosity` | 0.28 | in (0, 1) | brash porosity |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("volume \\| strict_two_layer"), std::string::npos);
  std::size_t rows = 0;
  for (std::size_t at = md.find("\n| `"); at != std::string::npos; at = md.find("\n| `", at + 1)) ++rows;
  EXPECT_EQ(rows, brash::case_key_reference().size());
}

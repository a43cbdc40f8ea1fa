// Tests of the case loader: defaults, path resolution, round trip, and one InputError per kind of
// bad input whose message must name the file and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

#include "brash/case.hpp"
#include "brash/error.hpp"
#include "brash/run/runner_setup.hpp"

namespace fs = std::filesystem;
using brash::Case;

namespace {

fs::path temp_dir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("brash_test_case_" + tag + "_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

fs::path write_case(const fs::path& dir, const std::string& text, const std::string& name = "case.yaml") {
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

// Loads `text`; expects an InputError whose message contains the file name and every `parts`.
void expect_error(const std::string& text, std::initializer_list<std::string> parts) {
  const fs::path dir = temp_dir("bad");
  const fs::path p = write_case(dir, text, "bad_case.yaml");
  try {
    (void)brash::load_case(p);
    ADD_FAILURE() << "no InputError for:\n" << text;
  } catch (const brash::InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bad_case.yaml"), std::string::npos) << msg;
    for (const auto& part : parts) EXPECT_NE(msg.find(part), std::string::npos) << "'" << part << "' not in: " << msg;
  }
}

const fs::path kRepo = BRASH_SOURCE_DIR;

}  // namespace

TEST(CaseLoader, MinimalCaseFillsPaperDefaults) {
  const fs::path dir = temp_dir("min");
  const Case c = brash::load_case(write_case(dir, "name: m\n"));
  EXPECT_EQ(c.name, "m");
  EXPECT_DOUBLE_EQ(c.ship.speed_m_s, 0.482);
  EXPECT_DOUBLE_EQ(c.ship.scale_lambda, 28.5);
  EXPECT_EQ(c.ship.ice_class, brash::IceClass::IA);
  EXPECT_DOUBLE_EQ(c.channel.length_m, 21.0);
  EXPECT_DOUBLE_EQ(c.channel.width_m, 2.25);
  EXPECT_DOUBLE_EQ(c.ice.diameter_sd_m, 0.05 * 0.017578);
  EXPECT_DOUBLE_EQ(c.ice.porosity, 0.28);
  EXPECT_EQ(c.ice.packing_mode, brash::PackingMode::Volume);
  EXPECT_EQ(c.ice.seed, 1u);
  EXPECT_EQ(c.ice.packing_file, fs::absolute(dir / "generated/packing.csv").lexically_normal());
  EXPECT_DOUBLE_EQ(c.water.density_kg_m3, 1000);
  EXPECT_DOUBLE_EQ(c.friction.ice_ice, 1.35);
  EXPECT_DOUBLE_EQ(c.friction.ice_hull, 0.1);
  EXPECT_EQ(c.fluid.model, brash::FluidModel::Both);
  EXPECT_EQ(c.fluid.treatment, brash::Treatment::Implicit);
  EXPECT_EQ(c.run.window_s, (std::array<double, 2>{15.0, 40.0}));
  EXPECT_FALSE(c.hull.band_m.has_value());
  EXPECT_FALSE(c.fsicr.alpha_deg.has_value());
  EXPECT_TRUE(c.hull.file.is_absolute());
}

TEST(CaseLoader, SdDefaultsToFivePercentOfTheCasesMean) {
  const Case c =
      brash::load_case(write_case(temp_dir("sd"), "name: m\nice: {thickness_m: 0.08, diameter_mean_m: 0.04}\n"));
  EXPECT_DOUBLE_EQ(c.ice.diameter_sd_m, 0.002);
}

TEST(CaseLoader, IceOnePieceThickLoads) {
  // the thinnest ice the loader takes: one layer of pieces (thinner: tests/robustness/test_catalogue.cpp)
  const Case c = brash::parse_case("name: m\nice: {thickness_m: 0.035, diameter_mean_m: 0.035}\n", kRepo, "mem");
  EXPECT_DOUBLE_EQ(c.ice.thickness_m, c.ice.diameter_mean_m);
}

TEST(CaseLoader, ShortRunGetsWindowOverItsLastPart) {
  const Case c = brash::load_case(write_case(temp_dir("win"), "name: m\nrun: {duration_s: 5.0}\n"));
  EXPECT_DOUBLE_EQ(c.run.window_s[0], 2.0);
  EXPECT_DOUBLE_EQ(c.run.window_s[1], 5.0);
}

TEST(CaseLoader, HullFileSearchOrder) {
  const fs::path dir = temp_dir("hull");
  const fs::path other = temp_dir("hulldir");
  std::ofstream(other / "my_hull.stl") << "solid x\nendsolid x\n";
  ::setenv("BRASH_HULL_DIR", other.c_str(), 1);
  Case c = brash::load_case(write_case(dir, "name: m\nhull: {file: my_hull.stl}\n"));
  EXPECT_EQ(c.hull.file, fs::absolute(other / "my_hull.stl").lexically_normal());
  std::ofstream(dir / "my_hull.stl") << "solid x\nendsolid x\n";  // the case folder wins
  c = brash::load_case(dir / "case.yaml");
  EXPECT_EQ(c.hull.file, fs::absolute(dir / "my_hull.stl").lexically_normal());
  ::unsetenv("BRASH_HULL_DIR");
  // Missing everywhere: resolved against the case folder (runners report it missing).
  c = brash::load_case(write_case(dir, "name: m\nhull: {file: nowhere.stl}\n"));
  EXPECT_EQ(c.hull.file, fs::absolute(dir / "nowhere.stl").lexically_normal());
}

TEST(CaseLoader, PaperCaseLoadsWithPaperNumbers) {
  const Case c = brash::load_case(kRepo / "cases/jbc_ia_5kn/case.yaml");
  EXPECT_EQ(c.name, "jbc_ia_5kn");
  EXPECT_DOUBLE_EQ(c.ship.speed_m_s, 0.482);
  EXPECT_DOUBLE_EQ(c.run.duration_s, 40.0);
  EXPECT_EQ(c.run.window_s, (std::array<double, 2>{15.0, 40.0}));
  EXPECT_DOUBLE_EQ(c.ship.scale_lambda, 28.5);
  EXPECT_DOUBLE_EQ(c.friction.ice_ice, 1.35);
  EXPECT_DOUBLE_EQ(c.friction.ice_hull, 0.1);
  EXPECT_DOUBLE_EQ(c.friction.ice_wall, 1.35);
  EXPECT_DOUBLE_EQ(brash::h_m_for_ice_class(c.ship.ice_class), 1.0);
  EXPECT_DOUBLE_EQ(c.channel.length_m, 21.0);
  EXPECT_DOUBLE_EQ(c.channel.width_m, 2.25);
  EXPECT_DOUBLE_EQ(c.ice.thickness_m, 0.03515);
  EXPECT_DOUBLE_EQ(c.ice.diameter_mean_m, 0.017578);
  EXPECT_DOUBLE_EQ(c.ice.porosity, 0.28);
  EXPECT_EQ(c.fluid.model, brash::FluidModel::Both);
  EXPECT_EQ(c.fluid.treatment, brash::Treatment::Implicit);
  EXPECT_EQ(c.hull.file.filename(), "jbc_panamax_model.stl");
  const Case q = brash::load_case(kRepo / "cases/jbc_quick/case.yaml");
  EXPECT_EQ(q.name, "jbc_quick");
  EXPECT_LT(q.run.duration_s, 12.0);
}

TEST(CaseLoader, IceClassThickness) {
  EXPECT_DOUBLE_EQ(brash::h_m_for_ice_class(brash::IceClass::IA_super), 1.0);
  EXPECT_DOUBLE_EQ(brash::h_m_for_ice_class(brash::IceClass::IA), 1.0);
  EXPECT_DOUBLE_EQ(brash::h_m_for_ice_class(brash::IceClass::IB), 0.8);
  EXPECT_DOUBLE_EQ(brash::h_m_for_ice_class(brash::IceClass::IC), 0.6);
}

TEST(CaseLoader, DumpThenLoadGivesTheSameCase) {
  for (const char* name : {"jbc_ia_5kn", "jbc_quick"}) {
    Case c = brash::load_case(kRepo / "cases" / name / "case.yaml");
    c.description = "quotes \" and backslash \\ and: colon\nnew line";
    c.fsicr.alpha_deg = 38.123456789012345;
    c.fsicr.A_wf_m2 = 1.0 / 3.0;
    c.hull.band_m = std::array<double, 2>{0.1, 0.2};
    c.ice.seed = 18446744073709551615ull;
    c.fluid.model = brash::FluidModel::Both;
    c.fluid.drag_law = brash::DragLaw::SchillerNaumann;
    c.fluid.hull_flow = brash::HullFlow::ThinShip;
    c.fluid.ca_table =
        std::string(name) == "jbc_quick" ? brash::CaTableSpec::uniform(1.0 / 3.0) : brash::CaTable::Text;
    c.ship.ice_class = brash::IceClass::IA_super;
    c.ice.packing_mode = brash::PackingMode::StrictTwoLayer;
    c.contact.youngs_modulus_pa *= 1.5;  // a changed value that keeps dt under the Rayleigh limit
    c.contact.rolling_friction = 0.05;
    c.speedups.farfield = true;
    c.speedups.farfield_ahead_m = 0.7;
    c.speedups.farfield_behind_m = 1.0 / 3.0;
    c.speedups.farfield_every_steps = 37;
    c.speedups.farfield_wake_force_weight = 0.02;
    c.speedups.farfield_wake_speed_m_s = 1.0 / 7.0;
    c.speedups.farfield_wake_by = brash::WakeBy::NeighbourSpeed;
    c.ice.settle = true;  // the moving window needs the settled bed
    c.speedups.moving_window = true;
    c.speedups.moving_window_ahead_m = 1.0 / 1.3;
    c.speedups.moving_window_behind_m = 2.5;
    c.speedups.symmetry_y = true;
    c.speedups.neighbor_skin_d = 0.35;
    c.speedups.early_stop_rel_ci = 0.03;
    c.speedups.early_stop_trend_check = false;
    c.guards.max_hull_penetration_d = 0.3;
    c.guards.every_steps = 7;
    const fs::path run = temp_dir(std::string("rt_") + name);
    const Case back = brash::load_case(write_case(run, brash::dump_case_yaml(c)));
    EXPECT_EQ(back, c) << brash::dump_case_yaml(c) << "\n---\n" << brash::dump_case_yaml(back);
    EXPECT_EQ(brash::dump_case_yaml(back), brash::dump_case_yaml(c));
  }
}

TEST(CaseLoaderErrors, UnknownKeyNamesFileKeyAndLine) {
  expect_error("name: x\nice:\n  porosty: 0.3\n", {"ice.porosty", "unknown key", ":3:"});
  expect_error("name: x\nhul: {}\n", {"hul", "unknown key"});
}

TEST(CaseLoaderErrors, WrongType) {
  expect_error("name: x\nship:\n  speed_m_s: fast\n", {"ship.speed_m_s", "expected a number", ":3:"});
  expect_error("name: x\nship: 3\n", {"ship", "mapping"});
  expect_error("name: x\nrun: {window_s: 15}\n", {"run.window_s", "two numbers"});
  expect_error("name: x\nice: {seed: -3}\n", {"ice.seed", "integer"});
  expect_error("name: x\nice: {seed: 1.5}\n", {"ice.seed", "integer"});
}

TEST(CaseLoaderErrors, NegativeDensity) {
  expect_error("name: x\nice: {density_kg_m3: -900}\n", {"ice.density_kg_m3", "> 0"});
  expect_error("name: x\nwater: {density_kg_m3: -1}\n", {"water.density_kg_m3", "> 0"});
  expect_error("name: x\nice: {density_kg_m3: 1100}\n", {"ice.density_kg_m3", "lighter"});
}

TEST(CaseLoaderErrors, PorosityOutsideOpenUnitInterval) {
  expect_error("name: x\nice: {porosity: 1.0}\n", {"ice.porosity", "(0, 1)"});
  expect_error("name: x\nice: {porosity: 0}\n", {"ice.porosity", "(0, 1)"});
  expect_error("name: x\nice: {porosity: -0.2}\n", {"ice.porosity", "(0, 1)"});
}

TEST(CaseLoaderErrors, WindowOutsideDuration) {
  expect_error("name: x\nrun: {duration_s: 40, window_s: [15, 45]}\n", {"run.window_s", "duration"});
  expect_error("name: x\nrun: {window_s: [20, 10]}\n", {"run.window_s"});
  expect_error("name: x\nrun: {window_s: [-1, 10]}\n", {"run.window_s"});
}

TEST(CaseLoaderErrors, UnknownEnumValue) {
  expect_error("name: x\nfluid:\n  model: potential_flow\n", {"fluid.model", "potential_flow", "added_mass"});
  expect_error("name: x\nfluid: {treatment: semi}\n", {"fluid.treatment", "semi"});
  expect_error("name: x\nship: {ice_class: II}\n", {"ship.ice_class", "II"});
  expect_error("name: x\nice: {packing_mode: dense}\n", {"ice.packing_mode", "dense"});
}

TEST(CaseLoader, UniformCaTableReadWrittenAndRoundTrips) {  // stability map: "ca_table: uniform <Ca>"
  const fs::path dir = temp_dir("ca_uniform");
  const Case c = brash::load_case(write_case(dir, "name: u\nfluid:\n  ca_table: uniform 0.5\n"));
  EXPECT_EQ(c.fluid.ca_table, brash::CaTableSpec::uniform(0.5));
  EXPECT_EQ(brash::to_string(c.fluid.ca_table), "uniform 0.5");
  EXPECT_EQ(brash::to_string(brash::CaTableSpec(brash::CaTable::Zero)), "zero");
  EXPECT_NE(brash::dump_case_yaml(c).find("  ca_table: uniform 0.5\n"), std::string::npos);
  EXPECT_EQ(brash::load_case(write_case(dir, brash::dump_case_yaml(c), "back.yaml")), c);
  EXPECT_EQ(brash::load_case(write_case(dir, "name: u\nfluid: {ca_table: uniform 10}\n", "ten.yaml"))
                .fluid.ca_table.uniform_ca,
            10.0);
}

TEST(CaseLoaderErrors, UniformCaTableNeedsAFiniteNonNegativeValue) {
  for (const char* bad : {"uniform", "uniform -1", "uniform abc", "uniform 1 2", "uniform .nan", "uniform2"})
    expect_error(std::string("name: x\nfluid:\n  ca_table: ") + bad + "\n", {"fluid.ca_table", ":3:"});
  expect_error("name: x\nfluid: {ca_table: table2}\n", {"fluid.ca_table", "table2", "uniform 2"});
}

TEST(CaseLoader, HullFlowDefaultsToStillWaterAndIsRead) {
  const fs::path dir = temp_dir("hull_flow");
  EXPECT_EQ(brash::load_case(write_case(dir, "name: h\n")).fluid.hull_flow, brash::HullFlow::None);
  const Case c =
      brash::load_case(write_case(dir, "name: h\nfluid: {model: drag, hull_flow: thin_ship}\n", "t.yaml"));
  EXPECT_EQ(c.fluid.hull_flow, brash::HullFlow::ThinShip);
  EXPECT_NE(brash::dump_case_yaml(c).find("  hull_flow: thin_ship\n"), std::string::npos);
}

// contact.rolling_friction: 0 by default, and then not in the resolved case (which stays as it was without the
// key); a value is read and written back.
TEST(CaseLoader, RollingFrictionDefaultsToNoneAndIsRead) {
  const fs::path dir = temp_dir("rolling");
  const Case d = brash::load_case(write_case(dir, "name: r\n"));
  EXPECT_EQ(d.contact.rolling_friction, 0.0);
  EXPECT_EQ(brash::dump_case_yaml(d).find("rolling_friction"), std::string::npos);
  const Case c = brash::load_case(write_case(dir, "name: r\ncontact: {rolling_friction: 0.05}\n", "t.yaml"));
  EXPECT_EQ(c.contact.rolling_friction, 0.05);
  EXPECT_NE(brash::dump_case_yaml(c).find("  rolling_friction: 0.05\n"), std::string::npos);
}

TEST(CaseLoader, FluidModelDefaultsToDragPlusAddedMass) {
  // both (Eq. 1 + Eq. 2) is the default: a case without fluid.model gets it (the core's FluidParams: test_fluid)
  const fs::path dir = temp_dir("default_model");
  EXPECT_EQ(brash::load_case(write_case(dir, "name: d\n")).fluid.model, brash::FluidModel::Both);
}

TEST(CaseLoader, ReferencesAreReadAndDumped) {
  const fs::path dir = temp_dir("references");
  EXPECT_FALSE(brash::load_case(write_case(dir, "name: r\n")).references.declared());
  const Case c = brash::load_case(write_case(
      dir, "name: r\nreferences:\n  source: \"A paper\"\n  resistance_full_kN: {both: 393, drag: 378}\n"
           "  fsicr_R_CH_kN: 999\n  ratio_fsicr_to_sim: {both: 2.54}\n", "r.yaml"));
  EXPECT_EQ(c.references.source, "A paper");
  EXPECT_EQ(c.references.resistance_full_kN.at("both"), 393.0);
  EXPECT_EQ(c.references.resistance_full_kN.at("drag"), 378.0);
  EXPECT_EQ(c.references.resistance_full_kN.count("added_mass"), 0U);
  EXPECT_EQ(*c.references.fsicr_R_CH_kN, 999.0);
  EXPECT_EQ(c.references.ratio_fsicr_to_sim.at("both"), 2.54);
  // the resolved dump reads back to the same case
  const Case again = brash::parse_case(brash::dump_case_yaml(c), dir, "[dump]");
  EXPECT_EQ(again.references, c.references);
  // the paper case declares the paper's values
  const Case paper = brash::load_case(fs::path(BRASH_SOURCE_DIR) / "cases/jbc_ia_5kn/case.yaml");
  EXPECT_EQ(paper.references.resistance_full_kN.at("both"), 393.0);
  EXPECT_EQ(paper.references.resistance_full_kN.at("drag"), 378.0);
  EXPECT_EQ(*paper.references.fsicr_R_CH_kN, 999.0);
  EXPECT_FALSE(brash::load_case(fs::path(BRASH_SOURCE_DIR) / "cases/jbc_quick/case.yaml").references.declared());
}

TEST(CaseLoaderErrors, FsicrOverridesNoHullHasAreRefused) {
  expect_error("name: x\nfsicr:\n  alpha_deg: 95\n", {"fsicr.alpha_deg", "(0, 90]", ":3:"});
  expect_error("name: x\nfsicr: {phi2_deg: 0}\n", {"fsicr.phi2_deg", "(0, 90]"});
  expect_error("name: x\nfsicr:\n  L_bow_m: -40\n", {"fsicr.L_bow_m", "> 0", ":3:"});
  expect_error("name: x\nfsicr:\n  L_par_m: -1\n", {"fsicr.L_par_m", ">= 0"});
  expect_error("name: x\nfsicr:\n  A_wf_m2: 0\n", {"fsicr.A_wf_m2", "> 0"});
}

TEST(CaseLoaderErrors, ReferencesNeedASourceKnownModelsAndPositiveValues) {
  expect_error("name: x\nreferences:\n  resistance_full_kN: {both: 393}\n", {"references.source", "missing"});
  expect_error("name: x\nreferences:\n  source: s\n  resistance_full_kN: {wet: 393}\n",
               {"references.resistance_full_kN.wet", "unknown key", ":4:"});
  expect_error("name: x\nreferences:\n  source: s\n  fsicr_R_CH_kN: -1\n", {"references.fsicr_R_CH_kN", "> 0", ":4:"});
  expect_error("name: x\nreferences:\n  source: s\n  ratio_fsicr_to_sim: {drag: .nan}\n",
               {"references.ratio_fsicr_to_sim.drag", "finite"});
}

TEST(CaseLoaderErrors, HullFlowNeedsTheDragAndAKnownName) {
  // with added_mass the flow would do nothing, and silently
  expect_error("name: x\nfluid:\n  model: added_mass\n  hull_flow: thin_ship\n",
               {"fluid.hull_flow", ":4:", "added_mass has none"});
  expect_error("name: x\nfluid: {model: both, hull_flow_coupling: drag}\n",
               {"fluid.hull_flow_coupling", "hull_flow is none"});
  expect_error("name: x\nfluid: {model: both, hull_flow: panel, hull_flow_coupling: morison}\n",
               {"fluid.hull_flow_coupling", "morison", "full | drag | drag_regular_table"});
  expect_error("name: x\nfluid: {model: both, hull_flow: potential}\n",
               {"fluid.hull_flow", "potential", "none | thin_ship"});
}

TEST(CaseLoader, HullFlowCaseRunsWithTheModelGivenOnTheCommandLine) {
  // a case with model added_mass and the flow is valid once a runner's --model drag overrides the model, and
  // --model added_mass on a drag case with the flow is refused by the final parse
  const fs::path dir = temp_dir("hull_flow_override");
  const fs::path am = write_case(dir, "name: h\nfluid:\n  model: added_mass\n  hull_flow: thin_ship\n");
  const Case c = brash::run::load_case_with_overrides(am, {"drag", "", -1, {}}, "[test]");
  EXPECT_EQ(c.fluid.model, brash::FluidModel::Drag);
  EXPECT_EQ(c.fluid.hull_flow, brash::HullFlow::ThinShip);
  EXPECT_THROW(brash::run::load_case_with_overrides(am, {"", "", -1, {}}, "[test]"), brash::InputError);
  const fs::path drag = write_case(dir, "name: h\nfluid: {model: drag, hull_flow: thin_ship}\n", "d.yaml");
  try {
    (void)brash::run::load_case_with_overrides(drag, {"added_mass", "", -1, {}}, "[test]");
    ADD_FAILURE() << "no InputError";
  } catch (const brash::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fluid.hull_flow"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("command-line overrides"), std::string::npos) << e.what();
  }
}

TEST(CaseLoader, ChannelEndsAreOpenUnlessWalledByTheCaseOrTheCommandLine) {
  EXPECT_EQ(brash::parse_case("name: x\n", kRepo, "mem").channel.ends, brash::ChannelEnds::Open);
  const Case walls = brash::parse_case("name: x\nchannel: {ends: walls}\n", kRepo, "mem");
  EXPECT_EQ(walls.channel.ends, brash::ChannelEnds::Walls);
  // written back only when walled, so an open case's file (and every cache keyed by it) is unchanged
  EXPECT_NE(brash::dump_case_yaml(walls).find("  ends: walls\n"), std::string::npos);
  EXPECT_EQ(brash::dump_case_yaml(brash::parse_case("name: x\n", kRepo, "mem")).find("ends:"), std::string::npos);
  EXPECT_EQ(brash::parse_case(brash::dump_case_yaml(walls), kRepo, "[dump]").channel.ends, brash::ChannelEnds::Walls);
  const fs::path dir = temp_dir("channel_ends");
  const fs::path open_case = write_case(dir, "name: e\n");
  // a runner's --set channel.ends=walls is a change of the case
  EXPECT_EQ(brash::run::load_case_with_overrides(open_case, {"", "", -1, {{"channel.ends", "walls"}}}, "[test]")
                .channel.ends,
            brash::ChannelEnds::Walls);
  expect_error("name: x\nchannel: {ends: closed}\n", {"channel.ends", "closed", "open | walls"});
}

TEST(CaseLoader, SettleIsOffUnlessAskedAndItsSpeedPositive) {
  const Case d = brash::parse_case("name: x\n", kRepo, "mem");
  EXPECT_FALSE(d.ice.settle);
  // an unsettled case's file is unchanged: no ice.settle keys (ode.settle_s is brash-ode's own settling)
  EXPECT_EQ(brash::dump_case_yaml(d).find("\n  settle:"), std::string::npos);
  EXPECT_EQ(brash::dump_case_yaml(d).find("settle_speed_m_s"), std::string::npos);
  const Case s = brash::parse_case("name: x\nice: {settle: true, settle_speed_m_s: 0.002}\n", kRepo, "mem");
  EXPECT_TRUE(s.ice.settle);
  EXPECT_EQ(s.ice.settle_speed_m_s, 0.002);
  const Case again = brash::parse_case(brash::dump_case_yaml(s), kRepo, "[dump]");
  EXPECT_TRUE(again.ice.settle);
  EXPECT_EQ(again.ice.settle_speed_m_s, 0.002);
  expect_error("name: x\nice: {settle: maybe}\n", {"ice.settle"});
  expect_error("name: x\nice: {settle_speed_m_s: 0}\n", {"ice.settle_speed_m_s", "> 0"});
}

TEST(CaseLoaderErrors, NaNAndInfinity) {
  expect_error("name: x\nship: {speed_m_s: .nan}\n", {"ship.speed_m_s", "finite"});
  expect_error("name: x\nfriction: {ice_ice: .inf}\n", {"friction.ice_ice", "finite"});
  expect_error("name: x\nfsicr: {alpha_deg: .nan}\n", {"fsicr.alpha_deg", "finite"});
  expect_error("name: x\nice: {porosity: nan}\n", {"ice.porosity"});
}

TEST(CaseLoaderErrors, OtherChecks) {
  expect_error("description: no name\n", {"name", "missing"});
  expect_error("name: x\nice: {diameter_mean_m: 0.01, diameter_sd_m: 0.005}\n", {"ice.diameter_sd_m"});
  expect_error("name: x\nrun: {timestep_s: 0.1, output_interval_s: 0.01}\n", {"run.timestep_s"});
  expect_error("name: x\ncontact: {poisson_ratio: 0.6}\n", {"contact.poisson_ratio"});
  expect_error("name: x\ncontact: {rolling_friction: -0.01}\n", {"contact.rolling_friction", ">= 0"});
  expect_error("name: [x\n", {"YAML syntax"});
}

TEST(CaseLoader, SpeedupsDefaultOffAndRead) {
  const Case d = brash::parse_case("name: x\n", kRepo, "mem");
  EXPECT_FALSE(d.speedups.farfield);
  EXPECT_FALSE(d.speedups.symmetry_y);
  EXPECT_FALSE(d.speedups.moving_window);
  EXPECT_DOUBLE_EQ(d.speedups.neighbor_skin_d, 0.2);
  EXPECT_DOUBLE_EQ(d.speedups.farfield_wake_force_weight, 1e-3);  // the far field wakes pushed ice by default
  EXPECT_EQ(d.speedups.farfield_wake_by, brash::WakeBy::Force);
  EXPECT_TRUE(d.speedups.early_stop_trend_check);
  EXPECT_FALSE(brash::parse_case("name: x\nspeedups:\n  early_stop_trend_check: false\n", kRepo, "mem")
                   .speedups.early_stop_trend_check);
  const Case c = brash::parse_case(
      "name: x\nspeedups:\n  farfield: true\n  farfield_ahead_m: 0.5\n  farfield_behind_m: 2\n"
      "  farfield_every_steps: 50\n  symmetry_y: yes\n  neighbor_skin_d: 0.3\n",
      kRepo, "mem");
  EXPECT_TRUE(c.speedups.farfield);
  EXPECT_DOUBLE_EQ(c.speedups.farfield_ahead_m, 0.5);
  EXPECT_DOUBLE_EQ(c.speedups.farfield_behind_m, 2.0);
  EXPECT_EQ(c.speedups.farfield_every_steps, 50);
  EXPECT_TRUE(c.speedups.symmetry_y);
  EXPECT_DOUBLE_EQ(c.speedups.neighbor_skin_d, 0.3);
}

TEST(CaseLoaderErrors, SpeedupsKeysNamed) {
  expect_error("name: x\nspeedups:\n  farfeld: true\n", {"speedups.farfeld", "unknown key", ":3:"});
  expect_error("name: x\nspeedups: {farfield: maybe}\n", {"speedups.farfield", "true or false"});
  expect_error("name: x\nspeedups: {farfield_every_steps: 2.5}\n", {"speedups.farfield_every_steps", "integer"});
  expect_error("name: x\nspeedups: {farfield_every_steps: 0}\n", {"speedups.farfield_every_steps"});
  expect_error("name: x\nspeedups: {farfield_ahead_m: -1}\n", {"speedups.farfield_ahead_m", ">= 0"});
  expect_error("name: x\nspeedups: {farfield_wake_force_weight: -0.1}\n", {"speedups.farfield_wake_force_weight", "[0, 1]"});
  expect_error("name: x\nspeedups: {farfield_wake_speed_m_s: -1}\n", {"speedups.farfield_wake_speed_m_s", ">= 0"});
  expect_error("name: x\nspeedups: {farfield_wake_by: push}\n",
               {"speedups.farfield_wake_by", "force", "neighbour_speed", "push_front"});
  expect_error("name: x\nspeedups: {farfield: true, farfield_wake_by: neighbour_speed, farfield_wake_speed_m_s: 0}\n",
               {"speedups.farfield_wake_speed_m_s", "> 0", "neighbour_speed"});
  expect_error("name: x\nspeedups: {farfield: true, farfield_wake_by: push_front, farfield_front_speed_m_s: 0}\n",
               {"speedups.farfield_front_speed_m_s", "> 0", "push_front"});
  expect_error("name: x\nspeedups: {farfield_front_speed_m_s: -0.1}\n", {"speedups.farfield_front_speed_m_s", ">= 0"});
  expect_error("name: x\nspeedups: {moving_window_behind_m: 0}\n", {"speedups.moving_window_behind_m", "> 0"});
  expect_error("name: x\nspeedups: {moving_window: true}\n", {"speedups.moving_window", "ice.settle: true"});
  expect_error("name: x\nice: {settle: true}\nspeedups: {farfield: true, farfield_ahead_m: 0.3, moving_window: true, "
               "moving_window_ahead_m: 0.2}\n",
               {"speedups.moving_window_ahead_m", "farfield_ahead_m", "held-out bed"});
  expect_error("name: x\nspeedups: {farfield: true, farfield_ahead_m: 0.01}\n",
               {"speedups.farfield_ahead_m", "2 ice diameters"});
  expect_error("name: x\nspeedups: {neighbor_skin_d: 0}\n", {"speedups.neighbor_skin_d", "(0, 2]"});
  expect_error("name: x\nspeedups: {symmetry_y: [1]}\n", {"speedups.symmetry_y"});
}

TEST(CaseLoader, GuardsDefaultAndRead) {
  const Case d = brash::parse_case("name: x\n", kRepo, "mem");
  EXPECT_DOUBLE_EQ(d.guards.max_hull_penetration_d, 0.5);
  EXPECT_EQ(d.guards.every_steps, 10);
  const Case c =
      brash::parse_case("name: x\nguards:\n  max_hull_penetration_d: 0.25\n  every_steps: 5\n", kRepo, "mem");
  EXPECT_DOUBLE_EQ(c.guards.max_hull_penetration_d, 0.25);
  EXPECT_EQ(c.guards.every_steps, 5);
  EXPECT_DOUBLE_EQ(brash::parse_case("name: x\nguards: {max_hull_penetration_d: 0}\n", kRepo, "mem")
                       .guards.max_hull_penetration_d,
                   0.0);  // 0 = off
}

TEST(CaseLoaderErrors, GuardsKeysNamed) {
  expect_error("name: x\nguards:\n  max_hull_penetration: 0.3\n",
               {"guards.max_hull_penetration", "unknown key", ":3:"});
  expect_error("name: x\nguards: {max_hull_penetration_d: -0.1}\n",
               {"guards.max_hull_penetration_d", "[0, 10]"});
  expect_error("name: x\nguards: {max_hull_penetration_d: .nan}\n",
               {"guards.max_hull_penetration_d", "finite"});
  expect_error("name: x\nguards: {every_steps: 0}\n", {"guards.every_steps", "integer"});
  expect_error("name: x\nguards: {every_steps: 2.5}\n", {"guards.every_steps", "integer"});
  expect_error("name: x\nguards: 3\n", {"guards", "mapping"});
}

// brash-ode's settings (the ode: section): the defaults brash-ode ran with before they were keys, and each read.
TEST(CaseLoader, OdeDefaultsAndRead) {
  const Case d = brash::parse_case("name: x\n", kRepo, "mem");
  EXPECT_DOUBLE_EQ(d.ode.timestep_s, 5e-4);
  EXPECT_EQ(d.ode.iterations, 8);
  EXPECT_DOUBLE_EQ(d.ode.erp, 0.2);
  EXPECT_DOUBLE_EQ(d.ode.cfm, 1e-5);
  EXPECT_EQ(d.ode.implicit, brash::OdeImplicit::EffectiveMass);
  EXPECT_EQ(d.ode.broad_phase, brash::OdeBroadPhase::Grid);
  EXPECT_EQ(d.ode.sphere_order, brash::OdeSphereOrder::Spatial);
  EXPECT_TRUE(d.ode.idle_geoms_out);
  EXPECT_FALSE(d.ode.auto_disable);
  EXPECT_EQ(d.ode.auto_disable_steps, 20);
  EXPECT_DOUBLE_EQ(d.ode.settle_s, 0.0);
  const Case c = brash::parse_case(
      "name: x\node:\n  timestep_s: 1.0e-3\n  iterations: 20\n  erp: 0.4\n  cfm: 0\n  surface_layer_m: 1e-4\n"
      "  angular_damping: 0.01\n  implicit: scale_forces\n  broad_phase: sap\n  sphere_order: packing\n"
      "  idle_geoms_out: false\n  auto_disable: true\n  auto_disable_linear_m_s: 0.01\n"
      "  auto_disable_angular_rad_s: 0.2\n  auto_disable_steps: 5\n  settle_s: 0.6\n  settle_damping: 0.02\n",
      kRepo, "mem");
  EXPECT_DOUBLE_EQ(c.ode.timestep_s, 1e-3);
  EXPECT_EQ(c.ode.iterations, 20);
  EXPECT_DOUBLE_EQ(c.ode.erp, 0.4);
  EXPECT_DOUBLE_EQ(c.ode.cfm, 0.0);
  EXPECT_DOUBLE_EQ(c.ode.surface_layer_m, 1e-4);
  EXPECT_DOUBLE_EQ(c.ode.angular_damping, 0.01);
  EXPECT_EQ(c.ode.implicit, brash::OdeImplicit::ScaleForces);
  EXPECT_EQ(c.ode.broad_phase, brash::OdeBroadPhase::Sap);
  EXPECT_EQ(c.ode.sphere_order, brash::OdeSphereOrder::Packing);
  EXPECT_FALSE(c.ode.idle_geoms_out);
  EXPECT_TRUE(c.ode.auto_disable);
  EXPECT_DOUBLE_EQ(c.ode.auto_disable_linear_m_s, 0.01);
  EXPECT_DOUBLE_EQ(c.ode.auto_disable_angular_rad_s, 0.2);
  EXPECT_EQ(c.ode.auto_disable_steps, 5);
  EXPECT_DOUBLE_EQ(c.ode.settle_s, 0.6);
  EXPECT_DOUBLE_EQ(c.ode.settle_damping, 0.02);
  // the resolved case writes them back
  EXPECT_EQ(brash::parse_case(brash::dump_case_yaml(c), kRepo, "mem"), c);
}

TEST(CaseLoaderErrors, OdeKeysNamed) {
  expect_error("name: x\node:\n  dt: 1e-3\n", {"ode.dt", "unknown key", ":3:"});
  expect_error("name: x\node: {timestep_s: 0}\n", {"ode.timestep_s", "> 0"});
  expect_error("name: x\node: {timestep_s: .inf}\n", {"ode.timestep_s", "finite"});
  expect_error("name: x\node: {iterations: 0}\n", {"ode.iterations", "integer"});
  expect_error("name: x\node: {iterations: 8.5}\n", {"ode.iterations", "integer"});
  expect_error("name: x\node: {erp: 1.5}\n", {"ode.erp", "[0, 1]"});
  expect_error("name: x\node: {cfm: -1e-5}\n", {"ode.cfm", ">= 0"});
  expect_error("name: x\node: {surface_layer_m: -0.001}\n", {"ode.surface_layer_m", ">= 0"});
  expect_error("name: x\node: {angular_damping: 2}\n", {"ode.angular_damping", "[0, 1]"});
  expect_error("name: x\node: {implicit: lagged}\n", {"ode.implicit", "lagged", "effective_mass | scale_forces"});
  expect_error("name: x\node: {broad_phase: octree}\n", {"ode.broad_phase", "octree", "grid | sap"});
  expect_error("name: x\node: {sphere_order: random}\n", {"ode.sphere_order", "random", "spatial | packing"});
  expect_error("name: x\node: {idle_geoms_out: maybe}\n", {"ode.idle_geoms_out"});
  expect_error("name: x\node: {auto_disable: 1.5}\n", {"ode.auto_disable"});
  expect_error("name: x\node: {auto_disable_linear_m_s: -1}\n", {"ode.auto_disable_linear_m_s", ">= 0"});
  expect_error("name: x\node: {auto_disable_angular_rad_s: -1}\n", {"ode.auto_disable_angular_rad_s", ">= 0"});
  expect_error("name: x\node: {auto_disable_steps: 0}\n", {"ode.auto_disable_steps", "integer"});
  expect_error("name: x\node: {settle_s: -0.1}\n", {"ode.settle_s", ">= 0"});
  expect_error("name: x\node: {settle_damping: 0.6}\n", {"ode.settle_damping", "[0, 0.5]"});
  expect_error("name: x\node: 3\n", {"ode", "mapping"});
}

TEST(CaseLoaderErrors, MissingFile) {
  try {
    (void)brash::load_case("/nonexistent/brash_missing_case.yaml");
    ADD_FAILURE();
  } catch (const brash::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("brash_missing_case.yaml"), std::string::npos);
  }
}

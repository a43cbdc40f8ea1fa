// The case file's keys as one table (inside brash_case): each key with its field of brash::Case, how it is read
// and checked, how the resolved case writes it and its line of documentation. The loader (parse_case), the writer
// (dump_case_yaml) and the key reference (brash/case_keys.hpp, docs/case_format.md) all walk this table; the
// default of a key is its field's initial value in brash/case.hpp, or the key's `default_text` where the loader
// fills it in (a file name, a default that follows another key).
#pragma once
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "brash/case.hpp"

namespace brash::case_keys {

template <class E>
struct EnumText {
  E value;
  std::string_view text;
};
inline constexpr EnumText<IceClass> kIceClass[] = {
    {IceClass::IA_super, "IA_super"}, {IceClass::IA, "IA"}, {IceClass::IB, "IB"}, {IceClass::IC, "IC"}};
inline constexpr EnumText<PackingMode> kPackingMode[] = {{PackingMode::Volume, "volume"},
                                                         {PackingMode::StrictTwoLayer, "strict_two_layer"}};
inline constexpr EnumText<FluidModel> kFluidModel[] = {
    {FluidModel::Drag, "drag"}, {FluidModel::AddedMass, "added_mass"}, {FluidModel::Both, "both"}};
inline constexpr EnumText<Treatment> kTreatment[] = {{Treatment::Implicit, "implicit"},
                                                     {Treatment::Explicit, "explicit"}};
inline constexpr EnumText<DragLaw> kDragLaw[] = {{DragLaw::Constant, "constant"},
                                                 {DragLaw::SchillerNaumann, "schiller_naumann"}};
inline constexpr EnumText<HullFlow> kHullFlow[] = {
    {HullFlow::None, "none"}, {HullFlow::ThinShip, "thin_ship"}, {HullFlow::Panel, "panel"}};
inline constexpr EnumText<HullFlowCoupling> kHullFlowCoupling[] = {
    {HullFlowCoupling::Full, "full"},
    {HullFlowCoupling::Drag, "drag"},
    {HullFlowCoupling::DragRegularTable, "drag_regular_table"}};
inline constexpr EnumText<ChannelEnds> kChannelEnds[] = {{ChannelEnds::Open, "open"}, {ChannelEnds::Walls, "walls"}};
inline constexpr EnumText<WakeBy> kWakeBy[] = {
    {WakeBy::Force, "force"}, {WakeBy::NeighbourSpeed, "neighbour_speed"}, {WakeBy::PushFront, "push_front"}};
inline constexpr EnumText<OdeImplicit> kOdeImplicit[] = {{OdeImplicit::EffectiveMass, "effective_mass"},
                                                         {OdeImplicit::ScaleForces, "scale_forces"}};
inline constexpr EnumText<OdeBroadPhase> kOdeBroadPhase[] = {{OdeBroadPhase::Grid, "grid"},
                                                             {OdeBroadPhase::Sap, "sap"}};
inline constexpr EnumText<OdeSphereOrder> kOdeSphereOrder[] = {{OdeSphereOrder::Spatial, "spatial"},
                                                               {OdeSphereOrder::Packing, "packing"}};
inline constexpr EnumText<CaTable> kCaTable[] = {
    {CaTable::Table1, "table1"}, {CaTable::Text, "text"}, {CaTable::Zero, "zero"}, {CaTable::Uniform, "uniform"}};

template <class E, std::size_t N>
std::string_view text_of(const EnumText<E> (&table)[N], E v) {
  for (const auto& e : table)
    if (e.value == v) return e.text;
  return "?";
}

// "a | b | c": the spellings of an enumeration, as messages and the key reference list them.
template <class E, std::size_t N>
std::string choices(const EnumText<E> (&table)[N]) {
  std::string list;
  for (const auto& e : table) list += (list.empty() ? "" : " | ") + std::string(e.text);
  return list;
}

// Reads values of one case file; every error names the file, the line and column where known, and the key.
struct Reader {
  std::string source;              // file name for messages
  std::filesystem::path base_dir;  // relative paths resolve against it
  bool check_model_keys = true;    // the checks that tie keys to fluid.model (brash/case.hpp, load_case)

  [[noreturn]] void fail(const YAML::Node& n, const std::string& key, const std::string& msg) const;
  // Every key of a mapping is one of `known` and given once; a section that is not a mapping is an error.
  void check_map(const YAML::Node& n, const std::string& where, std::span<const std::string_view> known) const;
  double to_double(const YAML::Node& v, const std::string& key) const;
  // A finite number that passes `ok` ("must be <need>, got x" when it does not).
  double number(const YAML::Node& v, const std::string& key, bool (*ok)(double), std::string_view need) const;
  std::string text(const YAML::Node& v, const std::string& key) const;
  bool boolean(const YAML::Node& v, const std::string& key) const;
  std::array<double, 2> pair(const YAML::Node& v, const std::string& key) const;
  std::uint64_t seed(const YAML::Node& v, const std::string& key) const;
  CaTableSpec ca_table(const YAML::Node& v, const std::string& key) const;
  template <class E, std::size_t N>
  E enumeration(const YAML::Node& v, const std::string& key, const EnumText<E> (&table)[N]) const {
    if (!v.IsScalar()) fail(v, key, "expected a text value");
    for (const auto& e : table)
      if (e.text == v.Scalar()) return e.value;
    fail(v, key, "unknown value '" + v.Scalar() + "' (one of: " + choices(table) + ")");
  }
};

struct KeySpec;
using ReadFn = void (*)(const KeySpec& k, const Reader& r, const YAML::Node& value, const std::string& key, Case& c);
using AbsentFn = void (*)(const KeySpec& k, const Reader& r, Case& c);
using ValueFn = std::string (*)(const Case& c);  // the YAML text of the value; "" = an optional key not set

struct KeySpec {
  std::string_view name{};
  std::string_view doc{};           // one line for the key reference
  std::string_view need{};          // the check as text ("> 0"); for enumerations filled in by `values`
  bool (*ok)(double) = nullptr;     // the check of a number
  ReadFn read = nullptr;            // the value is given (null included)
  AbsentFn absent = nullptr;        // the key is not given: a default that is not the field's initial value
  ValueFn value = nullptr;
  bool (*written)(const Case&) = nullptr;  // the resolved case writes the key only when this holds (nullptr: always)
  std::string (*values)(const KeySpec&) = nullptr;  // the accepted values in words, for the key reference
  std::string_view default_text{};  // the default where the field's initial value is not it
};

// A check across keys, run once the keys of its section are read.
struct CrossCheck {
  std::string_view name;
  void (*run)(const Reader& r, const YAML::Node& root, const YAML::Node& section, Case& c);
};

struct SectionSpec {
  std::string_view name{};  // "" = the top level (name, description)
  std::span<const KeySpec> keys{};
  std::span<const CrossCheck> checks{};
  bool (*written)(const Case&) = nullptr;  // the resolved case writes the section only when this holds
};

// Every section in file order, the top level first.
std::span<const SectionSpec> sections();

// Shortest text that reads back to the same double; always carries a '.' or exponent.
std::string yaml_number(double x);
// Double-quoted YAML string (always quoted so text like "no" or "1.0" stays text).
std::string yaml_quoted(std::string_view s);

}  // namespace brash::case_keys

// Case variants through the case library: a base case with some keys set to new values (brash-case derive, study
// runners). The base's YAML is edited as a node tree (never as text) and the result is validated by the case loader,
// so a variant is refused exactly as a case file with the same text would be (unknown key, bad value, ...).
//
// Paths: a derived case is meant to live in another folder than its base, so
//   - hull.file: a relative name found in the base's folder becomes absolute; one found elsewhere (the other places
//     brash::hull_file_candidates searches) stays as it is and is found in the same place;
//   - ice.packing_file: the base's packing (made absolute) when the derived case packs the same ice as the base (every
//     key the packing depends on, brash::packing_request: channel.*, ice.*, water.density_kg_m3, water.level_m, has
//     its base value) and the base's packing folder can be written (the packing and its settled bed are made there
//     when missing), else `generated/packing.csv` of the derived case's folder, which the runners generate
//     (brash-pack) when it is missing: a case derived from a read-only installed case makes its ice in its own folder;
//   - a hull.file or ice.packing_file given as an override is taken as given (relative to the derived case's folder,
//     as in any case file).
// Window: a variant that shortens the run (run.duration_s) below its base's averaging window, without setting
// run.window_s, gets the window [min(start, duration / 2), duration]: the rule of the runners' --duration, which
// goes through here.
// References: the base's references: section is dropped when the variant changes a key they depend on
// (keys_beyond_references), unless an override sets a references.* key itself.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "brash/case.hpp"

namespace brash {

// One override: a dotted case key ("fluid.model", "run.window_s") and its value as YAML text ("drag",
// "[0.375, 0.75]", "uniform 0.5"). An empty value (or `~`, `null`) removes the key, so the loader's default applies.
using CaseOverride = std::pair<std::string, std::string>;
using CaseOverrides = std::vector<CaseOverride>;

// "key=value" (the text of brash-case derive --set) -> {key, value}; InputError naming the text when there is no '='
// or the key is empty.
CaseOverride parse_case_override(std::string_view key_equals_value);

// The case.yaml text of `base_case_file` (a case.yaml) with the overrides applied and the paths fixed as above,
// already validated by the case loader. Throws InputError naming the base file and the key for an invalid base, a
// key given twice among the overrides, a key that is not a dotted name or leads through a value that is not a
// section, a value that is not YAML, and anything the loader refuses in the derived case (unknown key, bad value).
std::string derive_case(const std::filesystem::path& base_case_file, const CaseOverrides& overrides);

// derive_case() written to <out_dir>/case.yaml (folder made when missing) and loaded back with load_case (its
// messages name that file). An existing <out_dir>/case.yaml is an InputError unless `overwrite`; when the derived
// case packs its own ice (generated/packing.csv of out_dir) and a packing is there from an earlier case of that
// folder with other packing inputs, that stale packing (packing.csv and packing.json) is removed, so the runners
// generate the right one. Returns the derived case as loaded.
Case write_derived_case(const std::filesystem::path& base_case_file, const CaseOverrides& overrides,
                        const std::filesystem::path& out_dir, bool overwrite = false);

// True when the two cases' packings are the same bed: every input of brash::packing_request is equal.
bool same_packing_inputs(const Case& a, const Case& b);

// The dotted keys of the resolved cases (dump_case_yaml: every default filled in, paths absolute) whose values differ
// between `a` and `b`, a key set on one side only included, in sorted order.
std::vector<std::string> differing_case_keys(const Case& a, const Case& b);

// Published references (references:) describe one hull, ship speed, ice and fluid: the dotted keys of the resolved
// case whose value differs between `base` and `variant` and that change what references describe, i.e. every key
// but those of how the run is computed (docs/case_format.md "references": name, description, run.*, speedups.*,
// guards.*, ode.*, fsicr.*, contact.youngs_modulus_pa, fluid.model, fluid.treatment, hull.band_m, hull.start_x_m,
// ice.seed, ice.settle, ice.settle_speed_m_s, ice.packing_file). Empty: the variant may keep the base's references.
std::vector<std::string> keys_beyond_references(const Case& base, const Case& variant);

// The value of a dotted key in the resolved case (every default filled in, paths absolute), as dump_case_yaml
// writes it: "5e-05", "drag", "[5.5, 11.0]". Throws InputError naming the key when the resolved case has no such key
// (an unknown key, a section, or an optional key the case does not set).
std::string case_value(const Case& c, std::string_view dotted_key);

}  // namespace brash

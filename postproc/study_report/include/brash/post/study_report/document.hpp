// The whole study document (a study.md, docs/validation.md) and its machine-readable summary, from a loaded study.
#pragma once
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include <brash/post/study_report/study.hpp>
#include <brash/post/study_report/text_template.hpp>

namespace brash::post::study_report {

struct DocumentOptions {
  std::string title = "brash study";
  std::string manifest_name;  // the manifest's file name, as the header names it
  std::string study_command;  // the command that ran the whole study (empty: not shown)
  std::filesystem::path doc_dir;                    // the document's folder (figure links are relative to it)
  std::filesystem::path speed_plot;                 // speed-sweep PNG (empty: no plot)
  std::optional<std::filesystem::path> figure_dir;  // Fig. 4/5/6 analogs (unset: no figures)
};

// The markdown of the document, section by section, its prose from TEXT; writes the figures and the speed plot
// on the way.
std::string render_document(const Study& s, const TextTemplate& text, const DocumentOptions& options);

// The speed fits, every run's and ensemble's state, and the counts of failed and running ones.
nlohmann::json summary_json(const Study& s);

}  // namespace brash::post::study_report

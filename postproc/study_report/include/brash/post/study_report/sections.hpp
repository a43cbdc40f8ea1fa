// The sections of the study document (a study.md, docs/validation.md), in document order; each renders its markdown from the
// loaded study (study.hpp) and what analysis.hpp derives from it, its prose from the text template
// (text_template.hpp: templates/study.md.tmpl).
#pragma once
#include <filesystem>
#include <string>

#include <brash/post/study_report/study.hpp>
#include <brash/post/study_report/text_template.hpp>

namespace brash::post::study_report {

// Title, where the document comes from, and how to read its numbers.
std::string section_header(const TextTemplate& text, const std::string& title, const std::string& manifest_name,
                           const std::string& study_command);
// Runs in progress, and the runs and ensembles without a usable result.
std::string section_failures(const Study& s, const TextTemplate& text);
// (a) our runs of group paper against the paper's numbers, hull parameters, added mass vs drag.
std::string section_paper(const Study& s, const TextTemplate& text);
// The paper case's set-up as each of its started runs used it, beside the paper's own.
std::string section_setup(const Study& s, const TextTemplate& text);
// The gap of each completed paper-case run to the paper, and the candidates the study measured.
std::string section_gap(const Study& s, const TextTemplate& text);
// Fig. 4, 5 and 6 analogs in FIG_DIR (its previous content is replaced), linked from a document in DOC_DIR.
std::string section_figures(const Study& s, const TextTemplate& text, const std::filesystem::path& fig_dir,
                            const std::filesystem::path& doc_dir);
// (b) the speed sweep and its power-law fits; the plot PLOT_PNG unless empty.
std::string section_speed(const Study& s, const TextTemplate& text, const std::filesystem::path& plot_png);
// (c) each sensitivity group against its baseline.
std::string section_sensitivity(const Study& s, const TextTemplate& text);
// (c) the paired-seed ensembles.
std::string section_paired(const Study& s, const TextTemplate& text);
// (d) the engines against LIGGGHTS.
std::string section_engines(const Study& s, const TextTemplate& text);
// (e) every run with the command that produced it.
std::string section_runs(const Study& s, const TextTemplate& text);

}  // namespace brash::post::study_report

// brash-study-report: a study document generated from a study manifest and the report.json of every run it
// lists: a study's own (brash-study, <work>/study.md) or the project's validation page (`make validation`:
// evidence/manifest.tsv -> docs/validation.md). Nothing in the document is typed by hand: every number
// comes from a report.json and every run is listed with the command that produced it. The manifest's format
// is described in brash/post/study_report/study.hpp; the document is made by the library brash_study_report,
// its prose read from a text template (--template; postproc/study_report/templates/study.md.tmpl).
#include <filesystem>
#include <fstream>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <brash/paths.hpp>
#include <brash/post/study_report/document.hpp>

namespace fs = std::filesystem;
namespace report = brash::post::study_report;

namespace {

// Writes TEXT to PATH through a temporary file, so a reader never sees half a document.
void write_atomically(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp";
  std::ofstream o(tmp);
  o << text;
  o.close();
  if (!o) throw std::runtime_error("cannot write " + tmp.string());
  fs::rename(tmp, path);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-study-report: a study document from a study manifest and the report.json of its runs",
               "brash-study-report"};
  std::string manifest, out = "study.md", plot, figures, summary_path, title = "brash study", study_command;
  app.add_option("manifest", manifest, "study manifest (tab-separated, see the file header)")->required();
  app.add_option("--out", out, "markdown output")->capture_default_str();
  app.add_option("--plot", plot, "speed-sweep PNG (default: <out stem>_speed.png next to --out; 'none' = no plot)");
  app.add_option("--figures", figures,
                 "folder for the Fig. 4/5/6 analogs of section (a) (default: <out stem>_figs next to --out; "
                 "'none' = no figures; its previous content is replaced)");
  app.add_option("--summary-json", summary_path, "also write the fits and run statuses as JSON");
  app.add_option("--title", title, "document title")->capture_default_str();
  app.add_option("--study-command", study_command, "the command that ran the whole study (shown at the top)");
  std::string paper_case = "cases/jbc_ia_5kn/case.yaml";
  app.add_option("--paper-case", paper_case, "the paper case, whose published values (its references) the "
                 "document compares with")->capture_default_str();
  std::string text_template;
  app.add_option("--template", text_template, "the document's prose: named text blocks with {{placeholders}} "
                 "(default: <data>/study_report/templates/study.md.tmpl, data = <prefix>/share/brash or "
                 "$BRASH_DATA_DIR)");
  CLI11_PARSE(app, argc, argv);
  try {
    if (text_template.empty())
      text_template = brash::paths::data_file("study_report/templates/study.md.tmpl", "the study text template").string();
    const auto text = report::TextTemplate::load(text_template);
    const report::Study study = report::load_study(manifest, paper_case);
    const fs::path out_p = out;
    if (out_p.has_parent_path()) fs::create_directories(out_p.parent_path());
    report::DocumentOptions options;
    options.title = title;
    options.manifest_name = fs::path(manifest).filename().string();
    options.study_command = study_command;
    options.doc_dir = out_p.parent_path();
    if (plot != "none")
      options.speed_plot = plot.empty() ? out_p.parent_path() / (out_p.stem().string() + "_speed.png") : fs::path(plot);
    if (figures != "none")
      options.figure_dir = figures.empty() ? out_p.parent_path() / (out_p.stem().string() + "_figs") : fs::path(figures);
    write_atomically(out_p, report::render_document(study, text, options));
    const auto summary = report::summary_json(study);
    if (!summary_path.empty()) std::ofstream(summary_path) << summary.dump(2) << "\n";
    fmt::print("brash-study-report: {} ({} run(s), {} failed or missing, {} in progress)\n", out_p.string(),
               study.runs.size(), summary["failed"].get<std::size_t>(), summary["in_progress"].get<std::size_t>());
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "brash-study-report: {}\n", e.what());
    return 2;
  }
}

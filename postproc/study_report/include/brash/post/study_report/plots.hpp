// The study document's figures drawn with gnuplot: each writer puts a data file and a script in a folder, and
// run_gnuplot draws the PNG there (the script can be re-run in that folder by hand).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <brash/post/study_report/analysis.hpp>

namespace brash::post::study_report {

// Runs `gnuplot GP` in GP's folder (file names in the script are relative to it, so it can be re-run there).
// Returns "" on success, else what went wrong (the script's stderr is kept in GP.err).
std::string run_gnuplot(const std::filesystem::path& gp, const std::filesystem::path& png);

// The files of one figure: data, script and image, side by side.
struct PlotFiles {
  std::filesystem::path dat, gp, png;
};
PlotFiles plot_files(const std::filesystem::path& png);  // PNG's stem with .dat and .gp

// Fig. 6 analog: BARS' full-scale resistance with its CI beside the paper's numbers and our R_CH.
void write_paper_bars(const PlotFiles& f, const std::vector<const Run*>& bars, const brash::ReferenceSpec& paper,
                      bool paper_case_runs);
// The paper case's histories in one plot, window shaded, the paper's two levels dashed.
void write_paper_histories(const PlotFiles& f, const PaperHistories& h, const brash::ReferenceSpec& paper);
// The speed sweep, log-log: each fit's points with CI bars and its fitted line.
void write_speed_sweep(const PlotFiles& f, const std::vector<SpeedFit>& fits);

}  // namespace brash::post::study_report

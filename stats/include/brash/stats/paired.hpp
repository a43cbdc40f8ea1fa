// Mean of a sample with its Student-t 95 % confidence interval, and the paired-ensemble difference built on it.
//
// A contact scene diverges chaotically from round-off, so one run per variant is one realisation and the difference
// of two runs is dominated by run-to-run scatter. A paired ensemble runs each packing seed twice, as side A and as
// side B on the same packing; the pair's relative difference d_i = (b_i - a_i) / ((a_i + b_i) / 2) then holds the
// chaotic scatter and the effect of the change, not the packing's. The ensemble's statement is the mean of the d_i
// with CI95 = t_{0.975, pairs - 1} sd / sqrt(pairs): B is within a tolerance tol of A when [mean - CI, mean + CI]
// lies inside (-tol, +tol).
#pragma once
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace brash::stats {

struct MeanCi {
  std::size_t n = 0;
  double mean = NAN;
  double sd = NAN;    // sample standard deviation (n - 1)
  double ci95 = NAN;  // t_{0.975, n - 1} sd / sqrt(n)
  double lo() const { return mean - ci95; }
  double hi() const { return mean + ci95; }
};

// Needs >= 2 values (std::invalid_argument otherwise).
MeanCi mean_ci95(std::span<const double> x);

// (b - a) / ((a + b) / 2)
double relative_difference(double a, double b);

struct PairedDifference {
  double mean_a = NAN, mean_b = NAN;  // ensemble means of each side
  std::vector<double> relative;       // d_i, one per pair
  MeanCi difference;                  // of the d_i
};

// a[i] and b[i] are pair i; needs >= 2 pairs and a.size() == b.size() (std::invalid_argument otherwise).
PairedDifference paired_relative_difference(std::span<const double> a, std::span<const double> b);

// Two independent estimates (separate runs, not pairs), each a mean with its own 95 % CI: the relative
// difference (mean - reference) / reference and its CI, sqrt(ci_ref^2 + ci^2) / reference (the CIs of
// independent errors add in quadrature). A single run per side holds the run-to-run scatter only through its
// CI: a difference inside it is not resolved. Needs reference != 0 (std::invalid_argument).
struct IndependentDifference {
  double relative = NAN;       // (mean - reference) / reference
  double ci95_relative = NAN;  // combined CI over the reference
  bool resolved() const { return std::abs(relative) > ci95_relative; }
};
IndependentDifference independent_relative_difference(double reference, double reference_ci95, double mean,
                                                      double ci95);

// The CI lies inside (-tol, +tol).
bool within(const MeanCi& m, double tol);

// Pairs that would put the CI inside (-tol, +tol) at this scatter and mean (normal quantile 1.96: a planning
// estimate), or nothing when |mean| >= tol (no number of pairs would).
std::optional<std::size_t> pairs_to_resolve(const MeanCi& m, double tol);

}  // namespace brash::stats

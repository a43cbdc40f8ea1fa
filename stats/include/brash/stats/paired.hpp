// Mean of a sample with its Student-t 95 % confidence interval, and the paired-ensemble effect built on it.
//
// Every change is reported as a fraction of side A, the baseline: effect = (B - A) / A (relative_effect). That
// is the one definition of a percentage change in the project: paired ensembles, two separate runs and the
// paper-case comparisons all use it.
//
// A contact scene diverges chaotically from round-off, so one run per variant is one realisation and the difference
// of two runs is dominated by run-to-run scatter. A paired ensemble runs each packing seed twice, as side A and as
// side B on the same packing; pair i's a_i and b_i then share the packing's scatter, which cancels in b_i - a_i.
// The ensemble's effect is E = (mean b - mean a) / mean a, a ratio of means, with the delta-method CI: to first
// order E's error is the mean of z_i = (b_i - (1 + E) a_i) / mean a (whose sample mean is 0), so
// sd = sd(z_i) and CI95 = t_{0.975, pairs - 1} sd / sqrt(pairs). B is within a tolerance tol of A when
// [E - CI, E + CI] lies inside (-tol, +tol).
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

// (b - a) / a: B's change as a fraction of A. Needs a finite, non-zero a (std::invalid_argument otherwise).
double relative_effect(double a, double b);

struct PairedEffect {
  double mean_a = NAN, mean_b = NAN;  // ensemble means of each side
  std::vector<double> relative;       // relative_effect(a_i, b_i), one per pair (the pairs' table)
  MeanCi effect;                      // mean: relative_effect(mean_a, mean_b); sd, ci95: the delta method's
};

// a[i] and b[i] are pair i; needs >= 2 pairs, a.size() == b.size() and mean a != 0 (std::invalid_argument
// otherwise).
PairedEffect paired_effect(std::span<const double> a, std::span<const double> b);

// Two independent estimates (separate runs, not pairs), each a mean with its own 95 % CI: the relative
// effect (mean - reference) / reference (relative_effect) and its CI, sqrt(ci_ref^2 + ci^2) / reference (the CIs of
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

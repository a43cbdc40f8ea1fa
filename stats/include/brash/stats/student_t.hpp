// Student-t quantile of the two-sided 95 % interval, the one table every CI in brash uses (block averaging, paired
// ensembles, power-law exponents).
#pragma once
#include <cstddef>

namespace brash::stats {

// t_{0.975, dof}: the table (3 decimals) for dof <= 30, a Cornish-Fisher expansion around the normal quantile above
// (error < 1e-4); infinity for dof = 0.
double student_t975(std::size_t dof);

}  // namespace brash::stats

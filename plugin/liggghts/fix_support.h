// Pieces shared by brash's LIGGGHTS fixes: a keyword's number, the hull's track along x, and deleting local atoms
// and re-counting the atoms at PRE_EXCHANGE (fix brash/farfield, brash/window, brash/exit).
#pragma once

#include <fmt/format.h>
#include <mpi.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "atom.h"
#include "atom_vec.h"
#include "error.h"

namespace brash::liggghts {

// A keyword's value as a finite number; an error naming the fix style and the keyword otherwise.
inline double keyword_number(LAMMPS_NS::Error* error, const char* style, const std::string& key, const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(v))
    error->all(FLERR, fmt::format("fix {}: keyword '{}' expects a number, got '{}'", style, key, text).c_str());
  return v;
}

// The hull along x as fix move/mesh linear moves it from hull_x0 at step 0 (keywords hull_x0, speed, bow_offset,
// stern_offset): bow at X0 + LB + U t, stern at X0 + LS + U t.
struct HullTrack {
  double x0_m = 0, speed_m_s = 0, bow_offset_m = 0, stern_offset_m = 0;
  int given = 0;  // a bit per keyword

  static bool keyword(const std::string& key) {
    return key == "hull_x0" || key == "speed" || key == "bow_offset" || key == "stern_offset";
  }
  // Takes one of the four keywords (true) or leaves the keyword to the caller (false).
  bool take(const std::string& key, double v) {
    if (key == "hull_x0") return set(x0_m, v, 1);
    if (key == "speed") return set(speed_m_s, v, 2);
    if (key == "bow_offset") return set(bow_offset_m, v, 4);
    if (key == "stern_offset") return set(stern_offset_m, v, 8);
    return false;
  }
  bool complete() const { return given == 15; }
  double bow_x_m(double t_s) const { return x0_m + bow_offset_m + speed_m_s * t_s; }
  double stern_x_m(double t_s) const { return x0_m + stern_offset_m + speed_m_s * t_s; }

 private:
  bool set(double& field, double v, int bit) {
    field = v;
    given |= bit;
    return true;
  }
};

// Deletes the local atoms for which gone(i) holds: the last local atom takes each freed slot (AtomVec::copy, which
// carries every fix's per-atom arrays, as an exchange between ranks does) and is checked in turn, so gone() sees
// every atom once, before it is deleted. Returns the number deleted on this rank.
template <class Gone>
int delete_local_atoms(LAMMPS_NS::Atom* atom, Gone gone) {
  int n = atom->nlocal, deleted = 0;
  for (int i = 0; i < n;) {
    if (gone(i)) {
      atom->avec->copy(n - 1, i, 1);
      --n;
      ++deleted;
    } else {
      ++i;
    }
  }
  atom->nlocal = n;
  return deleted;
}

// After atoms were added or deleted at PRE_EXCHANGE: natoms from every rank, and the atom map rebuilt at once, as
// LIGGGHTS' own insertion and deletion do (the ghosts are rebuilt by the exchange that follows).
inline void recount_atoms(LAMMPS_NS::Atom* atom, MPI_Comm world) {
  LAMMPS_NS::bigint nlocal = atom->nlocal;
  MPI_Allreduce(&nlocal, &atom->natoms, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (atom->map_style) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
}

}  // namespace brash::liggghts

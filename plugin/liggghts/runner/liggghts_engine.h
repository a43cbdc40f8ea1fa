// The LIGGGHTS adapter of the run driver (brash/run/engine.hpp): the scene as a LIGGGHTS input script
// (liggghts_input.h) run by `brash-liggghts` under an MPI launcher (mpi_launcher.h), its thermo lines as progress, its raw hull-force and
// dump files turned into the run layout, its periodic restart files (restart/a.restart, restart/b.restart).
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "brash/hull/mesh.hpp"
#include "brash/run/engine.hpp"
#include "liggghts_input.h"
#include "particle_snapshots.h"  // convert_dumps

namespace brash::liggghts {

class LiggghtsEngine final : public run::Engine {
 public:
  // launch_prefix: the launcher's words before the engine's executable ("" for one rank; mpi_launcher.h)
  LiggghtsEngine(int ranks, double restart_every_s, std::string launch_prefix)
      : ranks_(ranks), restart_every_s_(restart_every_s), launch_prefix_(std::move(launch_prefix)) {}
  std::string name() const override { return "liggghts"; }
  std::string runner() const override { return "brash-liggghts-run"; }
  bool starts_from_settled_bed() const override { return true; }
  bool runs_half_channel() const override { return true; }
  bool idles_far_field() const override { return true; }
  bool moves_window() const override { return true; }
  WakeRefusal wake_refusal(WakeBy by) const override {
    if (by != WakeBy::PushFront) return {};
    return {"fix brash/farfield has no push front (brash-ode's far field ahead of the bow, for its rigid contacts); "
            "on LIGGGHTS' soft contacts the pushed ice moves into the idle ice, which the neighbour-speed wake sees",
            WakeBy::NeighbourSpeed};
  }
  nlohmann::json meta() const override;
  void load(const Case& c, const std::filesystem::path& case_file, const std::vector<Sphere>& spheres) override;
  void write_scene(const std::filesystem::path& run_dir, bool resume) override;
  std::vector<std::string> restarts(const std::filesystem::path& run_dir) const override;
  run::Attempt advance(const std::filesystem::path& run_dir, const std::string& restart, run::Monitor& m) override;
  run::ForceRecord force_record(const std::filesystem::path& run_dir, double t_max_s) const override;
  void finish(const std::filesystem::path& run_dir) override;

 private:
  int ranks_;
  double restart_every_s_;
  std::string launch_prefix_;
  Case case_;
  std::vector<Sphere> spheres_;
  hull::Mesh full_mesh_, contact_mesh_;
  bool full_closed_ = false;
  Box box_{};
  SceneOptions options_;
};

// The raw hull-force files of a run directory, oldest first: those of earlier (killed) attempts
// (hull_force.part<k>.raw), then the current one.
std::vector<std::filesystem::path> hull_force_raws(const std::filesystem::path& run_dir);
// Rows of the raw files by model time, up to t_max_s (see liggghts_engine.cpp for how attempts overlap).
run::ForceRecord read_hull_force_raws(const std::vector<std::filesystem::path>& raws, double t_max_s);
// fix brash/exit's line "... ; N in all" -> N (-1 for any other line).
long exit_total(const std::string& line);

}  // namespace brash::liggghts

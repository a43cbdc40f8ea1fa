// The YADE adapter of the run driver (brash/run/engine.hpp): the scene as scene.json for
// plugin/yade/py/brash_yade_scene.py, run by `yade -n -j<N> -x` with brash_yade on PYTHONPATH; its progress lines
// and the hull_force.csv it writes go to the driver. The scene writes restart points restart/<iteration>/
// (O.save's scene.yade + state.json, the last two kept); a resumed attempt passes one to the scene, which O.loads
// it and rewrites hull_force.csv from that time on.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "brash/hull/mesh.hpp"
#include "brash/run/engine.hpp"

namespace brash::yade {

class YadeEngine final : public run::Engine {
 public:
  // restart_every_s: model time between restart points (<= 0: a tenth of the run, run::restart_interval_s).
  YadeEngine(int threads, double restart_every_s) : threads_(threads), restart_every_s_(restart_every_s) {}
  std::string name() const override { return "yade"; }
  std::string runner() const override { return "brash-yade-run"; }
  nlohmann::json meta() const override;
  void load(const Case& c, const std::filesystem::path& case_file, const std::vector<Sphere>& spheres) override;
  void write_scene(const std::filesystem::path& run_dir, bool resume) override;
  std::vector<std::string> restarts(const std::filesystem::path& run_dir) const override;
  run::Attempt advance(const std::filesystem::path& run_dir, const std::string& restart, run::Monitor& m) override;
  run::ForceRecord force_record(const std::filesystem::path& run_dir, double t_max_s) const override;

 private:
  nlohmann::json guards_json(const std::filesystem::path& run_dir) const;

  int threads_;
  double restart_every_s_;
  Case case_;
  std::size_t particles_ = 0;
  hull::Mesh full_mesh_, contact_mesh_;
  bool full_closed_ = false;
  hull::MeshCheck full_{};
};

}  // namespace brash::yade

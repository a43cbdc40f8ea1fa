// SIGTERM / SIGINT / SIGHUP while a run goes (a batch system, `kill`, a closed terminal): recorded, and forwarded
// to the engine process if there is one, so that the run ends as `interrupted`, resumable, instead of leaving an
// orphaned engine or losing the work since the last restart file.
#pragma once
#include <csignal>

namespace brash::run {

class StopSignals {
 public:
  StopSignals();   // installs the handlers; the previous ones come back on destruction
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  int received() const;            // the signal received, 0 if none
  void engine_process(long pid);   // forward a signal to this process (0: none); one already received goes now

 private:
  struct sigaction old_[3];
};

}  // namespace brash::run

#include "stop_signals.hpp"

#include <atomic>
#include <signal.h>

namespace brash::run {
namespace {

constexpr int kStopSignals[3] = {SIGTERM, SIGINT, SIGHUP};
std::atomic<long> g_engine_pid{0};  // lock-free: read in the handler
volatile std::sig_atomic_t g_signal = 0;

extern "C" void record_and_forward(int sig) {
  g_signal = sig;
  if (const long pid = g_engine_pid.load(); pid > 0) ::kill(static_cast<pid_t>(pid), SIGTERM);
}

}  // namespace

StopSignals::StopSignals() {
  g_signal = 0;
  g_engine_pid = 0;
  struct sigaction sa {};
  sa.sa_handler = record_and_forward;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // an engine's output keeps being read until it exits
  for (int k = 0; k < 3; ++k) ::sigaction(kStopSignals[k], &sa, &old_[k]);
}

StopSignals::~StopSignals() {
  for (int k = 0; k < 3; ++k) ::sigaction(kStopSignals[k], &old_[k], nullptr);
  g_engine_pid = 0;
}

int StopSignals::received() const { return g_signal; }

void StopSignals::engine_process(long pid) {
  g_engine_pid = pid;
  if (pid > 0 && g_signal != 0) ::kill(static_cast<pid_t>(pid), SIGTERM);  // a signal that came before the pid
}

}  // namespace brash::run

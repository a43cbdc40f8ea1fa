// brash-ode: the standalone ODE simulator. `brash-ode --single rise|float|heave|all` runs the single-sphere scenes.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>

#include "brash/ode/single.hpp"

int main(int argc, char** argv) {
  CLI::App app{"brash-ode: standalone ODE simulator of a ship in a brash-ice channel"};
  std::string scene;
  double dt = 5e-4;
  app.add_option("--single", scene, "single-sphere scene vs reference: rise | float | heave | all");
  app.add_option("--dt", dt, "time step (s)");
  CLI11_PARSE(app, argc, argv);
  try {
    brash::ode::OdeLibrary ode;
    brash::ode::single::Options o;
    o.dt_s = dt;
    if (scene == "rise" || scene == "all") fmt::print("{}\n", brash::ode::single::report(brash::ode::single::rise(o)));
    if (scene == "float" || scene == "all")
      fmt::print("{}\n", brash::ode::single::report(brash::ode::single::floating(o)));
    if (scene == "heave" || scene == "all") fmt::print("{}\n", brash::ode::single::report(brash::ode::single::heave(o)));
  } catch (const std::exception& e) {
    fmt::print(stderr, "brash-ode: error: {}\n", e.what());
    return 1;
  }
  return 0;
}

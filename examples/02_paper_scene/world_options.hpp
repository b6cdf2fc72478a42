// The command-line options that place the paper scene (world.hpp), one definition for
// 02_paper_scene, proceduray_accuracy and proceduray_sweep: --origin X,Y,Z and --raw-floats.
//
//   paper::WorldOptions where;
//   paper::add_world_options(app, where);      // a CLI::App (CLI11, Debian: libcli11-dev)
//   const paper::World world = where.world();  // after parsing; throws UsageError for a non-finite X,Y,Z
#pragma once

#include "world.hpp"

#include <CLI/CLI.hpp>

#include <vector>

namespace paper {

/// What --origin and --raw-floats were given (origin empty: not given).
struct WorldOptions {
  std::vector<double> origin;
  bool raw_floats = false;

  bool given() const { return !origin.empty(); }
  World world() const { return World::from_options(origin, raw_floats); }
};

/// Adds --origin (three numbers) and --raw-floats (which needs --origin) to `app`, filling `w`.
inline void add_world_options(CLI::App& app, WorldOptions& w) {
  CLI::Option* origin = app.add_option("--origin", w.origin, "paper scene: place it at X,Y,Z (world units, e.g. "
                                       "1e6,0,0), drawn relative to a WorldOrigin at the camera")
                            ->expected(3)->delimiter(',');
  app.add_flag("--raw-floats", w.raw_floats, "with --origin: float coordinates from (0, 0, 0), the error WorldOrigin removes")
      ->needs(origin);
}

}  // namespace paper

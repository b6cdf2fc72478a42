// proceduray-field: a user's distance field measured and calibrated from the command line, with
// no C++ written: the GLSL file is compiled as C++ (the system compiler, shader/glsl_cpp.hpp's
// subset) into a small shared library for the ground truth, and marched on the device by the
// library's generated shader.
//
//   proceduray-field measure   --sdf gyroid.glsl --aabb -1,-1,-1,1,1,1 --lipschitz 1.75 --knob method=relaxed
//   proceduray-field calibrate --sdf gyroid.glsl --aabb -1,-1,-1,1,1,1 --lipschitz 1.75 --out gyroid.csv
//   parallel proceduray-field calibrate ... --shard {}/3 --out part{}.csv ::: 1 2 3    # GNU parallel
//   proceduray-field merge part1.csv part2.csv part3.csv --out gyroid.csv
//   proceduray-field where     # the headers, shaders and cache folder it uses (an installed tool: its prefix's)
//
// Shards split the settings into n contiguous blocks, so merging the parts in shard order gives
// the table one unsharded run writes (errors and evaluation counts do not depend on timing).
#include "field_tool.hpp"

#include <cstdio>
#include <string>
#include <vector>


using namespace field_tool;

int main(int argc, char** argv) {
  CLI::App app{"A distance field measured and calibrated on this device against its own ground truth"};
  app.require_subcommand(1);
  FieldOptions mo, co;
  std::vector<std::string> knobs, parts;
  std::string csv, shard, cal_out, merge_out;
  CLI::App* m = app.add_subcommand("measure", "one setting: errors against the truth, evaluations, GPU time");
  add_field_options(*m, mo);
  m->add_option("--knob", knobs, "name=value of march/knobs.hpp (repeat it)");
  m->add_option("--csv", csv, "also write the metrics as CSV (accuracy/report.hpp's columns)");
  CLI::App* c = app.add_subcommand("calibrate", "the preset of methods and knobs at --size, as a calibration table");
  add_field_options(*c, co);
  c->add_option("--shard", shard, "i/n: the i-th of n contiguous blocks of settings");
  c->add_option("--out", cal_out, "the table to write")->required();
  CLI::App* w = app.add_subcommand("where", "the headers, shaders and cache folder this tool uses");
  CLI::App* g = app.add_subcommand("merge", "calibration tables of shards, in shard order, into one");
  g->add_option("parts", parts, "the shards' tables")->required();
  g->add_option("--out", merge_out, "the merged table")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return guarded("proceduray-field", [&] {
    if (m->parsed()) return measure(mo, knobs, csv);
    if (c->parsed()) return calibrate(co, shard, cal_out);
    if (w->parsed()) {
      std::printf("headers %s\nshaders %s\ncache %s\n", headers_dir().c_str(), shaders_dir().c_str(),
                  pr::vk::default_cache_dir().c_str());
      return 0;
    }
    return merge(parts, merge_out);
  });
}

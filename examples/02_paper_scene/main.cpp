// The report's figure 3: a plane, two CSG Pac-men, a Julia set cut by a plane and a
// Mandelbulb, with shadows and reflections; animated over --frames. Prints timings and the SBT.
#include "paper_scene.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <vector>

int main(int argc, char** argv) {
  examples::Options o = examples::parse(argc, argv, "02_paper_scene", {.width = 1024, .height = 768, .frames = 1});
  if (o.exit) return *o.exit;
  try {
    proceduray::check_writable(o.out);
    proceduray::vk::Context ctx({.device = o.device, .validation = o.validation});
    paper::PaperScene scene;
    const proceduray::ShaderBindingTable& sbt = scene.build(ctx.limits());
    proceduray::vk::Renderer renderer(ctx, sbt, paper::renderer_options(o.cache));
    const auto& t = renderer.timings();
    std::printf("device: %s\nacceleration structures: %.1f ms\nshaders compiled: %.1f ms\npipeline: %.1f ms (%s)\n",
                ctx.name().c_str(), t.acceleration_ms, t.compile_ms, t.pipeline_ms,
                t.pipeline_cached ? "from cache" : "cold");
    renderer.set(paper::constants_slot, paper::default_constants(o.width, o.height, 0.0f));
    std::printf("warm-up: %.1f ms\n", renderer.warm_up());
    std::vector<double> trace_ms, host_ms;
    proceduray::vk::Frame frame;
    for (std::uint32_t f = 0; f < o.frames; ++f) {
      renderer.set(paper::constants_slot, paper::default_constants(o.width, o.height, 0.1f * static_cast<float>(f)));
      frame = renderer.render(o.width, o.height, f + 1 == o.frames);
      trace_ms.push_back(frame.trace_ms);
      host_ms.push_back(frame.host_ms);
    }
    auto median = [](std::vector<double> v) {
      std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
      return v[v.size() / 2];
    };
    const double trace = median(trace_ms);
    std::printf("trace: %.2f ms median of %u frames at %ux%u (%.1f Mrays/s primary)\nhost per frame: %.3f ms\n", trace,
                o.frames, o.width, o.height, o.width * o.height / (trace * 1e3), median(host_ms));
    std::printf("%s", proceduray::format_sbt(sbt).c_str());
    proceduray::write_png(o.out, o.width, o.height, frame.rgba);
    std::printf("%s\n", std::filesystem::absolute(o.out).string().c_str());
    return ctx.validation_messages().empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "02_paper_scene: %s\n", e.what());
    return 1;
  }
}

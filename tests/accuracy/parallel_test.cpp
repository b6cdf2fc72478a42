// Tests for proceduray/accuracy/parallel.hpp: every row once, worker indices in range, the lowest
// failing row's exception, PROCEDURAY_THREADS; and a scene's ground truth equal on one thread and
// on many (the shared GLSL keeps no state).
#include "proceduray/accuracy/parallel.hpp"

#include <doctest/doctest.h>

#include "02_paper_scene/reference.hpp"
#include "vk/scoped_env.hpp"

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace acc = proceduray::accuracy;

TEST_CASE("parallel_rows calls every row once, on workers below the count") {
  for (const std::uint32_t workers : {1u, 2u, 5u, 64u}) {
    CAPTURE(workers);
    std::vector<std::atomic<int>> seen(37);
    std::atomic<std::uint32_t> worst_worker{0};
    acc::parallel_rows(
        37,
        [&](std::uint32_t y, std::uint32_t w) {
          ++seen[y];
          std::uint32_t prev = worst_worker.load();
          while (w > prev && !worst_worker.compare_exchange_weak(prev, w)) {
          }
        },
        workers);
    for (const auto& s : seen) CHECK(s.load() == 1);
    CHECK(worst_worker.load() < std::min(workers, 37u));
  }
  acc::parallel_rows(0, [](std::uint32_t, std::uint32_t) { FAIL("no rows, no calls"); }, 4);
}

TEST_CASE("parallel_rows rethrows the lowest failing row's exception after every worker stopped") {
  std::atomic<int> calls{0};
  CHECK_THROWS_WITH_AS(acc::parallel_rows(
                           100,
                           [&](std::uint32_t y, std::uint32_t) {
                             ++calls;
                             if (y % 10 == 3) throw std::runtime_error("row " + std::to_string(y));
                           },
                           4),
                       "row 3", std::runtime_error);
  CHECK(calls.load() == 100);  // the others still ran: no worker was left running
}

TEST_CASE("worker_count follows PROCEDURAY_THREADS and refuses what is no count") {
  {
    ScopedEnv env("PROCEDURAY_THREADS", "3");
    CHECK(acc::worker_count() == 3);
  }
  for (const char* bad : {"0", "-2", "many", "4x", "2000"}) {
    CAPTURE(bad);
    ScopedEnv env("PROCEDURAY_THREADS", bad);
    const std::string expected = std::string("accuracy::worker_count: PROCEDURAY_THREADS='") + bad +
                                 "' is not a thread count; give 1 to 1024, or unset it to use every core";
    CHECK_THROWS_WITH_AS(acc::worker_count(), expected.c_str(), proceduray::UsageError);
  }
}

TEST_CASE("the paper scene's ground truth is the same on one thread and on four") {
  const paper::Frame c = paper::default_frame(48, 32, 0.3f);
  const auto truth = [&](const char* threads) {
    ScopedEnv env("PROCEDURAY_THREADS", threads);
    return paper::reference_image(c, 48, 32, {.spacing = 1.0e-2});
  };
  const paper::ReferenceImage one = truth("1"), four = truth("4");
  REQUIRE(one.pixels.size() == four.pixels.size());
  std::size_t hits = 0;
  for (std::size_t i = 0; i < one.pixels.size(); ++i) {
    CHECK(one.pixels[i].outcome == four.pixels[i].outcome);
    CHECK(one.pixels[i].t == four.pixels[i].t);
    CHECK(one.objects[i] == four.objects[i]);
    hits += one.pixels[i].outcome == acc::Outcome::hit;
  }
  CHECK(hits > one.pixels.size() / 4);  // the view holds the objects: the comparison is not of misses
  CHECK(one.evaluations == four.evaluations);
  CHECK(one.undetermined == four.undetermined);
  for (std::size_t k = 0; k < one.costs.size(); ++k) CHECK(one.costs[k].hit_evaluations == four.costs[k].hit_evaluations);
}

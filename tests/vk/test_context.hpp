// A Context for tests: validation layer on, and any message it reports fails the test.
//
//   TEST_CASE("...") { TestContext t; use(t.ctx); }   // checks the messages when t goes away
#pragma once

#include <proceduray/vk/context.hpp>

#include <doctest/doctest.h>

#include <string>

struct TestContext {
  proceduray::vk::Context ctx{{.validation = true}};

  TestContext() = default;
  TestContext(const TestContext&) = delete;
  TestContext& operator=(const TestContext&) = delete;
  ~TestContext() {
    const auto messages = ctx.validation_messages();
    std::string all;
    for (const auto& m : messages) all += m + "\n";
    CHECK_MESSAGE(messages.empty(), "validation layer reported:\n" << all);
  }
};

// Tests that change the environment: ScopedEnv sets a variable for one scope and restores it.
//
//   ScopedEnv env("PROCEDURAY_DEVICE", "cpu");   // restored (or unset) when env goes away
#pragma once

#include <cstdlib>
#include <string>

/// Sets an environment variable for one scope.
struct ScopedEnv {
  std::string name;
  std::string old;
  bool had;
  ScopedEnv(const char* n, const char* value) : name(n), had(std::getenv(n) != nullptr) {
    if (had) old = std::getenv(n);
    setenv(n, value, 1);
  }
  ~ScopedEnv() {
    if (had) setenv(name.c_str(), old.c_str(), 1);
    else unsetenv(name.c_str());
  }
};

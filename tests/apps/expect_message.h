// What the config tests share: the message a loader's InputError carries, checked for every fragment
// it must name, and a scratch folder of the test's own.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>

#include "apps/config.h"

namespace tribo::cli::fixture {

// The message of the InputError `load()` raises; empty when it loads.
template <class Load>
std::string input_error_of(Load&& load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

// The message names each fragment (the file, key, line, reason …); an empty message means the
// input was accepted.
inline void expect_all(const std::string& message, std::initializer_list<std::string> fragments) {
  EXPECT_FALSE(message.empty()) << "accepted";
  for (const auto& f : fragments) EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
}

// temp/<suite>/<test name>, created: ctest runs each test as its own process, two at once under
// -j2, and two tests writing the same file in one folder read each other's (two RigConfig tests'
// bad.toml, once, 2026-11-29).
inline std::filesystem::path test_folder(const std::string& suite) {
  const auto dir = std::filesystem::temp_directory_path() / suite / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace tribo::cli::fixture

// The fixture the bundle reader's tests share (bundle_test.cpp, bundle_hostile_test.cpp): a fresh
// bundle folder with an empty traces/ per test, named after the test and removed afterwards, a
// helper to write a file into it, and the reason read_bundle gives for it.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "gap/bundle.h"

namespace tribo::gap {

class BundleFixture : public ::testing::Test {
 protected:
  // `prefix` starts the folder's name under the temporary directory; the test's name ends it.
  explicit BundleFixture(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           (prefix_ + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "traces");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
  // The reason read_bundle gives, or "" when it accepts the bundle.
  std::string error() {
    try {
      read_bundle(dir_);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  }
  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace tribo::gap

// What the config tests share: an error message checked for every fragment it must name.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

namespace tribo::cli::fixture {

// The message names each fragment (the file, key, line, reason …); an empty message means the
// input was accepted.
inline void expect_all(const std::string& message, std::initializer_list<std::string> fragments) {
  EXPECT_FALSE(message.empty()) << "accepted";
  for (const auto& f : fragments) EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
}

}  // namespace tribo::cli::fixture

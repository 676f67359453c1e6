// The journal of `tribo gap selftest` (apps/cmd_gap.cpp): OUT/cases.jsonl, one JSON object a line,
// appended and flushed as each case finishes, so that the same command after a kill resumes where
// it stopped. The reader keeps the rows of the set asked for (quick or full) and skips, without a
// word, every line that is not one: a line cut short by a kill (or otherwise not JSON), a value
// that is not an object, a row of the other set, and a row that lacks a key it needs or holds one
// of the wrong type. Keys added since the first journals are optional (NaN, 0 or empty when
// absent). `correct` is recomputed (verdict == true_effect), not read. A `quick` that is not a boolean
// and a seed that is not an unsigned integer skip the line too (fuzz_selftest_journal found both).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "gap/selftest.h"

namespace tribo::cli {

// What a verdict ("none", "unexplained", "a" or "a+b") adds to a model with `model_effects`
// (gap::Verdict::adds), for journals from before it was written.
std::vector<std::string> adds_of_verdict(const std::string& verdict, const std::vector<std::string>& model_effects);

// The rows of an earlier run of the same set in `file` (a missing file: none), in file order.
std::vector<gap::SelftestRow> finished_rows(const std::filesystem::path& file, bool quick);

}  // namespace tribo::cli

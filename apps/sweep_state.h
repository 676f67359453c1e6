// What `tribo sweep SPEC --out DIR` reads of DIR when it starts again (apps/cmd_sweep.cpp): the
// state an earlier start left there, read before any point runs. DIR/sweep.json records the hashes
// of the spec and configs the folder's sweep was started with: a start with other files is refused
// (InputError), as is a sweep.json that is not JSON. DIR/results.csv holds the rows of finished
// points, one a line after the column header: a header other than this spec's is refused
// (InputError); a torn last line (a kill mid-write: no newline) is dropped; provenance lines ('#')
// before the header, written by builds before 2026-11-27, are skipped. A row whose point id is
// not a non-negative integer, a point twice, and a sweep.json that is JSON but not an object are
// refused too (InputError naming the file and line; fuzz_sweep_state found them). The writing half
// (the runs log, the provenance, the rows) stays in cmd_sweep.cpp.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace tribo::cli {

// DIR/sweep.json: nullopt when there is none (a fresh folder), its document when it records these
// hashes (`rig_hash` empty unless the sweep is a chain), an InputError naming DIR otherwise.
std::optional<nlohmann::json> read_sweep_json(const std::filesystem::path& dir, const std::string& spec_hash,
                                              const std::string& base_hash, const std::string& rig_hash);

// The rows already in results.csv by point id (the field before the first comma). A missing file
// gives none; a header that differs from `expected` is refused.
std::map<int, std::string> finished_sweep_rows(const std::filesystem::path& file, const std::string& expected);

}  // namespace tribo::cli

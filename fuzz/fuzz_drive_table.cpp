// libFuzzer harness for the drive table a rig config names (`[drive] kind = "table", file =
// "drive.csv"`, apps/rig_config.h): the input is the CSV's bytes, written beside a config that
// names it, and the config is loaded as `tribo rig` loads it. Bad input must end as InputError
// naming a file (the CLI's exit status 2); any other exception, a sanitizer report or a hang is a
// finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "apps/config.h"
#include "apps/rig_config.h"
#include "fuzz/fuzz_check.h"
#include "fuzz/fuzz_temp_dir.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::clear_scratch();
  const std::filesystem::path config = tribo::fuzz::scratch_dir() / "rig.toml";
  tribo::fuzz::write_file(config, "[drive]\nkind = \"table\"\nfile = \"drive.csv\"\n[run]\nduration_s = 1.0\n");
  tribo::fuzz::write_file(tribo::fuzz::scratch_dir() / "drive.csv", std::string(reinterpret_cast<const char*>(data), size));
  try {
    const tribo::cli::RigRun run = tribo::cli::load_rig_run(config);
    TRIBO_FUZZ_CHECK(run.drive.has_value());
    TRIBO_FUZZ_CHECK(run.input_files.size() == 1);  // the table, for provenance
  } catch (const tribo::cli::InputError& e) {
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find('/') != std::string_view::npos);
  }
  return 0;
}

// libFuzzer harness for the homogenised law table a rig reads (`[friction] law = "homogenised"`,
// rig/law_table.h, rig/homogenised_law.h): the input is the bytes of law.json, written to a
// scratch folder and read as a rig of the thesis' normal load would read it. Bad input must end as
// std::invalid_argument naming the file (the CLI's exit status 2); any other exception, a
// sanitizer report or a hang is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzz_temp_dir.h"
#include "rig/homogenised_law.h"
#include "rig/parameters.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::clear_scratch();
  const std::filesystem::path path = tribo::fuzz::scratch_dir() / "law.json";
  tribo::fuzz::write_file(path, std::string(reinterpret_cast<const char*>(data), size));
  try {
    const auto base = tribo::rig::load_homogenised_base(path, tribo::rig::RigParameters{}.normal_load_N);
    TRIBO_FUZZ_CHECK(base != nullptr);
  } catch (const std::invalid_argument& e) {
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find("law.json") != std::string_view::npos);
  }
  return 0;
}

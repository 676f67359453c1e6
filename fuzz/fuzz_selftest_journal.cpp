// libFuzzer harness for the reader of the `tribo gap selftest` journal (apps/selftest_journal.h):
// the input is OUT/cases.jsonl's bytes, written to the scratch folder and read for the quick set
// and for the full one. The reader skips what is not a row and throws nothing: any exception, a
// sanitizer report or a hang is a finding, as is a row whose `correct` is not verdict ==
// true_effect or more rows than the file has lines (a line is a row of one set at most).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "apps/selftest_journal.h"
#include "fuzz/fuzz_check.h"
#include "fuzz/fuzz_temp_dir.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::clear_scratch();
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::filesystem::path journal = tribo::fuzz::scratch_dir() / "cases.jsonl";
  tribo::fuzz::write_file(journal, text);
  // Lines as std::getline counts them: one per newline, and a last one without.
  const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) +
                            (!text.empty() && text.back() != '\n' ? 1 : 0);
  const std::vector<tribo::gap::SelftestRow> quick = tribo::cli::finished_rows(journal, true);
  const std::vector<tribo::gap::SelftestRow> full = tribo::cli::finished_rows(journal, false);
  TRIBO_FUZZ_CHECK(quick.size() + full.size() <= lines);
  for (const std::vector<tribo::gap::SelftestRow>* rows : {&quick, &full})
    for (const tribo::gap::SelftestRow& r : *rows) TRIBO_FUZZ_CHECK(r.correct == (r.verdict == r.c.true_effect));
  return 0;
}

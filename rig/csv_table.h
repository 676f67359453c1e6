// Comma-separated tables as tribo reads them: experiment bundles (gap/bundle.h) and drive tables
// (a [drive] file of a rig config). One set of rules for every reader:
//   - blank lines and lines starting with '#' are skipped (comments, and the provenance block
//     tribo writes above the columns of its own CSVs);
//   - the first other line names the columns: none empty, none repeated; a column the caller does
//     not know is reported in `warnings` and otherwise ignored;
//   - each row has exactly as many cells as the header; cells are trimmed of blanks;
//   - a number is a whole cell that strtod reads and that is finite; an empty cell where a number
//     is asked for is an error.
// A file with no header or no data rows, or that is not a regular file (a FIFO or /dev/zero would
// never end), is an error. Errors are std::invalid_argument "FILE:LINE: reason".
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tribo::rig {

struct CsvTable {
  std::filesystem::path file;
  std::vector<std::string> header;
  std::vector<std::pair<long, std::vector<std::string>>> rows;  // (line number, cells)

  // The column's index, or -1 when the header does not name it.
  int column(const std::string& name) const;
  // The column's index; a header without it is an error.
  int required(const std::string& name) const;
  // The cell of `row` (read at `line`) in column c as a finite number.
  double number(long line, const std::vector<std::string>& row, int c) const;
};

CsvTable read_csv_table(const std::filesystem::path& file, const std::set<std::string>& known,
                        std::vector<std::string>& warnings);

// Throws std::invalid_argument "FILE:LINE: reason" (no line when line <= 0): the reader's errors,
// and those of the checks a caller makes on the rows it reads (or on other files of a bundle).
[[noreturn]] void fail_at(const std::filesystem::path& file, long line, const std::string& reason);

}  // namespace tribo::rig

// Writing results: files appear whole or not at all (written to a temporary name, then renamed),
// and a terminal progress bar for long jobs.
#pragma once

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "numerics/format.h"

namespace tribo::cli {

// A file written under a temporary name and renamed into place by commit(); destroyed
// uncommitted, it leaves nothing behind.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  std::ofstream& stream() { return stream_; }
  void commit();

 private:
  std::filesystem::path path_, tmp_;
  std::ofstream stream_;
  bool committed_ = false;
};

void write_file_atomically(const std::filesystem::path& path, const std::string& content);
// A field (nx, ny) or a profile as float64 .npy (contact/surface_io.h's layout), whole or not at all.
void write_npy_atomically(const std::filesystem::path& path, const Eigen::ArrayXXd& field);
void write_npy_atomically(const std::filesystem::path& path, const std::vector<double>& profile);

// A CSV as the readers people reach for take it: plain, its first line the column header, so
// numpy.genfromtxt(names=True), pandas.read_csv and csv.DictReader read it without options. How it
// was made goes beside it, in NAME.csv.provenance.json ({"csv": NAME.csv, "provenance": {...}});
// commit() writes that first, so a CSV is never without it. Both appear whole or not at all.
class CsvFile {
 public:
  CsvFile(std::filesystem::path path, nlohmann::json provenance);
  std::ofstream& stream() { return csv_.stream(); }
  void commit();

 private:
  std::filesystem::path path_;
  nlohmann::json provenance_;
  AtomicFile csv_;
};

std::filesystem::path csv_provenance_path(const std::filesystem::path& csv);  // NAME.csv.provenance.json
void write_csv_provenance(const std::filesystem::path& csv, const nlohmann::json& provenance);  // that file, whole
void write_csv_atomically(const std::filesystem::path& path, const std::string& content, const nlohmann::json& provenance);

// A number for reports and CSV fields: numerics/format.h.
using numerics::fmt;

// A CSV field: 10 significant digits, empty for NaN or ∞ (an unknown value: numpy reads nan,
// pandas NaN).
std::string csv_number(double v);

// A number with all 17 significant digits: read back, it is the same double.
std::string exact(double v);

// A file that ships with tribo (the plotting script, the examples). For an installed tribo it is
// `installed`, relative to the data folder beside the binary (<prefix>/share/tribo, reached from
// <prefix>/bin — so a moved prefix still works); otherwise `in_source`, relative to the source
// tree the binary was built from. `executable` is the running binary unless given (tests).
std::filesystem::path shipped_file(const std::string& installed, const std::string& in_source,
                                   std::filesystem::path executable = {});

// Creates DIR (and parents); an error names DIR.
void make_output_dir(const std::filesystem::path& dir);

// Removes an earlier run's results DIR/NAME (and a CSV's provenance beside it) before a run that
// keeps its caches in DIR starts, so that a run which then fails leaves no result from another
// config beside them. An error names the file.
void remove_previous_results(const std::filesystem::path& dir, std::initializer_list<const char*> names);

// "[#####.....] 12/40 label" on stderr when it is a terminal, a line per 10 % otherwise.
class Progress {
 public:
  Progress(std::string label, int total);
  void step(const std::string& what = "");
  void done();

 private:
  std::string label_;
  int total_, count_ = 0, last_decile_ = -1;
  bool tty_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace tribo::cli

#include "apps/output.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "apps/config.h"
#include "contact/surface_io.h"

namespace tribo::cli {

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  // Unique among the processes writing a folder at once (the pid) and within this one (the count);
  // cheaper than a std::random_device per file, which a sweep writing thousands of files felt.
  static std::atomic<unsigned long> count{0};
  tmp_ = path_;
  tmp_ += ".partial-" + std::to_string(getpid()) + "-" + std::to_string(count++);
  stream_.open(tmp_);
  if (!stream_) throw InputError(path_.string() + ": cannot open for writing");
  stream_.precision(10);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    stream_.close();
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
  }
}

void AtomicFile::commit() {
  stream_.flush();
  if (!stream_) throw std::runtime_error(path_.string() + ": write failed");
  stream_.close();
  std::filesystem::rename(tmp_, path_);
  committed_ = true;
}

std::string csv_number(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  AtomicFile f(path);
  f.stream() << content;
  f.commit();
}

void write_npy_atomically(const std::filesystem::path& path, const Eigen::ArrayXXd& field) {
  AtomicFile f(path);
  contact::write_npy(f.stream(), field);
  f.commit();
}

void write_npy_atomically(const std::filesystem::path& path, const std::vector<double>& profile) {
  AtomicFile f(path);
  contact::write_npy(f.stream(), profile);
  f.commit();
}

std::filesystem::path csv_provenance_path(const std::filesystem::path& csv) {
  std::filesystem::path p = csv;
  p += ".provenance.json";
  return p;
}

CsvFile::CsvFile(std::filesystem::path path, nlohmann::json provenance)
    : path_(path), provenance_(std::move(provenance)), csv_(std::move(path)) {}

void write_csv_provenance(const std::filesystem::path& csv, const nlohmann::json& provenance) {
  const nlohmann::json beside = {{"csv", csv.filename().string()}, {"provenance", provenance}};
  write_file_atomically(csv_provenance_path(csv), beside.dump(2) + "\n");
}

void CsvFile::commit() {
  write_csv_provenance(path_, provenance_);
  csv_.commit();
}

void write_csv_atomically(const std::filesystem::path& path, const std::string& content, const nlohmann::json& provenance) {
  CsvFile f(path, provenance);
  f.stream() << content;
  f.commit();
}

std::filesystem::path shipped_file(const std::string& installed, const std::string& in_source,
                                   std::filesystem::path executable) {
  std::error_code ec;
  if (executable.empty()) executable = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec && !executable.empty()) {
    // TRIBO_DATA_FROM_BIN: the install's data folder relative to its bin folder ("../share/tribo").
    const std::filesystem::path candidate = executable.parent_path() / TRIBO_DATA_FROM_BIN / installed;
    if (std::filesystem::exists(candidate, ec)) return candidate.lexically_normal();
  }
  return std::filesystem::path(TRIBO_SOURCE_DIR) / in_source;
}

void make_output_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw InputError(dir.string() + ": cannot create output directory (" + ec.message() + ")");
  }
  // An existing folder may still refuse files (read-only, another owner, a read-only mount): say so
  // now rather than at the first write, after the work (a 30-min selftest lost its results so).
  const std::filesystem::path probe = dir / (".tribo-write-probe-" + std::to_string(getpid()));
  const bool writable = static_cast<bool>(std::ofstream(probe));
  std::filesystem::remove(probe, ec);
  if (!writable) throw InputError(dir.string() + ": output directory is not writable");
}

void remove_previous_results(const std::filesystem::path& dir, std::initializer_list<const char*> names) {
  for (const char* name : names)
    for (const std::filesystem::path& f : {dir / name, csv_provenance_path(dir / name)}) {
      std::error_code ec;
      std::filesystem::remove(f, ec);
      if (ec) throw std::runtime_error(f.string() + ": cannot remove the previous run's result: " + ec.message());
    }
}

Progress::Progress(std::string label, int total)
    : label_(std::move(label)), total_(total), tty_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

void Progress::step(const std::string& what) {
  ++count_;
  const double frac = total_ > 0 ? std::min(1.0, static_cast<double>(count_) / total_) : 1.0;  // a step past the estimate stays full
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (tty_) {
    const int width = 30, filled = static_cast<int>(frac * width);
    std::fprintf(stderr, "\r%s [%s%s] %d/%d %5.1f s %-30s", label_.c_str(),
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), count_,
                 total_, elapsed, what.c_str());
    std::fflush(stderr);
  } else {
    const int decile = static_cast<int>(frac * 10);
    if (decile != last_decile_) {
      last_decile_ = decile;
      std::fprintf(stderr, "%s: %d/%d (%.0f %%) %.1f s\n", label_.c_str(), count_, total_, 100 * frac, elapsed);
    }
  }
}

void Progress::done() {
  if (tty_) std::fprintf(stderr, "\n");
}

}  // namespace tribo::cli

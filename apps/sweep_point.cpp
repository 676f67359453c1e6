#include "apps/sweep_point.h"

#include <cstdio>
#include <stdexcept>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/provenance.h"

namespace tribo::cli {
namespace {

// A message's first string says its kind.
const std::string kCommandLine = "argv";
const std::string kInMemory = "memory";

}  // namespace

bool runs_in_memory(const std::string& command) {
  return command == "rig" || command == "contact" || command == "reynolds";
}

std::vector<std::string> command_line_step(const std::vector<std::string>& args) {
  std::vector<std::string> message{kCommandLine};
  message.insert(message.end(), args.begin(), args.end());
  return message;
}

std::vector<std::string> in_memory_step(const std::string& command, const std::string& config_text,
                                        const std::filesystem::path& path, const std::string& out) {
  return {kInMemory, command, config_text, path.string(), out};
}

int run_step(std::vector<std::string>& message, std::vector<std::string>& answer) {
  if (!message.empty() && message[0] == kCommandLine) {
    std::vector<char*> argv;
    for (std::size_t k = 1; k < message.size(); ++k) argv.push_back(message[k].data());
    argv.push_back(nullptr);
    return run_command_line(static_cast<int>(message.size() - 1), argv.data());
  }
  if (message.size() != 5 || message[0] != kInMemory) {
    std::fprintf(stderr, "tribo: failed: sweep: a malformed step message\n");
    return 1;
  }
  const std::string &command = message[1], &text = message[2], &path = message[3], &out = message[4];
  // The provenance's command line: the command this point stands for, as a file step records it.
  const char* const argv[] = {"/proc/self/exe", command.c_str(), path.c_str(), "--out", out.c_str(), "--summary-only"};
  record_command_line(6, argv);
  const JsonSink sink = [&answer](const std::string& name, const std::string& json) {
    answer.push_back(name);
    answer.push_back(json);
  };
  try {
    const toml::table config = parse_toml_text(text, path);
    const std::string hash = bytes_hash(text);
    if (command == "rig") {
      run_rig_summary(config, path, hash, out, sink);
    } else if (command == "contact") {
      run_contact_summary(config, path, hash, out, sink);
    } else if (command == "reynolds") {
      run_reynolds_summary(config, path, hash, out, sink);
    } else {
      throw std::logic_error("sweep: " + command + " does not run in memory");
    }
  } catch (...) {
    return report_failure(std::current_exception());
  }
  return 0;
}

}  // namespace tribo::cli

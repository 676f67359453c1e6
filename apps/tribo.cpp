// tribo — contact mechanics, lubrication and the friction rig, from the asperity up.
// Exit codes: 0 success, 1 a solver or run failure, 2 bad input (config, file, option).
#include <cstdio>
#include <exception>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/provenance.h"

int tribo::cli::report_failure(std::exception_ptr failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const tribo::cli::InputError& e) {
    std::fprintf(stderr, "tribo: error: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "tribo: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo: failed: %s\n", e.what());
    return 1;
  }
}

// The whole command line, in this process: main's body, and what a sweep's forked point runs.
int tribo::cli::run_command_line(int argc, char** argv) {
  tribo::cli::record_command_line(argc, argv);  // into every output's provenance
  CLI::App app{"tribo: rough-surface contact, Reynolds lubrication and the friction rig of the thesis"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "tribo " TRIBO_VERSION);
  tribo::cli::add_demo_command(app);
  tribo::cli::add_rig_command(app);
  tribo::cli::add_contact_command(app);
  tribo::cli::add_reynolds_command(app);
  tribo::cli::add_ehl_command(app);
  tribo::cli::add_homogenise_command(app);
  tribo::cli::add_sweep_command(app);
  tribo::cli::add_gap_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (...) {
    return tribo::cli::report_failure(std::current_exception());
  }
  return 0;
}

int main(int argc, char** argv) { return tribo::cli::run_command_line(argc, argv); }

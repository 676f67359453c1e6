// Files a rig run writes: trace.csv (streamed), events.csv and summary.json. SI units with the
// unit in every column name; friction_N is the force as the thesis instrument measures it (4.2.3).
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <vector>

#include "rig/observables.h"
#include "rig/simulator.h"

namespace tribo::cli {

void write_trace_header(std::ostream& os);
// `measured_friction_N` is the instrument's reading at this sample (rig/instrument.h).
void write_trace_row(std::ostream& os, const rig::Sample& s, double measured_friction_N);
void write_events_csv(std::ostream& os, const std::vector<rig::Event>& events);
nlohmann::json observables_json(const rig::RunObservables& o);
nlohmann::json rig_json(const rig::RigParameters& rig);
// summary.json without its provenance: the observables, how the integration went, the law's name,
// the rig and the wall time (the CLI and the Python binding write the same keys from here).
nlohmann::json rig_summary_json(const rig::RunObservables& o, const rig::SimulationSummary& summary, const std::string& law_name,
                                const rig::RigParameters& rig, double wall_s);

// Runs tools/tribo_plots.py MODE DIR with the Python that has matplotlib (Debian's
// /usr/bin/python3), spawned with an argument vector — no shell, so any DIR is passed as it is.
// Returns the script's exit status (127 when it could not start); plots are optional extras, so
// callers warn on failure.
int run_plot_script(const std::string& mode, const std::string& dir);

}  // namespace tribo::cli

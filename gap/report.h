// The diagnosis' last stage (diagnosis.h): what it says — the verdict's name, the one sentence a
// tribologist can act on, and gap_report.json.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "gap/diagnosis_types.h"

namespace tribo::gap {

// The conclusion for a finished diagnosis (verdict, confidence, localisation and candidates set):
// "Add EFFECT to the model (its parameters): it cuts the held-out gap from … to …", or
// "Unexplained: …" with where the gap lies, or "No catalogue effect earns its parameters …".
// `chosen`: the verdict's candidate, nullptr for "none" and "unexplained".
std::string conclusion(const Diagnosis& d, const Candidate* chosen);

// "87 %", or what stands in for a confidence the data cannot give (NaN: one held-out block and no
// noise estimate, bootstrap_confidence in verdict.h).
std::string confidence_text(double confidence);

// gap_report.json content (keys of DESIGN §7 plus details; a confidence that cannot be estimated
// is null).
nlohmann::json report_json(const Diagnosis& d);

// {"calibration": …, "candidates": …, "recalibration": …, "refinement": …, "confidence": …} in
// seconds: gap_report.json's and a selftest row's `stage_wall_s`.
nlohmann::json stage_times_json(const StageTimes& t);

}  // namespace tribo::gap

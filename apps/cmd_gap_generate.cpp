// `tribo gap generate --generator G --kind K --effect E --seed N [--set S] --out DIR`: one
// synthetic experiment bundle with a known truth, as the selftest diagnoses it — so a user can run
// `tribo gap diagnose` on a case whose answer is known, and see what the diagnosis does with it
// (a selftest case of set S with this seed is the same case: `cases.jsonl` gives the seed).
//   DIR/bundle/      the experiment bundle (gap/bundle.h; experiment.toml, runs.csv, traces/)
//   DIR/test/        pin-on-disc: the test block (the same truth at the set's test speeds, noise
//                    drawn afresh), for `tribo gap diagnose --test`
//   DIR/proposed/T/  pin-on-disc: the same truth under each test T the diagnosis may propose to
//                    tell two candidates apart (gap/discriminate.h: wider_speeds, stiffer_spring,
//                    heavier_load; slide_hold_slide from the rig generator), for `--test` likewise
//   DIR/model.toml   the model the diagnosis starts from: the rig as told, a Coulomb baseline
//                    miscalibrated as the selftest's is, and no effect
//   DIR/truth.json   the withheld effect with its parameters (the rig generator's in catalogue
//                    names; the independent one's in its own forms, with its rig and chain), the form it was
//                    written in, generator, kind, set, seed, provenance
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/output.h"
#include "apps/provenance.h"
#include "gap/bundle.h"
#include "gap/independent/generator.h"
#include "gap/selftest.h"
#include "numerics/format.h"
#include "rig/friction_model.h"

namespace tribo::cli {
namespace {

struct GenerateArgs {
  std::string generator = "independent", kind = "pin_on_disc", effect = "none", set = "development", out = "out/gap-case";
  std::uint64_t seed = 1;
  std::vector<double> speeds_m_per_s;  // pin_on_disc: instead of the set's; the test speeds between them
};

struct GeneratedCase {
  gap::ExperimentBundle bundle, test;  // test: empty for the drive-history kinds
  std::map<std::string, gap::ExperimentBundle> proposed;  // by test name; empty for the drive-history kinds
  rig::RigParameters rig;  // as the model is told it
  double mu_s = 0.0, mu_k = 0.0;
  std::map<std::string, std::vector<double>> model_effects;  // the rig generator's model beside its baseline
  std::string form;
  std::map<std::string, double> truth_parameters;
};

GeneratedCase generate(const GenerateArgs& a) {
  GeneratedCase g;
  if (a.kind == "pin_on_disc") {
    gap::SyntheticOptions options = gap::synthetic_options(a.set == "validation" ? gap::SelftestSet::validation : gap::SelftestSet::development);
    if (!a.speeds_m_per_s.empty()) {
      if (a.speeds_m_per_s.size() < 2) throw InputError("--speeds: give at least two driven speeds");
      for (std::size_t i = 0; i < a.speeds_m_per_s.size(); ++i)
        if (!(std::isfinite(a.speeds_m_per_s[i]) && a.speeds_m_per_s[i] > 0.0) || (i > 0 && !(a.speeds_m_per_s[i] > a.speeds_m_per_s[i - 1])))
          throw InputError("--speeds: the speeds must be positive and increasing (m/s)");
      options.speeds_m_per_s = a.speeds_m_per_s;
      options.test_speeds_m_per_s.clear();
      for (std::size_t i = 1; i < a.speeds_m_per_s.size(); ++i)  // between them, as the sets' test speeds
        options.test_speeds_m_per_s.push_back(std::sqrt(a.speeds_m_per_s[i - 1] * a.speeds_m_per_s[i]));
    }
    // The selftest's case with this seed: the rig generator's model as its selftest has it.
    const gap::SelftestCase sc{a.effect, a.generator == gap::kRigGenerator ? gap::rig_model_effects(a.effect) : std::vector<std::string>{},
                               a.seed, a.generator};
    gap::CaseBundles c = gap::make_case_bundles(sc, options);
    g.proposed = gap::make_proposed_test_bundles(sc, options);
    g.bundle = std::move(c.bundle), g.test = std::move(c.test);
    g.mu_s = c.model.baseline.mu_s, g.mu_k = c.model.baseline.mu_k;
    g.model_effects = c.model.effects;
    g.form = c.form;
    g.truth_parameters = c.truth_parameters;
  } else {
    if (a.generator == "rig") throw InputError("--kind " + a.kind + ": the rig's simulator writes pin_on_disc bundles only");
    if (!a.speeds_m_per_s.empty()) throw InputError("--speeds: a " + a.kind + " case has its own drive history (pin_on_disc only)");
    gap::independent::IndependentCase c = a.kind == "slide_hold_slide" ? gap::independent::make_slide_hold_slide_case(a.effect, a.seed)
                                                                       : gap::independent::make_velocity_step_case(a.effect, a.seed);
    g.bundle = std::move(c.bundle);
    g.mu_s = c.model_mu_s, g.mu_k = c.model_mu_k;
    g.form = c.form;
    g.truth_parameters = gap::independent::truth_parameters(c);
  }
  g.rig = gap::apply_bundle_rig(g.bundle, rig::RigParameters{});
  return g;
}

std::string model_toml(const GeneratedCase& g, const GenerateArgs& a) {
  const auto n = [](double v) { return numerics::shortest(v); };
  std::ostringstream os;
  os << "# The model `tribo gap diagnose` starts from, written by `tribo gap generate` (generator " << a.generator << ", kind "
     << a.kind << ", seed " << a.seed << "):\n"
     << "# the rig as the bundle tells it and a Coulomb baseline a few per cent off; the withheld effect is in truth.json.\n"
     << "[rig]\n"
     << "mass_kg = " << n(g.rig.mass_kg) << "\n"
     << "stiffness_N_per_m = " << n(g.rig.stiffness_N_per_m) << "\n"
     << "damping_N_s_per_m = " << n(g.rig.damping_N_s_per_m) << "\n"
     << "normal_load_N = " << n(g.rig.normal_load_N) << "\n"
     << "slider_radius_m = " << n(g.rig.slider_radius_m) << "\n\n"
     << "[friction]\nlaw = \"coulomb\"\n"
     << "mu_s = " << n(g.mu_s) << "\n"
     << "mu_k = " << n(g.mu_k) << "\n";
  if (g.model_effects.empty()) return os.str();
  std::vector<std::string> names;
  for (const auto& [name, values] : g.model_effects) names.push_back("\"" + name + "\"");
  os << "effects = [" << numerics::join(names, ", ") << "]\n";
  for (const auto& [name, values] : g.model_effects) {
    os << "\n[friction." << name << "]\n";
    const auto& parameters = rig::effect_info(name).parameters;
    for (std::size_t i = 0; i < values.size(); ++i) os << parameters[i].name << " = " << n(values[i]) << "\n";
  }
  return os.str();
}

void run_generate(const GenerateArgs& a) {
  GeneratedCase g;
  try {
    g = generate(a);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--effect ") + a.effect + " (--generator " + a.generator + ", --kind " + a.kind + "): " + e.what());
  }
  make_output_dir(a.out);
  const std::filesystem::path dir(a.out);
  gap::write_bundle(g.bundle, dir / "bundle");
  if (!g.test.runs.empty()) gap::write_bundle(g.test, dir / "test");
  for (const auto& [name, bundle] : g.proposed) gap::write_bundle(bundle, dir / "proposed" / name);
  write_file_atomically(dir / "model.toml", model_toml(g, a));
  nlohmann::json truth{{"true_effect", a.effect}, {"form", g.form},           {"generator", a.generator},
                       {"kind", a.kind},          {"seed", a.seed},           {"set", a.set},
                       {"provenance", provenance_json(std::filesystem::path())}};
  if (!g.truth_parameters.empty()) truth["parameters"] = g.truth_parameters;
  if (!a.speeds_m_per_s.empty()) truth["speeds_m_per_s"] = a.speeds_m_per_s;
  write_file_atomically(dir / "truth.json", truth.dump(2) + "\n");
  const bool test = !g.test.runs.empty();
  std::printf("%s case, %s (%s, %s set), seed %llu -> %s/{bundle/,%smodel.toml,truth.json}\n", a.generator.c_str(), a.effect.c_str(),
              a.kind.c_str(), a.set.c_str(), static_cast<unsigned long long>(a.seed), a.out.c_str(), test ? "test/,proposed/," : "");
  std::printf("diagnose it: tribo gap diagnose --experiment %s/bundle --model %s/model.toml%s%s --out %s/diagnosis\n", a.out.c_str(),
              a.out.c_str(), test ? " --test " : "", test ? (a.out + "/test").c_str() : "", a.out.c_str());
}

}  // namespace

void add_gap_generate_command(CLI::App& gap) {
  auto args = std::make_shared<GenerateArgs>();
  CLI::App* cmd = gap.add_subcommand("generate",
                                     "Write one synthetic experiment bundle with a known withheld effect, and the model to diagnose it with "
                                     "(pin_on_disc: also its test block and the truth under each test a diagnosis may propose, proposed/T)");
  cmd->add_option("--generator", args->generator, "rig (the rig's own simulator, catalogue forms) or independent (gap/independent/: other forms, integrator and measuring chain)")
      ->check(CLI::IsMember({"rig", "independent"}))
      ->capture_default_str();
  cmd->add_option("--kind", args->kind, "pin_on_disc (five driven speeds), slide_hold_slide or velocity_step (independent generator; effect rate_and_state or none)")
      ->check(CLI::IsMember({"pin_on_disc", "slide_hold_slide", "velocity_step"}))
      ->capture_default_str();
  cmd->add_option("--effect", args->effect, "The withheld effect (a catalogue name the generator writes), or none for a control")->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the case's parameters and noise")->capture_default_str();
  cmd->add_option("--set", args->set, "pin_on_disc: the selftest set whose speeds, test speeds and effect strengths the case is drawn with (development or validation; the case of `tribo gap selftest --set S` with this seed)")
      ->check(CLI::IsMember({"development", "validation"}))
      ->capture_default_str();
  cmd->add_option("--speeds", args->speeds_m_per_s,
                  "pin_on_disc: the driven speeds (m/s, increasing, comma-separated) instead of the set's; the test block at the geometric "
                  "means between them — a case drawn at the speeds of one's own rig, or a development draw at speeds neither set uses")
      ->delimiter(',');
  cmd->add_option("--out", args->out, "Output directory")->capture_default_str();
  cmd->callback([args] { run_generate(*args); });
}

}  // namespace tribo::cli

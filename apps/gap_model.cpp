#include "apps/gap_model.h"

#include <optional>

#include "apps/config.h"
#include "apps/rig_config.h"

namespace tribo::cli {

GapModel load_gap_model(const std::filesystem::path& path) { return load_gap_model(parse_toml_file(path), path); }

GapModel load_gap_model(const toml::table& doc, const std::filesystem::path& path) {
  ConfigTable root(doc, path.string(), "");
  GapModel m;
  std::optional<ConfigTable> rig_table = root.table("rig");
  for (const char* key : {"stiffness_N_per_m", "damping_N_s_per_m", "mass_kg"})
    if (!rig_table || !rig_table->has(key)) m.missing_rig_keys.push_back(key);
  if (rig_table) {
    m.rig = read_rig_parameters(*rig_table);
    rig_table->accept("drive_speed_m_per_s");
    rig_table->finish();
  }
  std::optional<ConfigTable> friction = root.table("friction");
  // A homogenised law (law.json) is read at the model's normal load.
  m.friction = read_friction_model(friction ? &*friction : nullptr, m.rig.normal_load_N);
  if (friction) friction->finish();
  root.accept("drive");
  root.accept("run");
  root.finish();
  m.input_files = root.input_files();
  return m;
}

}  // namespace tribo::cli

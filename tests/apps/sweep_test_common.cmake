# Shared by the rig sweep tests (sweep_resume_test.cmake, sweep_mpi_test.cmake): the 12-point rig
# sweep both run, and rows_without_wall (sweep_rows.cmake) to compare its results.csv files.

include(${CMAKE_CURRENT_LIST_DIR}/sweep_rows.cmake)

# A fresh WORK folder holding rig.toml (a Coulomb rig, 400 s: ≈ 10–1300 ms a point, so kills land mid-sweep) and spec.toml: 4 drive speeds × 3
# masses, the mass -1 a bad config (4 failed points), `jobs` points at a time; outputs from
# summary.json, its config hash among them: a point run on its config in memory must hash the bytes
# a file step reads (the tests compare such sweeps with file-step ones: MPI, artefacts = true).
function(write_rig_sweep jobs)
  file(REMOVE_RECURSE ${WORK})
  file(MAKE_DIRECTORY ${WORK})
  file(WRITE ${WORK}/rig.toml "[rig]\ndrive_speed_m_per_s = 1e-3\n[friction]\nlaw = \"coulomb\"\nmu_s = 0.3\nmu_k = 0.2\n[run]\nduration_s = 400.0\n")
  file(WRITE ${WORK}/spec.toml "[base]\ncommand = \"rig\"\nconfig = \"rig.toml\"\n"
    "[[axis]]\nkey = \"rig.drive_speed_m_per_s\"\nfrom = 1e-3\nto = 1e-1\ncount = 4\nscale = \"log\"\n"
    "[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [0.99822, 2.0, -1.0]\n"
    "[sweep]\njobs = ${jobs}\n[outputs]\ncolumns = [\"summary.json:regime\", \"summary.json:peak_to_peak_m\", \"summary.json:breakaways\", "
    "\"summary.json:provenance.config_hash\"]\n")
endfunction()

# `tribo gap generate` writes a case a diagnosis can start from: the bundle, a model whose rig is
# the one the bundle tells (so `tribo gap diagnose` refines it within the bundle's uncertainty,
# not from the thesis rig) and the truth. Checked with Python's own TOML and JSON readers.
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${TRIBO} gap generate --kind slide_hold_slide --effect rate_and_state --seed 3 --out ${WORK}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "tribo gap generate failed (${status}): ${err}")
endif()
execute_process(COMMAND ${PYTHON} -c "
import json, sys, tomllib
d = sys.argv[1]
truth = json.load(open(d + '/truth.json'))
assert truth['true_effect'] == 'rate_and_state' and truth['kind'] == 'slide_hold_slide' and truth['seed'] == 3, truth
assert truth['provenance']['git_commit'], truth['provenance']
model = tomllib.load(open(d + '/model.toml', 'rb'))
told = tomllib.load(open(d + '/bundle/experiment.toml', 'rb'))['rig']
assert told['kind'] == 'slide_hold_slide', told
for key in ('mass_kg', 'stiffness_N_per_m', 'damping_N_s_per_m', 'normal_load_N'):
    assert abs(model['rig'][key] / told[key] - 1) < 1e-8, (key, model['rig'][key], told[key])
f = model['friction']
assert f['law'] == 'coulomb' and 0 < f['mu_k'] <= f['mu_s'] < 1.5, f
header = open(d + '/bundle/traces/run_0.csv').readline().strip().split(',')
assert header == ['t_s', 'x_m', 'friction_N', 'x_drive_m', 'v_drive_m_per_s'], header
" ${WORK} RESULT_VARIABLE check ERROR_VARIABLE why)
if(NOT check EQUAL 0)
  message(FATAL_ERROR "tribo gap generate: the case does not read back as written: ${why}")
endif()

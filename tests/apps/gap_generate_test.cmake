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

# A validation-set case of the rig's simulator, as `tribo gap selftest --set validation` diagnoses
# it: the set's five speeds (README, "The validation set"), its test block at the four speeds
# between them, and the withheld effect's parameters in truth.json.
file(REMOVE_RECURSE ${WORK}-validation)
execute_process(COMMAND ${TRIBO} gap generate --generator rig --effect instrument --seed 14010 --set validation --out ${WORK}-validation
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "tribo gap generate --set validation failed (${status}): ${err}")
endif()
if(NOT out MATCHES "--test ${WORK}-validation/test")
  message(FATAL_ERROR "tribo gap generate: the diagnose line does not pass the test block: ${out}")
endif()
execute_process(COMMAND ${PYTHON} -c "
import csv, json, sys
d = sys.argv[1]
speeds = lambda b: [float(r['v_m_per_s']) for r in csv.DictReader(open(d + '/' + b + '/runs.csv'))]
assert speeds('bundle') == [4.5e-3, 8e-3, 1.4e-2, 2.4e-2, 3.8e-2], speeds('bundle')
assert speeds('test') == [6e-3, 1.06e-2, 1.83e-2, 3.02e-2], speeds('test')
truth = json.load(open(d + '/truth.json'))
assert truth['set'] == 'validation' and truth['generator'] == 'rig', truth
p = truth['parameters']
g = p['instrument.gain']
assert 1.075 - 1e-12 <= max(g, 1 / g) <= 1.45 + 1e-12, p  # 1 + (0.15 ... 0.3) x strength 0.5 ... 1.5, or its inverse
assert 0.5e-3 <= p['instrument.lag_s'] <= 4.5e-3, p
# The truth under each test the diagnosis may propose (gap/discriminate.h), for --test: speeds a
# factor 3 beyond, the spring twice as stiff, twice the load, a slide-hold-slide at the middle speed.
import tomllib
rig = lambda b: tomllib.load(open(d + '/' + b + '/experiment.toml', 'rb'))['rig']
w = speeds('proposed/wider_speeds')
assert len(w) == 2 and abs(w[0] - 1.5e-3) < 1e-12 and abs(w[1] - 0.114) < 1e-12, w
assert speeds('proposed/stiffer_spring') == speeds('bundle') and speeds('proposed/heavier_load') == speeds('bundle')
assert abs(rig('proposed/stiffer_spring')['stiffness_N_per_m'] / rig('bundle')['stiffness_N_per_m'] - 2) < 1e-12
assert abs(rig('proposed/heavier_load')['normal_load_N'] / rig('bundle')['normal_load_N'] - 2) < 1e-12
assert rig('proposed/slide_hold_slide')['kind'] == 'slide_hold_slide'
v = [float(r['v_drive_m_per_s']) for r in csv.DictReader(open(d + '/proposed/slide_hold_slide/traces/run_0.csv'))]
assert v.count(0.0) > 0 and max(v) == 1.4e-2, (v.count(0.0), max(v))
" ${WORK}-validation RESULT_VARIABLE check ERROR_VARIABLE why)
if(NOT check EQUAL 0)
  message(FATAL_ERROR "tribo gap generate --set validation: ${why}")
endif()

# --speeds: a case at one's own speeds (here slower than either set's), the test block at the
# geometric means between them; decreasing speeds are refused with status 2 and nothing written.
file(REMOVE_RECURSE ${WORK}-speeds)
execute_process(COMMAND ${TRIBO} gap generate --effect rate_dependent_static --seed 304 --speeds 0.0035,0.006,0.01 --out ${WORK}-speeds
                RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "tribo gap generate --speeds failed (${status}): ${err}")
endif()
execute_process(COMMAND ${PYTHON} -c "
import csv, json, math, sys
d = sys.argv[1]
speeds = lambda b: [float(r['v_m_per_s']) for r in csv.DictReader(open(d + '/' + b + '/runs.csv'))]
assert speeds('bundle') == [0.0035, 0.006, 0.01], speeds('bundle')
t = speeds('test')
assert len(t) == 2 and abs(t[0] / math.sqrt(0.0035 * 0.006) - 1) < 1e-9 and abs(t[1] / math.sqrt(0.006 * 0.01) - 1) < 1e-9, t  # runs.csv: 10 digits
assert json.load(open(d + '/truth.json'))['speeds_m_per_s'] == [0.0035, 0.006, 0.01]
" ${WORK}-speeds RESULT_VARIABLE check ERROR_VARIABLE why)
if(NOT check EQUAL 0)
  message(FATAL_ERROR "tribo gap generate --speeds: ${why}")
endif()
file(REMOVE_RECURSE ${WORK}-speeds-bad)
execute_process(COMMAND ${TRIBO} gap generate --speeds 0.01,0.005 --out ${WORK}-speeds-bad RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "--speeds: the speeds must be positive and increasing" OR EXISTS ${WORK}-speeds-bad)
  message(FATAL_ERROR "tribo gap generate --speeds 0.01,0.005: expected status 2 naming --speeds and no output, got ${status}: ${err}")
endif()

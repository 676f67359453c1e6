# `tribo ehl`: one line contact end to end — ehl.json with the films, pressure, traction and
# convergence the issue asks for, the profiles as .npy of one length that numpy reads, a pressure
# at the dry Hertz contact's peak (3e6 N/m on the steel rollers: the film is thin against the
# deflection, tests/lubrication/ehl_line_test.cpp); and bad input exits 2, names the key and
# writes nothing.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
# Config `text` must be refused: exit status 2, a message naming `key`, and no output directory.
function(expect_refused name text key)
  file(WRITE ${WORK}/${name}.toml "${text}")
  execute_process(COMMAND ${TRIBO} ehl ${WORK}/${name}.toml --out ${WORK}/out_${name} RESULT_VARIABLE status ERROR_VARIABLE err)
  if(NOT status EQUAL 2 OR NOT err MATCHES "${key}" OR EXISTS ${WORK}/out_${name})
    message(FATAL_ERROR "tribo ehl, ${name}: expected status 2 naming ${key} and no output, got ${status}: ${err}")
  endif()
endfunction()
# `config` must run, solved into out_NAME (ARGN: more options).
function(run_ehl_config name what config)
  execute_process(COMMAND ${TRIBO} ehl ${config} --out ${WORK}/out_${name} ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "tribo ehl, ${what}, failed (${status}): ${out} ${err}")
  endif()
endfunction()
# The python `script` must pass on out_NAME (its sys.argv[1]): its assertions are what the docs say
# of ehl.json and the written fields.
function(expect_outputs name what script)
  execute_process(COMMAND ${PYTHON} -c "${script}" ${WORK}/out_${name} RESULT_VARIABLE check ERROR_VARIABLE why)
  if(NOT check EQUAL 0)
    message(FATAL_ERROR "tribo ehl, ${what}: ehl.json or the fields are not as documented: ${why}")
  endif()
endfunction()
# Config `text` must run: written to NAME.toml, solved into out_NAME (ARGN: more options).
function(run_ehl name what text)
  file(WRITE ${WORK}/${name}.toml "${text}")
  run_ehl_config(${name} "${what}" ${WORK}/${name}.toml ${ARGN})
endfunction()
set(contact "[contact]\ngeometry = \"line\"\nload_per_length_N_per_m = 3e6\nreduced_radius_m = 0.01\nreduced_modulus_Pa = 2.26e11\nmean_speed_m_per_s = 1.0\nsliding_speed_m_per_s = 0.05\n")
run_ehl(ehl "line contact" "${contact}[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2.2e-8\neyring_stress_Pa = 5e6\n")
expect_outputs(ehl "line contact" "
import json, math, sys
import numpy as np
d = sys.argv[1]
s = json.load(open(d + '/ehl.json'))
for key in ('central_film_m', 'minimum_film_m', 'max_pressure_Pa', 'friction_coefficient', 'converged', 'iterations', 'provenance'):
    assert key in s, key
assert s['converged'] and s['residual'] <= 1e-10, s['message']
p_hertz = math.sqrt(3e6 * 2.26e11 / (2 * math.pi * 0.01))  # dry Hertz line contact, sqrt(w E' / (2 pi R))
assert abs(s['hertz_pressure_Pa'] / p_hertz - 1) < 1e-12, s['hertz_pressure_Pa']
assert abs(s['max_pressure_Pa'] / p_hertz - 1) < 0.05, (s['max_pressure_Pa'], p_hertz)
assert 0 < s['minimum_film_m'] < s['central_film_m'] < 1e-6, s
assert 0 < s['friction_coefficient'] < 0.2, s['friction_coefficient']
assert s['max_film_temperature_rise_K'] == 0, s  # no conductivity given: an isothermal film
assert s['max_surface_temperature_rise_K'] is None and s['surface_peclet_number'] is None, s  # no [solids]
x, p, h = (np.load(d + '/' + s['fields'][k]) for k in ('x_m', 'pressure_Pa', 'film_m'))
assert x.shape == p.shape == h.shape == (s['inputs']['nodes'],), (x.shape, p.shape, h.shape)
assert abs(np.trapz(p, x) / 3e6 - 1) < 1e-9, np.trapz(p, x)  # the load balance, from the written profile
assert s['provenance']['config_hash'], s['provenance']
")

# A limiting shear stress τ_L = τ_L0 + Λ p (ehl_traction.h): no node shears above it, so the
# traction is at most Λ w + τ_L0 L, L the pressurised length (∫ p dx = w to the load balance, 1e-9);
# the limit is echoed and its share of nodes written (null without one); a negative coefficient is
# refused.
run_ehl(limited "line contact, limiting shear" "${contact}[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2.2e-8\neyring_stress_Pa = 5e6\nlimiting_shear_stress_Pa = 1e6\nlimiting_shear_pressure_coefficient = 0.03\n")
expect_outputs(limited "line contact, limiting shear" "
import json, sys
import numpy as np
d = sys.argv[1]
s = json.load(open(d + '/ehl.json'))
e = json.load(open(d + '/../out_ehl/ehl.json'))
assert s['inputs']['limiting_shear_pressure_coefficient'] == 0.03 and s['inputs']['limiting_shear_stress_Pa'] == 1e6, s['inputs']
assert s['inputs']['limiting_shear_temperature_per_K'] == 0, s['inputs']
assert e['limited_node_share'] is None and e['inputs']['limiting_shear_pressure_coefficient'] == 0, e
assert 0 < s['limited_node_share'] <= 1, s['limited_node_share']
x, p = np.load(d + '/x_m.npy'), np.load(d + '/pressure_Pa.npy')
pressurised = x[p > 0].max() - x[p > 0].min()
bound = 0.03 + 1e6 * pressurised / 3e6
assert s['friction_coefficient'] <= bound * (1 + 1e-9) and s['friction_coefficient'] < e['friction_coefficient'], (s['friction_coefficient'], bound, e['friction_coefficient'])
assert s['max_shear_stress_Pa'] <= 1e6 + 0.03 * s['max_pressure_Pa'], s
")
expect_refused(limited_negative "${contact}[lubricant]\nviscosity_Pa_s = 0.04\neyring_stress_Pa = 5e6\nlimiting_shear_pressure_coefficient = -0.03\n" "lubricant.limiting_shear_pressure_coefficient")
# The limit's temperature coefficient without a limit to act on is refused.
expect_refused(limited_beta_alone "${contact}[lubricant]\nviscosity_Pa_s = 0.04\neyring_stress_Pa = 5e6\nlimiting_shear_temperature_per_K = 0.01\n" "lubricant.limiting_shear_temperature_per_K")

# [solids]: the surfaces warm by the heat the film hands them (lubrication/moving_heat_source.h), so
# the film is warmer than its own heating alone makes it; the solids' constants are echoed; without
# the oil's conductivity, with a constant missing, or with a surface at rest, the config is refused.
set(heated "${contact}[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2.2e-8\neyring_stress_Pa = 5e6\nthermal_conductivity_W_per_m_K = 0.13\n")
set(steel "[solids]\nthermal_conductivity_W_per_m_K = 46.0\ndensity_kg_per_m3 = 7800.0\nspecific_heat_J_per_kg_K = 460.0\n")
run_ehl(film_heated "line contact, film heating" "${heated}")
run_ehl(solids_heated "line contact, film and surface heating" "${heated}${steel}")
expect_outputs(solids_heated "line contact, film and surface heating" "
import json, sys
s = json.load(open(sys.argv[1] + '/ehl.json'))
f = json.load(open(sys.argv[1] + '/../out_film_heated/ehl.json'))
assert s['inputs']['surfaces'] == {'thermal_conductivity_W_per_m_K': 46.0, 'density_kg_per_m3': 7800.0, 'specific_heat_J_per_kg_K': 460.0}, s['inputs']
assert f['inputs']['surfaces'] is None and f['max_surface_temperature_rise_K'] is None, f
assert 0 < s['max_surface_temperature_rise_K'] < s['max_film_temperature_rise_K'], s
assert s['max_film_temperature_rise_K'] > f['max_film_temperature_rise_K'], (s['max_film_temperature_rise_K'], f['max_film_temperature_rise_K'])
assert s['surface_peclet_number'] > 5, s['surface_peclet_number']
")
run_ehl(solids_two "line contact, a steel surface on a glass one" "${heated}${steel}[solids.second]\nthermal_conductivity_W_per_m_K = 1.0\ndensity_kg_per_m3 = 2500.0\nspecific_heat_J_per_kg_K = 840.0\n")
expect_outputs(solids_two "line contact, a steel surface on a glass one" "
import json, sys
s = json.load(open(sys.argv[1] + '/ehl.json'))
steel = json.load(open(sys.argv[1] + '/../out_solids_heated/ehl.json'))
assert s['inputs']['second_surface'] == {'thermal_conductivity_W_per_m_K': 1.0, 'density_kg_per_m3': 2500.0, 'specific_heat_J_per_kg_K': 840.0}, s['inputs']
assert steel['inputs']['second_surface'] is None, steel['inputs']
assert s['max_surface_temperature_rise_K'] > steel['max_surface_temperature_rise_K'], (s['max_surface_temperature_rise_K'], steel['max_surface_temperature_rise_K'])
")
expect_refused(solids_second_bad "${heated}${steel}[solids.second]\nthermal_conductivity_W_per_m_K = 1.0\ndensity_kg_per_m3 = 2500.0\n" "solids.second.specific_heat_J_per_kg_K")
expect_refused(solids_no_film_k "${contact}[lubricant]\nviscosity_Pa_s = 0.04\neyring_stress_Pa = 5e6\n${steel}" "solids.thermal_conductivity_W_per_m_K")
expect_refused(solids_no_density "${heated}[solids]\nthermal_conductivity_W_per_m_K = 46.0\nspecific_heat_J_per_kg_K = 460.0\n" "solids.density_kg_per_m3")
string(REPLACE "sliding_speed_m_per_s = 0.05" "sliding_speed_m_per_s = 2.0" at_rest "${heated}")
expect_refused(solids_at_rest "${at_rest}${steel}" "solids")

# No Eyring stress: the lubricant's τ0 has no default; a point contact takes load_N, not a load per length.
expect_refused(no_tau "${contact}[lubricant]\nviscosity_Pa_s = 0.04\n" "lubricant.eyring_stress_Pa")
string(REPLACE "geometry = \"line\"" "geometry = \"point\"" point "${contact}")
expect_refused(point "${point}[lubricant]\neyring_stress_Pa = 5e6\n" "contact.load_per_length_N_per_m")

# A ball on a disc (geometry = "point"): ehl.json with the films, the Hertz circle, Hamrock and
# Dowson's fits and the traction; the fields as (nx, ny) arrays whose integral is the load.
set(ball "[contact]\ngeometry = \"point\"\nload_N = 20\nreduced_radius_m = 9.525e-3\nreduced_modulus_Pa = 2.308e11\nmean_speed_m_per_s = 0.5\nslide_to_roll_ratio = 0.05\n[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2e-8\neyring_stress_Pa = 5e6\n")
run_ehl(ball "point contact" "${ball}[solver]\nnodes_x = 31\nnodes_y = 25\n")
expect_outputs(ball "point contact" "
import json, math, sys
import numpy as np
d = sys.argv[1]
s = json.load(open(d + '/ehl.json'))
assert s['geometry'] == 'point' and s['converged'], s['message']
a = (3 * 20 * 9.525e-3 / (2 * 2.308e11)) ** (1 / 3)  # dry Hertz circle, (3 W R / (2 E'))^(1/3)
assert abs(s['hertz_radius_m'] / a - 1) < 1e-12 and abs(s['hertz_pressure_Pa'] / (3 * 20 / (2 * math.pi * a * a)) - 1) < 1e-12, s
assert 0 < s['minimum_film_m'] < s['central_film_m'] < 1e-6 and s['fits']['hamrock_dowson_central_film_m'] > 0, s
assert 0 < s['friction_coefficient'] < 0.2 and abs(s['traction_N'] / 20 - s['friction_coefficient']) < 1e-12, s
x, y, p, h = (np.load(d + '/' + s['fields'][k]) for k in ('x_m', 'y_m', 'pressure_Pa', 'film_m'))
assert x.shape == (31,) and y.shape == (25,) and p.shape == h.shape == (31, 25), (x.shape, y.shape, p.shape)
load = p.sum() * (x[1] - x[0]) * (y[1] - y[0])
assert abs(load / 20 - 1) < 1e-9, load  # the load balance, from the written field
")
# The rough ball: the mixed regime over the Hertz circle (lubrication/mixed_point.h), its load split
# and friction as the line's.
run_ehl(ball_rough "rough ball" "${ball}[roughness]\nsummit_density_per_m2 = 4e10\nsummit_radius_m = 1e-5\nsummit_std_m = 1e-7\nsummit_height_m = 1e-7\nboundary_friction_coefficient = 0.1\n[solver]\nnodes_x = 31\nnodes_y = 25\n" --summary-only)
expect_outputs(ball_rough "rough ball" "
import json, sys
s = json.load(open(sys.argv[1] + '/ehl.json'))
m = s['mixed']
assert s['geometry'] == 'point' and s['converged'] and m['load_balance_residual'] <= 1e-6, m['message']
assert 0.0 < m['film_share'] <= 1.0, m['film_share']
assert abs(m['film_load_N'] + m['asperity_load_N'] - 20) <= 1e-6 * 20, m
mu = (m['boundary_friction_N'] + m['film_friction_N']) / 20
assert abs(s['friction_coefficient'] - mu) <= 1e-12, (s['friction_coefficient'], mu)
assert s['inputs']['roughness']['summit_std_m'] == 1e-7, s['inputs']
")
expect_refused(ball_nodes "${ball}[solver]\nnodes = 41\n" "solver.nodes")

# With [roughness]: the mixed regime by load sharing. ehl.json splits the load between film and
# summits and its friction coefficient is the boundary friction on the summits' share plus the
# film's traction, over the whole load; the sliding speed may be given as a slide-to-roll ratio.
set(rough_contact "[contact]\ngeometry = \"line\"\nload_per_length_N_per_m = 1e5\nreduced_radius_m = 0.01\nreduced_modulus_Pa = 2.26e11\nmean_speed_m_per_s = 0.3\nslide_to_roll_ratio = 0.05\n")
set(rough_rest "[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2.2e-8\neyring_stress_Pa = 5e6\n[roughness]\nsummit_density_per_m2 = 4e10\nsummit_radius_m = 1e-5\nsummit_std_m = 1e-7\nsummit_height_m = 1e-7\nboundary_friction_coefficient = 0.1\n[solver]\nnodes = 151\n")
run_ehl(rough "rough contact" "${rough_contact}${rough_rest}" --summary-only)
expect_outputs(rough "rough contact" "
import json, sys
s = json.load(open(sys.argv[1] + '/ehl.json'))
m = s['mixed']
assert s['converged'] and m['converged'] and m['load_balance_residual'] <= 1e-6, m['message']
assert 0.2 < m['film_share'] < 0.95, m['film_share']  # mixed at 0.3 m/s (tests/lubrication/mixed_line_test.cpp)
assert abs(m['film_load_per_length_N_per_m'] + m['asperity_load_per_length_N_per_m'] - 1e5) <= 1e-6 * 1e5, m
assert abs(m['boundary_friction_N_per_m'] - 0.1 * m['asperity_load_per_length_N_per_m']) <= 1e-9 * m['boundary_friction_N_per_m'], m
mu = (m['boundary_friction_N_per_m'] + m['film_friction_N_per_m']) / 1e5
assert abs(s['friction_coefficient'] - mu) <= 1e-12, (s['friction_coefficient'], mu)
assert s['inputs']['sliding_speed_m_per_s'] == 0.05 * 0.3, s['inputs']
assert s['inputs']['roughness']['summit_height_m'] == 1e-7, s['inputs']
")
expect_refused(both_sliding "${rough_contact}sliding_speed_m_per_s = 0.01\n${rough_rest}" "contact.slide_to_roll_ratio")
string(REPLACE "summit_height_m = 1e-7\n" "" no_height "${rough_rest}")
expect_refused(no_height "${rough_contact}${no_height}" "roughness.summit_height_m")

# With [profile]: a wavy stationary surface solved node by node (examples/ehl-wavy-pin.toml). Crawling,
# every node of the Hertz strip is in contact, so the friction coefficient is the boundary friction;
# the contact block splits the friction; the profile is the line's and needs a boundary friction.
set(wavy_contact "[contact]\ngeometry = \"line\"\nload_per_length_N_per_m = 3e5\nreduced_radius_m = 0.01\nreduced_modulus_Pa = 2.26e11\nmean_speed_m_per_s = 1e-5\nslide_to_roll_ratio = 2.0\n")
set(wavy_rest "[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2.2e-8\neyring_stress_Pa = 5e6\n[profile]\namplitude_m = 2.7e-8\nwavelength_m = 4.6e-5\nboundary_friction_coefficient = 0.1\n[solver]\nnodes = 401\n")
run_ehl(wavy "wavy pin" "${wavy_contact}${wavy_rest}" --summary-only)
expect_outputs(wavy "wavy pin" "
import json, sys
s = json.load(open(sys.argv[1] + '/ehl.json'))
c = s['contact']
assert s['converged'], s['message']
assert c['contact_load_share'] > 0.999 and c['contact_nodes'] > 100, c
assert abs(c['contact_load_per_length_N_per_m'] - c['contact_load_share'] * 3e5) <= 1e-9 * 3e5, c
assert abs(c['boundary_friction_N_per_m'] - 0.1 * c['contact_load_per_length_N_per_m']) <= 1e-9 * 3e4, c
mu = (c['boundary_friction_N_per_m'] + c['film_friction_N_per_m']) / 3e5
assert abs(s['friction_coefficient'] - mu) <= 1e-12 and abs(mu - 0.1) < 1e-3, (s['friction_coefficient'], mu)
assert s['minimum_film_m'] < s['inputs']['profile']['contact_film_m'] == 5e-9, s
")
string(REPLACE "boundary_friction_coefficient = 0.1\n" "" no_fc "${wavy_rest}")
expect_refused(wavy_no_fc "${wavy_contact}${no_fc}" "profile.boundary_friction_coefficient")
expect_refused(wavy_and_rough "${rough_contact}${rough_rest}[profile]\namplitude_m = 1e-8\nwavelength_m = 1e-5\nboundary_friction_coefficient = 0.1\n" "profile")
string(REPLACE "wavelength_m = 4.6e-5" "wavelength_m = 4e-6" short_wave "${wavy_rest}")
expect_refused(wavy_short "${wavy_contact}${short_wave}" "profile.wavelength_m")

# [profile] file: examples/ehl-measured-pin.toml, the stylus trace of tests/contact/data/topography
# as the pin's profile. At 1 mm/s the film has lifted it (every node open, the film's Eyring traction
# alone); the trace's Rq over the domain as measured and as filtered; the trace among provenance's
# inputs with its hash.
run_ehl_config(measured "measured pin" ${EXAMPLES}/ehl-measured-pin.toml --summary-only)
expect_outputs(measured "measured pin" "
import json, sys
s = json.load(open(sys.argv[1] + '/ehl.json'))
p, c = s['inputs']['profile'], s['contact']
assert s['converged'], s['message']
assert c['contact_nodes'] == 0 and c['boundary_friction_N_per_m'] == 0.0, c
assert 0.03 < s['friction_coefficient'] < 0.08, s['friction_coefficient']
assert p['file'].endswith('dektak-1.csv') and abs(p['sample_spacing_m'] - 1.5e-3 / 9600) < 1e-15, p
assert 0.0 < p['filtered_rq_m'] <= p['rq_m'] < 1e-6, p
inputs = s['provenance']['inputs']
assert len(inputs) == 2 and inputs[1]['path'].endswith('dektak-1.csv') and len(inputs[1]['hash']) == 16, inputs
")

# [profile] on a point contact: examples/ehl-ridged-ball.toml, the ball held still over a sliding disc
# with ridges across the track. Crawling, the Hertz circle is in contact, so the friction coefficient
# is the boundary friction; the contact block in N; the margin among the inputs; its domain fitted to
# the film (1.5 Hamrock & Dowson's flooded inlet m*, the film theirs plus the layers). Refused: a
# fitted domain with extents, an unknown domain.
run_ehl_config(ridged "ridged ball" ${EXAMPLES}/ehl-ridged-ball.toml --summary-only)
expect_outputs(ridged "ridged ball" "
import json, sys
s = json.load(open(sys.argv[1] + '/ehl.json'))
c, p = s['contact'], s['inputs']['profile']
assert s['converged'] and s['geometry'] == 'point', s['message']
assert c['contact_load_share'] > 0.99 and c['contact_nodes'] > 500, c
assert abs(c['contact_load_N'] - c['contact_load_share'] * 20.0) <= 1e-9 * 20.0, c
assert abs(c['boundary_friction_N'] - 0.1 * c['contact_load_N']) <= 1e-9 * 2.0, c
mu = (c['boundary_friction_N'] + c['film_friction_N']) / 20.0
assert abs(s['friction_coefficient'] - mu) <= 1e-12 and abs(mu - 0.1) < 1e-3, (s['friction_coefficient'], mu)
assert abs(s['traction_N'] - mu * 20.0) <= 1e-9, s['traction_N']
assert p['contact_film_m'] == 5e-9 and p['contact_margin_m'] == 1e-9 and p['wavelength_m'] == 2.7e-5, p
i = s['inputs']
R, a = i['reduced_radius_m'], s['hertz_radius_m']
m = 1.0 + 3.06 * ((R / a) ** 2 * (s['fits']['hamrock_dowson_central_film_m'] + p['contact_film_m']) / R) ** 0.58
inlet = min(max(1.5 * m, 1.5), 3.5)
assert i['domain'] == 'fitted' and abs(i['inlet_over_radius'] + inlet) <= 1e-9 * inlet, (i, inlet)
assert i['outlet_over_radius'] == 1.5 and i['side_over_radius'] == min(inlet, 2.5), i
")
expect_refused(fitted_extents "${ball}[solver]\ndomain = \"fitted\"\ninlet_over_radius = -2\n" "solver.inlet_over_radius")
expect_refused(domain_unknown "${ball}[solver]\ndomain = \"auto\"\n" "solver.domain")
expect_refused(ridged_short "${ball}[profile]\namplitude_m = 1e-8\nwavelength_m = 1e-6\nboundary_friction_coefficient = 0.1\n" "profile.wavelength_m")
expect_refused(ridged_margin "${ball}[profile]\namplitude_m = 1e-8\nwavelength_m = 1e-4\ncontact_margin_m = -1e-9\nboundary_friction_coefficient = 0.1\n" "profile.contact_margin_m")

# [surface] on a point contact: a generated height map (the reader of `tribo contact`), levelled,
# filtered at 8 node spacings and placed at the Hertz centre, with no ridges. Crawling on 65² nodes
# (the full grid: a map has no symmetry), the Hertz circle is in contact; the map's Rq over the domain
# as generated and as filtered, the cut-off and the seed among the inputs. Refused: a map on a line, a
# map without [profile], a map coarser than the nodes, a cut-off below 8 node spacings, a map smaller
# than the domain.
set(map_ball "[contact]\ngeometry = \"point\"\nload_N = 20\nreduced_radius_m = 9.525e-3\nreduced_modulus_Pa = 2.308e11\nmean_speed_m_per_s = 1e-5\nslide_to_roll_ratio = 2.0\n[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2e-8\neyring_stress_Pa = 5e6\n[solver]\nnodes_x = 65\nnodes_y = 65\n")
set(map_profile "[profile]\nboundary_friction_coefficient = 0.1\n")
set(map_surface "[surface]\nkind = \"gaussian\"\ncorrelation_length_m = 4e-5\nrms_height_m = 2e-8\nseed = 3\nsize_m = 8e-4\ngrid = 128\n")
run_ehl(map "rough ball map" "${map_ball}${map_profile}${map_surface}" --summary-only)
expect_outputs(map "rough ball map" "
import json, sys
s = json.load(open(sys.argv[1] + '/ehl.json'))
c, m = s['contact'], s['inputs']['surface']
assert s['converged'] and s['geometry'] == 'point', s['message']
assert c['contact_load_share'] > 0.99, c
assert abs(s['friction_coefficient'] - 0.1) < 1e-3, s['friction_coefficient']
a = s['hertz_radius_m']
assert abs(m['cutoff_m'] - 8 * 5 * a / 64) <= 1e-9 * m['cutoff_m'], (m, a)
assert 0.0 < m['filtered_rq_m'] <= m['rq_m'] < 4e-8 and m['seed'] == 3 and m['sample_spacing_x_m'] == 8e-4 / 128, m
assert s['inputs']['profile']['ridges'] is None, s['inputs']['profile']
")
expect_refused(map_line "${wavy_contact}${wavy_rest}${map_surface}" "surface")
expect_refused(map_no_profile "${map_ball}${map_surface}" "profile")
string(REPLACE "grid = 128" "grid = 64" coarse_map "${map_surface}")
expect_refused(map_coarse "${map_ball}${map_profile}${coarse_map}" "surface")
expect_refused(map_cutoff "${map_ball}${map_profile}${map_surface}cutoff_m = 1e-5\n" "surface.cutoff_m")
string(REPLACE "size_m = 8e-4" "size_m = 4e-4" small_map "${map_surface}")
string(REPLACE "grid = 128" "grid = 64" small_map "${small_map}")
expect_refused(map_small "${map_ball}${map_profile}${small_map}" "surface.centre_x_m")

# [material] hardness_Pa on a crawling ball (a flat profile, 31² nodes): the pressure capped at the
# hardness (0.8 of Hertz's 0.828 GPa), the centre yielded — the plastic nodes and their share of the
# load in the contact block (the ring reference is tests/lubrication/ehl_point_mixed_test.cpp) — and
# the hardness among the profile's inputs. Refused: a hardness without [profile], one not positive.
string(REPLACE "mean_speed_m_per_s = 0.5" "mean_speed_m_per_s = 1e-6" crawling_ball "${ball}")
set(flat_profile "[profile]\namplitude_m = 0.0\nwavelength_m = 1e-3\nboundary_friction_coefficient = 0.1\n[solver]\nnodes_x = 31\nnodes_y = 31\n")
run_ehl(yielding "yielding ball" "${crawling_ball}${flat_profile}[material]\nhardness_Pa = 6.656e8\n")
expect_outputs(yielding "yielding ball" "
import json, sys
import numpy as np
s = json.load(open(sys.argv[1] + '/ehl.json'))
c, p = s['contact'], s['inputs']['profile']
assert s['converged'], s['message']
assert p['hardness_Pa'] == 6.656e8 and s['max_pressure_Pa'] == 6.656e8, (p, s['max_pressure_Pa'])
assert abs(s['hertz_pressure_Pa'] / 8.282e8 - 1) < 1e-3, s['hertz_pressure_Pa']
assert c['plastic_nodes'] > 40 and 0.6 < c['plastic_load_share'] < 0.7 and c['contact_load_share'] > 0.98, c
# The plastic flow: positive only where the pressure is at the hardness, 0 wherever it is below,
# on every yielded node but those exactly at the cap's edge (q = P_cap: flow 0).
pr, flow = (np.load(sys.argv[1] + '/' + s['fields'][k]) for k in ('pressure_Pa', 'plastic_flow_m'))
assert flow.shape == pr.shape == (31, 31), (flow.shape, pr.shape)
assert np.all(flow[pr < 6.656e8] == 0) and np.all(pr[flow > 0] == 6.656e8), (flow.max(), pr.max())
assert c['plastic_nodes'] - 4 <= np.count_nonzero(flow) <= c['plastic_nodes'], (np.count_nonzero(flow), c['plastic_nodes'])
")
expect_refused(hardness_alone "${ball}[material]\nhardness_Pa = 6.656e8\n" "material")
expect_refused(hardness_negative "${crawling_ball}${flat_profile}[material]\nhardness_Pa = -1\n" "material.hardness_Pa")

# A thick line film (u_m = 5 m/s on R = 0.02 m rollers, h_c ≈ 1.2 µm) with [solver] domain = "fitted":
# the inlet moved out past the default −4.5 b at the given node spacing (lubrication::fit_inlet_to_film)
# until the central film settled, echoed among the inputs with the fit's account. Refused: a fitted
# inlet with an inlet given, or with a [profile] (whose samples are placed on the given domain).
set(thick "[contact]\ngeometry = \"line\"\nload_per_length_N_per_m = 2e5\nreduced_radius_m = 0.02\nreduced_modulus_Pa = 2.27e11\nmean_speed_m_per_s = 5.0\n[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2e-8\neyring_stress_Pa = 5e6\n")
run_ehl(line_fitted "fitted line inlet" "${thick}[solver]\nnodes = 101\ndomain = \"fitted\"\n" --summary-only)
expect_outputs(line_fitted "fitted line inlet" "
import json, sys
s = json.load(open(sys.argv[1] + '/ehl.json'))
i, f = s['inputs'], s['inlet_fit']
assert s['converged'] and f['settled'] and f['solves'] >= 3, (s['message'], f)
assert i['domain'] == 'fitted' and i['inlet_over_half_width'] < -4.5 and i['outlet_over_half_width'] == 1.5, i
spacing = (i['outlet_over_half_width'] - i['inlet_over_half_width']) / (i['nodes'] - 1)
assert abs(spacing - 0.06) < 1e-3, (spacing, i)  # the given spacing, 6/100
assert 1.0e-6 < s['central_film_m'] < 1.4e-6, s['central_film_m']
")
expect_refused(line_fitted_inlet "${thick}[solver]\ndomain = \"fitted\"\ninlet_over_half_width = -6\n" "solver.inlet_over_half_width")
expect_refused(line_fitted_rough "${thick}[solver]\ndomain = \"fitted\"\n[profile]\namplitude_m = 1e-8\nwavelength_m = 1e-4\nboundary_friction_coefficient = 0.1\n" "solver.domain")

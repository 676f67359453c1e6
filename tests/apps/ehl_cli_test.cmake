# `tribo ehl`: one line contact end to end — ehl.json with the films, pressure, traction and
# convergence the issue asks for, the profiles as .npy of one length that numpy reads, a pressure
# at the dry Hertz contact's peak (3e6 N/m on the steel rollers: the film is thin against the
# deflection, tests/lubrication/ehl_line_test.cpp); and bad input exits 2, names the key and
# writes nothing.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(contact "[contact]\ngeometry = \"line\"\nload_per_length_N_per_m = 3e6\nreduced_radius_m = 0.01\nreduced_modulus_Pa = 2.26e11\nmean_speed_m_per_s = 1.0\nsliding_speed_m_per_s = 0.05\n")
file(WRITE ${WORK}/ehl.toml "${contact}[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2.2e-8\neyring_stress_Pa = 5e6\n")
execute_process(COMMAND ${TRIBO} ehl ${WORK}/ehl.toml --out ${WORK}/out RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "tribo ehl failed (${status}): ${out} ${err}")
endif()
execute_process(COMMAND ${PYTHON} -c "
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
x, p, h = (np.load(d + '/' + s['fields'][k]) for k in ('x_m', 'pressure_Pa', 'film_m'))
assert x.shape == p.shape == h.shape == (s['inputs']['nodes'],), (x.shape, p.shape, h.shape)
assert abs(np.trapz(p, x) / 3e6 - 1) < 1e-9, np.trapz(p, x)  # the load balance, from the written profile
assert s['provenance']['config_hash'], s['provenance']
" ${WORK}/out RESULT_VARIABLE check ERROR_VARIABLE why)
if(NOT check EQUAL 0)
  message(FATAL_ERROR "tribo ehl: ehl.json or the profiles are not as documented: ${why}")
endif()

# No Eyring stress: the lubricant's τ0 has no default; point contacts are refused until solved.
file(WRITE ${WORK}/no_tau.toml "${contact}[lubricant]\nviscosity_Pa_s = 0.04\n")
execute_process(COMMAND ${TRIBO} ehl ${WORK}/no_tau.toml --out ${WORK}/out_no_tau RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "lubricant.eyring_stress_Pa" OR EXISTS ${WORK}/out_no_tau)
  message(FATAL_ERROR "tribo ehl without eyring_stress_Pa: expected status 2 naming the key and no output, got ${status}: ${err}")
endif()
string(REPLACE "geometry = \"line\"" "geometry = \"point\"" point "${contact}")
file(WRITE ${WORK}/point.toml "${point}[lubricant]\neyring_stress_Pa = 5e6\n")
execute_process(COMMAND ${TRIBO} ehl ${WORK}/point.toml --out ${WORK}/out_point RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "contact.geometry" OR EXISTS ${WORK}/out_point)
  message(FATAL_ERROR "tribo ehl, point contact: expected status 2 naming contact.geometry and no output, got ${status}: ${err}")
endif()

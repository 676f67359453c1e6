# The homogenise → rig chain as one sweep point: a tiny homogenisation (32² patch, one realisation,
# a few speeds) per Hurst exponent, then the rig with that point's own law.json; outputs from both
# steps' JSON files. Inputs: TRIBO, WORK.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/tiny_homogenise.cmake)
write_tiny_homogenise_config(${WORK}/hom.toml 1 5)
# The rig config's own table path is a placeholder: the chain points it at the point's law.json.
file(WRITE ${WORK}/rig.toml "[rig]\ndrive_speed_m_per_s = 1e-2\n[friction]\nlaw = \"homogenised\"\ntable = \"nowhere/law.json\"\n[run]\nduration_s = 2.0\n")
file(WRITE ${WORK}/spec.toml "[base]\ncommand = \"homogenise+rig\"\nconfig = \"hom.toml\"\nrig_config = \"rig.toml\"\n"
  "[[axis]]\nkey = \"homogenise:surface.hurst\"\nvalues = [0.6, 1.0]\n"
  "[[axis]]\nkey = \"rig:rig.drive_speed_m_per_s\"\nvalues = [1e-2]\n"
  "[sweep]\njobs = 2\n"
  "[outputs]\ncolumns = [\"law.json:junction.mu_s_max\", \"homogenise/law.json:stribeck.2.mu\", \"summary.json:regime\", "
  "\"rig/summary.json:mean_friction_N\"]\n")

execute_process(COMMAND ${TRIBO} sweep ${WORK}/spec.toml --out ${WORK}/out RESULT_VARIABLE status ERROR_VARIABLE err
                TIMEOUT 600)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "chain sweep failed (${status}): ${err}")
endif()
file(STRINGS ${WORK}/out/results.csv lines)
list(FILTER lines EXCLUDE REGEX "^#")
list(GET lines 0 head)
if(NOT head STREQUAL "point_id,homogenise:surface.hurst,rig:rig.drive_speed_m_per_s,status,error,wall_s,mu_s_max,mu_2,regime,mean_friction_N")
  message(FATAL_ERROR "unexpected header: ${head}")
endif()
list(FILTER lines INCLUDE REGEX "^[01],[^,]*,[^,]*,ok,,[0-9.e-]+,0\\.[0-9]+,0\\.[0-9]+,[a-z_]+,[0-9.e+-]+$")
list(LENGTH lines ok)
if(NOT ok EQUAL 2)
  file(READ ${WORK}/out/results.csv all)
  message(FATAL_ERROR "expected 2 ok rows with values from both steps:\n${all}")
endif()
# Each rig step read its own point's law: the two surfaces' laws differ, so do the rig's forces.
list(GET lines 0 row0)
list(GET lines 1 row1)
string(REGEX REPLACE ".*," "" force0 "${row0}")
string(REGEX REPLACE ".*," "" force1 "${row1}")
if(force0 STREQUAL force1)
  message(FATAL_ERROR "both points' rigs gave the mean friction ${force0} N: not their own laws")
endif()
file(READ ${WORK}/out/points/00001/rig/config.toml rig_config)
if(NOT rig_config MATCHES "table = '../homogenise/law.json'" AND NOT rig_config MATCHES "table = \"../homogenise/law.json\"")
  message(FATAL_ERROR "point 1's rig config does not read its own law: ${rig_config}")
endif()
file(READ ${WORK}/out/points/00001/homogenise/config.toml hom_config)
if(NOT hom_config MATCHES "hurst = 1")
  message(FATAL_ERROR "point 1's homogenise config lacks its Hurst exponent: ${hom_config}")
endif()

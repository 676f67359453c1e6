# `cmake --install build [--prefix DIR]`: the libraries with their headers and an exported package
# (find_package(tribo) → tribo::contact, ...), the `tribo` program, its plotting script and the
# examples. Layout under the prefix:
#   lib/libtribo_*.a, lib/cmake/tribo/{triboConfig,triboConfigVersion,triboTargets*}.cmake
#   include/tribo/{numerics,contact,lubrication,rig,homogenise,gap}/...h
#   bin/tribo, share/tribo/tribo_plots.py, share/tribo/examples/
# The program finds the plotting script and examples relative to itself (apps/output.h
# shipped_file), so the installed tree can be moved.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(TRIBO_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/tribo)
set(TRIBO_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/tribo)

# tribo_gap_independent is exported because tribo_gap links it (static libraries carry their
# dependencies). Listed by name rather than from tribo_add_library so that a library made for the
# tree's own use (tests, fuzzing) is not exported by accident.
install(TARGETS tribo_numerics tribo_contact tribo_lubrication tribo_rig tribo_homogenise tribo_gap_independent tribo_gap
        EXPORT triboTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# Not installed: numerics/mpi.h, the MPI include guard of this tree's own sources (no installed
# header includes it, and tribo::numerics does not carry MPI's include path).
foreach(folder numerics contact lubrication rig homogenise gap)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/ DESTINATION ${TRIBO_INSTALL_INCLUDEDIR}/${folder}
          FILES_MATCHING PATTERN "*.h" REGEX "/numerics/mpi\\.h$" EXCLUDE)
endforeach()
install(EXPORT triboTargets NAMESPACE tribo:: DESTINATION ${TRIBO_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/triboConfig.cmake.in ${PROJECT_BINARY_DIR}/triboConfig.cmake
                              INSTALL_DESTINATION ${TRIBO_INSTALL_CMAKEDIR}
                              PATH_VARS TRIBO_INSTALL_INCLUDEDIR)
# Before 1.0 a minor version may change the API: only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/triboConfigVersion.cmake VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/triboConfig.cmake ${PROJECT_BINARY_DIR}/triboConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/TriboSystemLibraries.cmake
        DESTINATION ${TRIBO_INSTALL_CMAKEDIR})

install(TARGETS tribo RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/tools/tribo_plots.py DESTINATION ${CMAKE_INSTALL_DATADIR}/tribo)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/tribo/examples)

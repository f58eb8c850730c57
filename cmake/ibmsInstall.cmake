# Installed CMake package: `cmake --install BUILD --prefix P` installs the module
# libraries, the public headers (P/include/ibms/<module>/*.hpp), the `ibms` command and
# P/lib/cmake/ibms/{ibmsConfig,ibmsConfigVersion,ibmsTargets}.cmake, so that another project does
#   find_package(ibms REQUIRED)
#   target_link_libraries(app PRIVATE ibms::ibms)   # or one module: ibms::fluid, ibms::ibm, ...
# Test: package_consumer_builds_and_runs (verification/package/).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(IBMS_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/ibms)
set(IBMS_EXPORTED_TARGETS ibms_lib)
foreach(module ${IBMS_MODULES})
  set_target_properties(ibms_${module} PROPERTIES EXPORT_NAME ${module})  # ibms::core, ibms::fluid, ...
  list(APPEND IBMS_EXPORTED_TARGETS ibms_${module})
endforeach()
set_target_properties(ibms_lib PROPERTIES EXPORT_NAME ibms)               # ibms::ibms: all modules
# A sanitizer build (IBMS_SANITIZE, IBMS_FUZZ) installs instrumented static libraries: a program
# linking them needs the sanitizer runtimes, so every module carries the link flags as a usage
# requirement (a consumer links with -fsanitize=address,undefined; its own code stays uninstrumented).
if(IBMS_SANITIZE_LINK_OPTIONS)
  foreach(module ${IBMS_MODULES})
    target_link_options(ibms_${module} INTERFACE ${IBMS_SANITIZE_LINK_OPTIONS})
  endforeach()
endif()

install(TARGETS ${IBMS_EXPORTED_TARGETS} EXPORT ibmsTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ibms)
install(TARGETS ibms RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Headers keep their module folder, as in the source tree: #include "fluid/spectral_solver.hpp".
foreach(module ${IBMS_MODULES})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/solver/${module}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ibms/${module}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(EXPORT ibmsTargets NAMESPACE ibms:: DESTINATION ${IBMS_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ibmsConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/cmake/ibmsConfig.cmake
                              INSTALL_DESTINATION ${IBMS_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/ibmsConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/ibmsConfig.cmake ${CMAKE_BINARY_DIR}/cmake/ibmsConfigVersion.cmake
        DESTINATION ${IBMS_INSTALL_CMAKEDIR})
# The validation cases' scenes and reference data, for `ibms compare` of an installed ibms
# (it looks in <prefix>/share/ibms/validation when the source tree is not there).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/validation/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ibms/validation
        FILES_MATCHING PATTERN "*.csv" PATTERN "*.toml" PATTERN "*.md")

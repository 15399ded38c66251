# SPDX-License-Identifier: GPL-3.0-or-later
# Install and export lepp as a CMake package: find_package(lepp) gives
# lepp::core (data model, formats, validation), lepp::version (lepp/version.h), lepp::certify (the exact
# certifier), lepp::certify_report (its JSON, SVG and HTML reports), lepp::render (SVG drawings), lepp::html (HTML pages),
# lepp::gen (RapidCheck generators, when RapidCheck was found),
# lepp::reference and lepp::impl (the two engines), lepp::engines (every engine by name, lepp/engines/registry.h),
# lepp::audit (`lepp audit` as a library: the engine interface, the rows; with RapidCheck) and lepp::audit_engines
# (lepp's engines and the command adapter as audit engines; with lepp::audit). examples/outside_project uses it;
# scripts/ci.d/20-example.sh builds that against a temporary install prefix.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set_target_properties(lepp_core PROPERTIES EXPORT_NAME core)
set_target_properties(lepp_reference PROPERTIES EXPORT_NAME reference)
set_target_properties(lepp_impl PROPERTIES EXPORT_NAME impl)
set(LEPP_EXPORTED_TARGETS lepp_core lepp_version lepp_certify lepp_certify_report lepp_render lepp_html lepp_reference lepp_impl lepp_engines)
set(LEPP_EXPORT_GEN OFF)
if(TARGET lepp_gen)
  list(APPEND LEPP_EXPORTED_TARGETS lepp_gen)
  set(LEPP_EXPORT_GEN ON)
endif()
if(TARGET lepp_audit)
  list(APPEND LEPP_EXPORTED_TARGETS lepp_audit lepp_audit_engines)
endif()

install(TARGETS ${LEPP_EXPORTED_TARGETS} EXPORT leppTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY
    ${PROJECT_SOURCE_DIR}/core/include/lepp
    ${PROJECT_SOURCE_DIR}/properties/certify/include/lepp
    ${PROJECT_SOURCE_DIR}/properties/certify/report/include/lepp
    ${PROJECT_SOURCE_DIR}/render/include/lepp
    ${PROJECT_SOURCE_DIR}/render/html/include/lepp
    ${PROJECT_SOURCE_DIR}/reference/include/lepp
    ${PROJECT_SOURCE_DIR}/impl/include/lepp
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The registry always; the audit adapters with lepp::audit; never the peers (lepp_peer_engines: not packaged).
set(_lepp_engine_headers_left_out PATTERN peer_engines.h EXCLUDE PATTERN audited_engines.h EXCLUDE
  PATTERN audit_setup.h EXCLUDE)
if(NOT TARGET lepp_audit)
  list(APPEND _lepp_engine_headers_left_out PATTERN builtin_engines.h EXCLUDE PATTERN command_engine.h EXCLUDE)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engines/include/lepp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  ${_lepp_engine_headers_left_out})
install(FILES ${LEPP_GENERATED_INCLUDE_DIR}/lepp/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lepp)
if(LEPP_EXPORT_GEN)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/properties/gen/include/lepp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
if(TARGET lepp_audit)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/audit/include/lepp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()

set(LEPP_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/lepp)
install(EXPORT leppTargets NAMESPACE lepp:: DESTINATION ${LEPP_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/leppConfig.cmake.in
  ${PROJECT_BINARY_DIR}/leppConfig.cmake INSTALL_DESTINATION ${LEPP_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/leppConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/leppConfig.cmake ${PROJECT_BINARY_DIR}/leppConfigVersion.cmake DESTINATION ${LEPP_CMAKE_DIR})

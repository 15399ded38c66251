# SPDX-License-Identifier: GPL-3.0-or-later
# `cpack -G DEB` (run in the build directory) makes the Debian packages from the install rules:
#   lepp      the command (component `runtime`); its shared-library dependencies (libc6, libstdc++6,
#             libgmp10, libmpfr6, libfmt9, ...) are read from the binary by dpkg-shlibdeps.
#   lepp-dev  the static libraries, headers and CMake package (component `dev`, the default
#             component of every install rule without one). The libraries are static and their
#             CMake package calls find_dependency(CGAL, fmt, rapidcheck), so a consumer needs the
#             -dev packages below to build, and nothing of lepp's at run time.
#   python3-lepp  the Python package (component `python`, python/CMakeLists.txt) in Debian's
#             /usr/lib/python3/dist-packages; its extension's shared libraries read by
#             dpkg-shlibdeps, plus the interpreter it was built for and NumPy.
# docs/DEPENDENCIES.md explains each dependency; scripts/ci.d/40-package.sh builds, installs and uses
# all three.
set(CPACK_PACKAGE_NAME lepp)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "lepp developers")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_STRIP_FILES ON)  # strips the command only: CMake never strips static libraries
set(CPACK_GENERATOR DEB)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)
if(LEPP_PYTHON_BUILT)
  list(APPEND CPACK_COMPONENTS_ALL python)
endif()
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # lepp_0.2.0_amd64.deb, lepp-dev_0.2.0_amd64.deb
set(LEPP_PACKAGE_MAINTAINER "lepp developers <lepp@localhost>" CACHE STRING "Maintainer field of the Debian packages")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${LEPP_PACKAGE_MAINTAINER}")

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME lepp)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
# Each description: its first line is the package synopsis (no CPACK_PACKAGE_DESCRIPTION_SUMMARY,
# which CPack would put before both).
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
"Lepp-centroid 2D quality triangulation with an exact certifier
lepp refines a planar straight-line graph (Triangle's .poly format) into a
constrained Delaunay triangulation with no angle below a chosen bound, by the
Lepp-centroid method (or Lepp-midpoint), with a fast engine and an exact
reference engine on CGAL. `lepp certify` checks any mesher's Triangle-format
output exactly. `lepp paper` needs a source checkout (Triangle, matplotlib).")

set(CPACK_DEBIAN_DEV_PACKAGE_NAME lepp-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(_lepp_dev_depends "libcgal-dev (>= 5.5), libgmp-dev, libmpfr-dev, libboost-dev, libfmt-dev, nlohmann-json3-dev")
# One -dev package per find_dependency() in cmake/leppConfig.cmake.in (40-package.sh checks it).
if(LEPP_EXPORT_GEN)  # lepp::gen (RapidCheck generators) is in the package
  string(APPEND _lepp_dev_depends ", librapidcheck-dev")
endif()
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "${_lepp_dev_depends}")
set(CPACK_DEBIAN_DEV_PACKAGE_RECOMMENDS "cmake (>= 3.20), g++")
set(CPACK_COMPONENT_DEV_DESCRIPTION
"lepp's libraries: exact mesh certifier, engines, PSLG generators
Static libraries, headers and the CMake package (find_package(lepp)) of lepp:
lepp::core (formats, validation), lepp::certify (the exact certifier),
lepp::reference and lepp::impl (the two Lepp engines), lepp::gen (RapidCheck
PSLG generators), lepp::render (SVG), lepp::version and the other exported
targets. Everything is GPL-3.0-or-later.")

if(LEPP_PYTHON_BUILT)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-lepp)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SHLIBDEPS ON)
  # The extension is built for one interpreter version (its file name says cpython-3XY).
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
    "python3 (>= ${LEPP_PYTHON_VERSION}), python3 (<< ${LEPP_PYTHON_VERSION_BELOW}), python3-numpy")
  # lepp.audit's built-in sources (corpus/paper, corpus/hostile) are the lepp package's share/lepp.
  set(CPACK_DEBIAN_PYTHON_PACKAGE_RECOMMENDS "lepp (= ${CPACK_PACKAGE_VERSION})")
  # lepp.testing needs Hypothesis; Mesh.to_meshio and lepp.from_meshio meshio; lepp.plot matplotlib.
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SUGGESTS "python3-hypothesis, python3-meshio, python3-matplotlib")
  set(CPACK_COMPONENT_PYTHON_DESCRIPTION
"Lepp-centroid quality triangulation and its exact certifier for Python
The lepp Python package: lepp.refine (Lepp-centroid refinement of a planar
straight-line graph into a constrained Delaunay mesh with no angle below a
bound, NumPy arrays in and out), lepp.triangulate (the triangle package's
dict API), lepp.certify (the exact certifier of any mesher's mesh),
lepp.render (SVG), lepp.plot (matplotlib), Mesh.to_meshio and
lepp.from_meshio (meshio), lepp.audit (a Python mesher checked against the paper's
statements) and lepp.testing (Hypothesis strategies of valid PSLGs).")
  install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/python3-lepp RENAME copyright COMPONENT python)
  install(FILES ${PROJECT_SOURCE_DIR}/docs/PYTHON.md DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/python3-lepp COMPONENT python)
endif()

# Debian wants the licence at /usr/share/doc/PACKAGE/copyright.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/lepp RENAME copyright COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md ${PROJECT_SOURCE_DIR}/docs/DEPENDENCIES.md
  DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/lepp COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/lepp-dev RENAME copyright COMPONENT dev)

include(CPack)

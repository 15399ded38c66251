// SPDX-License-Identifier: GPL-3.0-or-later
// lepp's build information: the version from CMake, the git commit, the library versions
// read from the headers this file is compiled against.
#include "lepp/version.h"

#include <CGAL/version.h>
#include <gmp.h>
#include <mpfr.h>

#include "lepp_git_commit.h"  // generated at build time by cmake/LeppGitCommit.cmake

#define LEPP_STR_(x) #x
#define LEPP_STR(x) LEPP_STR_(x)

namespace lepp {

const char* git_commit() { return LEPP_GIT_COMMIT; }

const char* cgal_version() { return CGAL_VERSION_STR; }

const char* gmp_version_built() {
  return LEPP_STR(__GNU_MP_VERSION) "." LEPP_STR(__GNU_MP_VERSION_MINOR) "." LEPP_STR(__GNU_MP_VERSION_PATCHLEVEL);
}

const char* mpfr_version_built() { return MPFR_VERSION_STRING; }

std::string version_text() {
  std::string text = std::string("lepp ") + kVersion + "\n";
  text += std::string("commit ") + git_commit() + "\n";
  text += std::string("built with CGAL ") + cgal_version() + ", GMP " + gmp_version_built() + ", MPFR " +
          mpfr_version_built() + "\n";
  // The shared GMP and MPFR actually loaded can be newer than the headers (same soname).
  const std::string gmp_run = ::gmp_version, mpfr_run = ::mpfr_get_version();
  if (gmp_run != gmp_version_built() || mpfr_run != mpfr_version_built())
    text += "running with GMP " + gmp_run + ", MPFR " + mpfr_run + "\n";
  return text;
}

}  // namespace lepp

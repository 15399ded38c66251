// SPDX-License-Identifier: GPL-3.0-or-later
// One thread's MPFR constant cache freed when the thread exits (the audit's -j threads).
#pragma once
// MPFR keeps the constants it computes (pi, and what mpfr_sin and mpfr_acos
// need) in a cache per thread and frees it only when asked. A thread that
// exits without asking leaks it: LeakSanitizer reports it after every
// `lepp audit -j N`. Include this only in a file that links MPFR, and call
// free_mpfr_cache_at_thread_exit() in every function that uses MPFR.
#include <mpfr.h>

namespace lepp {

inline void free_mpfr_cache_at_thread_exit() {
  struct Guard {
    ~Guard() { mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE); }
  };
  thread_local Guard guard;
  (void)guard;  // odr-use: constructed once per thread, destroyed at its exit
}

}  // namespace lepp

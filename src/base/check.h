#pragma once
// Contract checks for programming errors (never for bad input: that returns a Result).
// PROXYGI_CHECK is always on and prints the failed expression with file:line before aborting.
#include <cstdio>
#include <cstdlib>

#define PROXYGI_CHECK(condition, what)                                                     \
  do {                                                                                     \
    if (!(condition)) {                                                                    \
      std::fprintf(stderr, "%s:%d: check failed: %s (%s)\n", __FILE__, __LINE__, #condition, \
                   what);                                                                  \
      std::abort();                                                                        \
    }                                                                                      \
  } while (0)

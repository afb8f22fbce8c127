// What every fuzz target reports when a documented property does not hold: a message and an
// abort, which libFuzzer records as a crash with the input that caused it.
#ifndef SFE_FUZZ_CHECK_H
#define SFE_FUZZ_CHECK_H

#include <cstdio>
#include <cstdlib>

#define SFE_FUZZ_CHECK(condition)                                                              \
  do                                                                                           \
  {                                                                                            \
    if(!(condition))                                                                           \
    {                                                                                          \
      std::fprintf(stderr, "%s:%d: property violated: %s\n", __FILE__, __LINE__, #condition); \
      std::abort();                                                                            \
    }                                                                                          \
  } while(false)

#endif

/* fuzz_api.h — the libcanopy API fuzzer: seeded random call sequences through canopy.h, checked after every call. */
#ifndef CANOPY_FUZZ_API_H
#define CANOPY_FUZZ_API_H

#include <stdio.h>

/* What a run did. A crash ends the process (the sanitizers report it). */
typedef struct canopy_fuzz_counts {
    long calls;       /* library calls made by the fuzzer (checks excluded) */
    long rejections;  /* calls that returned a status other than CANOPY_OK */
    long violations;  /* broken promises: changed state on rejection, stale
                         message, output on stdout/stderr, ... */
} canopy_fuzz_counts;

/* Run `calls` random calls from `seed` in a fresh temporary directory
 * (removed at the end). Library output on fd 1 and 2 is captured and
 * counted as a violation; the fuzzer's own reports go to `report`.
 * Returns 0 when there was no violation. */
int canopy_fuzz_run(unsigned long long seed, long calls, FILE *report,
                    canopy_fuzz_counts *counts);

#endif /* CANOPY_FUZZ_API_H */

/* fuzz_main.c — canopy-fuzz: runs the libcanopy API fuzzer (fuzz_api.c) and prints its counts. */
#include "fuzz_api.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__SANITIZE_ADDRESS__)
/* LeakSanitizer: HDF5 1.10.8 keeps internal structures it cannot free
 * after failing to open an object of a damaged file (reproduced with HDF5
 * alone: H5Fopen, a failing H5Gopen2, H5Fclose; at exit it prints
 * "HDF5: infinite loop closing library"). The fuzzer's byte-flipped files
 * trigger it. Allocations inside libhdf5 are therefore not reported; the
 * fuzzer checks after every call that libcanopy left no HDF5 identifier
 * open, which is how a leak of ours would show. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:libhdf5\n";
}
#endif

#if defined(__SANITIZE_ADDRESS__)
/* AddressSanitizer: HDF5 asks for absurd sizes (size fields of a damaged
 * file) and copes with malloc returning NULL, as it does without the
 * sanitizer; aborting there would report HDF5's input, not a bug. An
 * absurd allocation of libcanopy's own shows as CANOPY_ERR_MEMORY from a
 * call on the fuzzer's small models, which the fuzzer reports. */
const char *__asan_default_options(void);
const char *__asan_default_options(void)
{
    return "allocator_may_return_null=1";
}

/* UndefinedBehaviorSanitizer: abort after a report (fuzz_api.c reports the
 * abort with the call it happened in; exiting would lose the report, which
 * went to the captured stderr). */
const char *__ubsan_default_options(void);
const char *__ubsan_default_options(void)
{
    return "abort_on_error=1";
}
#endif

static int usage(void)
{
    fprintf(stderr, "usage: canopy-fuzz [--seed S] [--calls N]\n"
                    "  S: unsigned seed (default 1); N: calls (default "
                    "10000)\n");
    return 2;
}

int main(int argc, char **argv)
{
    unsigned long long seed = 1;
    long calls = 10000;
    for (int a = 1; a < argc; ++a) {
        char *end = NULL;
        if (strcmp(argv[a], "--seed") == 0 && a + 1 < argc) {
            seed = strtoull(argv[++a], &end, 10);
        } else if (strcmp(argv[a], "--calls") == 0 && a + 1 < argc) {
            calls = strtol(argv[++a], &end, 10);
            if (calls < 0) return usage();
        } else {
            return usage();
        }
        if (end == NULL || *end != '\0') return usage();
    }
    canopy_fuzz_counts c;
    const int rc = canopy_fuzz_run(seed, calls, stderr, &c);
    printf("seed %llu: calls %ld, rejections %ld, violations %ld, crashes 0\n",
           seed, c.calls, c.rejections, c.violations);
    fflush(stdout); /* before LeakSanitizer's report at exit */
    return rc;
}

/* test_main.c — runs the registered libcanopy tests: --list, one name, or all. */
#include "test.h"

#include <string.h>
#include <time.h>

#define MAX_TESTS 256

static struct { const char *name; canopy_test_fn fn; } registry[MAX_TESTS];
static int registry_count;
int canopy_test_failures;

void canopy_test_register(const char *name, canopy_test_fn fn)
{
    if (registry_count < MAX_TESTS) {
        registry[registry_count].name = name;
        registry[registry_count].fn = fn;
        ++registry_count;
    }
}

static int compare(const void *a, const void *b)
{
    const char *const *x = a, *const *y = b;
    return strcmp(*x, *y);
}

static int run(int i)
{
    canopy_test_failures = 0;
    clock_t c0 = clock();
    registry[i].fn();
    double s = (double)(clock() - c0) / CLOCKS_PER_SEC;
    printf("%s %s (%.2f s cpu)\n", canopy_test_failures ? "FAIL" : "PASS",
           registry[i].name, s);
    fflush(stdout);
    return canopy_test_failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    /* Sorted so --list and "all" are stable. The name is the first member. */
    qsort(registry, (size_t)registry_count, sizeof registry[0], compare);
    if (argc > 1 && strcmp(argv[1], "--list") == 0) {
        for (int i = 0; i < registry_count; ++i) printf("%s\n", registry[i].name);
        return 0;
    }
    int failed = 0, passed = 0;
    for (int i = 0; i < registry_count; ++i) {
        int selected = argc < 2;
        for (int a = 1; a < argc; ++a)
            if (strcmp(argv[a], registry[i].name) == 0) selected = 1;
        if (!selected) continue;
        if (run(i)) ++failed; else ++passed;
    }
    if (passed + failed == 0) {
        fprintf(stderr, "no test matches");
        for (int a = 1; a < argc; ++a) fprintf(stderr, " '%s'", argv[a]);
        fprintf(stderr, "; see --list\n");
        return 2;
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}

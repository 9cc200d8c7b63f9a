/* test.h — a tiny test framework for libcanopy: self-registering tests and ASSERT macros that fail loudly. */
#ifndef CANOPY_TEST_H
#define CANOPY_TEST_H

#include "canopy.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef void (*canopy_test_fn)(void);
void canopy_test_register(const char *name, canopy_test_fn fn);
/* Number of failed assertions in the running test. */
extern int canopy_test_failures;

/* Define a test: CANOPY_TEST(name) { ... }  — registered before main runs. */
#define CANOPY_TEST(name)                                                   \
    static void test_##name(void);                                         \
    __attribute__((constructor)) static void register_##name(void)        \
    {                                                                       \
        canopy_test_register(#name, test_##name);                          \
    }                                                                       \
    static void test_##name(void)

#define CANOPY_TEST_FAIL_(...)                                              \
    do {                                                                    \
        fprintf(stderr, "%s:%d: ", __FILE__, __LINE__);                     \
        fprintf(stderr, __VA_ARGS__);                                       \
        fprintf(stderr, "\n");                                              \
        ++canopy_test_failures;                                             \
    } while (0)

/* Assert a condition (the test goes on, and fails at its end). */
#define ASSERT_TRUE(cond)                                                   \
    do { if (!(cond)) CANOPY_TEST_FAIL_("assertion failed: %s", #cond); } while (0)

/* Assert a libcanopy call returns CANOPY_OK; on failure print its message
 * and stop the test (later steps would only cascade). */
#define ASSERT_OK(model, call)                                              \
    do {                                                                    \
        canopy_status st_ = (call);                                         \
        if (st_ != CANOPY_OK) {                                             \
            CANOPY_TEST_FAIL_("%s returned %s: %s", #call,                  \
                              canopy_status_name(st_),                      \
                              canopy_model_message(model));                 \
            return;                                                         \
        }                                                                   \
    } while (0)

/* Assert a call returns the given status. */
#define ASSERT_STATUS(expected, call)                                       \
    do {                                                                    \
        canopy_status st_ = (call);                                         \
        if (st_ != (expected))                                              \
            CANOPY_TEST_FAIL_("%s returned %s, expected %s", #call,         \
                              canopy_status_name(st_),                      \
                              canopy_status_name(expected));                \
    } while (0)

/* |actual - expected| <= tol (absolute). */
#define ASSERT_NEAR(actual, expected, tol)                                  \
    do {                                                                    \
        double a_ = (actual), e_ = (expected), t_ = (tol);                  \
        if (!(fabs(a_ - e_) <= t_))                                         \
            CANOPY_TEST_FAIL_("%s = %.17g, expected %.17g within %g",       \
                              #actual, a_, e_, t_);                         \
    } while (0)

/* |actual - expected| <= rel * |expected|. */
#define ASSERT_REL(actual, expected, rel)                                   \
    do {                                                                    \
        double a_ = (actual), e_ = (expected), r_ = (rel);                  \
        if (!(fabs(a_ - e_) <= r_ * fabs(e_)))                              \
            CANOPY_TEST_FAIL_("%s = %.17g, expected %.17g within %g "       \
                              "relative (off by %.3g)", #actual, a_, e_, r_, \
                              e_ != 0.0 ? fabs(a_ - e_) / fabs(e_) : a_);   \
    } while (0)

/* The handle's message contains `text`. */
#define ASSERT_MESSAGE_HAS(model, text)                                      \
    do {                                                                     \
        if (strstr(canopy_model_message(model), (text)) == NULL)             \
            CANOPY_TEST_FAIL_("message '%s' lacks '%s'",                     \
                              canopy_model_message(model), (text));          \
    } while (0)

/* Largest |a - b| over n values, relative to the largest |a|. */
static inline double rel_diff(const double *a, const double *b, int n)
{
    double d = 0.0, s = 0.0;
    for (int i = 0; i < n; ++i) {
        if (fabs(a[i] - b[i]) > d) d = fabs(a[i] - b[i]);
        if (fabs(a[i]) > s) s = fabs(a[i]);
    }
    return s > 0.0 ? d / s : d;
}

#endif /* CANOPY_TEST_H */

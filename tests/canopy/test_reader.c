/* test_reader.c — canopy_reader: steps and times of an output file, a step by time, a step's state and nodal forces, structure checks, clean failures. */
#include "test.h"

#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { N = 4, NT = 2, STEPS = 5 };

/* Two triangles on a square of side `side`, five Model-II springs, a
 * payload-free cloth; node 3 fixed so gravity moves the others. */
static canopy_status build_square(canopy_model *m, double side, int flip)
{
    const double x[N][3] = {{0, 0, 0}, {side, 0, 0}, {side, side, 0},
                            {0, side, 0}};
    canopy_status st;
    for (int i = 0; i < N; ++i)
        if ((st = canopy_model_add_node(m, x[i], 0.01, CANOPY_GROUP_FABRIC,
                                        NULL)))
            return st;
    if ((st = canopy_model_add_triangle(m, 0, 1, 2, NULL)) ||
        (st = canopy_model_add_triangle(m, 0, 2, flip ? 1 : 3, NULL)))
        return st;
    const int ends[5][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}};
    for (int s = 0; s < 5; ++s)
        if ((st = canopy_model_add_spring(m, ends[s][0], ends[s][1], 100.0,
                                          0.01, CANOPY_SPRING_MODEL_II,
                                          CANOPY_GROUP_FABRIC, NULL)))
            return st;
    return canopy_model_set_fixed(m, 3, 1);
}

typedef struct snapshot {
    double t, x[3 * N], v[3 * N], dp[NT], f[3 * N];
} snapshot;

static void take(canopy_model *m, snapshot *s)
{
    s->t = canopy_model_time(m);
    canopy_model_get_positions(m, s->x, N);
    canopy_model_get_velocities(m, s->v, N);
    canopy_model_get_pressure_jump(m, s->dp, NT);
}

static int same(const snapshot *a, const snapshot *b)
{
    return a->t == b->t && memcmp(a->x, b->x, sizeof a->x) == 0 &&
           memcmp(a->v, b->v, sizeof a->v) == 0 &&
           memcmp(a->dp, b->dp, sizeof a->dp) == 0;
}

#define ASSERT_READER_OK(r, call)                                           \
    do {                                                                    \
        canopy_status rs_ = (call);                                         \
        if (rs_ != CANOPY_OK) {                                             \
            CANOPY_TEST_FAIL_("%s returned %s: %s", #call,                  \
                              canopy_status_name(rs_),                      \
                              canopy_reader_message(r));                    \
            return;                                                         \
        }                                                                   \
    } while (0)

#define ASSERT_READER_HAS(r, text)                                          \
    do {                                                                    \
        if (strstr(canopy_reader_message(r), (text)) == NULL)               \
            CANOPY_TEST_FAIL_("message '%s' lacks '%s'",                     \
                              canopy_reader_message(r), (text));            \
    } while (0)

CANOPY_TEST(reader_steps_state_forces)
{
    char dir[64], path[128], h5[160];
    snprintf(dir, sizeof dir, "/tmp/canopy-test-reader-XXXXXX");
    ASSERT_TRUE(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/run", dir);
    snprintf(h5, sizeof h5, "%s.h5", path);

    /* A run of STEPS outputs, every step with its own loads. */
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, build_square(m, 1.0, 0));
    canopy_output *o = NULL;
    ASSERT_OK(m, canopy_output_create(m, path, CANOPY_OUTPUT_CREATE, &o));
    snapshot rec[STEPS];
    for (int s = 0; s < STEPS; ++s) {
        const double dp[NT] = {1.0 + s, 2.0 - 0.25 * s};
        double f[3 * N] = {0};
        for (int i = 0; i < 3 * N; ++i) f[i] = 0.01 * (i + 1) * (s + 1);
        ASSERT_OK(m, canopy_model_set_pressure_jump(m, dp, NT));
        ASSERT_OK(m, canopy_model_set_nodal_forces(m, f, N));
        if (s > 0) ASSERT_OK(m, canopy_model_advance(m, 0.01, NULL));
        take(m, &rec[s]);
        memcpy(rec[s].f, f, sizeof f);
        ASSERT_OK(m, canopy_output_write(o, m));
    }
    canopy_output_destroy(&o);

    canopy_reader *r = NULL;
    ASSERT_TRUE(canopy_reader_create(&r) == CANOPY_OK && r != NULL);
    ASSERT_TRUE(canopy_reader_step_count(r) == 0);
    ASSERT_READER_OK(r, canopy_reader_open(r, path));
    ASSERT_TRUE(canopy_reader_step_count(r) == STEPS);
    for (int s = 0; s < STEPS; ++s) {
        int number = -1;
        double t = -1.0;
        ASSERT_READER_OK(r, canopy_reader_step(r, s, &number, &t));
        ASSERT_TRUE(number == s);
        ASSERT_TRUE(t == rec[s].t);
    }

    /* By time: exact, within the tolerance, the nearest of two within it. */
    int index = -1;
    ASSERT_READER_OK(r, canopy_reader_find_step(r, rec[3].t, 0.0, &index));
    ASSERT_TRUE(index == 3);
    ASSERT_READER_OK(r, canopy_reader_find_step(r, rec[2].t + 0.004, 0.005,
                                                &index));
    ASSERT_TRUE(index == 2);
    ASSERT_READER_OK(r, canopy_reader_find_step(r, rec[2].t + 0.006, 0.02,
                                                &index));
    ASSERT_TRUE(index == 3);
    index = 7;
    ASSERT_STATUS(CANOPY_ERR_RANGE,
                  canopy_reader_find_step(r, rec[2].t + 0.004, 0.001, &index));
    ASSERT_TRUE(index == 7);
    ASSERT_READER_HAS(r, h5);
    ASSERT_READER_HAS(r, "nearest");
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_reader_find_step(r, 0.0, -1.0, &index));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_reader_find_step(r, 0.0, 1.0, NULL));

    /* The whole state: as canopy_model_read_state loads it. */
    canopy_model *a = NULL, *b = NULL;
    ASSERT_OK(a, canopy_model_create(&a));
    ASSERT_OK(a, build_square(a, 1.0, 0));
    ASSERT_OK(b, canopy_model_create(&b));
    ASSERT_OK(b, build_square(b, 1.0, 0));
    ASSERT_READER_OK(r, canopy_reader_read_state(r, 2, a));
    ASSERT_OK(b, canopy_model_read_state(b, path, 2));
    snapshot sa, sb;
    take(a, &sa);
    take(b, &sb);
    ASSERT_TRUE(same(&sa, &rec[2]));
    ASSERT_TRUE(same(&sa, &sb));
    double fa[3 * N], fb[3 * N];
    ASSERT_OK(a, canopy_model_get_forces(a, fa, N));
    ASSERT_OK(b, canopy_model_get_forces(b, fb, N));
    ASSERT_TRUE(memcmp(fa, fb, sizeof fa) == 0);
    /* Both continue alike. */
    ASSERT_OK(a, canopy_model_advance(a, 0.01, NULL));
    ASSERT_OK(b, canopy_model_advance(b, 0.01, NULL));
    take(a, &sa);
    take(b, &sb);
    ASSERT_TRUE(same(&sa, &sb));

    /* Nodal forces of a step, exactly as they were set. */
    double f[3 * N];
    ASSERT_READER_OK(r, canopy_reader_get_nodal_forces(r, 4, f, N));
    ASSERT_TRUE(memcmp(f, rec[4].f, sizeof f) == 0);
    ASSERT_READER_OK(r, canopy_reader_get_nodal_forces(r, 1, f, N));
    ASSERT_TRUE(memcmp(f, rec[1].f, sizeof f) == 0);

    /* Motion only: time and loads stay, velocities get the offset. */
    canopy_model *c = NULL;
    ASSERT_OK(c, canopy_model_create(&c));
    ASSERT_OK(c, build_square(c, 1.0, 0));
    ASSERT_OK(c, canopy_model_set_time(c, 7.5));
    const double dp7[NT] = {7.0, 8.0};
    ASSERT_OK(c, canopy_model_set_pressure_jump(c, dp7, NT));
    const double offset[3] = {0.5, -1.0, 2.0};
    ASSERT_READER_OK(r, canopy_reader_read_motion(r, 4, c, offset));
    snapshot sc;
    take(c, &sc);
    ASSERT_TRUE(sc.t == 7.5);
    ASSERT_TRUE(sc.dp[0] == 7.0 && sc.dp[1] == 8.0);
    ASSERT_TRUE(memcmp(sc.x, rec[4].x, sizeof sc.x) == 0);
    for (int i = 0; i < 3 * N; ++i)
        ASSERT_TRUE(sc.v[i] == rec[4].v[i] + offset[i % 3]);
    ASSERT_READER_OK(r, canopy_reader_read_motion(r, 4, c, NULL));
    take(c, &sc);
    ASSERT_TRUE(memcmp(sc.v, rec[4].v, sizeof sc.v) == 0);

    canopy_model_destroy(&a);
    canopy_model_destroy(&b);
    canopy_model_destroy(&c);
    canopy_model_destroy(&m);
    canopy_reader_destroy(&r);
    ASSERT_TRUE(r == NULL);
    canopy_reader_destroy(&r);
    canopy_reader_destroy(NULL);
    unlink(h5);
    snprintf(h5, sizeof h5, "%s.xdmf", path);
    unlink(h5);
    rmdir(dir);
}

CANOPY_TEST(reader_rejects_cleanly)
{
    char dir[64], path[128], h5[256], junk[160], missing[160];
    snprintf(dir, sizeof dir, "/tmp/canopy-test-reader-XXXXXX");
    ASSERT_TRUE(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/run", dir);
    snprintf(h5, sizeof h5, "%s.h5", path);
    snprintf(junk, sizeof junk, "%s/junk", dir);
    snprintf(missing, sizeof missing, "%s/none", dir);

    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, build_square(m, 1.0, 0));
    canopy_output *o = NULL;
    ASSERT_OK(m, canopy_output_create(m, path, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_OK(m, canopy_output_write(o, m));
    ASSERT_OK(m, canopy_model_advance(m, 0.01, NULL));
    ASSERT_OK(m, canopy_output_write(o, m));
    canopy_output_destroy(&o);
    {
        char j[200];
        snprintf(j, sizeof j, "%s.h5", junk);
        FILE *fj = fopen(j, "w");
        ASSERT_TRUE(fj != NULL);
        if (fj) { fputs("not HDF5\n", fj); fclose(fj); }
    }

    /* Quiet: nothing may be printed (stderr to a file, counted). */
    char err[128];
    snprintf(err, sizeof err, "%s/stderr", dir);
    fflush(stderr);
    int saved = dup(2), fd = open(err, O_CREAT | O_WRONLY | O_TRUNC, 0600);
    ASSERT_TRUE(fd >= 0 && saved >= 0);
    dup2(fd, 2);
    close(fd);

    canopy_reader *r = NULL;
    ASSERT_TRUE(canopy_reader_create(&r) == CANOPY_OK);
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_reader_create(NULL));
    int number = 0, index = 0;
    double t = 0.0, f[3 * N];
    /* Nothing open yet. */
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_reader_step(r, 0, &number, &t));
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_reader_find_step(r, 0.0, 1.0, &index));
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_reader_read_state(r, 0, m));
    ASSERT_STATUS(CANOPY_ERR_STATE, canopy_reader_get_nodal_forces(r, 0, f, N));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_reader_open(r, NULL));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_reader_open(r, ""));
    ASSERT_STATUS(CANOPY_ERR_IO, canopy_reader_open(r, missing));
    ASSERT_READER_HAS(r, missing);
    ASSERT_STATUS(CANOPY_ERR_IO, canopy_reader_open(r, junk));
    ASSERT_READER_HAS(r, junk);
    ASSERT_TRUE(canopy_reader_step_count(r) == 0);

    /* Open; a failed second open keeps the first file. */
    ASSERT_READER_OK(r, canopy_reader_open(r, path));
    ASSERT_TRUE(strcmp(canopy_reader_message(r), "") == 0);
    ASSERT_STATUS(CANOPY_ERR_IO, canopy_reader_open(r, missing));
    ASSERT_TRUE(canopy_reader_step_count(r) == 2);
    ASSERT_READER_OK(r, canopy_reader_step(r, 1, &number, &t));
    ASSERT_TRUE(number == 1 && t == canopy_model_time(m));
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_reader_step(r, 2, &number, &t));
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_reader_step(r, -1, &number, &t));
    ASSERT_TRUE(number == 1);

    /* Models that are not the file's structure: unchanged, FORMAT naming
     * the file and what differs. */
    struct { double side; int flip; int extra; const char *what; } bad[] = {
        {2.0, 0, 0, "rest length"},   /* same topology, other size */
        {1.0, 1, 0, "triangle 1"},    /* other connectivity */
        {1.0, 0, 1, "nodes"},         /* one node more */
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        canopy_model *other = NULL;
        ASSERT_OK(other, canopy_model_create(&other));
        ASSERT_OK(other, build_square(other, bad[k].side, bad[k].flip));
        if (bad[k].extra) {
            const double x[3] = {5.0, 5.0, 5.0};
            ASSERT_OK(other, canopy_model_add_node(other, x, 1.0,
                                                   CANOPY_GROUP_OTHER, NULL));
        }
        const int n = canopy_model_node_count(other);
        double xb[3 * (N + 1)], xa[3 * (N + 1)], vb[3 * (N + 1)],
            va[3 * (N + 1)];
        const double tb = canopy_model_time(other);
        ASSERT_OK(other, canopy_model_get_positions(other, xb, n));
        ASSERT_OK(other, canopy_model_get_velocities(other, vb, n));
        ASSERT_STATUS(CANOPY_ERR_FORMAT, canopy_reader_read_state(r, 1, other));
        ASSERT_READER_HAS(r, h5);
        ASSERT_READER_HAS(r, bad[k].what);
        ASSERT_STATUS(CANOPY_ERR_FORMAT,
                      canopy_reader_read_motion(r, 1, other, NULL));
        ASSERT_READER_HAS(r, bad[k].what);
        ASSERT_OK(other, canopy_model_get_positions(other, xa, n));
        ASSERT_OK(other, canopy_model_get_velocities(other, va, n));
        ASSERT_TRUE(canopy_model_time(other) == tb);
        ASSERT_TRUE(memcmp(xa, xb, sizeof(double) * 3 * (size_t)n) == 0);
        ASSERT_TRUE(memcmp(va, vb, sizeof(double) * 3 * (size_t)n) == 0);
        canopy_model_destroy(&other);
    }

    /* Bad arguments: nothing changes. */
    canopy_model *fresh = NULL;
    ASSERT_OK(fresh, canopy_model_create(&fresh));
    ASSERT_OK(fresh, build_square(fresh, 1.0, 0));
    snapshot before, after;
    take(fresh, &before);
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_reader_read_state(r, 0, NULL));
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_reader_read_state(r, 5, fresh));
    const double nan_offset[3] = {0.0, NAN, 0.0};
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_reader_read_motion(r, 1, fresh, nan_offset));
    take(fresh, &after);
    ASSERT_TRUE(same(&before, &after));
    for (int i = 0; i < 3 * N; ++i) f[i] = -3.0;
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_reader_get_nodal_forces(r, 0, f, N + 1));
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_reader_get_nodal_forces(r, 9, f, N));
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_reader_get_nodal_forces(r, 0, NULL, N));
    for (int i = 0; i < 3 * N; ++i) ASSERT_TRUE(f[i] == -3.0);

    /* A file rewritten without the step the reader listed: FORMAT, model
     * unchanged. */
    canopy_model *w = NULL;
    ASSERT_OK(w, canopy_model_create(&w));
    ASSERT_OK(w, build_square(w, 1.0, 0));
    ASSERT_OK(w, canopy_output_create(w, path, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_OK(w, canopy_output_write(o, w));
    canopy_output_destroy(&o);
    take(fresh, &before);
    ASSERT_TRUE(canopy_reader_read_state(r, 1, fresh) != CANOPY_OK);
    ASSERT_READER_HAS(r, h5);
    take(fresh, &after);
    ASSERT_TRUE(same(&before, &after));
    canopy_model_destroy(&w);

    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    /* What went there: the library's printing, or a failed assertion's. */
    FILE *fe = fopen(err, "r");
    char line[512];
    long printed = 0;
    while (fe && fgets(line, sizeof line, fe)) {
        printed += (long)strlen(line);
        fputs(line, stderr);
    }
    if (fe) fclose(fe);
    ASSERT_TRUE(printed == 0);

    canopy_reader_destroy(&r);
    canopy_model_destroy(&fresh);
    canopy_model_destroy(&m);
    unlink(err);
    unlink(h5);
    snprintf(h5, sizeof h5, "%s.xdmf", path);
    unlink(h5);
    snprintf(h5, sizeof h5, "%s.h5", junk);
    unlink(h5);
    rmdir(dir);
}

/* test_robustness.c — issue 32: every rejected call names its argument in a fresh message and leaves the model, its checkpoint and its files as they were. */
#include "test.h"
#include "test_membrane_fixture.h"

#include <hdf5.h>

#include <stdint.h>
#include <unistd.h>

/* A message no call under test would set: a rejection must replace it. */
static void set_sentinel(canopy_model *m)
{
    canopy_model_set_max_omega_dt(m, -7.77e-77);
}

#define ASSERT_FRESH(model, status, call, text)                              \
    do {                                                                     \
        set_sentinel(model);                                                 \
        ASSERT_STATUS(status, call);                                         \
        ASSERT_TRUE(strstr(canopy_model_message(model), "-7.77e-77") == NULL); \
        ASSERT_MESSAGE_HAS(model, text);                                     \
    } while (0)

/* The state a rejected call must leave alone. */
typedef struct state {
    int n, ns, nt, acc_valid;
    double t, x[3 * 400], v[3 * 400], a[3 * 400], mass[400];
} state;

static void take(canopy_model *m, state *s)
{
    memset(s, 0, sizeof *s);
    s->n = canopy_model_node_count(m);
    s->ns = canopy_model_spring_count(m);
    s->nt = canopy_model_triangle_count(m);
    s->t = canopy_model_time(m);
    if (s->n > 400) return;
    canopy_model_get_positions(m, s->x, s->n);
    canopy_model_get_velocities(m, s->v, s->n);
    canopy_model_get_acceleration_state(m, s->a, s->n, &s->acc_valid);
    canopy_model_get_masses(m, s->mass, s->n);
}

static int same(const state *a, const state *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

/* A membrane stepped once with hht (so it carries an acceleration), with a
 * checkpoint. */
static canopy_status hht_membrane(canopy_model *m)
{
    canopy_status st = membrane_fixture(m, 4, 0.1, 100.0, 0.0, 0.01);
    if (st == CANOPY_OK) st = canopy_model_set_integrator(m, "hht");
    if (st == CANOPY_OK) st = canopy_model_step(m, 1e-4);
    if (st == CANOPY_OK) st = canopy_model_checkpoint(m);
    return st;
}

/* After a rejection: state unchanged, and the checkpoint restores. */
static void assert_untouched(canopy_model *m, const state *before)
{
    state after, restored;
    take(m, &after);
    ASSERT_TRUE(same(before, &after));
    ASSERT_TRUE(after.acc_valid == 1);
    ASSERT_OK(m, canopy_model_restore(m));
    take(m, &restored);
    ASSERT_TRUE(same(before, &restored));
}

CANOPY_TEST(robust_null_outputs_set_message)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, membrane_fixture(m, 4, 0.1, 100.0, 0.0, 0.01));
    const int n = canopy_model_node_count(m), ns = canopy_model_spring_count(m),
              nt = canopy_model_triangle_count(m);
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_model_get_gravity(m, NULL),
                 "get_gravity: g is NULL");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_frequency_bound(m, NULL), "frequency_bound");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_model_stable_step(m, NULL),
                 "stable_step: dt is NULL");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_max_frequency(m, NULL, NULL), "max_frequency");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_model_energies(m, NULL),
                 "energies: e is NULL");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_model_canopy_area(m, NULL),
                 "canopy_area");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_projected_diameter(m, NULL),
                 "projected_diameter");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_model_get_forces(m, NULL, n),
                 "get_forces");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_get_tensions(m, NULL, ns), "get_tensions");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_get_triangle_velocities(m, NULL, nt),
                 "get_triangle_velocities");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_get_normal_velocities(m, NULL, nt),
                 "get_normal_velocities");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_get_positions(m, NULL, n),
                 "get_positions: array is NULL");
    double dp[64];
    ASSERT_FRESH(m, CANOPY_ERR_RANGE,
                 canopy_model_get_pressure_jump(m, dp, nt + 1),
                 "does not match");
    canopy_model_destroy(&m);
}

/* Write a canopy-looking file with zero nodes and one empty step. */
static int write_zero_node_file(const char *path)
{
    hid_t file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file < 0) return 0;
    hid_t mesh = H5Gcreate2(file, "mesh", H5P_DEFAULT, H5P_DEFAULT,
                            H5P_DEFAULT);
    hid_t scalar = H5Screate(H5S_SCALAR);
    const char *names[4] = {"nodes", "springs", "triangles", "lines"};
    const int zero = 0;
    for (int i = 0; i < 4; ++i) {
        hid_t a = H5Acreate2(mesh, names[i], H5T_NATIVE_INT, scalar,
                             H5P_DEFAULT, H5P_DEFAULT);
        H5Awrite(a, H5T_NATIVE_INT, &zero);
        H5Aclose(a);
    }
    H5Gclose(mesh);
    hid_t steps = H5Gcreate2(file, "steps", H5P_DEFAULT, H5P_DEFAULT,
                             H5P_DEFAULT);
    hid_t g = H5Gcreate2(steps, "000000", H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT);
    const double t = 2.5;
    hid_t a = H5Acreate2(g, "time", H5T_NATIVE_DOUBLE, scalar, H5P_DEFAULT,
                         H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_DOUBLE, &t);
    H5Aclose(a);
    const char *sets[3] = {"x", "v", "f_ext"};
    for (int i = 0; i < 3; ++i) {
        hsize_t dims[2] = {0, 3};
        hid_t sp = H5Screate_simple(2, dims, NULL);
        hid_t d = H5Dcreate2(g, sets[i], H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT,
                             H5P_DEFAULT, H5P_DEFAULT);
        H5Dclose(d);
        H5Sclose(sp);
    }
    hsize_t none = 0;
    hid_t sp = H5Screate_simple(1, &none, NULL);
    hid_t d = H5Dcreate2(g, "dp", H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT,
                         H5P_DEFAULT, H5P_DEFAULT);
    H5Dclose(d);
    H5Sclose(sp);
    H5Sclose(scalar);
    H5Gclose(g);
    H5Gclose(steps);
    return H5Fclose(file) >= 0;
}

CANOPY_TEST(robust_empty_model_checkpoint_and_read_state)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    /* No nodes: the copies have nothing to copy (used to memcpy NULL). */
    ASSERT_OK(m, canopy_model_set_time(m, 1.5));
    ASSERT_OK(m, canopy_model_checkpoint(m));
    ASSERT_OK(m, canopy_model_set_time(m, 3.0));
    ASSERT_OK(m, canopy_model_restore(m));
    ASSERT_TRUE(canopy_model_time(m) == 1.5);
    ASSERT_OK(m, canopy_model_commit(m));
    /* A file of zero nodes matches the empty model. */
    char path[] = "/tmp/canopy-robust-zero-XXXXXX";
    const int fd = mkstemp(path);
    ASSERT_TRUE(fd >= 0);
    close(fd);
    char h5[64];
    snprintf(h5, sizeof h5, "%s.h5", path);
    int written;
    H5E_BEGIN_TRY { written = write_zero_node_file(h5); } H5E_END_TRY;
    ASSERT_TRUE(written);
    ASSERT_OK(m, canopy_model_read_state(m, path, -1));
    ASSERT_TRUE(canopy_model_time(m) == 2.5);
    /* A model with nodes rejects it, unchanged. */
    ASSERT_OK(m, hht_membrane(m));
    state before;
    take(m, &before);
    ASSERT_FRESH(m, CANOPY_ERR_FORMAT, canopy_model_read_state(m, path, -1),
                 "read_state");
    assert_untouched(m, &before);
    unlink(h5);
    unlink(path);
    canopy_model_destroy(&m);
}

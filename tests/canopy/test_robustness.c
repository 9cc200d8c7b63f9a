/* test_robustness.c — issue 32: every rejected call names its argument in a fresh message and leaves the model, its checkpoint and its files as they were. */
#include "test.h"
#include "test_membrane_fixture.h"

#include <hdf5.h>

#include <stdint.h>
#include <sys/stat.h>
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

CANOPY_TEST(robust_rectangle_extreme_aspect)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, hht_membrane(m));
    state before;
    take(m, &before);
    canopy_rectangle_spec r = canopy_rectangle_spec_default();
    r.length = 1.0;
    r.edge_length = 0.1;
    /* Rows spaced like a 1e-10 wide row's nodes: ~1e10 rows (an int
     * overflow and a calloc of -2147483647 rows before). */
    r.width = 1e-10;
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_build_rectangle(m, &r),
                 "spec.width 1e-10, spec.length 1");
    ASSERT_MESSAGE_HAS(m, "more than the builder's limit");
    r.width = 4.9e-324;
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_build_rectangle(m, &r),
                 "spec.width 4.94066e-324");
    /* A denormal length: the rows coincide; the build is rolled back. */
    r.width = 1.0;
    r.length = 4.9e-324;
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_build_rectangle(m, &r),
                 "spec.length 4.94066e-324");
    ASSERT_MESSAGE_HAS(m, "degenerate model");
    /* Far from the origin a 1 mm cloth has no room between its nodes. */
    r.length = 1e-3;
    r.width = 1e-3;
    r.edge_length = 1e-4;
    r.origin[0] = 1e17;
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_build_rectangle(m, &r),
                 "spec.origin (1e+17, 0, 0)");
    assert_untouched(m, &before);
    canopy_model_destroy(&m);
}

CANOPY_TEST(robust_cross_thin_arms)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, hht_membrane(m));
    state before;
    take(m, &before);
    canopy_cross_spec c = canopy_cross_spec_default();
    c.span = 0.5;
    c.arm_width = 1e-10;
    c.edge_length = 0.1;
    c.n_attachments = 4;
    int attach[4] = {-5, -5, -5, -5};
    /* ~6e9 rows per arm: used to overflow int and return OK with
     * attachment indices like 1073741831. */
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_build_cross(m, &c, attach),
                 "spec.span 0.5, spec.arm_width 1e-10");
    ASSERT_MESSAGE_HAS(m, "more than the builder's limit");
    ASSERT_TRUE(attach[0] == -5 && attach[3] == -5);
    /* Tiny but within limits: nodes 1e-170 apart coincide in squares. */
    c.span = 1e-170;
    c.arm_width = 4e-171;
    c.edge_length = 1e-171;
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_build_cross(m, &c, attach),
                 "spec.span 1e-170");
    ASSERT_MESSAGE_HAS(m, "degenerate model");
    assert_untouched(m, &before);
    canopy_model_destroy(&m);
}

CANOPY_TEST(robust_chord_and_lines_degenerate)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, hht_membrane(m));
    state before;
    take(m, &before);
    const canopy_material line = canopy_material_line_default();
    const double a[3] = {0.0, 0.0, 0.0}, b[3] = {1e-161, 0.0, 0.0};
    /* E A / 1e-161 is infinite: named as the user's distance, not as an
     * internal spring's stiffness; the checkpoint survives. */
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_build_chord(m, a, b, 1, &line, CANOPY_GROUP_LINE, -1,
                                    NULL),
                 "the distance 1e-161 from start");
    ASSERT_TRUE(strstr(canopy_model_message(m), "add_spring") == NULL);
    const double far[3] = {1e300, 1e300, 0.0}, back[3] = {-1e300, -1e300, 0.0};
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_build_chord(m, back, far, 2, &line, CANOPY_GROUP_LINE,
                                    -1, NULL),
                 "build_chord");
    assert_untouched(m, &before);

    /* Three coincident attachment nodes, lines of 1e-300. */
    int att[3];
    const double p[3] = {5.0, 5.0, 5.0};
    for (int k = 0; k < 3; ++k)
        ASSERT_OK(m, canopy_model_add_node(m, p, 0.1, CANOPY_GROUP_OTHER,
                                           &att[k]));
    ASSERT_OK(m, canopy_model_checkpoint(m));
    take(m, &before);
    canopy_lines_spec l = canopy_lines_spec_default();
    l.line_length = 1e-300;
    l.edge_length = 1e-300;
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_build_suspension_lines(m, att, 3, &l, NULL),
                 "the line from attach[0]");
    ASSERT_TRUE(strstr(canopy_model_message(m), "stiffness inf") == NULL ||
                strstr(canopy_model_message(m), "length 1e-300") != NULL);
    state after;
    take(m, &after);
    ASSERT_TRUE(same(&before, &after));
    ASSERT_OK(m, canopy_model_restore(m));
    /* A mass that the line's share would make infinite. */
    ASSERT_OK(m, canopy_model_add_node_mass(m, att[0], 1.7e308));
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_add_node_mass(m, att[0], 1.7e308),
                 "not finite");
    canopy_model_destroy(&m);
}

/* The bytes of a file (NULL if it cannot be read); *size receives its size. */
static unsigned char *slurp(const char *path, long *size)
{
    FILE *fp = fopen(path, "rb");
    if (fp == NULL) return NULL;
    fseek(fp, 0, SEEK_END);
    *size = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    unsigned char *b = malloc((size_t)*size + 1);
    if (b && fread(b, 1, (size_t)*size, fp) != (size_t)*size) {
        free(b);
        b = NULL;
    }
    fclose(fp);
    return b;
}

CANOPY_TEST(robust_append_leaves_bad_file_alone)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, hht_membrane(m));
    state before;
    take(m, &before);
    char stem[] = "/tmp/canopy-robust-append-XXXXXX";
    const int fd = mkstemp(stem);
    ASSERT_TRUE(fd >= 0);
    close(fd);
    char h5[64], xdmf[64];
    snprintf(h5, sizeof h5, "%s.h5", stem);
    snprintf(xdmf, sizeof xdmf, "%s.xdmf", stem);
    /* An empty path.h5 (used to be left an 800-byte HDF5 file). */
    FILE *fp = fopen(h5, "wb");
    ASSERT_TRUE(fp != NULL);
    if (fp) fclose(fp);
    canopy_output *o = NULL;
    ASSERT_FRESH(m, CANOPY_ERR_IO,
                 canopy_output_create(m, stem, CANOPY_OUTPUT_APPEND, &o),
                 "output_create");
    ASSERT_MESSAGE_HAS(m, h5);
    ASSERT_TRUE(o == NULL);
    long size = -1;
    unsigned char *bytes = slurp(h5, &size);
    ASSERT_TRUE(bytes != NULL && size == 0);
    free(bytes);
    ASSERT_TRUE(access(xdmf, F_OK) != 0);
    /* Another model's file: FORMAT, both files byte-identical. */
    canopy_model *other = NULL;
    ASSERT_OK(other, canopy_model_create(&other));
    ASSERT_OK(other, membrane_fixture(other, 3, 0.1, 100.0, 0.0, 0.01));
    ASSERT_OK(other, canopy_output_create(other, stem, CANOPY_OUTPUT_CREATE,
                                          &o));
    ASSERT_OK(other, canopy_output_write(o, other));
    canopy_output_destroy(&o);
    long h5_size = 0, xdmf_size = 0;
    unsigned char *h5_bytes = slurp(h5, &h5_size);
    unsigned char *xdmf_bytes = slurp(xdmf, &xdmf_size);
    ASSERT_TRUE(h5_bytes != NULL && xdmf_bytes != NULL);
    ASSERT_FRESH(m, CANOPY_ERR_FORMAT,
                 canopy_output_create(m, stem, CANOPY_OUTPUT_APPEND, &o),
                 "output_create");
    long s1 = 0, s2 = 0;
    unsigned char *h5_after = slurp(h5, &s1), *xdmf_after = slurp(xdmf, &s2);
    ASSERT_TRUE(h5_after && s1 == h5_size &&
                memcmp(h5_after, h5_bytes, (size_t)s1) == 0);
    ASSERT_TRUE(xdmf_after && s2 == xdmf_size &&
                memcmp(xdmf_after, xdmf_bytes, (size_t)s2) == 0);
    free(h5_bytes); free(xdmf_bytes); free(h5_after); free(xdmf_after);
    assert_untouched(m, &before);
    unlink(h5);
    unlink(xdmf);
    unlink(stem);
    canopy_model_destroy(&other);
    canopy_model_destroy(&m);
}

CANOPY_TEST(robust_controls_bounded)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, hht_membrane(m));
    state before;
    take(m, &before);
    /* An iteration limit that would let one step run for hours. */
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_set_implicit_controls(m, 1e-10, 2147483647),
                 "max_iterations 2147483647 in [1, 1000]");
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT,
                 canopy_model_set_implicit_controls(m, NAN, 10),
                 "tolerance nan");
    ASSERT_OK(m, canopy_model_set_implicit_controls(m, 1e-10, 1000));
    /* A circular canopy out of double precision's range is named so. */
    canopy_circular_spec c = canopy_circular_spec_default();
    c.diameter = 1e-200;
    c.edge_length = 2e-201;
    ASSERT_FRESH(m, CANOPY_ERR_ARGUMENT, canopy_build_circular(m, &c, NULL),
                 "spec.diameter 1e-200");
    ASSERT_MESSAGE_HAS(m, "double precision");
    assert_untouched(m, &before);
    canopy_model_destroy(&m);
}

CANOPY_TEST(robust_failed_create_keeps_old_files)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, hht_membrane(m));
    char stem[] = "/tmp/canopy-robust-create-XXXXXX";
    const int fd = mkstemp(stem);
    ASSERT_TRUE(fd >= 0);
    close(fd);
    char h5[64], xdmf[64], tmp[64];
    snprintf(h5, sizeof h5, "%s.h5", stem);
    snprintf(xdmf, sizeof xdmf, "%s.xdmf", stem);
    snprintf(tmp, sizeof tmp, "%s.h5.tmp", stem);
    canopy_output *o = NULL;
    ASSERT_OK(m, canopy_output_create(m, stem, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_OK(m, canopy_output_write(o, m));
    canopy_output_destroy(&o);
    long size = 0;
    unsigned char *old = slurp(h5, &size);
    ASSERT_TRUE(old != NULL && size > 0);
    /* The sidecar's name is taken by a directory: create fails before it
     * replaces path.h5 (it used to truncate it first). */
    ASSERT_TRUE(remove(xdmf) == 0);
    ASSERT_TRUE(mkdir(xdmf, 0700) == 0);
    ASSERT_FRESH(m, CANOPY_ERR_IO,
                 canopy_output_create(m, stem, CANOPY_OUTPUT_CREATE, &o),
                 "not a regular file");
    ASSERT_TRUE(o == NULL);
    long now_size = 0;
    unsigned char *now = slurp(h5, &now_size);
    ASSERT_TRUE(now && now_size == size && memcmp(now, old, (size_t)size) == 0);
    ASSERT_TRUE(access(tmp, F_OK) != 0);
    /* Once the name is free again, create replaces both. */
    ASSERT_TRUE(rmdir(xdmf) == 0);
    ASSERT_OK(m, canopy_output_create(m, stem, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_TRUE(canopy_output_step_count(o) == 0);
    ASSERT_OK(m, canopy_output_write(o, m));
    ASSERT_TRUE(access(xdmf, F_OK) == 0 && access(tmp, F_OK) != 0);
    canopy_output_destroy(&o);
    canopy_model *copy = NULL;
    ASSERT_OK(copy, canopy_model_create(&copy));
    ASSERT_OK(copy, membrane_fixture(copy, 4, 0.1, 100.0, 0.0, 0.01));
    ASSERT_OK(copy, canopy_model_read_state(copy, stem, -1));
    free(old);
    free(now);
    unlink(h5);
    unlink(xdmf);
    unlink(stem);
    canopy_model_destroy(&copy);
    canopy_model_destroy(&m);
}

CANOPY_TEST(robust_second_output_on_open_file)
{
    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, membrane_fixture(m, 4, 0.1, 100.0, 0.0, 0.01));
    char stem[] = "/tmp/canopy-robust-twice-XXXXXX";
    const int fd = mkstemp(stem);
    ASSERT_TRUE(fd >= 0);
    close(fd);
    char h5[64], xdmf[64];
    snprintf(h5, sizeof h5, "%s.h5", stem);
    snprintf(xdmf, sizeof xdmf, "%s.xdmf", stem);
    canopy_output *o = NULL, *again = NULL;
    ASSERT_OK(m, canopy_output_create(m, stem, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_OK(m, canopy_output_write(o, m));
    /* A second handle on the open file would replace it under the first
     * (CREATE) or write beside it (APPEND): refused, nothing changed. */
    ASSERT_FRESH(m, CANOPY_ERR_IO,
                 canopy_output_create(m, stem, CANOPY_OUTPUT_CREATE, &again),
                 "open in another canopy_output");
    ASSERT_FRESH(m, CANOPY_ERR_IO,
                 canopy_output_create(m, stem, CANOPY_OUTPUT_APPEND, &again),
                 "open in another canopy_output");
    ASSERT_TRUE(again == NULL);
    ASSERT_OK(m, canopy_output_write(o, m));
    ASSERT_TRUE(canopy_output_step_count(o) == 2);
    canopy_output_destroy(&o);
    ASSERT_OK(m, canopy_output_create(m, stem, CANOPY_OUTPUT_APPEND, &again));
    ASSERT_TRUE(canopy_output_step_count(again) == 2);
    canopy_output_destroy(&again);
    unlink(h5);
    unlink(xdmf);
    unlink(stem);
    canopy_model_destroy(&m);
}

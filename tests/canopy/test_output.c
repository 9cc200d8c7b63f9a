/* test_output.c — HDF5/XDMF output holds exactly the model's state, restart continues a run exactly, failures are clean and silent. */
#include "test.h"

#include <dirent.h>
#include <fcntl.h>
#include <hdf5.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ------------------------------------------------------------------------ */
/* Fixtures. */

enum { MAX_RING = 8, MAX_NODES = MAX_RING + 2, MAX_SPRINGS = 3 * MAX_RING,
       MAX_TRIS = MAX_RING, MAX_STEPS = 64 };

/* A small umbrella: a hub node, `ring` rim nodes at radius 0.5 (z = 0),
 * triangles (hub, r_i, r_i+1) with normal +z, fabric spokes and rim springs
 * (the rim spring r_0–r_1 left out, so one triangle has an edge without a
 * spring), and tension-only lines from the rim to a payload 1 m below. */
static canopy_status build_umbrella(canopy_model *m, int ring)
{
    canopy_status st;
    const double hub[3] = {0.0, 0.0, 0.0}, payload[3] = {0.0, 0.0, -1.0};
    if ((st = canopy_model_add_node(m, hub, 0.01, CANOPY_GROUP_FABRIC, NULL)))
        return st;
    for (int i = 0; i < ring; ++i) {
        const double a = 2.0 * M_PI * i / ring;
        const double x[3] = {0.5 * cos(a), 0.5 * sin(a), 0.0};
        if ((st = canopy_model_add_node(m, x, 0.01, CANOPY_GROUP_FABRIC, NULL)))
            return st;
    }
    int p;
    if ((st = canopy_model_add_node(m, payload, 1.0, CANOPY_GROUP_PAYLOAD, &p)))
        return st;
    if ((st = canopy_model_set_payload_node(m, p))) return st;
    for (int i = 0; i < ring; ++i) {
        const int a = 1 + i, b = 1 + (i + 1) % ring;
        if ((st = canopy_model_add_triangle(m, 0, a, b, NULL))) return st;
        if ((st = canopy_model_add_spring(m, 0, a, 200.0, 0.05,
                                          CANOPY_SPRING_MODEL_II,
                                          CANOPY_GROUP_FABRIC, NULL)))
            return st;
        if (i > 0 && (st = canopy_model_add_spring(m, a, b, 200.0, 0.05,
                                                   CANOPY_SPRING_MODEL_II,
                                                   CANOPY_GROUP_FABRIC, NULL)))
            return st;
        if ((st = canopy_model_add_spring(m, a, p, 500.0, 0.1,
                                          CANOPY_SPRING_TENSION_ONLY,
                                          CANOPY_GROUP_LINE, NULL)))
            return st;
    }
    /* A steady side force on the payload, so f_ext is not all zero. */
    double f[3 * MAX_NODES] = {0.0};
    const int n = canopy_model_node_count(m);
    f[3 * p] = 0.1;
    f[3 * p + 2] = 2.0;
    return canopy_model_set_nodal_forces(m, f, n);
}

/* The load of the demo in small: dp = 5 + 0.5 |v_payload|^2 on every
 * triangle, a function of the state, so a restart must reproduce it. */
static canopy_status set_loads(canopy_model *m)
{
    double v[3];
    canopy_status st = canopy_model_payload_state(m, NULL, v);
    if (st) return st;
    const int nt = canopy_model_triangle_count(m);
    double dp[MAX_TRIS];
    for (int t = 0; t < nt; ++t)
        dp[t] = 5.0 + 0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + 0.1 * t;
    return canopy_model_set_pressure_jump(m, dp, nt);
}

/* A fresh directory under /tmp; `path` receives "dir/name". */
static int make_dir(char *dir, size_t size)
{
    snprintf(dir, size, "/tmp/canopy-test-output-XXXXXX");
    return mkdtemp(dir) != NULL;
}

static void remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (d == NULL) return;
    struct dirent *e;
    char path[512];
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        unlink(path);
    }
    closedir(d);
    rmdir(dir);
}

static int file_exists(const char *path)
{
    struct stat s;
    return stat(path, &s) == 0;
}

/* Occurrences of `needle` in the file (-1 if it cannot be read). */
static int count_in_file(const char *path, const char *needle)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) return -1;
    static char text[1 << 20];
    size_t len = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[len] = '\0';
    int count = 0;
    for (const char *p = strstr(text, needle); p; p = strstr(p + 1, needle))
        ++count;
    return count;
}

static int copy_file(const char *from, const char *to)
{
    FILE *a = fopen(from, "rb"), *b = fopen(to, "wb");
    int ok = a != NULL && b != NULL;
    char buf[8192];
    size_t n;
    while (ok && (n = fread(buf, 1, sizeof buf, a)) > 0)
        ok = fwrite(buf, 1, n, b) == n;
    if (a) fclose(a);
    if (b && fclose(b) != 0) ok = 0;
    return ok;
}

/* Redirect stderr to a file while the library runs, to prove it prints
 * nothing (HDF5 would print its error stack by default). */
typedef struct quiet { int saved; char path[64]; } quiet;

static void quiet_begin(quiet *q)
{
    fflush(stderr);
    snprintf(q->path, sizeof q->path, "/tmp/canopy-test-stderr-XXXXXX");
    int fd = mkstemp(q->path);
    q->saved = dup(2);
    if (fd >= 0) {
        dup2(fd, 2);
        close(fd);
    }
}

/* Restores stderr; returns the bytes the library printed. */
static long quiet_end(quiet *q)
{
    fflush(stderr);
    if (q->saved >= 0) {
        dup2(q->saved, 2);
        close(q->saved);
    }
    struct stat s;
    long bytes = stat(q->path, &s) == 0 ? (long)s.st_size : -1;
    unlink(q->path);
    return bytes;
}

/* Open HDF5 files, groups, datasets, datatypes and attributes: a failure
 * path that leaks one shows up as a difference. */
static long open_h5_ids(void)
{
    return (long)H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
}

/* Read a whole dataset (converted to double or int); returns its element
 * count, -1 on failure. */
static long read_all(hid_t file, const char *path, hid_t type, void *buf,
                     long capacity)
{
    hid_t set = H5Dopen2(file, path, H5P_DEFAULT);
    if (set < 0) return -1;
    hid_t space = H5Dget_space(set);
    long n = (long)H5Sget_simple_extent_npoints(space);
    if (n > capacity ||
        (n > 0 && H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0))
        n = -1;
    H5Sclose(space);
    H5Dclose(set);
    return n;
}

static int read_int_attr(hid_t obj, const char *name)
{
    int v = -1;
    hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
    if (a < 0) return -1;
    if (H5Aread(a, H5T_NATIVE_INT, &v) < 0) v = -1;
    H5Aclose(a);
    return v;
}

static double read_time_attr(hid_t file, const char *group)
{
    double t = NAN;
    hid_t g = H5Gopen2(file, group, H5P_DEFAULT);
    if (g < 0) return t;
    hid_t a = H5Aopen(g, "time", H5P_DEFAULT);
    if (a >= 0) {
        if (H5Aread(a, H5T_NATIVE_DOUBLE, &t) < 0) t = NAN;
        H5Aclose(a);
    }
    H5Gclose(g);
    return t;
}

static int exact_equal(const double *a, const double *b, long n)
{
    for (long i = 0; i < n; ++i)
        if (a[i] != b[i]) return 0;
    return 1;
}

/* ------------------------------------------------------------------------ */
/* (a) What the file holds is exactly what the model had. */

typedef struct recorded {
    double t;
    double x[3 * MAX_NODES], v[3 * MAX_NODES], f[3 * MAX_NODES];
    double dp[MAX_TRIS], T[MAX_SPRINGS];
} recorded;

CANOPY_TEST(output_file_layout)
{
    enum { RING = 6, STEPS = 5 };
    char dir[64], path[128], h5[160], xdmf[160], tmp[176];
    ASSERT_TRUE(make_dir(dir, sizeof dir));
    snprintf(path, sizeof path, "%s/run", dir);
    snprintf(h5, sizeof h5, "%s.h5", path);
    snprintf(xdmf, sizeof xdmf, "%s.xdmf", path);
    snprintf(tmp, sizeof tmp, "%s.xdmf.tmp", path);

    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, build_umbrella(m, RING));
    const int n = canopy_model_node_count(m), ns = canopy_model_spring_count(m),
              nt = canopy_model_triangle_count(m);
    ASSERT_TRUE(n == RING + 2 && nt == RING && ns == 3 * RING - 1);
    int ends[2 * MAX_SPRINGS], groups[MAX_SPRINGS], tris[3 * MAX_TRIS];
    double rest[MAX_SPRINGS], stiff[MAX_SPRINGS], mass[MAX_NODES];
    ASSERT_OK(m, canopy_model_get_springs(m, ends, rest, stiff, ns));
    ASSERT_OK(m, canopy_model_get_spring_groups(m, groups, ns));
    ASSERT_OK(m, canopy_model_get_triangles(m, tris, nt));
    ASSERT_OK(m, canopy_model_get_masses(m, mass, n));
    ASSERT_OK(m, canopy_model_set_fixed(m, 0, 0));

    /* A sidecar left by an earlier run must not survive a new file. */
    FILE *stale = fopen(xdmf, "w");
    ASSERT_TRUE(stale != NULL);
    fputs("<Xdmf>stale</Xdmf>\n", stale);
    fclose(stale);
    canopy_output *o = NULL;
    ASSERT_OK(m, canopy_output_create(m, path, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_TRUE(o != NULL);
    ASSERT_TRUE(canopy_output_step_count(o) == 0);
    ASSERT_TRUE(!file_exists(xdmf)); /* no steps yet: no sidecar */

    static recorded rec[STEPS];
    for (int s = 0; s < STEPS; ++s) {
        if (s > 0) {
            ASSERT_OK(m, set_loads(m));
            ASSERT_OK(m, canopy_model_advance(m, 2e-3, NULL));
        }
        recorded *r = &rec[s];
        r->t = canopy_model_time(m);
        ASSERT_OK(m, canopy_model_get_positions(m, r->x, n));
        ASSERT_OK(m, canopy_model_get_velocities(m, r->v, n));
        ASSERT_OK(m, canopy_model_get_pressure_jump(m, r->dp, nt));
        ASSERT_OK(m, canopy_model_get_tensions(m, r->T, ns));
        ASSERT_STATUS(CANOPY_OK, canopy_output_write(o, m));
        ASSERT_TRUE(canopy_output_step_count(o) == s + 1);
        ASSERT_TRUE(strcmp(canopy_output_message(o), "") == 0);
        /* The sidecar after every write: the collection plus one grid per
         * step, no temporary left. */
        ASSERT_TRUE(count_in_file(xdmf, "<Grid ") == s + 2);
        ASSERT_TRUE(count_in_file(xdmf, "<Time ") == s + 1);
        ASSERT_TRUE(count_in_file(xdmf, "</Xdmf>") == 1);
        ASSERT_TRUE(!file_exists(tmp));
    }
    /* Tensions must not be trivial for the comparison to mean something. */
    double tmax = 0.0;
    for (int k = 0; k < ns; ++k)
        if (fabs(rec[STEPS - 1].T[k]) > tmax) tmax = fabs(rec[STEPS - 1].T[k]);
    ASSERT_TRUE(tmax > 1e-3);
    /* Topology written once, referenced by the other grids. */
    ASSERT_TRUE(count_in_file(xdmf, "<Topology ") == 1);
    ASSERT_TRUE(count_in_file(xdmf, "/Topology)") == STEPS - 1);
    ASSERT_TRUE(count_in_file(xdmf, "run.h5:/steps/000004/x") == 1);
    ASSERT_TRUE(count_in_file(xdmf, dir) == 0); /* relative references */
    canopy_output_destroy(&o);
    ASSERT_TRUE(o == NULL);
    canopy_output_destroy(&o); /* harmless */

    /* Reopen with the HDF5 API. */
    hid_t file = H5Fopen(h5, H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_TRUE(file >= 0);
    hid_t mesh = H5Gopen2(file, "/mesh", H5P_DEFAULT);
    ASSERT_TRUE(mesh >= 0);
    ASSERT_TRUE(read_int_attr(mesh, "nodes") == n);
    ASSERT_TRUE(read_int_attr(mesh, "springs") == ns);
    ASSERT_TRUE(read_int_attr(mesh, "triangles") == nt);
    ASSERT_TRUE(read_int_attr(mesh, "lines") == RING);
    H5Gclose(mesh);

    int ibuf[256];
    double dbuf[256];
    ASSERT_TRUE(read_all(file, "/mesh/triangles", H5T_NATIVE_INT, ibuf, 256) ==
                3 * nt);
    ASSERT_TRUE(memcmp(ibuf, tris, sizeof(int) * 3 * (size_t)nt) == 0);
    ASSERT_TRUE(read_all(file, "/mesh/springs", H5T_NATIVE_INT, ibuf, 256) ==
                2 * ns);
    ASSERT_TRUE(memcmp(ibuf, ends, sizeof(int) * 2 * (size_t)ns) == 0);
    ASSERT_TRUE(read_all(file, "/mesh/spring_group", H5T_NATIVE_INT, ibuf,
                         256) == ns);
    ASSERT_TRUE(memcmp(ibuf, groups, sizeof(int) * (size_t)ns) == 0);
    ASSERT_TRUE(read_all(file, "/mesh/spring_rest_length", H5T_NATIVE_DOUBLE,
                         dbuf, 256) == ns);
    ASSERT_TRUE(exact_equal(dbuf, rest, ns));
    ASSERT_TRUE(read_all(file, "/mesh/spring_stiffness", H5T_NATIVE_DOUBLE,
                         dbuf, 256) == ns);
    ASSERT_TRUE(exact_equal(dbuf, stiff, ns));
    ASSERT_TRUE(read_all(file, "/mesh/node_mass", H5T_NATIVE_DOUBLE, dbuf,
                         256) == n);
    ASSERT_TRUE(exact_equal(dbuf, mass, n));
    ASSERT_TRUE(read_all(file, "/mesh/node_group", H5T_NATIVE_INT, ibuf, 256) ==
                n);
    for (int i = 0; i < n; ++i)
        ASSERT_TRUE(ibuf[i] == (i == n - 1 ? CANOPY_GROUP_PAYLOAD
                                           : CANOPY_GROUP_FABRIC));
    ASSERT_TRUE(read_all(file, "/mesh/node_fixed", H5T_NATIVE_INT, ibuf, 256) ==
                n);
    for (int i = 0; i < n; ++i) ASSERT_TRUE(ibuf[i] == 0);

    /* XDMF mixed topology: triangles, then each line spring as 2 2 i j. */
    int cells[256], c = 0;
    int line_spring[MAX_SPRINGS], lines = 0;
    for (int t = 0; t < nt; ++t) {
        cells[c++] = 4;
        for (int v = 0; v < 3; ++v) cells[c++] = tris[3 * t + v];
    }
    for (int k = 0; k < ns; ++k) {
        if (groups[k] == CANOPY_GROUP_FABRIC) continue;
        line_spring[lines++] = k;
        cells[c++] = 2;
        cells[c++] = 2;
        cells[c++] = ends[2 * k];
        cells[c++] = ends[2 * k + 1];
    }
    ASSERT_TRUE(lines == RING);
    ASSERT_TRUE(read_all(file, "/mesh/cells", H5T_NATIVE_INT, ibuf, 256) == c);
    ASSERT_TRUE(memcmp(ibuf, cells, sizeof(int) * (size_t)c) == 0);

    /* Steps. */
    hid_t steps = H5Gopen2(file, "/steps", H5P_DEFAULT);
    H5G_info_t info;
    ASSERT_TRUE(steps >= 0 && H5Gget_info(steps, &info) >= 0);
    ASSERT_TRUE(info.nlinks == STEPS);
    H5Gclose(steps);
    for (int s = 0; s < STEPS; ++s) {
        const recorded *r = &rec[s];
        char g[64], d[96];
        snprintf(g, sizeof g, "/steps/%06d", s);
        ASSERT_TRUE(read_time_attr(file, g) == r->t);
        snprintf(d, sizeof d, "%s/x", g);
        ASSERT_TRUE(read_all(file, d, H5T_NATIVE_DOUBLE, dbuf, 256) == 3 * n);
        ASSERT_TRUE(exact_equal(dbuf, r->x, 3 * n));
        snprintf(d, sizeof d, "%s/v", g);
        ASSERT_TRUE(read_all(file, d, H5T_NATIVE_DOUBLE, dbuf, 256) == 3 * n);
        ASSERT_TRUE(exact_equal(dbuf, r->v, 3 * n));
        snprintf(d, sizeof d, "%s/f_ext", g);
        ASSERT_TRUE(read_all(file, d, H5T_NATIVE_DOUBLE, dbuf, 256) == 3 * n);
        ASSERT_TRUE(dbuf[3 * (n - 1)] == 0.1 && dbuf[3 * (n - 1) + 2] == 2.0 &&
                    dbuf[0] == 0.0);
        snprintf(d, sizeof d, "%s/dp", g);
        ASSERT_TRUE(read_all(file, d, H5T_NATIVE_DOUBLE, dbuf, 256) == nt);
        ASSERT_TRUE(exact_equal(dbuf, r->dp, nt));
        snprintf(d, sizeof d, "%s/tension", g);
        ASSERT_TRUE(read_all(file, d, H5T_NATIVE_DOUBLE, dbuf, 256) == ns);
        ASSERT_TRUE(exact_equal(dbuf, r->T, ns));

        /* Per cell: a triangle's dp and the mean tension of the springs on
         * its edges (found here by linear search); a line's 0 and its own. */
        double cell_dp[MAX_TRIS + MAX_SPRINGS], cell_T[MAX_TRIS + MAX_SPRINGS];
        for (int t = 0; t < nt; ++t) {
            double sum = 0.0;
            int found = 0;
            for (int e = 0; e < 3; ++e) {
                const int a = tris[3 * t + e], b = tris[3 * t + (e + 1) % 3];
                for (int k = 0; k < ns; ++k)
                    if ((ends[2 * k] == a && ends[2 * k + 1] == b) ||
                        (ends[2 * k] == b && ends[2 * k + 1] == a)) {
                        sum += r->T[k];
                        ++found;
                        break;
                    }
            }
            /* Triangle 0 lacks its rim spring. */
            ASSERT_TRUE(found == (t == 0 ? 2 : 3));
            cell_dp[t] = r->dp[t];
            cell_T[t] = sum / found;
        }
        for (int l = 0; l < lines; ++l) {
            cell_dp[nt + l] = 0.0;
            cell_T[nt + l] = r->T[line_spring[l]];
        }
        snprintf(d, sizeof d, "%s/cell_dp", g);
        ASSERT_TRUE(read_all(file, d, H5T_NATIVE_DOUBLE, dbuf, 256) ==
                    nt + lines);
        ASSERT_TRUE(exact_equal(dbuf, cell_dp, nt + lines));
        snprintf(d, sizeof d, "%s/cell_tension", g);
        ASSERT_TRUE(read_all(file, d, H5T_NATIVE_DOUBLE, dbuf, 256) ==
                    nt + lines);
        for (int k = 0; k < nt + lines; ++k)
            ASSERT_NEAR(dbuf[k], cell_T[k], 1e-14 * (fabs(cell_T[k]) + 1.0));
    }
    ASSERT_TRUE(H5Fclose(file) >= 0);

    /* Restart from step 2 into a second, identically built model. */
    canopy_model *m2 = NULL;
    ASSERT_OK(m2, canopy_model_create(&m2));
    ASSERT_OK(m2, build_umbrella(m2, RING));
    ASSERT_OK(m2, canopy_model_read_state(m2, path, 2));
    double x[3 * MAX_NODES], v[3 * MAX_NODES], dp[MAX_TRIS];
    ASSERT_OK(m2, canopy_model_get_positions(m2, x, n));
    ASSERT_OK(m2, canopy_model_get_velocities(m2, v, n));
    ASSERT_OK(m2, canopy_model_get_pressure_jump(m2, dp, nt));
    ASSERT_TRUE(canopy_model_time(m2) == rec[2].t);
    ASSERT_TRUE(exact_equal(x, rec[2].x, 3 * n));
    ASSERT_TRUE(exact_equal(v, rec[2].v, 3 * n));
    ASSERT_TRUE(exact_equal(dp, rec[2].dp, nt));
    ASSERT_OK(m2, canopy_model_read_state(m2, path, -1));
    ASSERT_TRUE(canopy_model_time(m2) == rec[STEPS - 1].t);
    ASSERT_OK(m2, canopy_model_get_positions(m2, x, n));
    ASSERT_TRUE(exact_equal(x, rec[STEPS - 1].x, 3 * n));

    canopy_model_destroy(&m2);
    canopy_model_destroy(&m);
    remove_dir(dir);
}

/* ------------------------------------------------------------------------ */
/* (b) Acceptance test 7, restart part: a run restarted from step SPLIT of its
 * own output ends exactly where the uninterrupted run ends, and its output,
 * appended to the file, continues the numbering and the times. */

static canopy_status advance_loaded(canopy_model *m, double dt)
{
    canopy_status st = set_loads(m);
    return st ? st : canopy_model_advance(m, dt, NULL);
}

static void restart_case(const char *integrator)
{
    enum { RING = 7, STEPS = 30, SPLIT = 12 };
    const double dt = 1e-3;
    char dir[64], path_a[128], path_b[128], h5_a[160], h5_b[160], xdmf_b[160];
    ASSERT_TRUE(make_dir(dir, sizeof dir));
    snprintf(path_a, sizeof path_a, "%s/a", dir);
    snprintf(path_b, sizeof path_b, "%s/b", dir);
    snprintf(h5_a, sizeof h5_a, "%s.h5", path_a);
    snprintf(h5_b, sizeof h5_b, "%s.h5", path_b);
    snprintf(xdmf_b, sizeof xdmf_b, "%s.xdmf", path_b);

    /* Run A: STEPS steps, output every step (step 0 the initial state). */
    canopy_model *a = NULL;
    ASSERT_OK(a, canopy_model_create(&a));
    ASSERT_OK(a, build_umbrella(a, RING));
    ASSERT_OK(a, canopy_model_set_integrator(a, integrator));
    const int n = canopy_model_node_count(a);
    double times[STEPS + 1];
    canopy_output *oa = NULL;
    ASSERT_OK(a, canopy_output_create(a, path_a, CANOPY_OUTPUT_CREATE, &oa));
    ASSERT_STATUS(CANOPY_OK, canopy_output_write(oa, a));
    times[0] = canopy_model_time(a);
    for (int s = 1; s <= STEPS; ++s) {
        ASSERT_OK(a, advance_loaded(a, dt));
        ASSERT_STATUS(CANOPY_OK, canopy_output_write(oa, a));
        times[s] = canopy_model_time(a);
    }
    ASSERT_TRUE(canopy_output_step_count(oa) == STEPS + 1);
    canopy_output_destroy(&oa);
    double xa[3 * MAX_NODES], va[3 * MAX_NODES];
    ASSERT_OK(a, canopy_model_get_positions(a, xa, n));
    ASSERT_OK(a, canopy_model_get_velocities(a, va, n));
    /* The run moved: the comparison is not between two rest states. */
    double x0[3 * MAX_NODES];
    canopy_model *fresh = NULL;
    ASSERT_OK(fresh, canopy_model_create(&fresh));
    ASSERT_OK(fresh, build_umbrella(fresh, RING));
    ASSERT_OK(fresh, canopy_model_get_positions(fresh, x0, n));
    ASSERT_TRUE(rel_diff(xa, x0, 3 * n) > 1e-3);
    canopy_model_destroy(&fresh);

    /* Run B: the same model rebuilt, restarted from step SPLIT of a copy of
     * A's file, output appended to that copy. */
    ASSERT_TRUE(copy_file(h5_a, h5_b));
    canopy_model *b = NULL;
    ASSERT_OK(b, canopy_model_create(&b));
    ASSERT_OK(b, build_umbrella(b, RING));
    ASSERT_OK(b, canopy_model_set_integrator(b, integrator));
    ASSERT_OK(b, canopy_model_read_state(b, path_b, SPLIT));
    ASSERT_TRUE(canopy_model_time(b) == times[SPLIT]);
    canopy_output *ob = NULL;
    ASSERT_OK(b, canopy_output_create(b, path_b, CANOPY_OUTPUT_APPEND, &ob));
    /* Steps later than the restart time were dropped. */
    ASSERT_TRUE(canopy_output_step_count(ob) == SPLIT + 1);
    ASSERT_TRUE(count_in_file(xdmf_b, "<Grid ") == SPLIT + 2);
    for (int s = SPLIT + 1; s <= STEPS; ++s) {
        ASSERT_OK(b, advance_loaded(b, dt));
        ASSERT_STATUS(CANOPY_OK, canopy_output_write(ob, b));
        ASSERT_TRUE(canopy_output_step_count(ob) == s + 1);
    }
    canopy_output_destroy(&ob);
    double xb[3 * MAX_NODES], vb[3 * MAX_NODES];
    ASSERT_OK(b, canopy_model_get_positions(b, xb, n));
    ASSERT_OK(b, canopy_model_get_velocities(b, vb, n));
    ASSERT_TRUE(rel_diff(xa, xb, 3 * n) <= 1e-12);
    ASSERT_TRUE(rel_diff(va, vb, 3 * n) <= 1e-12);
    ASSERT_NEAR(canopy_model_time(b), canopy_model_time(a), 1e-12);

    /* B's file: steps 0..STEPS, in order, with A's times, no gaps; the
     * sidecar has one grid per step. */
    hid_t file = H5Fopen(h5_b, H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_TRUE(file >= 0);
    hid_t steps = H5Gopen2(file, "/steps", H5P_DEFAULT);
    H5G_info_t info;
    ASSERT_TRUE(steps >= 0 && H5Gget_info(steps, &info) >= 0);
    ASSERT_TRUE(info.nlinks == STEPS + 1);
    H5Gclose(steps);
    for (int s = 0; s <= STEPS; ++s) {
        char g[64];
        snprintf(g, sizeof g, "/steps/%06d", s);
        ASSERT_NEAR(read_time_attr(file, g), times[s], 1e-12);
    }
    double xf[3 * MAX_NODES];
    ASSERT_TRUE(read_all(file, "/steps/000030/x", H5T_NATIVE_DOUBLE, xf,
                         3 * MAX_NODES) == 3 * n);
    ASSERT_TRUE(rel_diff(xa, xf, 3 * n) <= 1e-12);
    H5Fclose(file);
    ASSERT_TRUE(count_in_file(xdmf_b, "<Grid ") == STEPS + 2);
    ASSERT_TRUE(count_in_file(xdmf_b, "b.h5:/steps/000030/v") == 1);

    /* Reading B's last step gives A's final state. */
    canopy_model *c = NULL;
    ASSERT_OK(c, canopy_model_create(&c));
    ASSERT_OK(c, build_umbrella(c, RING));
    ASSERT_OK(c, canopy_model_read_state(c, path_b, -1));
    double xc[3 * MAX_NODES], vc[3 * MAX_NODES];
    ASSERT_OK(c, canopy_model_get_positions(c, xc, n));
    ASSERT_OK(c, canopy_model_get_velocities(c, vc, n));
    ASSERT_TRUE(rel_diff(xa, xc, 3 * n) <= 1e-12);
    ASSERT_TRUE(rel_diff(va, vc, 3 * n) <= 1e-12);

    printf("%-4s restart from step %d of %d: final state identical to the "
           "uninterrupted run (positions %.1e, velocities %.1e relative)\n",
           integrator, SPLIT, STEPS, rel_diff(xa, xb, 3 * n),
           rel_diff(va, vb, 3 * n));
    canopy_model_destroy(&c);
    canopy_model_destroy(&b);
    canopy_model_destroy(&a);
    remove_dir(dir);
}

/* rk4 depends on (t, x, v) alone; hht also carries its acceleration, which
 * the file stores. */
CANOPY_TEST(output_restart_continues_run)
{
    restart_case("rk4");
    restart_case("hht");
}

/* ------------------------------------------------------------------------ */
/* (c) Acceptance test 8, output part: failures name the file, change
 * nothing, leave no handle and print nothing. */

typedef struct snapshot {
    double t;
    double x[3 * MAX_NODES], v[3 * MAX_NODES], dp[MAX_TRIS];
} snapshot;

static canopy_status take(canopy_model *m, snapshot *s)
{
    const int n = canopy_model_node_count(m), nt = canopy_model_triangle_count(m);
    canopy_status st;
    s->t = canopy_model_time(m);
    if ((st = canopy_model_get_positions(m, s->x, n))) return st;
    if ((st = canopy_model_get_velocities(m, s->v, n))) return st;
    return canopy_model_get_pressure_jump(m, s->dp, nt);
}

static int same(const snapshot *a, const snapshot *b, int n, int nt)
{
    return a->t == b->t && exact_equal(a->x, b->x, 3 * n) &&
           exact_equal(a->v, b->v, 3 * n) && exact_equal(a->dp, b->dp, nt);
}

CANOPY_TEST(output_errors)
{
    char dir[64], path[128], other[128], missing[128], junk[128], junk_h5[160];
    ASSERT_TRUE(make_dir(dir, sizeof dir));
    snprintf(path, sizeof path, "%s/good", dir);
    snprintf(other, sizeof other, "%s/other", dir);
    snprintf(missing, sizeof missing, "%s/missing", dir);
    snprintf(junk, sizeof junk, "%s/junk", dir);
    snprintf(junk_h5, sizeof junk_h5, "%s.h5", junk);
    FILE *f = fopen(junk_h5, "w");
    ASSERT_TRUE(f != NULL);
    fputs("this is not an HDF5 file\n", f);
    fclose(f);

    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, build_umbrella(m, 6));
    ASSERT_OK(m, advance_loaded(m, 1e-3)); /* a state that is not the build */
    const int n = canopy_model_node_count(m), nt = canopy_model_triangle_count(m);
    canopy_model *m8 = NULL; /* a different model */
    ASSERT_OK(m8, canopy_model_create(&m8));
    ASSERT_OK(m8, build_umbrella(m8, 8));
    canopy_output *o = NULL;
    ASSERT_OK(m8, canopy_output_create(m8, other, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_STATUS(CANOPY_OK, canopy_output_write(o, m8));
    canopy_output_destroy(&o);
    ASSERT_OK(m, canopy_output_create(m, path, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_STATUS(CANOPY_OK, canopy_output_write(o, m));

    snapshot before, after;
    ASSERT_OK(m, take(m, &before));
    const long ids_before = open_h5_ids();
    quiet q;
    canopy_status st;
    long printed;

    /* Unwritable path: CANOPY_ERR_IO naming it, no handle. */
    canopy_output *bad = (canopy_output *)&before; /* must be reset to NULL */
    quiet_begin(&q);
    st = canopy_output_create(m, "/nonexistent/dir/out", CANOPY_OUTPUT_CREATE,
                              &bad);
    printed = quiet_end(&q);
    ASSERT_STATUS(CANOPY_ERR_IO, st);
    ASSERT_TRUE(bad == NULL);
    ASSERT_TRUE(strstr(canopy_model_message(m), "/nonexistent/dir/out") != NULL);
    ASSERT_TRUE(printed == 0);

    /* Appending to a file that is not there, or of another model. */
    quiet_begin(&q);
    st = canopy_output_create(m, missing, CANOPY_OUTPUT_APPEND, &bad);
    printed = quiet_end(&q);
    ASSERT_STATUS(CANOPY_ERR_IO, st);
    ASSERT_TRUE(bad == NULL && printed == 0);
    ASSERT_TRUE(strstr(canopy_model_message(m), missing) != NULL);
    quiet_begin(&q);
    st = canopy_output_create(m, other, CANOPY_OUTPUT_APPEND, &bad);
    printed = quiet_end(&q);
    ASSERT_STATUS(CANOPY_ERR_FORMAT, st);
    ASSERT_TRUE(bad == NULL && printed == 0);
    ASSERT_TRUE(strstr(canopy_model_message(m), "nodes") != NULL);

    /* Reading a missing file, a file that is not HDF5, a file of another
     * model, a step that does not exist: the model is unchanged each time. */
    quiet_begin(&q);
    st = canopy_model_read_state(m, missing, -1);
    printed = quiet_end(&q);
    ASSERT_STATUS(CANOPY_ERR_IO, st);
    ASSERT_TRUE(printed == 0);
    ASSERT_TRUE(strstr(canopy_model_message(m), missing) != NULL);
    ASSERT_OK(m, take(m, &after));
    ASSERT_TRUE(same(&before, &after, n, nt));

    quiet_begin(&q);
    st = canopy_model_read_state(m, junk, -1);
    printed = quiet_end(&q);
    ASSERT_STATUS(CANOPY_ERR_IO, st);
    ASSERT_TRUE(printed == 0);
    ASSERT_OK(m, take(m, &after));
    ASSERT_TRUE(same(&before, &after, n, nt));

    quiet_begin(&q);
    st = canopy_model_read_state(m, other, -1);
    printed = quiet_end(&q);
    ASSERT_STATUS(CANOPY_ERR_FORMAT, st);
    ASSERT_TRUE(printed == 0);
    ASSERT_TRUE(strstr(canopy_model_message(m), "nodes") != NULL);
    ASSERT_TRUE(strstr(canopy_model_message(m), other) != NULL);
    ASSERT_OK(m, take(m, &after));
    ASSERT_TRUE(same(&before, &after, n, nt));

    canopy_output_destroy(&o); /* `path` holds step 0 only */
    quiet_begin(&q);
    st = canopy_model_read_state(m, path, 1);
    printed = quiet_end(&q);
    ASSERT_STATUS(CANOPY_ERR_RANGE, st);
    ASSERT_TRUE(printed == 0);
    ASSERT_STATUS(CANOPY_ERR_RANGE, canopy_model_read_state(m, path, -2));
    ASSERT_OK(m, take(m, &after));
    ASSERT_TRUE(same(&before, &after, n, nt));

    /* Writing a model that does not match the output. */
    ASSERT_OK(m8, canopy_output_create(m8, other, CANOPY_OUTPUT_APPEND, &o));
    ASSERT_TRUE(canopy_output_step_count(o) == 1);
    quiet_begin(&q);
    st = canopy_output_write(o, m);
    printed = quiet_end(&q);
    ASSERT_STATUS(CANOPY_ERR_FORMAT, st);
    ASSERT_TRUE(printed == 0);
    ASSERT_TRUE(strstr(canopy_output_message(o), "nodes") != NULL);
    ASSERT_TRUE(canopy_output_step_count(o) == 1);
    canopy_output_destroy(&o);

    /* Every failure above closed what it opened. */
    ASSERT_TRUE(open_h5_ids() == ids_before - 1); /* `o` was open before */

    /* NULL handles. */
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_output_write(NULL, m));
    ASSERT_TRUE(canopy_output_step_count(NULL) == 0);
    ASSERT_TRUE(canopy_output_message(NULL) != NULL);
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT,
                  canopy_output_create(m, NULL, CANOPY_OUTPUT_CREATE, &bad));
    ASSERT_TRUE(bad == NULL);
    canopy_output_destroy(NULL);

    canopy_model_destroy(&m8);
    canopy_model_destroy(&m);
    remove_dir(dir);
}

/* canopy_output_write_framed: a step that also holds the positions in a
 * moving frame has x_frame = x - origin exactly and the origin; the
 * sidecar run-frame.xdmf shows exactly those steps with x_frame as their
 * geometry (run.xdmf shows every step with x); without framed steps there
 * is no run-frame.xdmf; APPEND rebuilds both from the file, and a
 * non-finite origin is refused with a message and writes nothing. */
CANOPY_TEST(output_moving_frame)
{
    char dir[64], path[128], h5[160], xdmf[160], frame[176];
    ASSERT_TRUE(make_dir(dir, sizeof dir));
    snprintf(path, sizeof path, "%s/run", dir);
    snprintf(h5, sizeof h5, "%s.h5", path);
    snprintf(xdmf, sizeof xdmf, "%s.xdmf", path);
    snprintf(frame, sizeof frame, "%s-frame.xdmf", path);

    canopy_model *m = NULL;
    ASSERT_OK(m, canopy_model_create(&m));
    ASSERT_OK(m, build_umbrella(m, 6));
    const int n = canopy_model_node_count(m);
    canopy_output *o = NULL;
    ASSERT_OK(m, canopy_output_create(m, path, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_OK(m, canopy_output_write(o, m));            /* step 0: plain */
    ASSERT_TRUE(file_exists(xdmf) && !file_exists(frame));
    const double origin[3] = {0.25, -1.5, 75.125};
    ASSERT_OK(m, canopy_model_step(m, 1e-3));
    ASSERT_OK(m, canopy_output_write_framed(o, m, origin)); /* step 1 */
    ASSERT_OK(m, canopy_model_step(m, 1e-3));
    ASSERT_OK(m, canopy_output_write_framed(o, m, origin)); /* step 2 */
    const double bad[3] = {0.0, NAN, 0.0};
    ASSERT_STATUS(CANOPY_ERR_ARGUMENT, canopy_output_write_framed(o, m, bad));
    ASSERT_TRUE(strstr(canopy_output_message(o), "origin") != NULL);
    ASSERT_TRUE(canopy_output_step_count(o) == 3);
    printf("run.xdmf: %d grids, %d x; run-frame.xdmf: %d grids, %d x_frame\n",
           count_in_file(xdmf, "<Grid Name=\"step_"),
           count_in_file(xdmf, "/x</DataItem>"),
           count_in_file(frame, "<Grid Name=\"step_"),
           count_in_file(frame, "/x_frame</DataItem>"));
    ASSERT_TRUE(count_in_file(xdmf, "<Grid Name=\"step_") == 3);
    ASSERT_TRUE(count_in_file(xdmf, "/x</DataItem>") == 3);
    ASSERT_TRUE(count_in_file(frame, "<Grid Name=\"step_") == 2);
    ASSERT_TRUE(count_in_file(frame, "/x_frame</DataItem>") == 2);
    ASSERT_TRUE(count_in_file(frame, "step_000000") == 0);
    canopy_output_destroy(&o);

    double x[3 * MAX_NODES], xf[3 * MAX_NODES], org[3];
    hid_t file = H5Fopen(h5, H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_TRUE(file >= 0);
    ASSERT_TRUE(read_all(file, "/steps/000002/x", H5T_NATIVE_DOUBLE, x,
                         3 * MAX_NODES) == 3 * n);
    ASSERT_TRUE(read_all(file, "/steps/000002/x_frame", H5T_NATIVE_DOUBLE, xf,
                         3 * MAX_NODES) == 3 * n);
    ASSERT_TRUE(read_all(file, "/steps/000002/frame_origin",
                         H5T_NATIVE_DOUBLE, org, 3) == 3);
    int exact = 1;
    for (int k = 0; k < 3 * n; ++k) exact &= xf[k] == x[k] - origin[k % 3];
    ASSERT_TRUE(exact);
    ASSERT_TRUE(org[0] == origin[0] && org[1] == origin[1] &&
                org[2] == origin[2]);
    ASSERT_TRUE(H5Lexists(file, "/steps/000000/x_frame", H5P_DEFAULT) == 0);
    H5Fclose(file);

    /* APPEND from the file alone: both sidecars are rebuilt */
    remove(frame);
    ASSERT_OK(m, canopy_output_create(m, path, CANOPY_OUTPUT_APPEND, &o));
    ASSERT_TRUE(count_in_file(frame, "/x_frame</DataItem>") == 2);
    ASSERT_TRUE(count_in_file(xdmf, "/x</DataItem>") == 3);
    canopy_output_destroy(&o);
    /* a new file without framed steps removes the old frame sidecar */
    ASSERT_OK(m, canopy_output_create(m, path, CANOPY_OUTPUT_CREATE, &o));
    ASSERT_OK(m, canopy_output_write(o, m));
    ASSERT_TRUE(!file_exists(frame));
    canopy_output_destroy(&o);
    canopy_model_destroy(&m);
    remove_dir(dir);
}

/* fuzz_api.c — seeded random sequences of valid and invalid libcanopy calls; after each call the promises of canopy.h are checked.
 *
 * Built by src/canopy/Makefile as build/canopy/bin/canopy-fuzz with
 * -fsanitize=address,undefined -fno-sanitize-recover=all, so that a crash,
 * undefined behaviour or a leak ends the run with a report. ./Alltest runs
 * a bounded run (fuzz/api); a longer one, e.g. before a release:
 *
 *     for s in $(seq 1 50); do
 *         build/canopy/bin/canopy-fuzz --seed $s --calls 200000 || break
 *     done
 *
 * Checked after every call (through canopy.h only, save that bad input files
 * are crafted with the HDF5 library):
 * - nothing was written on stdout or stderr;
 * - a rejected call (status != CANOPY_OK) left the model as it was: counts,
 *   time, positions, velocities, carried acceleration and its validity,
 *   masses, fixed flags, pressure jumps, rest lengths, gravity, integrator;
 *   the checkpoint still restores the state it saved; files it was given
 *   are byte-identical;
 * - its message is fresh: a known failing call sets a sentinel message
 *   first, and afterwards the message must start with the returned status's
 *   name and must not be the sentinel.
 * Reader calls (canopy_reader_*) on the files the run wrote, the bad ones,
 * bad paths, steps out of range and models of another structure: no call
 * writes a file or leaves an HDF5 identifier open; a rejection leaves a fresh
 * message on the reader, and the reader, the model (its message too) and
 * the array it was given as they were. */
#include "fuzz_api.h"

#include "canopy.h"

#include <hdf5.h>

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/common_interface_defs.h>
#endif

/* Largest model the fuzzer lets a builder make (calls that would make more
 * are skipped), and the size at which the model is started afresh. */
enum { FUZZ_MAX_NEW_NODES = 6000, FUZZ_MAX_NODES = 8000 };

/* The sentinel: set_max_omega_dt with this value is rejected. */
#define FUZZ_SENTINEL_VALUE (-7.77e-77)
#define FUZZ_SENTINEL_TEXT "-7.77e-77"

/* ---- random numbers (splitmix64) ----------------------------------------- */

static uint64_t next_u64(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/* ---- model snapshots ------------------------------------------------------ */

typedef struct snapshot {
    int n, ns, nt, acc_valid, payload_ok;
    double t, g[3];
    double *x, *v, *acc, *mass, *dp, *rest, payload[6];
    int *fixed;
    char integrator[32];
} snapshot;

static void snapshot_free(snapshot *s)
{
    free(s->x); free(s->v); free(s->acc); free(s->mass); free(s->dp);
    free(s->rest); free(s->fixed);
    memset(s, 0, sizeof *s);
}

/* Every observable of the model, read through the getters. Returns 0 when a
 * getter failed (itself a broken promise). */
static int snapshot_take(canopy_model *m, snapshot *s)
{
    snapshot_free(s);
    s->n = canopy_model_node_count(m);
    s->ns = canopy_model_spring_count(m);
    s->nt = canopy_model_triangle_count(m);
    s->t = canopy_model_time(m);
    const size_t n = (size_t)s->n + 1, ns = (size_t)s->ns + 1,
                 nt = (size_t)s->nt + 1;
    s->x = calloc(3 * n, sizeof(double));
    s->v = calloc(3 * n, sizeof(double));
    s->acc = calloc(3 * n, sizeof(double));
    s->mass = calloc(n, sizeof(double));
    s->fixed = calloc(n, sizeof(int));
    s->dp = calloc(nt, sizeof(double));
    s->rest = calloc(ns, sizeof(double));
    if (!s->x || !s->v || !s->acc || !s->mass || !s->fixed || !s->dp ||
        !s->rest)
        return 0;
    int ok = canopy_model_get_positions(m, s->x, s->n) == CANOPY_OK &&
             canopy_model_get_velocities(m, s->v, s->n) == CANOPY_OK &&
             canopy_model_get_acceleration_state(m, s->acc, s->n,
                                                 &s->acc_valid) == CANOPY_OK &&
             canopy_model_get_masses(m, s->mass, s->n) == CANOPY_OK &&
             canopy_model_get_fixed(m, s->fixed, s->n) == CANOPY_OK &&
             canopy_model_get_pressure_jump(m, s->dp, s->nt) == CANOPY_OK &&
             canopy_model_get_springs(m, NULL, s->rest, NULL, s->ns) ==
                 CANOPY_OK &&
             canopy_model_get_gravity(m, s->g) == CANOPY_OK;
    s->payload_ok = canopy_model_payload_state(m, s->payload, s->payload + 3)
                    == CANOPY_OK;
    snprintf(s->integrator, sizeof s->integrator, "%s",
             canopy_model_integrator(m));
    return ok;
}

static int same_doubles(const double *a, const double *b, size_t n)
{
    return memcmp(a, b, n * sizeof(double)) == 0;
}

/* The first difference between two snapshots in what a checkpoint holds
 * (time, positions, velocities, carried acceleration), or NULL. */
static const char *snapshot_diff_dynamic(const snapshot *a, const snapshot *b)
{
    if (a->n != b->n) return "node count";
    if (memcmp(&a->t, &b->t, sizeof a->t) != 0) return "time";
    const size_t n = (size_t)a->n;
    if (!same_doubles(a->x, b->x, 3 * n)) return "positions";
    if (!same_doubles(a->v, b->v, 3 * n)) return "velocities";
    if (a->acc_valid != b->acc_valid) return "acceleration state validity";
    if (a->acc_valid && !same_doubles(a->acc, b->acc, 3 * n))
        return "acceleration state";
    return NULL;
}

/* The first difference between two snapshots, or NULL. */
static const char *snapshot_diff(const snapshot *a, const snapshot *b)
{
    if (a->n != b->n) return "node count";
    if (a->ns != b->ns) return "spring count";
    if (a->nt != b->nt) return "triangle count";
    if (memcmp(&a->t, &b->t, sizeof a->t) != 0) return "time";
    const size_t n = (size_t)a->n;
    if (!same_doubles(a->x, b->x, 3 * n)) return "positions";
    if (!same_doubles(a->v, b->v, 3 * n)) return "velocities";
    if (a->acc_valid != b->acc_valid) return "acceleration state validity";
    if (!same_doubles(a->acc, b->acc, 3 * n)) return "acceleration state";
    if (!same_doubles(a->mass, b->mass, n)) return "masses";
    if (memcmp(a->fixed, b->fixed, n * sizeof(int)) != 0) return "fixed flags";
    if (!same_doubles(a->dp, b->dp, (size_t)a->nt)) return "pressure jumps";
    if (!same_doubles(a->rest, b->rest, (size_t)a->ns)) return "rest lengths";
    if (!same_doubles(a->g, b->g, 3)) return "gravity";
    if (a->payload_ok != b->payload_ok) return "payload node";
    if (strcmp(a->integrator, b->integrator) != 0) return "integrator";
    return NULL;
}

/* ---- files ---------------------------------------------------------------- */

typedef struct file_image {
    int exists;
    size_t size;
    unsigned char *bytes;
} file_image;

static void file_image_free(file_image *f)
{
    free(f->bytes);
    memset(f, 0, sizeof *f);
}

static void file_image_take(const char *path, file_image *f)
{
    file_image_free(f);
    FILE *fp = fopen(path, "rb");
    if (fp == NULL) return;
    f->exists = 1;
    size_t cap = 4096;
    f->bytes = malloc(cap);
    size_t got;
    while (f->bytes && (got = fread(f->bytes + f->size, 1, cap - f->size, fp))
           > 0) {
        f->size += got;
        if (f->size == cap) {
            unsigned char *b = realloc(f->bytes, 2 * cap);
            if (b == NULL) break;
            f->bytes = b;
            cap *= 2;
        }
    }
    fclose(fp);
}

static int file_image_same(const file_image *a, const file_image *b)
{
    return a->exists == b->exists && a->size == b->size &&
           (a->size == 0 || memcmp(a->bytes, b->bytes, a->size) == 0);
}

static int write_bytes(const char *path, const unsigned char *bytes,
                       size_t size)
{
    FILE *fp = fopen(path, "wb");
    if (fp == NULL) return 0;
    const int ok = fwrite(bytes, 1, size, fp) == size;
    return fclose(fp) == 0 && ok;
}

/* ---- the fuzzer's state ---------------------------------------------------- */

enum { FUZZ_PATHS = 9 };
/* Output path stems (without .h5 / .xdmf) in the temporary directory. */
static const char *const stems[FUZZ_PATHS] = {
    "good", "other", "empty", "truncated", "random", "flipped", "zero_nodes",
    "wrong_shape", "missing"};

typedef struct fuzz {
    uint64_t rng;
    FILE *report;
    canopy_model *m;
    canopy_output *out;
    int out_stem;               /* f->stem index the output writes */
    canopy_reader *r;
    int reader_stem;            /* f->stem index the reader has open, -1 */
    canopy_model *spare;        /* a model of another structure */
    char dir[256];
    char stem[FUZZ_PATHS][300];
    canopy_fuzz_counts *c;
    int capture_fd;             /* library output lands here */
    off_t captured;             /* its size after the last check */
    const char *action;         /* the call under test */
    /* The checkpoint as the fuzzer knows it: 1 the state below was saved,
     * 0 no knowledge (a successful topology change may have dropped it). */
    int ckpt_known;
    snapshot ckpt;
    snapshot before, after;
    file_image file_before[3], file_after[3];
} fuzz;

static fuzz *active; /* for the sanitizers' death callback */

static int rnd(fuzz *f, int n) /* uniform in [0, n) */
{
    return (int)(next_u64(&f->rng) % (uint64_t)n);
}

static double uniform(fuzz *f, double lo, double hi)
{
    return lo + (hi - lo) * (double)(next_u64(&f->rng) >> 11) * 0x1.0p-53;
}

static const double specials[] = {
    0.0, -0.0, 1.0, -1.0, NAN, INFINITY, -INFINITY, 4.9e-324, 2.2e-308,
    1e-310, 1e-300, 1e-161, 1e-10, 1e308, -1e308, 1.7976931348623157e308,
    0.5, 2.0, 1e-3, 1e6, -5.0, 0.1};

/* A double: usually in [lo, hi], sometimes special. */
static double pick(fuzz *f, double lo, double hi)
{
    if (rnd(f, 5) == 0)
        return specials[rnd(f, (int)(sizeof specials / sizeof specials[0]))];
    return uniform(f, lo, hi);
}

/* An index-like int: usually in [0, n), sometimes at or past its ends. */
static int pick_index(fuzz *f, int n)
{
    switch (rnd(f, 10)) {
    case 0: return -1;
    case 1: return n;
    case 2: return rnd(f, 2) ? 2147483647 : -2147483647 - 1;
    default: return n > 0 ? rnd(f, n) : 0;
    }
}

/* A count: usually `want`, sometimes off. */
static int pick_count(fuzz *f, int want)
{
    switch (rnd(f, 8)) {
    case 0: return want + 1;
    case 1: return want - 1;
    case 2: return rnd(f, 2) ? 2147483647 : -2147483647 - 1;
    default: return want;
    }
}

static void violation(fuzz *f, const char *what, const char *detail)
{
    ++f->c->violations;
    fprintf(f->report, "canopy-fuzz: call %ld (%s): %s%s%s\n", f->c->calls,
            f->action, what, detail ? ": " : "", detail ? detail : "");
    fflush(f->report);
}

/* All HDF5 identifiers in use (files, objects, dataspaces, property
 * lists, error stacks): a call that does not create or destroy an output
 * handle must leave their number as it was. */
static long hdf5_ids(void)
{
    static const H5I_type_t types[] = {
        H5I_FILE, H5I_GROUP, H5I_DATATYPE, H5I_DATASPACE, H5I_DATASET,
        H5I_ATTR, H5I_GENPROP_LST, H5I_ERROR_STACK, H5I_ERROR_MSG,
        H5I_ERROR_CLASS};
    long total = 0;
    H5E_BEGIN_TRY {
        for (size_t i = 0; i < sizeof types / sizeof types[0]; ++i) {
            hsize_t n = 0;
            if (H5Inmembers(types[i], &n) >= 0) total += (long)n;
        }
    } H5E_END_TRY;
    return total;
}

static long ids_before;

/* Destroy the output handle: afterwards no HDF5 object may be open. */
static void destroy_output(fuzz *f)
{
    if (f->out == NULL) return;
    canopy_output_destroy(&f->out);
    if (f->out != NULL) violation(f, "output_destroy left the handle", NULL);
    const ssize_t open_ids = H5Fget_obj_count((hid_t)H5F_OBJ_ALL,
                                              H5F_OBJ_ALL);
    if (open_ids != 0) {
        char text[64];
        snprintf(text, sizeof text, "%zd still open", open_ids);
        violation(f, "output_destroy left HDF5 objects open", text);
    }
}

/* HDF5 identifiers the library left open: none, save the open output's
 * file. */
static void check_hdf5_ids(fuzz *f)
{
    const ssize_t open_ids = H5Fget_obj_count((hid_t)H5F_OBJ_ALL,
                                              H5F_OBJ_ALL);
    const ssize_t allowed = f->out ? 1 : 0;
    if (open_ids > allowed) {
        char text[64];
        snprintf(text, sizeof text, "%zd open, %zd expected", open_ids,
                 allowed);
        violation(f, "HDF5 identifiers left open", text);
    }
}

/* Anything the library wrote to fd 1 or 2 since the last check. */
static void check_quiet(fuzz *f)
{
    fflush(stdout);
    fflush(stderr);
    struct stat st;
    if (fstat(f->capture_fd, &st) != 0 || st.st_size == f->captured) return;
    char text[200] = "";
    const ssize_t got = pread(f->capture_fd, text, sizeof text - 1,
                              f->captured);
    if (got > 0) text[got] = '\0';
    f->captured = st.st_size;
    violation(f, "the library wrote on stdout/stderr", text);
}

/* ---- crafted bad files ----------------------------------------------------- */

static void path_of(fuzz *f, int k, const char *ext, char *buf, size_t size)
{
    snprintf(buf, size, "%s%s", f->stem[k], ext);
}

/* A canopy-looking HDF5 file whose mesh has zero nodes and one step with
 * empty datasets, or (wrong_shape) one that claims the model's counts but
 * holds n x 2 positions. */
static void craft_h5(fuzz *f, int k, int nodes, int tris, int wrong_shape)
{
    char path[320];
    path_of(f, k, ".h5", path, sizeof path);
    H5E_BEGIN_TRY {
        hid_t file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        if (file >= 0) {
            hid_t mesh = H5Gcreate2(file, "mesh", H5P_DEFAULT, H5P_DEFAULT,
                                    H5P_DEFAULT);
            const char *names[4] = {"nodes", "springs", "triangles", "lines"};
            const int values[4] = {nodes, canopy_model_spring_count(f->m),
                                   tris, 0};
            hid_t scalar = H5Screate(H5S_SCALAR);
            for (int i = 0; i < 4; ++i) {
                hid_t a = H5Acreate2(mesh, names[i], H5T_NATIVE_INT, scalar,
                                     H5P_DEFAULT, H5P_DEFAULT);
                H5Awrite(a, H5T_NATIVE_INT, &values[i]);
                H5Aclose(a);
            }
            H5Gclose(mesh);
            hid_t steps = H5Gcreate2(file, "steps", H5P_DEFAULT, H5P_DEFAULT,
                                     H5P_DEFAULT);
            hid_t g = H5Gcreate2(steps, "000000", H5P_DEFAULT, H5P_DEFAULT,
                                 H5P_DEFAULT);
            const double t = 0.0;
            hid_t a = H5Acreate2(g, "time", H5T_NATIVE_DOUBLE, scalar,
                                 H5P_DEFAULT, H5P_DEFAULT);
            H5Awrite(a, H5T_NATIVE_DOUBLE, &t);
            H5Aclose(a);
            const char *sets[3] = {"x", "v", "f_ext"};
            double *zeros = calloc(3 * (size_t)nodes + (size_t)tris + 1,
                                   sizeof(double));
            for (int i = 0; i < 3; ++i) {
                hsize_t dims[2] = {(hsize_t)nodes,
                                   wrong_shape && i == 0 ? 2 : 3};
                hid_t sp = H5Screate_simple(2, dims, NULL);
                hid_t d = H5Dcreate2(g, sets[i], H5T_NATIVE_DOUBLE, sp,
                                     H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
                if (nodes > 0)
                    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL,
                             H5P_DEFAULT, zeros);
                H5Dclose(d);
                H5Sclose(sp);
            }
            hsize_t nt = (hsize_t)tris;
            hid_t sp = H5Screate_simple(1, &nt, NULL);
            hid_t d = H5Dcreate2(g, "dp", H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT);
            if (tris > 0)
                H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                         zeros);
            H5Dclose(d);
            H5Sclose(sp);
            free(zeros);
            H5Sclose(scalar);
            H5Gclose(g);
            H5Gclose(steps);
            H5Fclose(file);
        }
    } H5E_END_TRY;
}

/* (Re)make the bad files from the good one (if there is one). */
static void make_bad_files(fuzz *f)
{
    char path[320], good[320];
    path_of(f, 0, ".h5", good, sizeof good);
    file_image img = {0, 0, NULL};
    file_image_take(good, &img);
    path_of(f, 2, ".h5", path, sizeof path);
    write_bytes(path, (const unsigned char *)"", 0);
    if (img.exists && img.size > 16) {
        path_of(f, 3, ".h5", path, sizeof path);
        write_bytes(path, img.bytes, (size_t)rnd(f, (int)img.size));
        unsigned char *flip = malloc(img.size);
        if (flip) {
            memcpy(flip, img.bytes, img.size);
            for (int i = 0; i < 1 + rnd(f, 8); ++i)
                flip[rnd(f, (int)img.size)] ^= (unsigned char)(1 + rnd(f, 255));
            path_of(f, 5, ".h5", path, sizeof path);
            write_bytes(path, flip, img.size);
            free(flip);
        }
    }
    unsigned char noise[512];
    for (size_t i = 0; i < sizeof noise; ++i) noise[i] = (unsigned char)rnd(f, 256);
    path_of(f, 4, ".h5", path, sizeof path);
    write_bytes(path, noise, (size_t)rnd(f, (int)sizeof noise));
    craft_h5(f, 6, 0, 0, 0);
    craft_h5(f, 7, canopy_model_node_count(f->m),
             canopy_model_triangle_count(f->m), 1);
    file_image_free(&img);
}

/* ---- the checks around one call -------------------------------------------- */

static void set_sentinel(fuzz *f)
{
    if (canopy_model_set_max_omega_dt(f->m, FUZZ_SENTINEL_VALUE) !=
        CANOPY_ERR_ARGUMENT)
        violation(f, "the sentinel call was not rejected", NULL);
}

/* The message after a rejection: fresh and of the returned status. */
static void check_message(fuzz *f, const char *msg, canopy_status st)
{
    char prefix[64];
    snprintf(prefix, sizeof prefix, "%s: ", canopy_status_name(st));
    if (strstr(msg, FUZZ_SENTINEL_TEXT) != NULL)
        violation(f, "rejected with a stale message", msg);
    else if (strncmp(msg, prefix, strlen(prefix)) != 0)
        violation(f, "message does not start with the returned status", msg);
}

/* Put the model back into the state of snapshot s (positions, velocities,
 * time, carried acceleration). */
static void put_back(fuzz *f, const snapshot *s)
{
    if (canopy_model_set_positions(f->m, s->x, s->n) != CANOPY_OK ||
        canopy_model_set_velocities(f->m, s->v, s->n) != CANOPY_OK ||
        canopy_model_set_acceleration_state(f->m, s->acc, s->n,
                                            s->acc_valid) != CANOPY_OK ||
        canopy_model_set_time(f->m, s->t) != CANOPY_OK)
        violation(f, "cannot put the state back",
                  canopy_model_message(f->m));
}

/* After a rejection: is the checkpoint the fuzzer knows still restorable? */
static void check_checkpoint(fuzz *f)
{
    if (!f->ckpt_known) return;
    if (canopy_model_restore(f->m) != CANOPY_OK) {
        violation(f, "the checkpoint was dropped by a rejected call",
                  canopy_model_message(f->m));
        f->ckpt_known = 0;
        return;
    }
    snapshot now = {0};
    snapshot_take(f->m, &now);
    const char *d = snapshot_diff_dynamic(&now, &f->ckpt);
    if (d) violation(f, "restore after a rejected call changed", d);
    snapshot_free(&now);
    put_back(f, &f->after);
}

enum {
    KIND_QUERY = 0,     /* changes nothing */
    KIND_STATE = 1,     /* may change the dynamic state, not the checkpoint */
    KIND_TOPOLOGY = 2,  /* may drop the checkpoint when it succeeds */
    KIND_CHECKPOINT = 3,
    KIND_COMMIT = 4
};

/* Called before and after every call under test. files: the number of
 * output files (0..3, paths in f->file_path) the call must leave alone if
 * it is rejected. */
static char file_path[3][420];

static void before_call(fuzz *f, const char *action, int files)
{
    f->action = action;
    set_sentinel(f);
    if (!snapshot_take(f->m, &f->before))
        violation(f, "a getter failed on a sound model",
                  canopy_model_message(f->m));
    for (int i = 0; i < files; ++i) file_image_take(file_path[i],
                                                    &f->file_before[i]);
    check_quiet(f);
    ids_before = hdf5_ids();
    ++f->c->calls;
}

static void after_call(fuzz *f, canopy_status st, int kind, int files)
{
    check_quiet(f);
    check_hdf5_ids(f);
    const long ids_after = hdf5_ids();
    if (ids_after != ids_before && (st != CANOPY_OK ||
                                    strncmp(f->action, "output_create", 13))) {
        char text[64];
        snprintf(text, sizeof text, "%ld before, %ld after", ids_before,
                 ids_after);
        violation(f, "the call changed the number of HDF5 identifiers", text);
    }
    if (st == CANOPY_OK) {
        if (kind == KIND_TOPOLOGY) f->ckpt_known = 0;
        if (kind == KIND_COMMIT) f->ckpt_known = 0;
        if (kind == KIND_CHECKPOINT) {
            snapshot_free(&f->ckpt);
            f->ckpt_known = snapshot_take(f->m, &f->ckpt);
        }
        return;
    }
    ++f->c->rejections;
    check_message(f, canopy_model_message(f->m), st);
    /* The fuzzer's models are small: running out of memory means an
     * absurd allocation (a size from a bad argument), save when HDF5
     * reads a damaged file. */
    if (st == CANOPY_ERR_MEMORY && strncmp(f->action, "read_state", 10) != 0 &&
        strncmp(f->action, "output_create", 13) != 0)
        violation(f, "out of memory on a small model",
                  canopy_model_message(f->m));
    snapshot_take(f->m, &f->after);
    const char *d = snapshot_diff(&f->before, &f->after);
    if (d) violation(f, "a rejected call changed the model's", d);
    for (int i = 0; i < files; ++i) {
        file_image_take(file_path[i], &f->file_after[i]);
        if (!file_image_same(&f->file_before[i], &f->file_after[i]))
            violation(f, "a rejected call changed the file", file_path[i]);
    }
    check_checkpoint(f);
    check_quiet(f);
}


/* ---- the reader ------------------------------------------------------------ */

/* What a reader shows through canopy.h: whether a file is open, and its
 * steps' numbers and times. */
typedef struct reader_image {
    int open, count;
    int *number;
    double *time;
} reader_image;

static void reader_image_free(reader_image *img)
{
    free(img->number);
    free(img->time);
    memset(img, 0, sizeof *img);
}

/* Through the getters (which set the reader's message: take it before the
 * sentinel). Returns 0 when a getter broke its promise. */
static int reader_image_take(canopy_reader *r, reader_image *img)
{
    reader_image_free(img);
    img->count = canopy_reader_step_count(r);
    img->open = canopy_reader_step(r, 0, NULL, NULL) != CANOPY_ERR_STATE;
    const size_t n = img->count > 0 ? (size_t)img->count : 0;
    img->number = calloc(n + 1, sizeof(int));
    img->time = calloc(n + 1, sizeof(double));
    if (img->number == NULL || img->time == NULL || img->count < 0 ||
        (!img->open && img->count != 0))
        return 0;
    for (int i = 0; i < img->count; ++i)
        if (canopy_reader_step(r, i, &img->number[i], &img->time[i]) !=
            CANOPY_OK)
            return 0;
    return 1;
}

static int reader_image_same(const reader_image *a, const reader_image *b)
{
    const size_t n = a->count > 0 ? (size_t)a->count : 0;
    return a->open == b->open && a->count == b->count &&
           memcmp(a->number, b->number, n * sizeof(int)) == 0 &&
           memcmp(a->time, b->time, n * sizeof(double)) == 0;
}

/* The sentinels for a reader call: on the reader a failing open of a file
 * named after the sentinel, on the model (if any) the model's sentinel. */
static void set_reader_sentinels(fuzz *f, canopy_model *model)
{
    char path[400];
    snprintf(path, sizeof path, "%s/missing" FUZZ_SENTINEL_TEXT, f->dir);
    if (canopy_reader_open(f->r, path) != CANOPY_ERR_IO)
        violation(f, "the reader's sentinel call was not rejected",
                  canopy_reader_message(f->r));
    if (model != NULL &&
        canopy_model_set_max_omega_dt(model, FUZZ_SENTINEL_VALUE) !=
            CANOPY_ERR_ARGUMENT)
        violation(f, "the sentinel call was not rejected", NULL);
}

/* A successful find_step: the index names a step within the tolerance and
 * no step is nearer (of two equally near, the lower index). */
static void check_found(fuzz *f, const reader_image *img, double t,
                        double tol, int found)
{
    if (found < 0 || found >= img->count) {
        violation(f, "find_step gave an index out of range", NULL);
        return;
    }
    const double d = fabs(img->time[found] - t);
    if (!(d <= tol)) violation(f, "find_step gave a step beyond the tolerance",
                               NULL);
    for (int i = 0; i < img->count; ++i) {
        const double di = fabs(img->time[i] - t);
        if (di < d || (di == d && i < found))
            violation(f, "find_step did not give the nearest step", NULL);
    }
}

/* ---- actions ---------------------------------------------------------------- */

static canopy_material pick_material(fuzz *f, int sheet)
{
    canopy_material m = sheet ? canopy_material_fabric_default()
                              : canopy_material_line_default();
    if (rnd(f, 4) == 0) m.stiffness = pick(f, 0.0, 1e4);
    if (rnd(f, 4) == 0) m.modulus = pick(f, 0.0, 1e4);
    if (rnd(f, 4) == 0) m.density = pick(f, 0.0, 0.1);
    if (rnd(f, 6) == 0) m.damping = pick(f, 0.0, 1.0);
    if (rnd(f, 12) == 0) m.law = (canopy_spring_law)(rnd(f, 5) - 1);
    return m;
}

static void pick_point(fuzz *f, double p[3])
{
    for (int d = 0; d < 3; ++d) p[d] = rnd(f, 3) ? uniform(f, -1, 1) : pick(f, -1, 1);
}

/* Estimated node count of a w x l sheet at edge e (HUGE_VAL if absurd). */
static double sheet_nodes(double w, double l, double e)
{
    if (!(w > 0 && l > 0 && e > 0) || !isfinite(w * l / (e * e)))
        return 1.0; /* rejected or degenerate anyway */
    const double a = (w / e + 2.0) * (l / e + 2.0) * 1.2;
    return a;
}

static canopy_status act_build(fuzz *f, int which)
{
    canopy_status st = CANOPY_OK;
    if (which == 0) {
        canopy_rectangle_spec s = canopy_rectangle_spec_default();
        s.width = pick(f, 0.2, 1.5);
        s.length = pick(f, 0.2, 1.5);
        s.edge_length = pick(f, 0.08, 0.4);
        pick_point(f, s.origin);
        s.fabric = pick_material(f, 1);
        if (sheet_nodes(s.width, s.length, s.edge_length) > FUZZ_MAX_NEW_NODES)
            return CANOPY_OK;
        before_call(f, "build_rectangle", 0);
        st = canopy_build_rectangle(f->m, rnd(f, 40) ? &s : NULL);
    } else if (which == 1) {
        canopy_cross_spec s = canopy_cross_spec_default();
        s.span = pick(f, 0.5, 2.0);
        s.arm_width = pick(f, 0.1, 0.5);
        s.edge_length = pick(f, 0.08, 0.3);
        s.n_attachments = rnd(f, 5) ? 4 * (1 + rnd(f, 4)) : pick_index(f, 9);
        pick_point(f, s.center);
        s.fabric = pick_material(f, 1);
        if (sheet_nodes(s.span, s.arm_width, s.edge_length) * 2.0 >
                FUZZ_MAX_NEW_NODES ||
            (s.n_attachments > 64 && s.n_attachments < 2147483647))
            return CANOPY_OK;
        int attach[64];
        before_call(f, "build_cross", 0);
        st = canopy_build_cross(f->m, &s, rnd(f, 3) ? attach : NULL);
    } else if (which == 2) {
        canopy_circular_spec s = canopy_circular_spec_default();
        s.diameter = pick(f, 0.5, 2.0);
        s.edge_length = pick(f, 0.1, 0.4);
        s.vent_diameter = rnd(f, 2) ? 0.0 : pick(f, 0.0, 0.3);
        s.height = rnd(f, 2) ? 0.0 : pick(f, 0.0, 0.5);
        s.skirt_length = rnd(f, 3) ? 0.0 : pick(f, 0.0, 0.4);
        s.skirt_diameter = pick(f, 0.0, 2.0);
        s.n_attachments = rnd(f, 5) ? 4 + rnd(f, 20) : pick_index(f, 9);
        s.radial_tapes = rnd(f, 2);
        pick_point(f, s.center);
        s.fabric = pick_material(f, 1);
        s.tape = pick_material(f, 0);
        if (sheet_nodes(s.diameter, s.diameter, s.edge_length) >
                FUZZ_MAX_NEW_NODES ||
            (s.n_attachments > 64 && s.n_attachments < 2147483647))
            return CANOPY_OK;
        int attach[64];
        before_call(f, "build_circular", 0);
        st = canopy_build_circular(f->m, &s, rnd(f, 3) ? attach : NULL);
    } else if (which == 3) {
        double a[3], b[3];
        pick_point(f, a);
        pick_point(f, b);
        if (rnd(f, 6) == 0) { b[0] = a[0] + pick(f, 0, 1e-3); b[1] = a[1]; b[2] = a[2]; }
        int nseg = rnd(f, 4) ? 1 + rnd(f, 20) : pick_index(f, 3);
        if (nseg > FUZZ_MAX_NEW_NODES && nseg < 2147483647) nseg = 3;
        canopy_material mat = pick_material(f, 0);
        const int n = canopy_model_node_count(f->m);
        const int first = rnd(f, 2) ? -1 : pick_index(f, n);
        before_call(f, "build_chord", 0);
        int last;
        st = canopy_build_chord(f->m, rnd(f, 30) ? a : NULL,
                                rnd(f, 30) ? b : NULL, nseg, &mat,
                                (canopy_group)(rnd(f, 12) ? 2 : rnd(f, 7) - 1),
                                first, &last);
    } else {
        const int n = canopy_model_node_count(f->m);
        int attach[24];
        int na = rnd(f, 4) ? 3 + rnd(f, 10) : pick_index(f, 5);
        if (na > 24 || na < 0) na = rnd(f, 2) ? -1 : 0;
        for (int k = 0; k < (na > 0 ? na : 0); ++k)
            attach[k] = rnd(f, 10) ? (n > 0 ? rnd(f, n) : 0) : pick_index(f, n);
        canopy_lines_spec s = canopy_lines_spec_default();
        s.line_length = pick(f, 0.5, 3.0);
        s.edge_length = pick(f, 0.1, 0.5);
        s.payload_mass = pick(f, 0.0, 10.0);
        s.line = pick_material(f, 0);
        if (isfinite(s.line_length) && s.edge_length > 0 &&
            s.line_length / s.edge_length * (na + 1) > FUZZ_MAX_NEW_NODES &&
            s.line_length < 1e300)
            return CANOPY_OK;
        before_call(f, "build_suspension_lines", 0);
        int payload;
        st = canopy_build_suspension_lines(f->m, rnd(f, 30) ? attach : NULL,
                                           na, &s, &payload);
    }
    after_call(f, st, KIND_TOPOLOGY, 0);
    return st;
}

static canopy_status act_by_hand(fuzz *f)
{
    const int n = canopy_model_node_count(f->m);
    canopy_status st;
    int kind = KIND_TOPOLOGY;
    switch (rnd(f, 8)) {
    case 0: {
        double x[3];
        pick_point(f, x);
        before_call(f, "add_node", 0);
        st = canopy_model_add_node(f->m, rnd(f, 30) ? x : NULL,
                                   pick(f, 0.0, 1.0),
                                   (canopy_group)(rnd(f, 10) ? 0 : rnd(f, 7) - 1),
                                   NULL);
        break;
    }
    case 1:
        before_call(f, "add_node_mass", 0);
        st = canopy_model_add_node_mass(f->m, pick_index(f, n), pick(f, 0, 1));
        break;
    case 2:
        before_call(f, "set_fixed", 0);
        st = canopy_model_set_fixed(f->m, pick_index(f, n), rnd(f, 3) - 1);
        break;
    case 3:
        before_call(f, "add_spring", 0);
        st = canopy_model_add_spring(f->m, pick_index(f, n), pick_index(f, n),
                                     pick(f, 1.0, 1e4), pick(f, 0.0, 1.0),
                                     (canopy_spring_law)(rnd(f, 8) ? rnd(f, 3)
                                                                   : rnd(f, 6) - 1),
                                     (canopy_group)(rnd(f, 8) ? rnd(f, 5) : 9),
                                     NULL);
        break;
    case 4:
        before_call(f, "set_rest_length", 0);
        st = canopy_model_set_rest_length(
            f->m, pick_index(f, canopy_model_spring_count(f->m)),
            pick(f, 0.01, 1.0));
        kind = KIND_STATE;
        break;
    case 5:
        before_call(f, "add_triangle", 0);
        st = canopy_model_add_triangle(f->m, pick_index(f, n), pick_index(f, n),
                                       pick_index(f, n), NULL);
        break;
    case 6: {
        double axis[3];
        pick_point(f, axis);
        if (!rnd(f, 8)) axis[0] = axis[1] = axis[2] = 0.0;
        before_call(f, "set_guide", 0);
        st = canopy_model_set_guide(f->m, pick_index(f, n),
                                    rnd(f, 10) ? axis : NULL);
        break;
    }
    default:
        before_call(f, "set_payload_node", 0);
        st = canopy_model_set_payload_node(f->m, pick_index(f, n));
        kind = KIND_STATE;
        break;
    }
    after_call(f, st, kind, 0);
    return st;
}

/* Setters of controls and loads. */
static void act_settings(fuzz *f)
{
    const int n = canopy_model_node_count(f->m);
    const int nt = canopy_model_triangle_count(f->m);
    canopy_status st;
    int kind = KIND_STATE;
    double *buf = calloc(3 * (size_t)(n > nt ? n : nt) + 3, sizeof(double));
    double *dir = calloc(3 * (size_t)n + 3, sizeof(double));
    if (!buf || !dir) { free(buf); free(dir); return; }
    switch (rnd(f, 18)) {
    case 0: {
        double g[3] = {pick(f, -1, 1), pick(f, -1, 1), pick(f, -12, 0)};
        before_call(f, "set_gravity", 0);
        st = canopy_model_set_gravity(f->m, rnd(f, 20) ? g : NULL);
        break;
    }
    case 1:
        before_call(f, "set_porosity", 0);
        st = canopy_model_set_porosity(f->m, pick(f, 0, 300), pick(f, 0, 10));
        break;
    case 2: {
        static const char *const names[] = {
            "euler", "euler-cromer", "euler-richardson", "heun", "verlet",
            "rk4", "newmark", "hht", "kang", "rk5", "", NULL};
        before_call(f, "set_integrator", 0);
        st = canopy_model_set_integrator(f->m, names[rnd(f, 12)]);
        kind = KIND_TOPOLOGY; /* may re-validate */
        break;
    }
    case 3:
        before_call(f, "set_max_omega_dt", 0);
        st = canopy_model_set_max_omega_dt(f->m, pick(f, 0.05, 1.0));
        break;
    case 4:
        before_call(f, "set_hht_alpha", 0);
        st = canopy_model_set_hht_alpha(f->m, pick(f, -0.33, 0.0));
        break;
    case 5:
        before_call(f, "set_implicit_controls", 0);
        st = canopy_model_set_implicit_controls(f->m, pick(f, 1e-12, 1e-6),
                                                rnd(f, 5) ? 1 + rnd(f, 30)
                                                          : pick_index(f, 2));
        break;
    case 6:
        before_call(f, "set_bending_damping", 0);
        st = canopy_model_set_bending_damping(f->m, pick(f, 0, 100));
        break;
    case 7:
        before_call(f, "set_bending_damping_implicit", 0);
        st = canopy_model_set_bending_damping_implicit(f->m, rnd(f, 3) - 1);
        break;
    case 8:
        before_call(f, "set_bending_damping_filter", 0);
        st = canopy_model_set_bending_damping_filter(f->m, rnd(f, 3) - 1);
        break;
    case 9:
        before_call(f, "set_fabric_compression", 0);
        st = canopy_model_set_fabric_compression(f->m, pick(f, 0, 1));
        break;
    case 10:
        before_call(f, "set_speed_limit", 0);
        st = canopy_model_set_speed_limit(f->m, pick(f, 1, 1e4));
        break;
    case 11:
        for (int t = 0; t < nt; ++t) buf[t] = rnd(f, 50) ? uniform(f, -50, 50)
                                                         : pick(f, -50, 50);
        before_call(f, "set_pressure_jump", 0);
        st = canopy_model_set_pressure_jump(f->m, rnd(f, 20) ? buf : NULL,
                                            pick_count(f, nt));
        break;
    case 12:
        for (int i = 0; i < 3 * n; ++i) buf[i] = rnd(f, 50) ? uniform(f, -1, 1)
                                                            : pick(f, -1, 1);
        before_call(f, "set_nodal_forces", 0);
        st = canopy_model_set_nodal_forces(f->m, rnd(f, 20) ? buf : NULL,
                                           pick_count(f, n));
        break;
    case 13:
        for (int i = 0; i < n; ++i) buf[i] = rnd(f, 50) ? uniform(f, 0, 0.01)
                                                        : pick(f, 0, 0.01);
        before_call(f, "set_added_mass", 0);
        st = canopy_model_set_added_mass(f->m, rnd(f, 20) ? buf : NULL,
                                         pick_count(f, n));
        kind = KIND_TOPOLOGY;
        break;
    case 14:
        for (int i = 0; i < n; ++i) buf[i] = rnd(f, 50) ? uniform(f, 0, 0.01)
                                                        : pick(f, 0, 0.01);
        for (int i = 0; i < 3 * n; ++i) dir[i] = rnd(f, 50) ? uniform(f, -1, 1)
                                                            : pick(f, -1, 1);
        before_call(f, "set_directional_added_mass", 0);
        st = canopy_model_set_directional_added_mass(
            f->m, rnd(f, 20) ? buf : NULL, rnd(f, 20) ? dir : NULL,
            pick_count(f, n));
        kind = KIND_TOPOLOGY;
        break;
    case 15:
        for (int t = 0; t < nt; ++t) buf[t] = rnd(f, 50) ? uniform(f, 0, 0.01)
                                                         : pick(f, 0, 0.01);
        before_call(f, "set_triangle_added_mass", 0);
        st = canopy_model_set_triangle_added_mass(f->m, rnd(f, 20) ? buf : NULL,
                                                  pick_count(f, nt));
        kind = KIND_TOPOLOGY;
        break;
    case 16:
        before_call(f, "set_pressure_frozen", 0);
        st = canopy_model_set_pressure_frozen(f->m, rnd(f, 3) - 1);
        break;
    default:
        before_call(f, "set_time", 0);
        st = canopy_model_set_time(f->m, pick(f, 0, 10));
        break;
    }
    after_call(f, st, kind, 0);
    free(buf);
    free(dir);
}

/* Setters of the state, and every getter (with NULL or short arrays). */
static void act_state(fuzz *f)
{
    const int n = canopy_model_node_count(f->m);
    const int ns = canopy_model_spring_count(f->m);
    const int nt = canopy_model_triangle_count(f->m);
    const size_t big = 3 * (size_t)(n > ns ? (n > nt ? n : nt) : (ns > nt ? ns : nt)) + 6;
    double *buf = calloc(big, sizeof(double));
    double *buf2 = calloc(big, sizeof(double));
    int *ibuf = calloc(big, sizeof(int));
    if (!buf || !buf2 || !ibuf) { free(buf); free(buf2); free(ibuf); return; }
    const int null = rnd(f, 6) == 0;
    double *out = null ? NULL : buf;
    int *iout = null ? NULL : ibuf;
    canopy_status st;
    int kind = KIND_QUERY;
    canopy_model_get_positions(f->m, buf, n);
    switch (rnd(f, 25)) {
    case 0:
        for (int i = 0; i < 3 * n; ++i)
            buf[i] += rnd(f, 40) ? uniform(f, -1e-3, 1e-3) : pick(f, -1, 1);
        before_call(f, "set_positions", 0);
        st = canopy_model_set_positions(f->m, null ? NULL : buf,
                                        pick_count(f, n));
        kind = KIND_STATE;
        break;
    case 1:
        for (int i = 0; i < 3 * n; ++i)
            buf[i] = rnd(f, 40) ? uniform(f, -1, 1) : pick(f, -1, 1);
        before_call(f, "set_velocities", 0);
        st = canopy_model_set_velocities(f->m, out, pick_count(f, n));
        kind = KIND_STATE;
        break;
    case 2:
        for (int i = 0; i < 3 * n; ++i)
            buf[i] = rnd(f, 40) ? uniform(f, -1, 1) : pick(f, -1, 1);
        before_call(f, "set_acceleration_state", 0);
        st = canopy_model_set_acceleration_state(f->m, out, pick_count(f, n),
                                                 rnd(f, 3) - 1);
        kind = KIND_STATE;
        break;
    case 3:
        before_call(f, "get_positions", 0);
        st = canopy_model_get_positions(f->m, out, pick_count(f, n));
        break;
    case 4:
        before_call(f, "get_velocities", 0);
        st = canopy_model_get_velocities(f->m, out, pick_count(f, n));
        break;
    case 5: {
        int valid;
        before_call(f, "get_acceleration_state", 0);
        st = canopy_model_get_acceleration_state(f->m, out, pick_count(f, n),
                                                 rnd(f, 4) ? &valid : NULL);
        break;
    }
    case 6:
        before_call(f, "get_masses", 0);
        st = canopy_model_get_masses(f->m, out, pick_count(f, n));
        break;
    case 7:
        before_call(f, "get_fixed", 0);
        st = canopy_model_get_fixed(f->m, iout, pick_count(f, n));
        break;
    case 8:
        before_call(f, "get_node_groups", 0);
        st = canopy_model_get_node_groups(f->m, iout, pick_count(f, n));
        break;
    case 9:
        before_call(f, "get_springs", 0);
        st = canopy_model_get_springs(f->m, iout, rnd(f, 2) ? out : NULL,
                                      rnd(f, 2) ? buf2 : NULL,
                                      pick_count(f, ns));
        break;
    case 10:
        before_call(f, "get_spring_groups", 0);
        st = canopy_model_get_spring_groups(f->m, iout, pick_count(f, ns));
        break;
    case 11:
        before_call(f, "get_triangles", 0);
        st = canopy_model_get_triangles(f->m, iout, pick_count(f, nt));
        break;
    case 12:
        before_call(f, "get_pressure_jump", 0);
        st = canopy_model_get_pressure_jump(f->m, out, pick_count(f, nt));
        break;
    case 13:
        before_call(f, "get_triangle_geometry", 0);
        st = canopy_model_get_triangle_geometry(
            f->m, rnd(f, 2) ? out : NULL, rnd(f, 2) ? buf2 : NULL, NULL,
            pick_count(f, nt));
        break;
    case 14:
        before_call(f, "get_triangle_velocities", 0);
        st = canopy_model_get_triangle_velocities(f->m, out, pick_count(f, nt));
        break;
    case 15:
        before_call(f, "get_normal_velocities", 0);
        st = canopy_model_get_normal_velocities(f->m, out, pick_count(f, nt));
        break;
    case 16: {
        canopy_energies e;
        before_call(f, "energies", 0);
        st = canopy_model_energies(f->m, null ? NULL : &e);
        break;
    }
    case 17:
        before_call(f, "canopy_area", 0);
        st = canopy_model_canopy_area(f->m, out);
        break;
    case 18:
        before_call(f, "projected_diameter", 0);
        st = canopy_model_projected_diameter(f->m, out);
        break;
    case 19:
        before_call(f, "payload_state", 0);
        st = canopy_model_payload_state(f->m, out, rnd(f, 4) ? buf2 : NULL);
        break;
    case 20:
        before_call(f, "get_forces", 0);
        st = canopy_model_get_forces(f->m, out, pick_count(f, n));
        kind = KIND_TOPOLOGY; /* prepares */
        break;
    case 21:
        before_call(f, "get_tensions", 0);
        st = canopy_model_get_tensions(f->m, out, pick_count(f, ns));
        break;
    case 22:
        before_call(f, "get_gravity", 0);
        st = canopy_model_get_gravity(f->m, out);
        break;
    case 23: {
        /* the whole state: positions nudged, velocities and acceleration
         * from the fuzzer's values (NaN, huge, -0 among them) */
        for (int i = 0; i < 3 * n; ++i) {
            buf[i] += rnd(f, 40) ? uniform(f, -1e-3, 1e-3) : pick(f, -1, 1);
            buf2[i] = rnd(f, 40) ? uniform(f, -1, 1) : pick(f, -1, 1);
        }
        const int valid = rnd(f, 3) - 1;
        before_call(f, "set_state", 0);
        st = canopy_model_set_state(f->m, pick(f, 0, 10), out,
                                    rnd(f, 8) ? buf2 : NULL,
                                    rnd(f, 4) ? buf2 : NULL, valid,
                                    pick_count(f, n));
        kind = KIND_STATE;
        break;
    }
    default:
        if (n > 400) { st = CANOPY_OK; break; }
        before_call(f, "max_frequency", 0);
        st = canopy_model_max_frequency(f->m, out, rnd(f, 2) ? buf2 : NULL);
        kind = KIND_TOPOLOGY;
        break;
    }
    after_call(f, st, kind, 0);
    free(buf);
    free(buf2);
    free(ibuf);
}

static void act_time(fuzz *f)
{
    canopy_status st;
    switch (rnd(f, 7)) {
    case 0: {
        double w;
        before_call(f, "frequency_bound", 0);
        st = canopy_model_frequency_bound(f->m, rnd(f, 6) ? &w : NULL);
        after_call(f, st, KIND_TOPOLOGY, 0);
        return;
    }
    case 1: {
        double h;
        before_call(f, "stable_step", 0);
        st = canopy_model_stable_step(f->m, rnd(f, 6) ? &h : NULL);
        after_call(f, st, KIND_TOPOLOGY, 0);
        return;
    }
    default:
        break;
    }
    /* A step whose sub-step count the fuzzer can afford; absurd steps are
     * tried too, when the library must refuse them. */
    double h = 0.0;
    if (canopy_model_stable_step(f->m, &h) != CANOPY_OK || !(h > 0.0))
        h = 1e-4;
    if (!isfinite(h)) h = 1e-3;
    double dt = rnd(f, 5) ? h * uniform(f, 0.1, 20.0) : pick(f, 0, 1e-3);
    const double ratio = dt / h;
    if (ratio > 50.0 && ratio <= 1e9) dt = h * 10.0;
    const int n = canopy_model_node_count(f->m);
    if (n > 3000 && dt > h) dt = h;
    /* An implicit step on a large, stiff model may take minutes under the
     * sanitizers (Newton x conjugate gradients x halvings): not a bug, but
     * not what a bounded run can afford. */
    const char *name = canopy_model_integrator(f->m);
    if (n > 300 && (strcmp(name, "newmark") == 0 || strcmp(name, "hht") == 0 ||
                    strcmp(name, "kang") == 0))
        return;
    if (rnd(f, 2)) {
        before_call(f, "step", 0);
        st = canopy_model_step(f->m, dt > h * 2 ? h : dt);
    } else {
        int sub;
        before_call(f, "advance", 0);
        st = canopy_model_advance(f->m, dt, rnd(f, 2) ? &sub : NULL);
    }
    after_call(f, st, KIND_TOPOLOGY, 0);
}

static void act_checkpoint(fuzz *f)
{
    canopy_status st;
    switch (rnd(f, 3)) {
    case 0:
        before_call(f, "checkpoint", 0);
        st = canopy_model_checkpoint(f->m);
        after_call(f, st, KIND_CHECKPOINT, 0);
        break;
    case 1:
        before_call(f, "restore", 0);
        st = canopy_model_restore(f->m);
        after_call(f, st, KIND_STATE, 0);
        if (st == CANOPY_OK && f->ckpt_known) {
            snapshot now = {0};
            snapshot_take(f->m, &now);
            const char *d = snapshot_diff_dynamic(&now, &f->ckpt);
            if (d) violation(f, "restore did not return the checkpoint's", d);
            snapshot_free(&now);
        }
        break;
    default:
        before_call(f, "commit", 0);
        st = canopy_model_commit(f->m);
        after_call(f, st, KIND_COMMIT, 0);
        break;
    }
}

/* One call on the fuzzer's reader, on the file of stem k (favouring the one
 * the output writes), a bad path, an index out of range or a model of
 * another structure; the checks of the header's "Reader calls". */
static void act_reader(fuzz *f, int k)
{
    if (f->r == NULL || rnd(f, 40) == 0) {
        ++f->c->calls;
        f->action = "reader_destroy, reader_create";
        canopy_reader_destroy(&f->r);
        if (f->r != NULL) violation(f, "reader_destroy left the handle", NULL);
        f->reader_stem = -1;
        if (canopy_reader_create(&f->r) != CANOPY_OK || f->r == NULL) {
            violation(f, "reader_create failed", NULL);
            return;
        }
        check_quiet(f);
    }
    f->action = "reader (setting up)";
    if (f->out && rnd(f, 2)) k = f->out_stem;
    const int op = rnd(f, 6);
    /* The files the call could read: the one it opens, or the open one */
    const int touched = op == 0 || f->reader_stem < 0 ? k : f->reader_stem;
    path_of(f, touched, ".h5", file_path[0], sizeof file_path[0]);
    path_of(f, touched, ".xdmf", file_path[1], sizeof file_path[1]);
    /* The model a load goes into: mostly the fuzzer's, sometimes one of
     * another structure, rarely none */
    canopy_model *model = rnd(f, 8) ? f->m : f->spare;
    if (op >= 3 && rnd(f, 40) == 0) model = NULL;
    canopy_model *watched = model ? model : f->m;

    reader_image before = {0, 0, NULL, NULL}, after = {0, 0, NULL, NULL};
    if (!reader_image_take(f->r, &before))
        violation(f, "a reader getter failed", canopy_reader_message(f->r));
    if (!snapshot_take(watched, &f->before))
        violation(f, "a getter failed on a sound model",
                  canopy_model_message(watched));
    for (int i = 0; i < 2; ++i)
        file_image_take(file_path[i], &f->file_before[i]);

    /* The call's arguments */
    const int index = pick_index(f, before.count);
    char bad[400];
    const char *path = f->stem[k];
    int path_stem = k;
    if (op == 0 && rnd(f, 6) == 0) {
        path_stem = -1;
        switch (rnd(f, 3)) {
        case 0: path = NULL; break;
        case 1: path = ""; break;
        default:
            snprintf(bad, sizeof bad, "%s/no/such/dir/x", f->dir);
            path = bad;
            break;
        }
    }
    double t = pick(f, -1.0, 1.0);
    if (before.count > 0 && rnd(f, 2)) {
        t = before.time[rnd(f, before.count)];
        if (rnd(f, 2)) t += uniform(f, -1e-3, 1e-3);
    }
    const double tol = rnd(f, 4) ? uniform(f, 0.0, 1e-3) : pick(f, -1e-3, 1.0);
    double offset[3];
    for (int d = 0; d < 3; ++d) offset[d] = rnd(f, 6) ? uniform(f, -5, 5)
                                                      : pick(f, -5, 5);
    const int want = canopy_model_node_count(watched);
    const int n = pick_count(f, want);
    /* A buffer of 3 n doubles (4 for a count that is absurd), filled with a
     * pattern a rejection must leave */
    const size_t cap = n >= 0 && n <= FUZZ_MAX_NODES + 1 ? 3 * (size_t)n + 1
                                                         : 4;
    double *forces = malloc(cap * sizeof(double));
    double *pattern = malloc(cap * sizeof(double));
    if (forces == NULL || pattern == NULL) {
        violation(f, "the fuzzer ran out of memory", NULL);
        free(forces);
        free(pattern);
        reader_image_free(&before);
        return;
    }
    memset(pattern, 0x5a, cap * sizeof(double));
    memcpy(forces, pattern, cap * sizeof(double));
    int number = -12345, found = -12345;
    double time = -12345.0;

    set_reader_sentinels(f, model);
    check_quiet(f);
    ids_before = hdf5_ids();
    ++f->c->calls;
    canopy_status st;
    switch (op) {
    case 0:
        f->action = "reader_open";
        st = canopy_reader_open(f->r, path);
        break;
    case 1:
        f->action = "reader_step";
        st = canopy_reader_step(f->r, index, rnd(f, 4) ? &number : NULL,
                                rnd(f, 4) ? &time : NULL);
        break;
    case 2:
        f->action = "reader_find_step";
        st = canopy_reader_find_step(f->r, t, tol,
                                     rnd(f, 30) ? &found : NULL);
        break;
    case 3:
        f->action = "reader_read_state";
        st = canopy_reader_read_state(f->r, index, model);
        break;
    case 4:
        f->action = "reader_read_motion";
        st = canopy_reader_read_motion(f->r, index, model,
                                       rnd(f, 3) ? offset : NULL);
        break;
    default:
        f->action = "reader_get_nodal_forces";
        st = canopy_reader_get_nodal_forces(f->r, index,
                                            rnd(f, 30) ? forces : NULL, n);
        break;
    }

    /* Whatever the status: quiet, no identifier left, no file written */
    check_quiet(f);
    check_hdf5_ids(f);
    if (hdf5_ids() != ids_before)
        violation(f, "the reader changed the number of HDF5 identifiers",
                  NULL);
    for (int i = 0; i < 2; ++i) {
        file_image_take(file_path[i], &f->file_after[i]);
        if (!file_image_same(&f->file_before[i], &f->file_after[i]))
            violation(f, "a reader call changed the file", file_path[i]);
    }

    if (st == CANOPY_OK) {
        const int in_range = index >= 0 && index < before.count;
        if (op != 0 && op != 2 && !in_range)
            violation(f, "a step index out of range was accepted", NULL);
        if (op == 1 && in_range &&
            ((number != -12345 && number != before.number[index]) ||
             (time != -12345.0 &&
              memcmp(&time, &before.time[index], sizeof time) != 0)))
            violation(f, "reader_step gave another step than the list", NULL);
        if (op == 2 && found != -12345) check_found(f, &before, t, tol, found);
        if (op == 4) {
            snapshot_take(watched, &f->after);
            if (memcmp(&f->after.t, &f->before.t, sizeof f->after.t) != 0 ||
                f->after.acc_valid)
                violation(f, "read_motion changed the time or kept the "
                          "carried acceleration", NULL);
        }
        if (op == 5)
            for (size_t i = 0; i < 3 * (size_t)n; ++i)
                if (!isfinite(forces[i])) {
                    violation(f, "get_nodal_forces gave a value that is not "
                              "finite", NULL);
                    break;
                }
        if (op != 3 && op != 4) {
            /* Calls that take no model leave every model alone */
            snapshot_take(watched, &f->after);
            const char *d = snapshot_diff(&f->before, &f->after);
            if (d) violation(f, "a reader call without a model changed the "
                             "model's", d);
        }
        if (!reader_image_take(f->r, &after))
            violation(f, "a reader getter failed after a call",
                      canopy_reader_message(f->r));
        if (op == 0) {
            /* The new file's steps: sorted by number, finite times */
            f->reader_stem = path_stem;
            for (int i = 0; i < after.count; ++i)
                if (!isfinite(after.time[i]) ||
                    (i > 0 && after.number[i] <= after.number[i - 1]))
                    violation(f, "reader_open listed steps out of order or "
                              "with a time that is not finite", NULL);
        } else if (!reader_image_same(&before, &after)) {
            violation(f, "a reader call other than open changed the "
                      "reader's steps", NULL);
        }
    } else {
        ++f->c->rejections;
        check_message(f, canopy_reader_message(f->r), st);
        if (st == CANOPY_ERR_MEMORY && (op == 1 || op == 2))
            violation(f, "out of memory without reading a file",
                      canopy_reader_message(f->r));
        if (model != NULL && (op == 3 || op == 4) &&
            strstr(canopy_model_message(model), FUZZ_SENTINEL_TEXT) == NULL)
            violation(f, "a rejected reader call changed the model's message",
                      canopy_model_message(model));
        if (memcmp(forces, pattern, cap * sizeof(double)) != 0)
            violation(f, "a rejected get_nodal_forces wrote its array", NULL);
        if (!reader_image_take(f->r, &after))
            violation(f, "a reader getter failed after a rejection",
                      canopy_reader_message(f->r));
        if (!reader_image_same(&before, &after))
            violation(f, "a rejected reader call changed the reader", NULL);
        snapshot_take(watched, &f->after);
        const char *d = snapshot_diff(&f->before, &f->after);
        if (d) violation(f, "a rejected reader call changed the model's", d);
        if (watched == f->m) check_checkpoint(f);
    }
    check_quiet(f);
    free(forces);
    free(pattern);
    reader_image_free(&before);
    reader_image_free(&after);
}

static void act_files(fuzz *f)
{
    const int k = rnd(f, FUZZ_PATHS);
    path_of(f, k, ".h5", file_path[0], sizeof file_path[0]);
    path_of(f, k, ".xdmf", file_path[1], sizeof file_path[1]);
    canopy_status st;
    switch (rnd(f, 6)) {
    case 0: {
        /* Create: a fresh "good" file (or "other"); bad paths too. */
        destroy_output(f);
        const int which = rnd(f, 8) ? rnd(f, 2) : 8;
        char path[400];
        if (which == 8) snprintf(path, sizeof path, "%s/no/such/dir/x", f->dir);
        else snprintf(path, sizeof path, "%s", f->stem[which]);
        snprintf(file_path[0], sizeof file_path[0], "%s.h5", path);
        snprintf(file_path[1], sizeof file_path[1], "%s.xdmf", path);
        before_call(f, "output_create CREATE", 2);
        st = canopy_output_create(f->m, rnd(f, 30) ? path : NULL,
                                  CANOPY_OUTPUT_CREATE,
                                  rnd(f, 30) ? &f->out : NULL);
        after_call(f, st, KIND_QUERY, 2);
        if (st == CANOPY_OK) f->out_stem = which;
        if (st == CANOPY_OK && rnd(f, 2)) make_bad_files(f);
        break;
    }
    case 1: {
        if (f->out && rnd(f, 3) == 0) {
            /* A second handle on the file the first one writes. */
            path_of(f, f->out_stem, ".h5", file_path[0], sizeof file_path[0]);
            path_of(f, f->out_stem, ".xdmf", file_path[1],
                    sizeof file_path[1]);
            canopy_output *second = NULL;
            before_call(f, "output_create on an open file", 2);
            st = canopy_output_create(f->m, f->stem[f->out_stem],
                                      rnd(f, 2) ? CANOPY_OUTPUT_APPEND
                                                : CANOPY_OUTPUT_CREATE,
                                      &second);
            if (st == CANOPY_OK) {
                violation(f, "a second output on an open file", NULL);
                canopy_output_destroy(&second);
            }
            after_call(f, st, KIND_QUERY, 2);
            break;
        }
        destroy_output(f);
        before_call(f, "output_create APPEND", 2);
        st = canopy_output_create(f->m, f->stem[k],
                                  rnd(f, 20) ? CANOPY_OUTPUT_APPEND
                                             : (canopy_output_mode)7,
                                  &f->out);
        after_call(f, st, KIND_QUERY, 2);
        if (st == CANOPY_OK) f->out_stem = k;
        break;
    }
    case 2:
    case 3: {
        if (f->out == NULL) break;
        if (canopy_output_step_count(f->out) >= 12) {
            /* Keep the files (which the checks read) small. */
            destroy_output(f);
            break;
        }
        ++f->c->calls;
        /* the ground frame only, or a moving frame's too (its origin
         * sometimes NULL or not finite) */
        const int framed = rnd(f, 2);
        double origin[3];
        pick_point(f, origin);
        if (framed && !rnd(f, 10)) origin[rnd(f, 3)] = rnd(f, 2) ? NAN : INFINITY;
        f->action = framed ? "output_write_framed" : "output_write";
        /* Sentinel on the output handle: output_write with a NULL model. */
        if (canopy_output_write(f->out, NULL) != CANOPY_ERR_ARGUMENT)
            violation(f, "output_write(NULL model) was not rejected", NULL);
        snapshot_take(f->m, &f->before);
        path_of(f, f->out_stem, ".h5", file_path[0], sizeof file_path[0]);
        path_of(f, f->out_stem, ".xdmf", file_path[1], sizeof file_path[1]);
        path_of(f, f->out_stem, "-frame.xdmf", file_path[2],
                sizeof file_path[2]);
        for (int i = 0; i < 3; ++i)
            file_image_take(file_path[i], &f->file_before[i]);
        const int steps = canopy_output_step_count(f->out);
        check_quiet(f);
        const long ids0 = hdf5_ids();
        st = !framed ? canopy_output_write(f->out, f->m)
           : canopy_output_write_framed(f->out, f->m,
                                        rnd(f, 20) ? origin : NULL);
        check_quiet(f);
        check_hdf5_ids(f);
        if (hdf5_ids() != ids0)
            violation(f, "output_write changed the number of HDF5 "
                      "identifiers", NULL);
        if (st != CANOPY_OK) {
            ++f->c->rejections;
            const char *msg = canopy_output_message(f->out);
            if (strstr(msg, "model is NULL") != NULL)
                violation(f, "output_write rejected with a stale message", msg);
            if (canopy_output_step_count(f->out) != steps)
                violation(f, "a rejected output_write changed the step count",
                          NULL);
            for (int i = 0; i < 3; ++i) {
                file_image_take(file_path[i], &f->file_after[i]);
                if (!file_image_same(&f->file_before[i], &f->file_after[i]))
                    violation(f, "a rejected output_write changed the file",
                              file_path[i]);
            }
            snapshot_take(f->m, &f->after);
            const char *d = snapshot_diff(&f->before, &f->after);
            if (d) violation(f, "output_write changed the model's", d);
        }
        break;
    }
    case 4: {
        if (rnd(f, 3) == 0) make_bad_files(f);
        if (rnd(f, 2)) {
            act_reader(f, k);
            break;
        }
        const int step = rnd(f, 4) ? -1 : pick_index(f, 3);
        before_call(f, "read_state", 2);
        st = canopy_model_read_state(f->m, rnd(f, 30) ? f->stem[k] : "",
                                     step);
        after_call(f, st, KIND_STATE, 2);
        break;
    }
    default:
        if (f->out) {
            ++f->c->calls;
            f->action = "output_destroy";
            destroy_output(f);
        }
        break;
    }
}

/* Calls with a NULL handle: each must return CANOPY_ERR_ARGUMENT (or the
 * documented neutral value) without touching anything. */
static void act_null(fuzz *f)
{
    f->action = "NULL model";
    ++f->c->calls;
    double d[8] = {0};
    int i[8] = {0};
    canopy_status st[24];
    int k = 0;
    st[k++] = canopy_model_add_node(NULL, d, 1.0, CANOPY_GROUP_FABRIC, NULL);
    st[k++] = canopy_model_get_positions(NULL, d, 0);
    st[k++] = canopy_model_step(NULL, 1e-3);
    st[k++] = canopy_model_advance(NULL, 1e-3, i);
    st[k++] = canopy_model_checkpoint(NULL);
    st[k++] = canopy_model_restore(NULL);
    st[k++] = canopy_model_commit(NULL);
    st[k++] = canopy_model_get_gravity(NULL, d);
    st[k++] = canopy_model_energies(NULL, NULL);
    st[k++] = canopy_model_read_state(NULL, "x", -1);
    st[k++] = canopy_build_rectangle(NULL, NULL);
    st[k++] = canopy_output_write(NULL, f->m);
    st[k++] = canopy_model_frequency_bound(NULL, d);
    st[k++] = canopy_model_create(NULL);
    st[k++] = canopy_reader_create(NULL);
    st[k++] = canopy_reader_open(NULL, f->stem[0]);
    st[k++] = canopy_reader_step(NULL, 0, i, d);
    st[k++] = canopy_reader_find_step(NULL, 0.0, 1.0, i);
    st[k++] = canopy_reader_read_state(NULL, 0, f->m);
    st[k++] = canopy_reader_read_motion(NULL, 0, f->m, NULL);
    st[k++] = canopy_reader_get_nodal_forces(NULL, 0, d, 0);
    for (int j = 0; j < k; ++j)
        if (st[j] != CANOPY_ERR_ARGUMENT)
            violation(f, "a NULL handle was not CANOPY_ERR_ARGUMENT", NULL);
    canopy_model_destroy(NULL);
    canopy_output_destroy(NULL);
    canopy_reader_destroy(NULL);
    canopy_reader *none = NULL;
    canopy_reader_destroy(&none);
    if (canopy_model_node_count(NULL) != 0 ||
        canopy_output_step_count(NULL) != 0 ||
        canopy_reader_step_count(NULL) != 0 ||
        canopy_reader_message(NULL)[0] == '\0' ||
        canopy_model_memory_bytes(NULL) != 0 ||
        canopy_model_message(NULL)[0] == '\0' ||
        canopy_output_message(NULL)[0] == '\0' ||
        canopy_status_name((canopy_status)-5)[0] == '\0' ||
        canopy_integrator_name(-1) != NULL ||
        canopy_integrator_name(999) != NULL ||
        canopy_integrator_order(-1) != 0)
        violation(f, "a NULL or out-of-range query misbehaved", NULL);
    (void)canopy_model_seepage_velocity(NULL, 1.0);
    (void)canopy_model_seepage_velocity(f->m, NAN);
    check_quiet(f);
}

/* A fresh model, sometimes empty, sometimes with a small canopy. */
static void new_model(fuzz *f)
{
    destroy_output(f);
    canopy_model_destroy(&f->m);
    if (canopy_model_create(&f->m) != CANOPY_OK) {
        violation(f, "canopy_model_create failed", NULL);
        return;
    }
    f->ckpt_known = 0;
    if (rnd(f, 3) == 0) return;
    canopy_circular_spec s = canopy_circular_spec_default();
    s.diameter = uniform(f, 0.5, 1.5);
    s.edge_length = uniform(f, 0.15, 0.3);
    s.n_attachments = 8;
    int attach[8];
    if (canopy_build_circular(f->m, &s, attach) == CANOPY_OK && rnd(f, 2)) {
        canopy_lines_spec l = canopy_lines_spec_default();
        l.line_length = 1.5;
        l.edge_length = 0.5;
        canopy_build_suspension_lines(f->m, attach, 8, &l, NULL);
    }
}

/* ---- the run -------------------------------------------------------------------- */

#if defined(__SANITIZE_ADDRESS__)
/* The sanitizers end the process after their report, which went to the
 * captured stderr: copy it to the report and say which call it was. */
static void on_death(void)
{
    fuzz *f = active;
    if (f == NULL) return;
    char buf[4096];
    ssize_t got;
    off_t at = 0;
    while ((got = pread(f->capture_fd, buf, sizeof buf, at)) > 0) {
        fwrite(buf, 1, (size_t)got, f->report);
        at += got;
    }
    fprintf(f->report, "canopy-fuzz: crash in call %ld (%s)\n"
            "calls %ld, rejections %ld, violations %ld, crashes 1\n",
            f->c->calls, f->action ? f->action : "-", f->c->calls,
            f->c->rejections, f->c->violations);
    fflush(f->report);
}

/* UndefinedBehaviorSanitizer has a runtime of its own, which does not call
 * the death callback: fuzz_main.c has it abort instead, and the abort is
 * reported here the same way. */
static void on_abort(int sig)
{
    on_death();
    signal(sig, SIG_DFL);
    raise(sig);
}
#endif

static void remove_dir(fuzz *f)
{
    char path[400];
    for (int k = 0; k < FUZZ_PATHS; ++k) {
        snprintf(path, sizeof path, "%s.h5", f->stem[k]);
        unlink(path);
        snprintf(path, sizeof path, "%s.xdmf", f->stem[k]);
        unlink(path);
        snprintf(path, sizeof path, "%s-frame.xdmf", f->stem[k]);
        unlink(path);
    }
    rmdir(f->dir);
}

int canopy_fuzz_run(unsigned long long seed, long calls, FILE *report,
                    canopy_fuzz_counts *counts)
{
    fuzz f;
    memset(&f, 0, sizeof f);
    memset(counts, 0, sizeof *counts);
    f.rng = seed;
    /* Reports go to a copy of the caller's stream's descriptor, which the
     * capture below does not redirect. */
    fflush(report);
    const int report_fd = dup(fileno(report));
    f.report = report_fd >= 0 ? fdopen(report_fd, "w") : NULL;
    if (f.report == NULL) {
        if (report_fd >= 0) close(report_fd);
        return 2;
    }
    f.c = counts;
    const char *tmp = getenv("TMPDIR");
    snprintf(f.dir, sizeof f.dir, "%s/canopy-fuzz-XXXXXX",
             tmp && tmp[0] ? tmp : "/tmp");
    if (mkdtemp(f.dir) == NULL) {
        fprintf(f.report, "canopy-fuzz: cannot make a directory in %s: %s\n",
                tmp && tmp[0] ? tmp : "/tmp", strerror(errno));
        fclose(f.report);
        return 2;
    }
    for (int k = 0; k < FUZZ_PATHS; ++k)
        snprintf(f.stem[k], sizeof f.stem[k], "%s/%s", f.dir, stems[k]);
    /* Library output on fd 1 and 2 goes to a file the checks read. */
    char capture[320];
    snprintf(capture, sizeof capture, "%s/captured", f.dir);
    f.capture_fd = open(capture, O_RDWR | O_CREAT | O_TRUNC, 0600);
    unlink(capture);
    fflush(stdout);
    fflush(stderr);
    const int saved_out = dup(1), saved_err = dup(2);
    if (f.capture_fd < 0 || saved_out < 0 || saved_err < 0 ||
        dup2(f.capture_fd, 1) < 0 || dup2(f.capture_fd, 2) < 0) {
        fprintf(f.report, "canopy-fuzz: cannot capture stdout/stderr\n");
        fclose(f.report);
        remove_dir(&f);
        return 2;
    }
    active = &f;
#if defined(__SANITIZE_ADDRESS__)
    __sanitizer_set_death_callback(on_death);
    signal(SIGABRT, on_abort);
#endif
    f.reader_stem = -1;
    if (canopy_model_create(&f.spare) != CANOPY_OK) {
        violation(&f, "canopy_model_create failed", NULL);
    } else {
        canopy_rectangle_spec s = canopy_rectangle_spec_default();
        s.width = 0.5;
        s.length = 0.3;
        s.edge_length = 0.1;
        if (canopy_build_rectangle(f.spare, &s) != CANOPY_OK)
            violation(&f, "build_rectangle of the spare model failed",
                      canopy_model_message(f.spare));
    }
    new_model(&f);
    make_bad_files(&f);
    while (counts->calls < calls && f.m != NULL) {
        if (canopy_model_node_count(f.m) > FUZZ_MAX_NODES || rnd(&f, 400) == 0)
            new_model(&f);
        const int r = rnd(&f, 100);
        if (r < 14) act_build(&f, rnd(&f, 5));
        else if (r < 26) act_by_hand(&f);
        else if (r < 40) act_settings(&f);
        else if (r < 58) act_state(&f);
        else if (r < 72) act_time(&f);
        else if (r < 84) act_checkpoint(&f);
        else if (r < 97) act_files(&f);
        else act_null(&f);
        if (rnd(&f, 7) == 0 && !f.ckpt_known) {
            /* Keep a known checkpoint around most of the time. */
            before_call(&f, "checkpoint", 0);
            after_call(&f, canopy_model_checkpoint(f.m), KIND_CHECKPOINT, 0);
        }
    }
    destroy_output(&f);
    canopy_reader_destroy(&f.r);
    canopy_model_destroy(&f.m);
    canopy_model_destroy(&f.spare);
    check_quiet(&f);
#if defined(__SANITIZE_ADDRESS__)
    __sanitizer_set_death_callback(NULL);
    signal(SIGABRT, SIG_DFL);
#endif
    active = NULL;
    fflush(stdout);
    fflush(stderr);
    dup2(saved_out, 1);
    dup2(saved_err, 2);
    close(saved_out);
    close(saved_err);
    close(f.capture_fd);
    snapshot_free(&f.before);
    snapshot_free(&f.after);
    snapshot_free(&f.ckpt);
    for (int i = 0; i < 3; ++i) {
        file_image_free(&f.file_before[i]);
        file_image_free(&f.file_after[i]);
    }
    remove_dir(&f);
    fclose(f.report);
    return counts->violations ? 1 : 0;
}

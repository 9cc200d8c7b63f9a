/* output_hdf5.c — canopy_output: the HDF5 time series (/mesh once, /steps/NNNNNN per write) and its XDMF sidecar. */
#include "output_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Every HDF5 call of this file runs with HDF5's automatic error printing
 * switched off (H5E_BEGIN_TRY ... H5E_END_TRY around the public entry
 * points), so the library never prints; failures become canopy_status
 * values with a message naming the file and the object. */

struct canopy_output {
    hid_t file;
    char *h5_path;            /* path.h5 */
    char *xdmf_path;          /* path.xdmf */
    char *frame_xdmf_path;    /* path-frame.xdmf: the steps in a moving frame */
    double *x_frame;          /* 3*nodes: positions less the frame's origin */
    const char *h5_name;      /* basename of h5_path, as the sidecar names it */
    int nodes, springs, triangles, lines;
    int *line_spring;         /* lines: the spring of each line cell */
    int *edge_spring;         /* 3*triangles: spring on edge (a,b), (b,c),
                                 (c,a) of each triangle, or -1 */
    double *tension;          /* springs (at least 1) */
    double *cell_dp;          /* triangles + lines */
    double *cell_tension;     /* triangles + lines */
    canopy_output_step *steps;
    int step_count, step_capacity;
    int next_number;          /* NNNNNN of the next step */
    char message[CANOPY_MESSAGE_SIZE];
};

/* ------------------------------------------------------------------------ */
/* Helpers shared with restart.c (output_internal.h). */

char *canopy_path_with_ext(const char *path, const char *ext)
{
    const size_t a = strlen(path), b = strlen(ext);
    char *s = malloc(a + b + 1);
    if (s == NULL) return NULL;
    memcpy(s, path, a);
    memcpy(s + a, ext, b + 1);
    return s;
}

const char *canopy_path_basename(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

hid_t canopy_h5_open_read(const char *h5_path, char *msg, size_t msg_size)
{
    const hid_t fapl = canopy_h5_fapl();
    if (fapl < 0) {
        canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                              "cannot make an HDF5 file access property "
                              "list for '%s'", h5_path);
        return -1;
    }
    const hid_t file = H5Fopen(h5_path, H5F_ACC_RDONLY, fapl);
    H5Pclose(fapl);
    if (file < 0) {
        if (access(h5_path, F_OK) != 0)
            canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                  "'%s' does not exist", h5_path);
        else
            canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                  "cannot open '%s' (unreadable or not an "
                                  "HDF5 file)", h5_path);
    }
    return file;
}

hid_t canopy_h5_fapl(void)
{
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl < 0) return fapl;
#if (H5_VERS_MAJOR == 1 && H5_VERS_MINOR == 10 && H5_VERS_RELEASE >= 7) || \
    H5_VERSION_GE(1, 12, 1)
    /* Without a lock a reader (ParaView) can open the file between writes;
     * every write ends with a flush, so what it reads is consistent. */
    if (H5Pset_file_locking(fapl, 0, 1) < 0) {
        H5Pclose(fapl);
        return -1;
    }
#endif
    /* Objects in the HDF5 1.8 format, whose metadata (superblock v2, object
     * headers v2, link and attribute storage) carry checksums: a damaged
     * file is then refused by HDF5 instead of parsed, which HDF5 1.10.8
     * does not do memory-safely (canopy-fuzz's byte-flipped files). Not
     * the 1.10 format: its superblock marks a file open for writing, and a
     * killed run would leave a file that cannot be appended to.
     * No aggregation blocks, so the file ends where its data does:
     * otherwise, when read_state opens a file an output of this process is
     * writing (HDF5 shares the open file), closing it releases the blocks
     * and truncates the file under the writer. */
    if (H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_V18) < 0 ||
        H5Pset_meta_block_size(fapl, 0) < 0 ||
        H5Pset_small_data_block_size(fapl, 0) < 0) {
        H5Pclose(fapl);
        return -1;
    }
    return fapl;
}

herr_t canopy_h5_read_int_attribute(hid_t obj, const char *name, int *value)
{
    hid_t attr = H5Aopen(obj, name, H5P_DEFAULT);
    if (attr < 0) return -1;
    herr_t r = -1;
    hid_t space = H5Aget_space(attr);
    if (space >= 0) {
        if (H5Sget_simple_extent_npoints(space) == 1)
            r = H5Aread(attr, H5T_NATIVE_INT, value);
        H5Sclose(space);
    }
    H5Aclose(attr);
    return r;
}

static herr_t read_double_attribute(hid_t obj, const char *name,
                                    double *value)
{
    hid_t attr = H5Aopen(obj, name, H5P_DEFAULT);
    if (attr < 0) return -1;
    herr_t r = -1;
    hid_t space = H5Aget_space(attr);
    if (space >= 0) {
        if (H5Sget_simple_extent_npoints(space) == 1)
            r = H5Aread(attr, H5T_NATIVE_DOUBLE, value);
        H5Sclose(space);
    }
    H5Aclose(attr);
    return r;
}

static int compare_steps(const void *a, const void *b)
{
    const canopy_output_step *x = a, *y = b;
    return (x->number > y->number) - (x->number < y->number);
}

/* A step group name: decimal digits only, fits an int. */
static int parse_step_name(const char *name, int *number)
{
    if (name[0] == '\0' || strlen(name) > 9) return 0;
    int n = 0;
    for (const char *c = name; *c; ++c) {
        if (*c < '0' || *c > '9') return 0;
        n = 10 * n + (*c - '0');
    }
    *number = n;
    return 1;
}

canopy_status canopy_h5_list_steps(hid_t file, const char *file_name,
                                   canopy_output_step **steps_out, int *count,
                                   char *msg, size_t msg_size)
{
    *steps_out = NULL;
    *count = 0;
    htri_t exists = H5Lexists(file, "steps", H5P_DEFAULT);
    if (exists < 0)
        return canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                     "cannot read the root group of '%s'",
                                     file_name);
    if (exists == 0) return CANOPY_OK;
    hid_t group = H5Gopen2(file, "steps", H5P_DEFAULT);
    if (group < 0)
        return canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                     "'%s': /steps is not a group", file_name);
    canopy_status st = CANOPY_OK;
    canopy_output_step *steps = NULL;
    int n = 0;
    H5G_info_t info;
    if (H5Gget_info(group, &info) < 0) {
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                   "cannot list /steps in '%s'", file_name);
        goto done;
    }
    if (info.nlinks > (hsize_t)(1 << 30)) {
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                   "'%s': /steps holds too many entries",
                                   file_name);
        goto done;
    }
    if (info.nlinks > 0) {
        steps = malloc(sizeof *steps * (size_t)info.nlinks);
        if (steps == NULL) {
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_MEMORY,
                                       "no memory to list the steps of '%s'",
                                       file_name);
            goto done;
        }
    }
    for (hsize_t i = 0; i < info.nlinks; ++i) {
        char name[64];
        ssize_t len = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME,
                                         H5_ITER_INC, i, name, sizeof name,
                                         H5P_DEFAULT);
        if (len < 0) {
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                       "cannot read entry %llu of /steps in "
                                       "'%s'", (unsigned long long)i,
                                       file_name);
            goto done;
        }
        int number;
        if ((size_t)len >= sizeof name || !parse_step_name(name, &number))
            continue; /* not a step group: ignored */
        double t;
        hid_t step = H5Gopen2(group, name, H5P_DEFAULT);
        herr_t r = -1;
        if (step >= 0) {
            r = read_double_attribute(step, "time", &t);
            H5Gclose(step);
        }
        if (r < 0) {
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                       "'%s': /steps/%s is not a group with a "
                                       "scalar attribute 'time'", file_name,
                                       name);
            goto done;
        }
        steps[n].number = number;
        steps[n].time = t;
        steps[n].framed = 0;
        {
            char frame[96];
            snprintf(frame, sizeof frame, "%s/x_frame", name);
            steps[n].framed = H5Lexists(group, frame, H5P_DEFAULT) > 0;
        }
        ++n;
    }
    if (n > 1) qsort(steps, (size_t)n, sizeof *steps, compare_steps);
done:
    H5Gclose(group);
    if (st != CANOPY_OK || n == 0) {
        free(steps);
        steps = NULL;
        if (st != CANOPY_OK) n = 0;
    }
    *steps_out = steps;
    *count = n;
    return st;
}

canopy_status canopy_h5_read_counts(hid_t file, const char *file_name,
                                    canopy_h5_counts *c, char *msg,
                                    size_t msg_size)
{
    htri_t exists = H5Lexists(file, "mesh", H5P_DEFAULT);
    if (exists <= 0)
        return canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                     "'%s' has no /mesh group (not a canopy "
                                     "output file)", file_name);
    hid_t mesh = H5Gopen2(file, "mesh", H5P_DEFAULT);
    if (mesh < 0)
        return canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                     "'%s': /mesh is not a group", file_name);
    static const char *const names[4] = {"nodes", "springs", "triangles",
                                         "lines"};
    int *slots[4] = {&c->nodes, &c->springs, &c->triangles, &c->lines};
    canopy_status st = CANOPY_OK;
    for (int i = 0; i < 4 && st == CANOPY_OK; ++i)
        if (canopy_h5_read_int_attribute(mesh, names[i], slots[i]) < 0 ||
            *slots[i] < 0)
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                       "'%s': /mesh has no valid scalar "
                                       "attribute '%s'", file_name, names[i]);
    H5Gclose(mesh);
    return st;
}

/* Line cells: every spring that is not fabric. */
static int count_lines(const canopy_model *m)
{
    int n = 0;
    for (int k = 0; k < m->springs.count; ++k)
        if (m->springs.group[k] != CANOPY_GROUP_FABRIC) ++n;
    return n;
}

canopy_status canopy_h5_check_counts(const canopy_h5_counts *fc,
                                     const canopy_model *m,
                                     const char *file_name, char *msg,
                                     size_t msg_size)
{
    const char *what = NULL;
    int in_file = 0, in_model = 0;
    if (fc->nodes != m->nodes.count) {
        what = "nodes"; in_file = fc->nodes; in_model = m->nodes.count;
    } else if (fc->triangles != m->tris.count) {
        what = "triangles"; in_file = fc->triangles; in_model = m->tris.count;
    } else if (fc->springs != m->springs.count) {
        what = "springs"; in_file = fc->springs; in_model = m->springs.count;
    } else if (fc->lines != count_lines(m)) {
        what = "line cells (non-fabric springs)";
        in_file = fc->lines; in_model = count_lines(m);
    }
    if (what == NULL) return CANOPY_OK;
    return canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                 "'%s' does not match the model: %d %s in the "
                                 "file, %d in the model", file_name, in_file,
                                 what, in_model);
}

/* ------------------------------------------------------------------------ */
/* Writing. */

static herr_t write_int_attribute(hid_t obj, const char *name, int value)
{
    hid_t space = H5Screate(H5S_SCALAR);
    if (space < 0) return -1;
    herr_t r = -1;
    hid_t attr = H5Acreate2(obj, name, H5T_STD_I32LE, space, H5P_DEFAULT,
                            H5P_DEFAULT);
    if (attr >= 0) {
        r = H5Awrite(attr, H5T_NATIVE_INT, &value);
        if (H5Aclose(attr) < 0) r = -1;
    }
    H5Sclose(space);
    return r;
}

static herr_t write_double_attribute(hid_t obj, const char *name,
                                     double value)
{
    hid_t space = H5Screate(H5S_SCALAR);
    if (space < 0) return -1;
    herr_t r = -1;
    hid_t attr = H5Acreate2(obj, name, H5T_IEEE_F64LE, space, H5P_DEFAULT,
                            H5P_DEFAULT);
    if (attr >= 0) {
        r = H5Awrite(attr, H5T_NATIVE_DOUBLE, &value);
        if (H5Aclose(attr) < 0) r = -1;
    }
    H5Sclose(space);
    return r;
}

/* A dataset of rows x cols (cols 0: one-dimensional) written in one go.
 * Empty datasets are created but not written. */
static herr_t write_dataset(hid_t loc, const char *name, int is_int,
                            hsize_t rows, hsize_t cols, const void *data)
{
    hsize_t dims[2] = {rows, cols};
    hid_t space = H5Screate_simple(cols > 0 ? 2 : 1, dims, NULL);
    if (space < 0) return -1;
    herr_t r = -1;
    hid_t set = H5Dcreate2(loc, name, is_int ? H5T_STD_I32LE : H5T_IEEE_F64LE,
                           space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (set >= 0) {
        r = 0;
        if (rows > 0)
            r = H5Dwrite(set, is_int ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE,
                         H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
        if (H5Dclose(set) < 0) r = -1;
    }
    H5Sclose(space);
    return r;
}

static canopy_status out_fail(canopy_output *o, canopy_status st,
                              const char *fmt, const char *what)
{
    return canopy_format_message(o->message, sizeof o->message, st, fmt,
                                 what, o->h5_path);
}

/* /mesh: counts as attributes, connectivity, groups, masses, XDMF cells. */
static canopy_status write_mesh(canopy_output *o, const canopy_model *m)
{
    const int n = o->nodes, ns = o->springs, nt = o->triangles;
    const long cells_length = 4L * nt + 4L * o->lines;
    size_t ints = (size_t)cells_length;
    if ((size_t)n > ints) ints = (size_t)n;
    if ((size_t)ns > ints) ints = (size_t)ns;
    int *buf = malloc(sizeof *buf * (ints > 0 ? ints : 1));
    if (buf == NULL)
        return out_fail(o, CANOPY_ERR_MEMORY, "no memory for %s of '%s'",
                        "/mesh");
    canopy_status st = CANOPY_OK;
    const char *failed = NULL;
    hid_t mesh = H5Gcreate2(o->file, "mesh", H5P_DEFAULT, H5P_DEFAULT,
                            H5P_DEFAULT);
    if (mesh < 0) {
        failed = "/mesh";
        goto done;
    }
    if (write_int_attribute(mesh, "nodes", n) < 0 ||
        write_int_attribute(mesh, "springs", ns) < 0 ||
        write_int_attribute(mesh, "triangles", nt) < 0 ||
        write_int_attribute(mesh, "lines", o->lines) < 0) {
        failed = "the count attributes of /mesh";
        goto done;
    }
    if (write_dataset(mesh, "triangles", 1, (hsize_t)nt, 3, m->tris.nodes) < 0)
        { failed = "/mesh/triangles"; goto done; }
    if (write_dataset(mesh, "springs", 1, (hsize_t)ns, 2, m->springs.ends) < 0)
        { failed = "/mesh/springs"; goto done; }
    if (write_dataset(mesh, "spring_rest_length", 0, (hsize_t)ns, 0,
                      m->springs.rest) < 0)
        { failed = "/mesh/spring_rest_length"; goto done; }
    if (write_dataset(mesh, "spring_stiffness", 0, (hsize_t)ns, 0,
                      m->springs.k) < 0)
        { failed = "/mesh/spring_stiffness"; goto done; }
    for (int k = 0; k < ns; ++k) buf[k] = m->springs.group[k];
    if (write_dataset(mesh, "spring_group", 1, (hsize_t)ns, 0, buf) < 0)
        { failed = "/mesh/spring_group"; goto done; }
    for (int i = 0; i < n; ++i) buf[i] = m->nodes.group[i];
    if (write_dataset(mesh, "node_group", 1, (hsize_t)n, 0, buf) < 0)
        { failed = "/mesh/node_group"; goto done; }
    if (write_dataset(mesh, "node_mass", 0, (hsize_t)n, 0, m->nodes.mass) < 0)
        { failed = "/mesh/node_mass"; goto done; }
    for (int i = 0; i < n; ++i) buf[i] = m->nodes.fixed[i];
    if (write_dataset(mesh, "node_fixed", 1, (hsize_t)n, 0, buf) < 0)
        { failed = "/mesh/node_fixed"; goto done; }
    /* XDMF mixed topology: 4 a b c per triangle (XDMF type 4), then
     * 2 2 i j per line cell (type 2, a polyline of 2 nodes). */
    long c = 0;
    for (int t = 0; t < nt; ++t) {
        buf[c++] = 4;
        for (int v = 0; v < 3; ++v) buf[c++] = m->tris.nodes[3 * t + v];
    }
    for (int l = 0; l < o->lines; ++l) {
        const int k = o->line_spring[l];
        buf[c++] = 2;
        buf[c++] = 2;
        buf[c++] = m->springs.ends[2 * k];
        buf[c++] = m->springs.ends[2 * k + 1];
    }
    if (write_dataset(mesh, "cells", 1, (hsize_t)cells_length, 0, buf) < 0)
        { failed = "/mesh/cells"; goto done; }
    hid_t steps = H5Gcreate2(o->file, "steps", H5P_DEFAULT, H5P_DEFAULT,
                             H5P_DEFAULT);
    if (steps < 0) { failed = "/steps"; goto done; }
    H5Gclose(steps);
done:
    if (mesh >= 0) H5Gclose(mesh);
    free(buf);
    if (failed) st = out_fail(o, CANOPY_ERR_IO, "cannot write %s in '%s'",
                              failed);
    return st;
}

typedef struct edge_key {
    int a, b;    /* a < b */
    int spring;
} edge_key;

static int compare_edges(const void *x, const void *y)
{
    const edge_key *p = x, *q = y;
    if (p->a != q->a) return (p->a > q->a) - (p->a < q->a);
    if (p->b != q->b) return (p->b > q->b) - (p->b < q->b);
    return (p->spring > q->spring) - (p->spring < q->spring);
}

static int find_edge(const edge_key *keys, int n, int i, int j)
{
    const int a = i < j ? i : j, b = i < j ? j : i;
    int lo = 0, hi = n; /* first key >= (a, b) */
    while (lo < hi) {
        const int mid = lo + (hi - lo) / 2;
        if (keys[mid].a < a || (keys[mid].a == a && keys[mid].b < b))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < n && keys[lo].a == a && keys[lo].b == b ? keys[lo].spring : -1;
}

/* Cell maps: the springs drawn as line cells, and the spring on each
 * triangle edge (found once, by binary search in sorted spring ends). */
static canopy_status build_maps(canopy_output *o, const canopy_model *m)
{
    const int ns = o->springs, nt = o->triangles, cells = nt + o->lines;
    o->line_spring = malloc(sizeof(int) * (size_t)(o->lines > 0 ? o->lines : 1));
    o->edge_spring = malloc(sizeof(int) * 3 * (size_t)(nt > 0 ? nt : 1));
    o->tension = malloc(sizeof(double) * (size_t)(ns > 0 ? ns : 1));
    o->cell_dp = malloc(sizeof(double) * (size_t)(cells > 0 ? cells : 1));
    o->cell_tension = malloc(sizeof(double) * (size_t)(cells > 0 ? cells : 1));
    edge_key *keys = malloc(sizeof *keys * (size_t)(ns > 0 ? ns : 1));
    if (!o->line_spring || !o->edge_spring || !o->tension || !o->cell_dp ||
        !o->cell_tension || !keys) {
        free(keys);
        return CANOPY_ERR_MEMORY;
    }
    int l = 0;
    for (int k = 0; k < ns; ++k) {
        const int i = m->springs.ends[2 * k], j = m->springs.ends[2 * k + 1];
        keys[k].a = i < j ? i : j;
        keys[k].b = i < j ? j : i;
        keys[k].spring = k;
        if (m->springs.group[k] != CANOPY_GROUP_FABRIC) o->line_spring[l++] = k;
    }
    qsort(keys, (size_t)ns, sizeof *keys, compare_edges);
    for (int t = 0; t < nt; ++t) {
        const int *v = m->tris.nodes + 3 * t;
        for (int e = 0; e < 3; ++e)
            o->edge_spring[3 * t + e] = find_edge(keys, ns, v[e], v[(e + 1) % 3]);
    }
    free(keys);
    return CANOPY_OK;
}

static void output_free(canopy_output *o)
{
    if (o == NULL) return;
    if (o->file >= 0) H5Fclose(o->file);
    free(o->h5_path);
    free(o->xdmf_path);
    free(o->frame_xdmf_path);
    free(o->x_frame);
    free(o->line_spring);
    free(o->edge_spring);
    free(o->tension);
    free(o->cell_dp);
    free(o->cell_tension);
    free(o->steps);
    free(o);
}

/* The sidecars of the given steps: path.xdmf with every step, and
 * path-frame.xdmf with the steps that hold positions in a moving frame
 * (none: no such file). The moving frame's first, so that a failure leaves
 * path.xdmf as it was. */
static canopy_status rewrite_xdmf(canopy_output *o,
                                  const canopy_output_step *steps, int count)
{
    canopy_xdmf_mesh mesh;
    mesh.nodes = o->nodes;
    mesh.cells = o->triangles + o->lines;
    mesh.cells_length = 4L * o->triangles + 4L * o->lines;
    int framed = 0;
    for (int s = 0; s < count; ++s) framed += steps[s].framed != 0;
    canopy_output_step *sub = NULL;
    if (framed > 0) {
        sub = malloc(sizeof *sub * (size_t)framed);
        if (sub == NULL)
            return out_fail(o, CANOPY_ERR_MEMORY, "no memory for %s of '%s'",
                            "the moving frame's step list");
        int k = 0;
        for (int s = 0; s < count; ++s)
            if (steps[s].framed) sub[k++] = steps[s];
    }
    canopy_status st = canopy_xdmf_write(o->frame_xdmf_path, o->h5_name,
                                         "x_frame", &mesh, sub, framed,
                                         o->message, sizeof o->message);
    free(sub);
    if (st != CANOPY_OK) return st;
    return canopy_xdmf_write(o->xdmf_path, o->h5_name, "x", &mesh, steps,
                             count, o->message, sizeof o->message);
}

static int time_is_later(double t, double reference)
{
    const double scale = fabs(reference) > 1.0 ? fabs(reference) : 1.0;
    return t > reference + 1e-12 * scale;
}

/* APPEND, first: is the file a canopy output of this model with a readable
 * step list? Checked read-only, so that a file that is not (empty, not
 * HDF5, another model's, damaged) is left byte for byte as it was: HDF5
 * opening a file for writing may write to it even when reading it fails. */
static canopy_status check_for_append(canopy_output *o, const canopy_model *m,
                                      hid_t fapl)
{
    hid_t file = H5Fopen(o->h5_path, H5F_ACC_RDONLY, fapl);
    if (file < 0) {
        if (access(o->h5_path, F_OK) != 0)
            return out_fail(o, CANOPY_ERR_IO, "cannot append: %s '%s' does "
                            "not exist", "the HDF5 file");
        return out_fail(o, CANOPY_ERR_IO, "cannot open %s '%s' to append "
                        "(unreadable or not an HDF5 file)", "HDF5 file");
    }
    canopy_h5_counts counts;
    canopy_output_step *steps = NULL;
    int count = 0;
    canopy_status st = canopy_h5_read_counts(file, o->h5_path, &counts,
                                             o->message, sizeof o->message);
    if (st == CANOPY_OK)
        st = canopy_h5_check_counts(&counts, m, o->h5_path, o->message,
                                    sizeof o->message);
    if (st == CANOPY_OK)
        st = canopy_h5_list_steps(file, o->h5_path, &steps, &count,
                                  o->message, sizeof o->message);
    free(steps);
    if (H5Fclose(file) < 0 && st == CANOPY_OK)
        st = out_fail(o, CANOPY_ERR_IO, "cannot close %s '%s'", "HDF5 file");
    return st;
}

/* APPEND: check the file matches, drop the steps later than the model's
 * time, and continue after the last kept step. */
static canopy_status open_for_append(canopy_output *o, const canopy_model *m,
                                     hid_t fapl)
{
    canopy_status checked = check_for_append(o, m, fapl);
    if (checked != CANOPY_OK) return checked;
    o->file = H5Fopen(o->h5_path, H5F_ACC_RDWR, fapl);
    if (o->file < 0) {
        if (access(o->h5_path, F_OK) != 0)
            return out_fail(o, CANOPY_ERR_IO, "cannot append: %s '%s' does "
                            "not exist", "the HDF5 file");
        return out_fail(o, CANOPY_ERR_IO, "cannot open %s '%s' to append "
                        "(unwritable or not an HDF5 file)", "HDF5 file");
    }
    canopy_h5_counts counts;
    canopy_status st = canopy_h5_read_counts(o->file, o->h5_path, &counts,
                                             o->message, sizeof o->message);
    if (st != CANOPY_OK) return st;
    st = canopy_h5_check_counts(&counts, m, o->h5_path, o->message,
                                sizeof o->message);
    if (st != CANOPY_OK) return st;
    canopy_output_step *steps = NULL;
    int count = 0;
    st = canopy_h5_list_steps(o->file, o->h5_path, &steps, &count, o->message,
                              sizeof o->message);
    if (st != CANOPY_OK) return st;
    if (H5Lexists(o->file, "steps", H5P_DEFAULT) == 0) {
        hid_t g = H5Gcreate2(o->file, "steps", H5P_DEFAULT, H5P_DEFAULT,
                             H5P_DEFAULT);
        if (g < 0) {
            free(steps);
            return out_fail(o, CANOPY_ERR_IO, "cannot create %s in '%s'",
                            "/steps");
        }
        H5Gclose(g);
    }
    const double t = m->t;
    /* Drop every step later than t (wherever it stands, should the times
     * not increase), keep the order of the rest. */
    int kept = 0;
    for (int s = 0; s < count; ++s)
        if (!time_is_later(steps[s].time, t)) steps[kept++] = steps[s];
    /* The sidecar first (it names only kept steps), then the deletions. */
    st = rewrite_xdmf(o, steps, kept);
    if (st != CANOPY_OK) {
        free(steps);
        return st;
    }
    canopy_output_step *all = NULL;
    int all_count = 0;
    st = canopy_h5_list_steps(o->file, o->h5_path, &all, &all_count,
                              o->message, sizeof o->message);
    if (st != CANOPY_OK) {
        free(steps);
        return st;
    }
    for (int s = 0; s < all_count; ++s) {
        if (!time_is_later(all[s].time, t)) continue;
        char name[32];
        snprintf(name, sizeof name, "/steps/" CANOPY_STEP_NAME_FMT,
                 all[s].number);
        if (H5Ldelete(o->file, name, H5P_DEFAULT) < 0) {
            free(all);
            free(steps);
            return out_fail(o, CANOPY_ERR_IO, "cannot delete %s in '%s'",
                            name);
        }
    }
    free(all);
    if (H5Fflush(o->file, H5F_SCOPE_LOCAL) < 0) {
        free(steps);
        return out_fail(o, CANOPY_ERR_IO, "cannot flush %s '%s'",
                        "HDF5 file");
    }
    o->steps = steps;
    o->step_count = kept;
    o->step_capacity = count;
    o->next_number = 0;
    for (int s = 0; s < kept; ++s)
        if (steps[s].number + 1 > o->next_number)
            o->next_number = steps[s].number + 1;
    return CANOPY_OK;
}

/* Is path (an existing file) open in this process's HDF5 library, by
 * another canopy_output? Compared by device and inode (a CREATE's file was
 * opened under a temporary name). With the default sec2 driver the VFD
 * handle is the POSIX descriptor. */
static int open_in_hdf5(const char *path)
{
    struct stat want;
    if (stat(path, &want) != 0) return 0;
    const ssize_t n = H5Fget_obj_count((hid_t)H5F_OBJ_ALL, H5F_OBJ_FILE);
    if (n <= 0) return 0;
    hid_t *ids = malloc(sizeof *ids * (size_t)n);
    if (ids == NULL) return 0;
    const ssize_t got = H5Fget_obj_ids((hid_t)H5F_OBJ_ALL, H5F_OBJ_FILE,
                                       (size_t)n, ids);
    int found = 0;
    for (ssize_t i = 0; i < got && !found; ++i) {
        void *handle = NULL;
        struct stat have;
        if (H5Fget_vfd_handle(ids[i], H5P_DEFAULT, &handle) >= 0 &&
            handle != NULL && fstat(*(int *)handle, &have) == 0)
            found = have.st_dev == want.st_dev && have.st_ino == want.st_ino;
    }
    free(ids);
    return found;
}

/* CREATE: the new file is written under a temporary name and renamed over
 * path.h5 only once its mesh is written and flushed, and the old sidecar
 * removed after that, so a failed create leaves both files as they were
 * (HDF5 keeps writing through its open descriptor after the rename). */
static canopy_status create_new(canopy_output *o, const canopy_model *m,
                                hid_t fapl)
{
    struct stat sb;
    if (stat(o->xdmf_path, &sb) == 0 && !S_ISREG(sb.st_mode))
        return canopy_format_message(o->message, sizeof o->message,
                                     CANOPY_ERR_IO, "cannot replace '%s': "
                                     "not a regular file", o->xdmf_path);
    char *tmp = canopy_path_with_ext(o->h5_path, ".tmp");
    if (tmp == NULL)
        return out_fail(o, CANOPY_ERR_MEMORY, "no memory for %s of '%s'",
                        "the temporary name");
    canopy_status st = CANOPY_OK;
    o->file = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    if (o->file < 0)
        st = out_fail(o, CANOPY_ERR_IO, "cannot create %s '%s' (does the "
                      "directory exist and is it writable?)", "HDF5 file");
    else if ((st = write_mesh(o, m)) == CANOPY_OK &&
             H5Fflush(o->file, H5F_SCOPE_LOCAL) < 0)
        st = out_fail(o, CANOPY_ERR_IO, "cannot flush %s '%s'", "HDF5 file");
    if (st == CANOPY_OK && rename(tmp, o->h5_path) != 0)
        st = out_fail(o, CANOPY_ERR_IO, "cannot rename %s to '%s'",
                      "the new HDF5 file");
    if (st != CANOPY_OK) {
        if (o->file >= 0) H5Fclose(o->file);
        o->file = -1;
        remove(tmp);
        free(tmp);
        return st;
    }
    free(tmp);
    return rewrite_xdmf(o, NULL, 0); /* removes the old sidecar */
}

static canopy_status create_impl(canopy_model *m, const char *path,
                                 canopy_output_mode mode, canopy_output **out)
{
    canopy_output *o = calloc(1, sizeof *o);
    if (o == NULL)
        return canopy_fail(m, CANOPY_ERR_MEMORY, "output_create '%s': no "
                           "memory", path);
    o->file = -1;
    o->nodes = m->nodes.count;
    o->springs = m->springs.count;
    o->triangles = m->tris.count;
    o->lines = count_lines(m);
    o->h5_path = canopy_path_with_ext(path, CANOPY_H5_EXT);
    o->xdmf_path = canopy_path_with_ext(path, CANOPY_XDMF_EXT);
    o->frame_xdmf_path = canopy_path_with_ext(path, CANOPY_FRAME_XDMF_EXT);
    o->x_frame = malloc(3 * sizeof(double) * (size_t)(o->nodes > 0 ? o->nodes : 1));
    if (o->h5_path == NULL || o->xdmf_path == NULL ||
        o->frame_xdmf_path == NULL || o->x_frame == NULL ||
        build_maps(o, m) != CANOPY_OK) {
        output_free(o);
        return canopy_fail(m, CANOPY_ERR_MEMORY, "output_create '%s': no "
                           "memory", path);
    }
    o->h5_name = canopy_path_basename(o->h5_path);

    canopy_status st;
    if (open_in_hdf5(o->h5_path)) {
        st = out_fail(o, CANOPY_ERR_IO, "%s '%s' is open in another "
                      "canopy_output (destroy that first)", "the HDF5 file");
        const char *text = strchr(o->message, ':');
        canopy_fail(m, st, "output_create: %s",
                    text && text[1] ? text + 2 : o->message);
        output_free(o);
        return st;
    }
    hid_t fapl = canopy_h5_fapl();
    if (fapl < 0) {
        st = out_fail(o, CANOPY_ERR_IO, "cannot make %s for '%s'",
                      "an HDF5 file access property list");
    } else if (mode == CANOPY_OUTPUT_APPEND) {
        st = open_for_append(o, m, fapl);
    } else {
        st = create_new(o, m, fapl);
    }
    if (fapl >= 0) H5Pclose(fapl);
    if (st != CANOPY_OK) {
        /* The message names the file; "CANOPY_ERR_X: " is added again. */
        const char *text = strchr(o->message, ':');
        canopy_fail(m, st, "output_create: %s",
                    text && text[1] ? text + 2 : o->message);
        output_free(o);
        return st;
    }
    o->message[0] = '\0';
    *out = o;
    return CANOPY_OK;
}

canopy_status canopy_output_create(canopy_model *model, const char *path,
                                   canopy_output_mode mode,
                                   canopy_output **out)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (out == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "output_create: out is NULL");
    *out = NULL;
    if (path == NULL || path[0] == '\0')
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "output_create: path is NULL or empty");
    if (mode != CANOPY_OUTPUT_CREATE && mode != CANOPY_OUTPUT_APPEND)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "output_create '%s': unknown mode %d", path,
                           (int)mode);
    if (model->nodes.count == 0)
        return canopy_fail(model, CANOPY_ERR_STATE,
                           "output_create '%s': the model has no nodes", path);
    if (model->tris.count + count_lines(model) == 0)
        return canopy_fail(model, CANOPY_ERR_STATE,
                           "output_create '%s': the model has no triangles "
                           "and no non-fabric springs, so there are no cells "
                           "to draw", path);
    canopy_status st;
    H5E_BEGIN_TRY {
        st = create_impl(model, path, mode, out);
    } H5E_END_TRY;
    if (st == CANOPY_OK) canopy_clear_message(model);
    return st;
}

/* The per-cell fields: a triangle's dp and the mean tension of the springs
 * on its edges; a line cell's dp is 0 and its tension its spring's. */
static void cell_fields(canopy_output *o, const canopy_model *m)
{
    const int nt = o->triangles;
    for (int t = 0; t < nt; ++t) {
        double sum = 0.0;
        int found = 0;
        for (int e = 0; e < 3; ++e) {
            const int k = o->edge_spring[3 * t + e];
            if (k >= 0) {
                sum += o->tension[k];
                ++found;
            }
        }
        o->cell_dp[t] = m->tris.dp[t];
        o->cell_tension[t] = found ? sum / found : 0.0;
    }
    for (int l = 0; l < o->lines; ++l) {
        o->cell_dp[nt + l] = 0.0;
        o->cell_tension[nt + l] = o->tension[o->line_spring[l]];
    }
}

static canopy_status write_impl(canopy_output *o, const canopy_model *m,
                                const double *origin)
{
    if (o->step_count == o->step_capacity) {
        const int cap = o->step_capacity > 0 ? 2 * o->step_capacity : 64;
        canopy_output_step *s = realloc(o->steps, sizeof *s * (size_t)cap);
        if (s == NULL)
            return out_fail(o, CANOPY_ERR_MEMORY, "no memory for %s of '%s'",
                            "the step list");
        o->steps = s;
        o->step_capacity = cap;
    }
    if (o->springs > 0 &&
        canopy_model_get_tensions(m, o->tension, o->springs) != CANOPY_OK)
        return canopy_format_message(o->message, sizeof o->message,
                                     CANOPY_ERR_STATE, "output '%s': spring "
                                     "tensions failed: %s", o->h5_path,
                                     canopy_model_message(m));
    cell_fields(o, m);

    char name[32], number[CANOPY_STEP_NAME_SIZE];
    snprintf(number, sizeof number, CANOPY_STEP_NAME_FMT, o->next_number);
    snprintf(name, sizeof name, "/steps/%s", number);
    const hsize_t n = (hsize_t)o->nodes, cells =
        (hsize_t)(o->triangles + o->lines);
    const char *failed = NULL;
    hid_t g = H5Gcreate2(o->file, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (g < 0)
        return out_fail(o, CANOPY_ERR_IO, "cannot create group %s in '%s'",
                        name);
    if (write_double_attribute(g, "time", m->t) < 0) failed = "time";
    else if (write_dataset(g, "x", 0, n, 3, m->nodes.x) < 0) failed = "x";
    else if (write_dataset(g, "v", 0, n, 3, m->nodes.v) < 0) failed = "v";
    else if (write_dataset(g, "f_ext", 0, n, 3, m->nodes.force_ext) < 0)
        failed = "f_ext";
    else if (write_dataset(g, "acc", 0, n, 3, m->nodes.acc) < 0)
        failed = "acc";
    else if (write_int_attribute(g, "acc_valid", m->acc_valid) < 0)
        failed = "acc_valid";
    else if (write_dataset(g, "dp", 0, (hsize_t)o->triangles, 0,
                           m->tris.dp) < 0) failed = "dp";
    else if (write_dataset(g, "tension", 0, (hsize_t)o->springs, 0,
                           o->tension) < 0) failed = "tension";
    else if (write_dataset(g, "cell_dp", 0, cells, 0, o->cell_dp) < 0)
        failed = "cell_dp";
    else if (write_dataset(g, "cell_tension", 0, cells, 0,
                           o->cell_tension) < 0) failed = "cell_tension";
    if (!failed && origin != NULL) {
        for (int i = 0; i < o->nodes; ++i)
            for (int d = 0; d < 3; ++d)
                o->x_frame[3 * i + d] = m->nodes.x[3 * i + d] - origin[d];
        if (write_dataset(g, "x_frame", 0, n, 3, o->x_frame) < 0)
            failed = "x_frame";
        else if (write_dataset(g, "frame_origin", 0, 3, 0, origin) < 0)
            failed = "frame_origin";
    }
    if (H5Gclose(g) < 0 && !failed) failed = "(closing the group)";
    if (!failed && H5Fflush(o->file, H5F_SCOPE_LOCAL) < 0)
        failed = "(flushing the file)";
    if (failed) {
        /* Leave no half-written step behind. */
        H5Ldelete(o->file, name, H5P_DEFAULT);
        H5Fflush(o->file, H5F_SCOPE_LOCAL);
        return canopy_format_message(o->message, sizeof o->message,
                                     CANOPY_ERR_IO, "cannot write %s/%s in "
                                     "'%s'", name, failed, o->h5_path);
    }
    o->steps[o->step_count].number = o->next_number;
    o->steps[o->step_count].time = m->t;
    o->steps[o->step_count].framed = origin != NULL;
    canopy_status st = rewrite_xdmf(o, o->steps, o->step_count + 1);
    if (st != CANOPY_OK) {
        /* Keep the handle and the files as they were before the call. */
        H5Ldelete(o->file, name, H5P_DEFAULT);
        H5Fflush(o->file, H5F_SCOPE_LOCAL);
        return st;
    }
    ++o->step_count;
    ++o->next_number;
    return CANOPY_OK;
}

static canopy_status output_write(canopy_output *output,
                                  const canopy_model *model,
                                  const double *origin)
{
    if (output == NULL) return CANOPY_ERR_ARGUMENT;
    if (model == NULL)
        return canopy_format_message(output->message, sizeof output->message,
                                     CANOPY_ERR_ARGUMENT,
                                     "output_write: model is NULL");
    const char *what = NULL;
    int have = 0, want = 0;
    if (model->nodes.count != output->nodes) {
        what = "nodes"; have = model->nodes.count; want = output->nodes;
    } else if (model->springs.count != output->springs) {
        what = "springs"; have = model->springs.count; want = output->springs;
    } else if (model->tris.count != output->triangles) {
        what = "triangles"; have = model->tris.count; want = output->triangles;
    }
    if (what)
        return canopy_format_message(output->message, sizeof output->message,
                                     CANOPY_ERR_FORMAT,
                                     "output_write '%s': the model has %d %s, "
                                     "the file %d", output->h5_path, have,
                                     what, want);
    canopy_status st;
    H5E_BEGIN_TRY {
        st = write_impl(output, model, origin);
    } H5E_END_TRY;
    if (st == CANOPY_OK) output->message[0] = '\0';
    return st;
}

canopy_status canopy_output_write(canopy_output *output,
                                  const canopy_model *model)
{
    return output_write(output, model, NULL);
}

canopy_status canopy_output_write_framed(canopy_output *output,
                                         const canopy_model *model,
                                         const double origin[3])
{
    if (output == NULL) return CANOPY_ERR_ARGUMENT;
    if (origin == NULL || !isfinite(origin[0]) || !isfinite(origin[1]) ||
        !isfinite(origin[2]))
        return canopy_format_message(output->message, sizeof output->message,
                                     CANOPY_ERR_ARGUMENT,
                                     "output_write_framed '%s': the frame's "
                                     "origin is NULL or not finite",
                                     output->h5_path);
    return output_write(output, model, origin);
}

int canopy_output_step_count(const canopy_output *output)
{
    return output ? output->step_count : 0;
}

const char *canopy_output_message(const canopy_output *output)
{
    if (output == NULL) return "CANOPY_ERR_ARGUMENT: output is NULL";
    return output->message;
}

void canopy_output_destroy(canopy_output **output)
{
    if (output == NULL || *output == NULL) return;
    H5E_BEGIN_TRY {
        output_free(*output);
    } H5E_END_TRY;
    *output = NULL;
}

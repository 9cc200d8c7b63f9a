/* restart.c — reading one output step's state into a model: canopy_model_read_state and the loader behind canopy_reader_read_state / _read_motion. */
#include "output_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

canopy_status canopy_h5_read_doubles(hid_t group, const char *group_name,
                                  const char *name, hsize_t rows,
                                  hsize_t cols, double *buf,
                                  const char *file_name, char *msg,
                                  size_t msg_size)
{
    hid_t set = H5Dopen2(group, name, H5P_DEFAULT);
    if (set < 0)
        return canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                     "'%s' has no dataset %s/%s", file_name,
                                     group_name, name);
    canopy_status st = CANOPY_OK;
    hid_t space = H5Dget_space(set);
    int rank = space >= 0 ? H5Sget_simple_extent_ndims(space) : -1;
    hsize_t dims[2] = {0, 0};
    const int want_rank = cols > 0 ? 2 : 1;
    if (rank != want_rank ||
        H5Sget_simple_extent_dims(space, dims, NULL) != want_rank ||
        dims[0] != rows || (cols > 0 && dims[1] != cols)) {
        if (cols > 0)
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                       "'%s': %s/%s is not %llu x %llu",
                                       file_name, group_name, name,
                                       (unsigned long long)rows,
                                       (unsigned long long)cols);
        else
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                       "'%s': %s/%s does not hold %llu values",
                                       file_name, group_name, name,
                                       (unsigned long long)rows);
    } else if (rows > 0 && H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL,
                                   H5P_DEFAULT, buf) < 0) {
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                   "cannot read %s/%s in '%s'", group_name,
                                   name, file_name);
    }
    if (space >= 0) H5Sclose(space);
    H5Dclose(set);
    if (st != CANOPY_OK) return st;
    const size_t count = (size_t)rows * (size_t)(cols > 0 ? cols : 1);
    for (size_t i = 0; i < count; ++i)
        if (!isfinite(buf[i]))
            return canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                         "'%s': %s/%s value %zu is not finite",
                                         file_name, group_name, name, i);
    return CANOPY_OK;
}

typedef struct state_buffers {
    double t;
    double *x, *v, *f, *dp, *acc;
    int acc_valid;
} state_buffers;

/* Read the int dataset `name` (rows x cols) of the open file into buf. */
static canopy_status read_ints(hid_t file, const char *file_name,
                               const char *name, hsize_t rows, hsize_t cols,
                               int *buf, char *msg, size_t msg_size)
{
    hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
    if (set < 0)
        return canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                     "'%s' has no dataset %s", file_name,
                                     name);
    canopy_status st = CANOPY_OK;
    hid_t space = H5Dget_space(set);
    hsize_t dims[2] = {0, 0};
    if (space < 0 || H5Sget_simple_extent_ndims(space) != 2 ||
        H5Sget_simple_extent_dims(space, dims, NULL) != 2 ||
        dims[0] != rows || dims[1] != cols)
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                   "'%s': %s is not %llu x %llu", file_name,
                                   name, (unsigned long long)rows,
                                   (unsigned long long)cols);
    else if (rows > 0 && H5Dread(set, H5T_NATIVE_INT, H5S_ALL, H5S_ALL,
                                 H5P_DEFAULT, buf) < 0)
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                   "cannot read %s in '%s'", name, file_name);
    if (space >= 0) H5Sclose(space);
    H5Dclose(set);
    return st;
}

/* The file holds the model's structure: same triangles, same spring ends,
 * rest lengths within 1e-9 relative (the counts already checked). */
static canopy_status check_mesh(hid_t file, const char *file_name,
                                const canopy_model *m, char *msg,
                                size_t msg_size)
{
    const size_t nt = (size_t)m->tris.count, ns = (size_t)m->springs.count;
    int *tri = malloc(sizeof(int) * (3 * nt + 1));
    int *ends = malloc(sizeof(int) * (2 * ns + 1));
    double *rest = malloc(sizeof(double) * (ns + 1));
    canopy_status st = CANOPY_OK;
    if (tri == NULL || ends == NULL || rest == NULL) {
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_MEMORY,
                                   "no memory to check the mesh of '%s'",
                                   file_name);
        goto done;
    }
    if ((st = read_ints(file, file_name, "/mesh/triangles", nt, 3, tri, msg,
                        msg_size)) != CANOPY_OK ||
        (st = read_ints(file, file_name, "/mesh/springs", ns, 2, ends, msg,
                        msg_size)) != CANOPY_OK ||
        (st = canopy_h5_read_doubles(file, "", "mesh/spring_rest_length", ns,
                                     0, rest, file_name, msg, msg_size)) !=
            CANOPY_OK)
        goto done;
    for (size_t i = 0; i < 3 * nt; ++i)
        if (tri[i] != m->tris.nodes[i]) {
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                       "'%s' does not hold this structure: "
                                       "triangle %zu has other vertices in "
                                       "the file", file_name, i / 3);
            goto done;
        }
    for (size_t i = 0; i < 2 * ns; ++i)
        if (ends[i] != m->springs.ends[i]) {
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                       "'%s' does not hold this structure: "
                                       "spring %zu joins other nodes in the "
                                       "file", file_name, i / 2);
            goto done;
        }
    for (size_t k = 0; k < ns; ++k)
        if (!(fabs(rest[k] - m->springs.rest[k]) <= 1e-9 * m->springs.rest[k])) {
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                       "'%s' does not hold this structure: "
                                       "the rest length of spring %zu is %g m "
                                       "in the file, %g m in the model", file_name,
                                       k, rest[k], m->springs.rest[k]);
            goto done;
        }
done:
    free(tri);
    free(ends);
    free(rest);
    return st;
}

static canopy_status read_impl(canopy_model *m, const char *h5_path, int step,
                               canopy_h5_load what, state_buffers *b,
                               char *msg, size_t msg_size)
{
    const hid_t file = canopy_h5_open_read(h5_path, msg, msg_size);
    if (file < 0) return CANOPY_ERR_IO;
    canopy_h5_counts counts;
    canopy_output_step *steps = NULL;
    int count = 0;
    hid_t group = -1;
    canopy_status st = canopy_h5_read_counts(file, h5_path, &counts, msg,
                                             msg_size);
    if (st == CANOPY_OK)
        st = canopy_h5_check_counts(&counts, m, h5_path, msg, msg_size);
    if (st == CANOPY_OK && what != CANOPY_H5_LOAD_RESTART)
        st = check_mesh(file, h5_path, m, msg, msg_size);
    if (st == CANOPY_OK)
        st = canopy_h5_list_steps(file, h5_path, &steps, &count, msg,
                                  msg_size);
    if (st != CANOPY_OK) goto done;
    if (count == 0) {
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_RANGE,
                                   "'%s' holds no steps", h5_path);
        goto done;
    }
    int found = -1;
    if (step == -1) {
        found = count - 1;
    } else {
        for (int s = 0; s < count; ++s)
            if (steps[s].number == step) found = s;
    }
    if (found < 0) {
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_RANGE,
                                   "step %d is not in '%s' (its steps are "
                                   "numbered %d to %d; -1 is the last)", step,
                                   h5_path, steps[0].number,
                                   steps[count - 1].number);
        goto done;
    }
    char name[32];
    snprintf(name, sizeof name, "/steps/" CANOPY_STEP_NAME_FMT,
             steps[found].number);
    b->t = steps[found].time;
    group = H5Gopen2(file, name, H5P_DEFAULT);
    if (group < 0) {
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                   "cannot open %s in '%s'", name, h5_path);
        goto done;
    }
    const hsize_t n = (hsize_t)m->nodes.count, nt = (hsize_t)m->tris.count;
    if ((st = canopy_h5_read_doubles(group, name, "x", n, 3, b->x, h5_path, msg,
                           msg_size)) != CANOPY_OK ||
        (st = canopy_h5_read_doubles(group, name, "v", n, 3, b->v, h5_path, msg,
                           msg_size)) != CANOPY_OK)
        goto done;
    b->acc_valid = 0;
    if (what == CANOPY_H5_LOAD_MOTION) goto check_time;
    if ((st = canopy_h5_read_doubles(group, name, "f_ext", n, 3, b->f, h5_path, msg,
                           msg_size)) != CANOPY_OK ||
        (st = canopy_h5_read_doubles(group, name, "dp", nt, 0, b->dp, h5_path, msg,
                           msg_size)) != CANOPY_OK)
        goto done;
    /* The integrator's carried acceleration (HHT); absent or invalid means
     * the next step starts afresh. */
    b->acc_valid = 0;
    if (H5Aexists(group, "acc_valid") > 0 &&
        canopy_h5_read_int_attribute(group, "acc_valid", &b->acc_valid) >= 0 &&
        b->acc_valid) {
        if ((st = canopy_h5_read_doubles(group, name, "acc", n, 3, b->acc, h5_path, msg,
                               msg_size)) != CANOPY_OK)
            goto done;
    } else {
        b->acc_valid = 0;
    }
check_time:
    if (!isfinite(b->t))
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                   "'%s': the time of %s is not finite",
                                   h5_path, name);
done:
    if (group >= 0) H5Gclose(group);
    free(steps);
    H5Fclose(file);
    return st;
}

canopy_status canopy_h5_load_state(canopy_model *model, const char *h5_path,
                                   int step, canopy_h5_load what,
                                   const double velocity_offset[3], char *msg,
                                   size_t msg_size)
{
    const size_t n = (size_t)model->nodes.count, nt = (size_t)model->tris.count;
    state_buffers b = {0.0, NULL, NULL, NULL, NULL, NULL, 0};
    b.x = malloc(sizeof(double) * 3 * (n > 0 ? n : 1));
    b.v = malloc(sizeof(double) * 3 * (n > 0 ? n : 1));
    b.f = malloc(sizeof(double) * 3 * (n > 0 ? n : 1));
    b.dp = malloc(sizeof(double) * (nt > 0 ? nt : 1));
    b.acc = malloc(sizeof(double) * 3 * (n > 0 ? n : 1));
    canopy_status st;
    if (b.x == NULL || b.v == NULL || b.f == NULL || b.dp == NULL ||
        b.acc == NULL) {
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_MEMORY,
                                   "no memory to read a state of %zu nodes",
                                   n);
    } else {
        H5E_BEGIN_TRY {
            st = read_impl(model, h5_path, step, what, &b, msg, msg_size);
        } H5E_END_TRY;
    }
    if (st == CANOPY_OK && what == CANOPY_H5_LOAD_MOTION) {
        /* As set_positions and set_velocities would, with the offset added
         * to the file's velocities first; checked before anything changes. */
        for (size_t i = 0; i < 3 * n && velocity_offset != NULL; ++i) {
            b.v[i] += velocity_offset[i % 3];
            if (!isfinite(b.v[i])) {
                st = canopy_format_message(msg, msg_size, CANOPY_ERR_ARGUMENT,
                                           "component %zu of node %zu's "
                                           "velocity plus the offset is not "
                                           "finite", i % 3, i / 3);
                break;
            }
        }
    }
    if (st == CANOPY_OK) {
        /* Everything was read and checked: only now change the model. */
        /* A model without nodes has NULL arrays: copy only what exists. */
        if (n > 0) {
            memcpy(model->nodes.x, b.x, sizeof(double) * 3 * n);
            memcpy(model->nodes.v, b.v, sizeof(double) * 3 * n);
        }
        if (what == CANOPY_H5_LOAD_MOTION) {
            for (int i = 0; i < (int)n; ++i)
                canopy_guide_project(model, i, model->nodes.v + 3 * i);
            model->acc_valid = 0;
        } else {
            if (n > 0) {
                memcpy(model->nodes.force_ext, b.f, sizeof(double) * 3 * n);
                if (b.acc_valid)
                    memcpy(model->nodes.acc, b.acc, sizeof(double) * 3 * n);
            }
            if (nt > 0) memcpy(model->tris.dp, b.dp, sizeof(double) * nt);
            model->acc_valid = b.acc_valid;
            model->t = b.t;
        }
    }
    free(b.x);
    free(b.v);
    free(b.f);
    free(b.dp);
    free(b.acc);
    return st;
}

canopy_status canopy_model_read_state(canopy_model *model, const char *path,
                                      int step)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (path == NULL || path[0] == '\0')
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "read_state: path is NULL or empty");
    if (step < -1)
        return canopy_fail(model, CANOPY_ERR_RANGE,
                           "read_state '%s': step %d (use a step number or -1 "
                           "for the last)", path, step);
    char *h5_path = canopy_path_with_ext(path, CANOPY_H5_EXT);
    char msg[CANOPY_MESSAGE_SIZE] = "";
    canopy_status st;
    if (h5_path == NULL)
        st = canopy_format_message(msg, sizeof msg, CANOPY_ERR_MEMORY,
                                   "no memory for the path '%s'", path);
    else
        st = canopy_h5_load_state(model, h5_path, step,
                                  CANOPY_H5_LOAD_RESTART, NULL, msg,
                                  sizeof msg);
    if (st == CANOPY_OK) {
        canopy_clear_message(model);
    } else {
        const char *text = strchr(msg, ':');
        canopy_fail(model, st, "read_state: %s",
                    text && text[1] ? text + 2 : msg);
    }
    free(h5_path);
    return st;
}

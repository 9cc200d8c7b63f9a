/* restart.c — canopy_model_read_state: load time, positions, velocities, pressure jumps and nodal forces of one output step. */
#include "output_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Read the double dataset `group`/`name` into buf, checking its shape is
 * rows (cols 0) or rows x cols. */
static canopy_status read_doubles(hid_t group, const char *group_name,
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

static canopy_status read_impl(canopy_model *m, const char *h5_path, int step,
                               state_buffers *b, char *msg, size_t msg_size)
{
    hid_t fapl = canopy_h5_fapl();
    if (fapl < 0)
        return canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                     "cannot make an HDF5 file access "
                                     "property list for '%s'", h5_path);
    hid_t file = H5Fopen(h5_path, H5F_ACC_RDONLY, fapl);
    H5Pclose(fapl);
    if (file < 0) {
        if (access(h5_path, F_OK) != 0)
            return canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                         "'%s' does not exist", h5_path);
        return canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                     "cannot open '%s' (unreadable or not an "
                                     "HDF5 file)", h5_path);
    }
    canopy_h5_counts counts;
    canopy_output_step *steps = NULL;
    int count = 0;
    hid_t group = -1;
    canopy_status st = canopy_h5_read_counts(file, h5_path, &counts, msg,
                                             msg_size);
    if (st == CANOPY_OK)
        st = canopy_h5_check_counts(&counts, m, h5_path, msg, msg_size);
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
    if ((st = read_doubles(group, name, "x", n, 3, b->x, h5_path, msg,
                           msg_size)) != CANOPY_OK ||
        (st = read_doubles(group, name, "v", n, 3, b->v, h5_path, msg,
                           msg_size)) != CANOPY_OK ||
        (st = read_doubles(group, name, "f_ext", n, 3, b->f, h5_path, msg,
                           msg_size)) != CANOPY_OK ||
        (st = read_doubles(group, name, "dp", nt, 0, b->dp, h5_path, msg,
                           msg_size)) != CANOPY_OK)
        goto done;
    /* The integrator's carried acceleration (HHT); absent or invalid means
     * the next step starts afresh. */
    b->acc_valid = 0;
    if (H5Aexists(group, "acc_valid") > 0 &&
        canopy_h5_read_int_attribute(group, "acc_valid", &b->acc_valid) >= 0 &&
        b->acc_valid) {
        if ((st = read_doubles(group, name, "acc", n, 3, b->acc, h5_path, msg,
                               msg_size)) != CANOPY_OK)
            goto done;
    } else {
        b->acc_valid = 0;
    }
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
    const size_t n = (size_t)model->nodes.count, nt = (size_t)model->tris.count;
    state_buffers b = {0.0, NULL, NULL, NULL, NULL, NULL, 0};
    b.x = malloc(sizeof(double) * 3 * (n > 0 ? n : 1));
    b.v = malloc(sizeof(double) * 3 * (n > 0 ? n : 1));
    b.f = malloc(sizeof(double) * 3 * (n > 0 ? n : 1));
    b.dp = malloc(sizeof(double) * (nt > 0 ? nt : 1));
    b.acc = malloc(sizeof(double) * 3 * (n > 0 ? n : 1));
    char *h5_path = canopy_path_with_ext(path, CANOPY_H5_EXT);
    canopy_status st;
    char msg[CANOPY_MESSAGE_SIZE] = "";
    if (b.x == NULL || b.v == NULL || b.f == NULL || b.dp == NULL ||
        b.acc == NULL ||
        h5_path == NULL) {
        st = canopy_format_message(msg, sizeof msg, CANOPY_ERR_MEMORY,
                                   "no memory to read a state of %zu nodes",
                                   n);
    } else {
        H5E_BEGIN_TRY {
            st = read_impl(model, h5_path, step, &b, msg, sizeof msg);
        } H5E_END_TRY;
    }
    if (st == CANOPY_OK) {
        /* Everything was read and checked: only now change the model. */
        /* A model without nodes has NULL arrays: copy only what exists. */
        if (n > 0) {
            memcpy(model->nodes.x, b.x, sizeof(double) * 3 * n);
            memcpy(model->nodes.v, b.v, sizeof(double) * 3 * n);
            memcpy(model->nodes.force_ext, b.f, sizeof(double) * 3 * n);
            if (b.acc_valid)
                memcpy(model->nodes.acc, b.acc, sizeof(double) * 3 * n);
        }
        if (nt > 0) memcpy(model->tris.dp, b.dp, sizeof(double) * nt);
        model->acc_valid = b.acc_valid;
        model->t = b.t;
        canopy_clear_message(model);
    } else {
        const char *text = strchr(msg, ':');
        canopy_fail(model, st, "read_state: %s",
                    text && text[1] ? text + 2 : msg);
    }
    free(b.x);
    free(b.v);
    free(b.f);
    free(b.dp);
    free(b.acc);
    free(h5_path);
    return st;
}

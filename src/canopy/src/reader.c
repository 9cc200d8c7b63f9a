/* reader.c — canopy_reader: an output file's steps and times, a step found by time, its state loaded into a model, its nodal forces. */
#include "output_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct canopy_reader {
    char *h5_path;              /* path.h5 of the open file; NULL: none */
    canopy_h5_counts counts;    /* its /mesh counts */
    canopy_output_step *steps;  /* sorted by number */
    int count;
    char message[CANOPY_MESSAGE_SIZE];
};

static canopy_status reader_fail(canopy_reader *r, canopy_status st,
                                 const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static canopy_status reader_fail(canopy_reader *r, canopy_status st,
                                 const char *fmt, ...)
{
    char text[CANOPY_MESSAGE_SIZE];
    va_list args;
    va_start(args, fmt);
    vsnprintf(text, sizeof text, fmt, args);
    va_end(args);
    return canopy_format_message(r->message, sizeof r->message, st, "%s",
                                 text);
}

/* An internal message without its leading "CANOPY_ERR_...: ". */
static const char *reason(const char *msg)
{
    const char *text = strchr(msg, ':');
    return text && text[1] ? text + 2 : msg;
}

canopy_status canopy_reader_create(canopy_reader **out)
{
    if (out == NULL) return CANOPY_ERR_ARGUMENT;
    *out = calloc(1, sizeof **out);
    return *out ? CANOPY_OK : CANOPY_ERR_MEMORY;
}

void canopy_reader_destroy(canopy_reader **reader)
{
    if (reader == NULL || *reader == NULL) return;
    free((*reader)->h5_path);
    free((*reader)->steps);
    free(*reader);
    *reader = NULL;
}

const char *canopy_reader_message(const canopy_reader *reader)
{
    return reader ? reader->message : "reader is NULL";
}

/* Open h5_path, read its counts and steps into *counts, *steps, *count. */
static canopy_status open_impl(const char *h5_path, canopy_h5_counts *counts,
                               canopy_output_step **steps, int *count,
                               char *msg, size_t msg_size)
{
    const hid_t file = canopy_h5_open_read(h5_path, msg, msg_size);
    if (file < 0) return CANOPY_ERR_IO;
    canopy_status st = canopy_h5_read_counts(file, h5_path, counts, msg,
                                             msg_size);
    if (st == CANOPY_OK)
        st = canopy_h5_list_steps(file, h5_path, steps, count, msg, msg_size);
    for (int s = 0; st == CANOPY_OK && s < *count; ++s)
        if (!isfinite((*steps)[s].time))
            st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                       "'%s': the time of step %d is not "
                                       "finite", h5_path, (*steps)[s].number);
    if (st != CANOPY_OK) {
        free(*steps);
        *steps = NULL;
        *count = 0;
    }
    H5Fclose(file);
    return st;
}

canopy_status canopy_reader_open(canopy_reader *reader, const char *path)
{
    if (reader == NULL) return CANOPY_ERR_ARGUMENT;
    if (path == NULL || path[0] == '\0')
        return reader_fail(reader, CANOPY_ERR_ARGUMENT,
                           "open: path is NULL or empty");
    char *h5_path = canopy_path_with_ext(path, CANOPY_H5_EXT);
    if (h5_path == NULL)
        return reader_fail(reader, CANOPY_ERR_MEMORY,
                           "open: no memory for the path '%s'", path);
    canopy_h5_counts counts = {0, 0, 0, 0};
    canopy_output_step *steps = NULL;
    int count = 0;
    char msg[CANOPY_MESSAGE_SIZE] = "";
    canopy_status st;
    H5E_BEGIN_TRY {
        st = open_impl(h5_path, &counts, &steps, &count, msg, sizeof msg);
    } H5E_END_TRY;
    if (st != CANOPY_OK) {
        free(h5_path);
        return reader_fail(reader, st, "open: %s", reason(msg));
    }
    free(reader->h5_path);
    free(reader->steps);
    reader->h5_path = h5_path;
    reader->counts = counts;
    reader->steps = steps;
    reader->count = count;
    reader->message[0] = '\0';
    return CANOPY_OK;
}

int canopy_reader_step_count(const canopy_reader *reader)
{
    return reader ? reader->count : 0;
}

/* A file is open and index names one of its steps. */
static canopy_status check_index(canopy_reader *r, const char *call,
                                 int index)
{
    if (r->h5_path == NULL)
        return reader_fail(r, CANOPY_ERR_STATE, "%s: no file is open", call);
    if (index < 0 || index >= r->count)
        return reader_fail(r, CANOPY_ERR_RANGE,
                           "%s: step index %d is not in 0..%d ('%s' holds %d "
                           "steps)", call, index, r->count - 1, r->h5_path,
                           r->count);
    return CANOPY_OK;
}

canopy_status canopy_reader_step(canopy_reader *reader, int index,
                                 int *number, double *time)
{
    if (reader == NULL) return CANOPY_ERR_ARGUMENT;
    canopy_status st = check_index(reader, "step", index);
    if (st != CANOPY_OK) return st;
    if (number) *number = reader->steps[index].number;
    if (time) *time = reader->steps[index].time;
    reader->message[0] = '\0';
    return CANOPY_OK;
}

canopy_status canopy_reader_find_step(canopy_reader *reader, double time,
                                      double tolerance, int *index)
{
    if (reader == NULL) return CANOPY_ERR_ARGUMENT;
    if (index == NULL)
        return reader_fail(reader, CANOPY_ERR_ARGUMENT,
                           "find_step: index is NULL");
    if (reader->h5_path == NULL)
        return reader_fail(reader, CANOPY_ERR_STATE,
                           "find_step: no file is open");
    if (!isfinite(time) || !(tolerance >= 0) || !isfinite(tolerance))
        return reader_fail(reader, CANOPY_ERR_ARGUMENT,
                           "find_step: time %g and tolerance %g must be "
                           "finite, the tolerance >= 0", time, tolerance);
    const canopy_output_step *s = reader->steps;
    int best = -1, nearest = -1;
    for (int i = 0; i < reader->count; ++i) {
        const double d = fabs(s[i].time - time);
        if (nearest < 0 || d < fabs(s[nearest].time - time)) nearest = i;
        if (d <= tolerance && (best < 0 || d < fabs(s[best].time - time)))
            best = i;
    }
    if (best >= 0) {
        *index = best;
        reader->message[0] = '\0';
        return CANOPY_OK;
    }
    if (reader->count == 0)
        return reader_fail(reader, CANOPY_ERR_RANGE,
                           "find_step: '%s' holds no step at time %g "
                           "(tolerance %g); it holds no steps",
                           reader->h5_path, time, tolerance);
    double t_min = s[0].time, t_max = s[0].time;
    for (int i = 1; i < reader->count; ++i) {
        t_min = fmin(t_min, s[i].time);
        t_max = fmax(t_max, s[i].time);
    }
    return reader_fail(reader, CANOPY_ERR_RANGE,
                       "find_step: '%s' holds no step at time %g (tolerance "
                       "%g); %d steps from t = %g to %g, the nearest at t = "
                       "%g", reader->h5_path, time, tolerance, reader->count,
                       t_min, t_max, s[nearest].time);
}

/* Load step `index` into the model with canopy_h5_load_state. */
static canopy_status load(canopy_reader *r, const char *call, int index,
                          canopy_model *model, canopy_h5_load what,
                          const double velocity_offset[3])
{
    if (r == NULL) return CANOPY_ERR_ARGUMENT;
    if (model == NULL)
        return reader_fail(r, CANOPY_ERR_ARGUMENT, "%s: model is NULL", call);
    canopy_status st = check_index(r, call, index);
    if (st != CANOPY_OK) return st;
    if (velocity_offset != NULL)
        for (int d = 0; d < 3; ++d)
            if (!isfinite(velocity_offset[d]))
                return reader_fail(r, CANOPY_ERR_ARGUMENT,
                                   "%s: component %d of the velocity offset "
                                   "is not finite", call, d);
    char msg[CANOPY_MESSAGE_SIZE] = "";
    st = canopy_h5_load_state(model, r->h5_path, r->steps[index].number, what,
                              velocity_offset, msg, sizeof msg);
    if (st != CANOPY_OK) return reader_fail(r, st, "%s: %s", call, reason(msg));
    r->message[0] = '\0';
    return CANOPY_OK;
}

canopy_status canopy_reader_read_state(canopy_reader *reader, int index,
                                       canopy_model *model)
{
    return load(reader, "read_state", index, model, CANOPY_H5_LOAD_CHECKED,
                NULL);
}

canopy_status canopy_reader_read_motion(canopy_reader *reader, int index,
                                        canopy_model *model,
                                        const double velocity_offset[3])
{
    return load(reader, "read_motion", index, model, CANOPY_H5_LOAD_MOTION,
                velocity_offset);
}

/* Read /steps/NNNNNN/f_ext of the open file into f (3 n doubles). */
static canopy_status forces_impl(const canopy_reader *r, int number, int n,
                                 double *f, char *msg, size_t msg_size)
{
    const hid_t file = canopy_h5_open_read(r->h5_path, msg, msg_size);
    if (file < 0) return CANOPY_ERR_IO;
    char name[32];
    snprintf(name, sizeof name, "/steps/" CANOPY_STEP_NAME_FMT, number);
    canopy_status st;
    hid_t group = H5Gopen2(file, name, H5P_DEFAULT);
    if (group < 0)
        st = canopy_format_message(msg, msg_size, CANOPY_ERR_FORMAT,
                                   "'%s' has no group %s", r->h5_path, name);
    else
        st = canopy_h5_read_doubles(group, name, "f_ext", (hsize_t)n, 3, f,
                                    r->h5_path, msg, msg_size);
    if (group >= 0) H5Gclose(group);
    H5Fclose(file);
    return st;
}

canopy_status canopy_reader_get_nodal_forces(canopy_reader *reader, int index,
                                             double *f, int n)
{
    if (reader == NULL) return CANOPY_ERR_ARGUMENT;
    canopy_status st = check_index(reader, "get_nodal_forces", index);
    if (st != CANOPY_OK) return st;
    if (f == NULL && n > 0)
        return reader_fail(reader, CANOPY_ERR_ARGUMENT,
                           "get_nodal_forces: f is NULL");
    if (n != reader->counts.nodes)
        return reader_fail(reader, CANOPY_ERR_RANGE,
                           "get_nodal_forces: n = %d, '%s' holds %d nodes", n,
                           reader->h5_path, reader->counts.nodes);
    double *buf = malloc(sizeof(double) * 3 * (size_t)(n > 0 ? n : 1));
    if (buf == NULL)
        return reader_fail(reader, CANOPY_ERR_MEMORY,
                           "get_nodal_forces: no memory for %d nodes", n);
    char msg[CANOPY_MESSAGE_SIZE] = "";
    H5E_BEGIN_TRY {
        st = forces_impl(reader, reader->steps[index].number, n, buf, msg,
                         sizeof msg);
    } H5E_END_TRY;
    if (st == CANOPY_OK) {
        if (n > 0) memcpy(f, buf, sizeof(double) * 3 * (size_t)n);
        reader->message[0] = '\0';
    } else {
        reader_fail(reader, st, "get_nodal_forces: %s", reason(msg));
    }
    free(buf);
    return st;
}

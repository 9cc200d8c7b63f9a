/* output_internal.h — what the HDF5 writer, the XDMF writer and restart share: file layout names, step lists, helpers. */
#ifndef CANOPY_OUTPUT_INTERNAL_H
#define CANOPY_OUTPUT_INTERNAL_H

#include "model_internal.h"

#include <hdf5.h>
#include <stddef.h>

/* File layout (see canopy.h, Output). Step groups are /steps/NNNNNN, the
 * number zero-padded to six digits (more digits past 999999). */
#define CANOPY_H5_EXT        ".h5"
#define CANOPY_XDMF_EXT      ".xdmf"
#define CANOPY_FRAME_XDMF_EXT "-frame.xdmf"
#define CANOPY_STEP_NAME_FMT "%06d"
#define CANOPY_STEP_NAME_SIZE 16

/* One output step: its number (the NNNNNN of its group), its time, and
 * whether it holds the positions in a moving frame (x_frame). */
typedef struct canopy_output_step {
    int number;
    double time;
    int framed;
} canopy_output_step;

/* What the XDMF text needs to know about the mesh. */
typedef struct canopy_xdmf_mesh {
    int nodes;          /* points */
    int cells;          /* XDMF cells: triangles + line cells */
    long cells_length;  /* ints in /mesh/cells */
} canopy_xdmf_mesh;

/* "path" + ext in a new heap string (NULL when out of memory). */
char *canopy_path_with_ext(const char *path, const char *ext);

/* The final component of a path ("dir/drop.h5" -> "drop.h5"). */
const char *canopy_path_basename(const char *path);

/* A file access property list with HDF5's file locking switched off (where
 * the library supports it), so ParaView may read a file while a run writes
 * it. Returns a negative id on failure. The caller closes it. */
hid_t canopy_h5_fapl(void);

/* Open h5_path read-only with canopy_h5_fapl(). On failure returns a
 * negative id with a CANOPY_ERR_IO message in msg naming the file (it does
 * not exist, or is unreadable or not HDF5). HDF5 printing must be off. */
hid_t canopy_h5_open_read(const char *h5_path, char *msg, size_t msg_size);

/* Read the scalar int attribute `name` of `obj` into *value (any integer
 * type in the file). Returns a negative value on failure. */
herr_t canopy_h5_read_int_attribute(hid_t obj, const char *name, int *value);

/* The steps under /steps of an open file, sorted by number: *steps
 * (malloc'ed, free with free(); NULL when there are none) and *count.
 * A missing /steps group is an empty list. On failure returns an error with
 * a message in msg (naming `file_name`) and leaves *steps NULL. Must be
 * called with HDF5's automatic error printing off. */
canopy_status canopy_h5_list_steps(hid_t file, const char *file_name,
                                   canopy_output_step **steps, int *count,
                                   char *msg, size_t msg_size);

/* The counts stored as attributes of /mesh (nodes, springs, triangles,
 * lines). Returns an error (CANOPY_ERR_FORMAT when absent) with a message
 * naming `file_name`. HDF5 printing must be off. */
typedef struct canopy_h5_counts {
    int nodes, springs, triangles, lines;
} canopy_h5_counts;
canopy_status canopy_h5_read_counts(hid_t file, const char *file_name,
                                    canopy_h5_counts *counts, char *msg,
                                    size_t msg_size);

/* Compare the counts of a file with a model's; CANOPY_ERR_FORMAT naming the
 * first count that differs. */
canopy_status canopy_h5_check_counts(const canopy_h5_counts *file_counts,
                                     const canopy_model *model,
                                     const char *file_name, char *msg,
                                     size_t msg_size);

/* Write the XDMF sidecar `xdmf_path` for the given steps of the HDF5 file
 * whose name relative to the sidecar is `h5_name`, the geometry from each
 * step's dataset `geometry` ("x", or "x_frame" for the moving frame's
 * sidecar): written to
 * xdmf_path + ".tmp", then renamed over xdmf_path. With no steps, an old
 * sidecar is removed instead (an empty collection crashes ParaView's legacy
 * reader). On failure the old sidecar is untouched, the temporary removed,
 * and CANOPY_ERR_IO returned with a message in msg. */
canopy_status canopy_xdmf_write(const char *xdmf_path, const char *h5_name,
                                const char *geometry,
                                const canopy_xdmf_mesh *mesh,
                                const canopy_output_step *steps, int count,
                                char *msg, size_t msg_size);

/* Read the double dataset `group`/`name` (group_name: its path, for
 * messages) into buf, checking its shape is rows (cols 0) or rows x cols
 * and every value finite; CANOPY_ERR_FORMAT naming `file_name` otherwise.
 * HDF5 printing must be off. */
canopy_status canopy_h5_read_doubles(hid_t group, const char *group_name,
                                     const char *name, hsize_t rows,
                                     hsize_t cols, double *buf,
                                     const char *file_name, char *msg,
                                     size_t msg_size);

/* What canopy_h5_load_state takes from a step. */
typedef enum canopy_h5_load {
    /* time, x, v, f_ext, dp, carried acceleration; counts checked
     * (canopy_model_read_state) */
    CANOPY_H5_LOAD_RESTART = 0,
    /* the same, and the mesh checked (triangles, springs, rest lengths) */
    CANOPY_H5_LOAD_CHECKED = 1,
    /* x and v + velocity_offset only, as set_positions and set_velocities
     * (guided nodes' velocities projected, carried acceleration dropped);
     * the mesh checked */
    CANOPY_H5_LOAD_MOTION = 2
} canopy_h5_load;

/* Load step number `step` (-1: the last) of the file h5_path (with its
 * extension) into the model. On failure the model is unchanged and msg
 * holds the reason (naming the file). Sets no message on the model. */
canopy_status canopy_h5_load_state(canopy_model *model, const char *h5_path,
                                   int step, canopy_h5_load what,
                                   const double velocity_offset[3], char *msg,
                                   size_t msg_size);

#endif /* CANOPY_OUTPUT_INTERNAL_H */

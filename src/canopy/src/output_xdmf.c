/* output_xdmf.c — writes the XDMF 3 sidecar (temporal collection over the HDF5 steps) through a temporary file and rename(). */
#include "output_internal.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The first grid holds the topology and the per-node mesh attributes; the
 * other grids include them by XPointer (XInclude), so they are written once.
 * ParaView 5.11's Xdmf3 readers and its legacy XDMF reader both resolve
 * this. */
#define FIRST_GRID "/Xdmf/Domain/Grid/Grid[1]"

/* Text with XML's special characters escaped (file names may hold them). */
static void put_escaped(FILE *f, const char *text)
{
    for (const char *c = text; *c; ++c) {
        switch (*c) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&apos;", f); break;
        default: fputc(*c, f); break;
        }
    }
}

static void heavy(FILE *f, const char *indent, const char *dims,
                  const char *type, int precision, const char *h5_name,
                  const char *dataset)
{
    fprintf(f,
            "%s<DataItem Dimensions=\"%s\" NumberType=\"%s\" Precision=\"%d\" "
            "Format=\"HDF\">", indent, dims, type, precision);
    put_escaped(f, h5_name);
    fprintf(f, ":%s</DataItem>\n", dataset);
}

static void attribute(FILE *f, const char *name, const char *type,
                      const char *center, const char *dims,
                      const char *number_type, int precision,
                      const char *h5_name, const char *dataset)
{
    fprintf(f,
            "        <Attribute Name=\"%s\" AttributeType=\"%s\" "
            "Center=\"%s\">\n", name, type, center);
    heavy(f, "          ", dims, number_type, precision, h5_name, dataset);
    fprintf(f, "        </Attribute>\n");
}

static void write_grid(FILE *f, const canopy_xdmf_mesh *mesh,
                       const char *h5_name, const char *geometry,
                       const canopy_output_step *step, int first)
{
    char name[CANOPY_STEP_NAME_SIZE], path[64], nodes1[32], nodes3[32],
        cells1[32], cells_len[32], time_text[32];
    /* The shortest of %.15g, %.16g, %.17g that reads back exactly. */
    for (int digits = 15; digits <= 17; ++digits) {
        snprintf(time_text, sizeof time_text, "%.*g", digits, step->time);
        if (strtod(time_text, NULL) == step->time) break;
    }
    snprintf(name, sizeof name, CANOPY_STEP_NAME_FMT, step->number);
    snprintf(nodes1, sizeof nodes1, "%d", mesh->nodes);
    snprintf(nodes3, sizeof nodes3, "%d 3", mesh->nodes);
    snprintf(cells1, sizeof cells1, "%d", mesh->cells);
    snprintf(cells_len, sizeof cells_len, "%ld", mesh->cells_length);

    fprintf(f, "      <Grid Name=\"step_%s\" GridType=\"Uniform\">\n", name);
    fprintf(f, "        <Time Value=\"%s\"/>\n", time_text);
    if (first) {
        fprintf(f,
                "        <Topology TopologyType=\"Mixed\" "
                "NumberOfElements=\"%d\">\n", mesh->cells);
        heavy(f, "          ", cells_len, "Int", 4, h5_name, "/mesh/cells");
        fprintf(f, "        </Topology>\n");
    } else {
        fprintf(f, "        <xi:include xpointer=\"xpointer("
                   FIRST_GRID "/Topology)\"/>\n");
    }
    fprintf(f, "        <Geometry GeometryType=\"XYZ\">\n");
    snprintf(path, sizeof path, "/steps/%s/%s", name, geometry);
    heavy(f, "          ", nodes3, "Float", 8, h5_name, path);
    fprintf(f, "        </Geometry>\n");

    snprintf(path, sizeof path, "/steps/%s/v", name);
    attribute(f, "velocity", "Vector", "Node", nodes3, "Float", 8, h5_name,
              path);
    snprintf(path, sizeof path, "/steps/%s/f_ext", name);
    attribute(f, "nodal_force", "Vector", "Node", nodes3, "Float", 8, h5_name,
              path);
    snprintf(path, sizeof path, "/steps/%s/cell_dp", name);
    attribute(f, "cell_dp", "Scalar", "Cell", cells1, "Float", 8, h5_name,
              path);
    snprintf(path, sizeof path, "/steps/%s/cell_tension", name);
    attribute(f, "cell_tension", "Scalar", "Cell", cells1, "Float", 8,
              h5_name, path);
    if (first) {
        attribute(f, "node_group", "Scalar", "Node", nodes1, "Int", 4,
                  h5_name, "/mesh/node_group");
        attribute(f, "node_mass", "Scalar", "Node", nodes1, "Float", 8,
                  h5_name, "/mesh/node_mass");
        attribute(f, "node_fixed", "Scalar", "Node", nodes1, "Int", 4,
                  h5_name, "/mesh/node_fixed");
    } else {
        static const char *const names[] = {"node_group", "node_mass",
                                            "node_fixed"};
        for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
            fprintf(f, "        <xi:include xpointer=\"xpointer(" FIRST_GRID
                       "/Attribute[@Name='%s'])\"/>\n", names[i]);
    }
    fprintf(f, "      </Grid>\n");
}

canopy_status canopy_xdmf_write(const char *xdmf_path, const char *h5_name,
                                const char *geometry,
                                const canopy_xdmf_mesh *mesh,
                                const canopy_output_step *steps, int count,
                                char *msg, size_t msg_size)
{
    if (count == 0) {
        /* No steps: no sidecar. An empty temporal collection crashes
         * ParaView 5.11's legacy XDMF reader, and a sidecar left from an
         * earlier run would name steps this file no longer has. */
        if (remove(xdmf_path) != 0 && errno != ENOENT) {
            int err = errno;
            return canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                                         "cannot remove the old '%s': %s",
                                         xdmf_path, strerror(err));
        }
        return CANOPY_OK;
    }
    char *tmp = canopy_path_with_ext(xdmf_path, ".tmp");
    if (tmp == NULL)
        return canopy_format_message(msg, msg_size, CANOPY_ERR_MEMORY,
                                     "no memory for the name of '%s'",
                                     xdmf_path);
    FILE *f = fopen(tmp, "w");
    if (f == NULL) {
        int err = errno;
        canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                              "cannot create '%s': %s", tmp, strerror(err));
        free(tmp);
        return CANOPY_ERR_IO;
    }
    fprintf(f,
            "<?xml version=\"1.0\" ?>\n"
            "<!-- Written by libcanopy: the time series of the HDF5 file "
            "below, one grid per step. Regenerable from the .h5 file alone. "
            "-->\n"
            "<Xdmf Version=\"3.0\" "
            "xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
            "  <Domain>\n"
            "    <Grid Name=\"canopy\" GridType=\"Collection\" "
            "CollectionType=\"Temporal\">\n");
    for (int s = 0; s < count; ++s)
        write_grid(f, mesh, h5_name, geometry, &steps[s], s == 0);
    fprintf(f, "    </Grid>\n  </Domain>\n</Xdmf>\n");

    int failed = ferror(f) != 0;
    int err = errno;
    if (fclose(f) != 0 && !failed) {
        failed = 1;
        err = errno;
    }
    if (failed) {
        canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                              "cannot write '%s': %s", tmp, strerror(err));
        remove(tmp);
        free(tmp);
        return CANOPY_ERR_IO;
    }
    if (rename(tmp, xdmf_path) != 0) {
        err = errno;
        canopy_format_message(msg, msg_size, CANOPY_ERR_IO,
                              "cannot rename '%s' to '%s': %s", tmp,
                              xdmf_path, strerror(err));
        remove(tmp);
        free(tmp);
        return CANOPY_ERR_IO;
    }
    free(tmp);
    return CANOPY_OK;
}

/* build_internal.h — helpers shared by the geometry builders: spec/material validation, stiffness from materials, fabric triangles with lumped mass and one spring per edge, rollback. */
#ifndef CANOPY_BUILD_INTERNAL_H
#define CANOPY_BUILD_INTERNAL_H

#include "model_internal.h"

#include <stddef.h>

/* Most nodes (and, separately, springs or triangles) one builder call may
 * create: keeps int indices far from overflow and turns an absurd
 * edge_length into an argument error instead of an allocation failure. */
#define CANOPY_BUILD_MAX_ITEMS 20000000.0

/* What a material describes. A sheet (fabric) has an areal density and a 2-D
 * modulus E t [N/m]; a string (line, tape, chord) has a linear density and an
 * axial rigidity E A [N]. */
typedef enum canopy_material_kind {
    CANOPY_MATERIAL_SHEET = 0,
    CANOPY_MATERIAL_STRING = 1
} canopy_material_kind;

/* All three components finite. */
int canopy_build_finite3(const double x[3]);

/* Check a material: stiffness and modulus finite and >= 0 with at least one
 * > 0, density finite and >= 0, damping finite and >= 0, a known law. On
 * failure the message reads "<who>: <field>.<member> <value> must ...". */
canopy_status canopy_build_check_material(canopy_model *model, const char *who,
                                          const char *field,
                                          const canopy_material *material);

/* Spring constant of one fabric edge: material stiffness if > 0, else
 * (sqrt(3)/2) E t (a regular triangular lattice of springs k has
 * E t = (2/sqrt(3)) k, NOTES §3). */
double canopy_build_sheet_stiffness(const canopy_material *material);
/* Spring constant of one string segment of rest length l0: material
 * stiffness if > 0, else E A / l0. */
double canopy_build_string_stiffness(const canopy_material *material,
                                     double l0);

/* Counts at the start of a builder call, so that a failure after validation
 * (only an allocation can fail then) can drop everything the call added.
 * Builders add mass to nodes that existed before the call only as their last
 * action, after every allocation succeeded, so truncating the counts restores
 * the model (the user checkpoint may be dropped, as by any topology change). */
typedef struct canopy_build_mark {
    int nodes, springs, triangles;
} canopy_build_mark;
void canopy_build_mark_take(const canopy_model *model, canopy_build_mark *mark);
void canopy_build_rollback(canopy_model *model, const canopy_build_mark *mark);

/* Adds a string spring i–j (rest length = current distance) with stiffness
 * from the material, its damping and law; *l0_out (may be NULL) receives the
 * rest length. Does not add mass. */
canopy_status canopy_build_string_spring(canopy_model *model, int i, int j,
                                         const canopy_material *material,
                                         canopy_group group, double *l0_out);

/* A fabric under construction: triangles with their mass share and their
 * three edge springs, an edge shared by two triangles getting one spring. The
 * edge set (open-addressing hash of node pairs) lives for one build call. */
typedef struct canopy_fabric_builder {
    canopy_model *model;
    double stiffness, damping, density;
    canopy_spring_law law;
    canopy_group group;
    double up[3];               /* triangles are oriented so normal.up > 0 */
    unsigned long long *keys;   /* 0 = empty slot, else (min+1) << 32 | (max+1) */
    size_t capacity, used;
} canopy_fabric_builder;

/* Start a fabric with the given (validated) sheet material, springs in
 * `group`, triangles oriented towards `up`; expected_edges sizes the edge set
 * (it grows if needed). */
canopy_status canopy_fabric_begin(canopy_fabric_builder *fb,
                                  canopy_model *model,
                                  const canopy_material *material,
                                  canopy_group group, const double up[3],
                                  size_t expected_edges);
/* Add triangle a, b, c (reordered to a, c, b if its normal points against
 * `up`), add density x area / 3 to each vertex, and a spring for each edge
 * not yet in the fabric. */
canopy_status canopy_fabric_triangle(canopy_fabric_builder *fb, int a, int b,
                                     int c);
/* Free the edge set. */
void canopy_fabric_end(canopy_fabric_builder *fb);

/* The zipping rule on its own, for planners that work on coordinates: with
 * points xyz (3 doubles each) and chains lower[0..nl], upper[0..nu] of
 * indices into it, standing at diagonal lower[i]-upper[j], returns 1 if the
 * next triangle is lower[i], lower[i+1], upper[j] and 0 if it is lower[i],
 * upper[j+1], upper[j]. */
int canopy_zip_step(const double *xyz, const int *lower, int nl,
                    const int *upper, int nu, int i, int j);

/* Triangulate the strip between two node chains that run side by side,
 * lower[0..nl] and upper[0..nu] (nl + 1 and nu + 1 nodes, nl + nu >= 1),
 * whose first nodes face each other and whose last nodes face each other:
 * "zipping". At each step the shorter of the two candidate diagonals is
 * used (a local Delaunay choice); a near tie goes to the chain whose next
 * node is earlier by its fraction along the chain. Adds nl + nu triangles. */
canopy_status canopy_fabric_zip(canopy_fabric_builder *fb, const int *lower,
                                int nl, const int *upper, int nu);

/* CANOPY_OK when value is finite and > 0; else fails with
 * "<who>: spec.<name> <value> must be finite and > 0". */
canopy_status canopy_build_check_positive(canopy_model *model, const char *who,
                                          const char *name, double value);

/* Flat builders (rectangle, cross): spacings of a length at the target edge
 * e, round(len / e) >= 1; row spacings of a band of thickness T for node
 * spacing s, the fewest with spacing <= (sqrt(3)/2) s; the checks they share
 * (edge length finite and > 0, the placement point `point_name` finite, the
 * fabric a valid sheet material). */
int canopy_build_spacings(double len, double e);
int canopy_build_row_spacings(double T, double s);
canopy_status canopy_build_check_flat(canopy_model *model, const char *who,
                                      double edge, const double point[3],
                                      const char *point_name,
                                      const canopy_material *fabric);
#endif /* CANOPY_BUILD_INTERNAL_H */

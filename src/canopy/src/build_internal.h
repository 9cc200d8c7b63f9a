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

/* The model at the start of a builder call, so that a failure part-way can
 * drop everything the call added: the counts, and what adding changes
 * besides (the user checkpoint's validity, the carried acceleration's
 * validity, the payload node). Builders add mass to nodes that existed
 * before the call only as their last action, once nothing can fail, so
 * truncating the counts and restoring these restores the model exactly, as
 * canopy.h promises for a failed call. */
typedef struct canopy_build_mark {
    int nodes, springs, triangles;
    int checkpoint_valid, acc_valid, payload_node;
} canopy_build_mark;
void canopy_build_mark_take(const canopy_model *model, canopy_build_mark *mark);
void canopy_build_rollback(canopy_model *model, const canopy_build_mark *mark);
/* Roll back to mark after the call failed with st, and let the message name
 * the user's arguments: an ARGUMENT or RANGE failure of an internal add_*
 * call (a degenerate mesh: coincident nodes, an infinite stiffness or mass)
 * becomes "<who>: <args> make a degenerate model (<internal message>)" with
 * status CANOPY_ERR_ARGUMENT. Returns the status. */
canopy_status canopy_build_abort(canopy_model *model,
                                 const canopy_build_mark *mark,
                                 canopy_status st, const char *who,
                                 const char *args);

/* A string's segment of length seg (one of n_segments over `length`) must
 * make a sound spring: seg^2 a normal number (so that the nodes are apart
 * in double precision) and finite, the stiffness and the half-segment mass
 * from the material finite and the stiffness > 0. On failure the message
 * names `what` (the user's arguments that give the length). */
canopy_status canopy_build_check_segment(canopy_model *model, const char *who,
                                         const char *what, double length,
                                         int n_segments,
                                         const canopy_material *material);

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
 * spacing s, the fewest with spacing <= (sqrt(3)/2) s (both saturate at
 * CANOPY_BUILD_SPACINGS_MAX, beyond the builders' limits, and for NaN,
 * so that a huge ratio is never converted to int); the checks they share
 * (edge length finite and > 0, the placement point `point_name` finite, the
 * fabric a valid sheet material). */
#define CANOPY_BUILD_SPACINGS_MAX 100000000
int canopy_build_spacings(double len, double e);
int canopy_build_row_spacings(double T, double s);
canopy_status canopy_build_check_flat(canopy_model *model, const char *who,
                                      double edge, const double point[3],
                                      const char *point_name,
                                      const canopy_material *fabric);
#endif /* CANOPY_BUILD_INTERNAL_H */

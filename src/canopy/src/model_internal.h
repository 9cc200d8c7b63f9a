/* model_internal.h — the canopy_model structure and helpers shared inside libcanopy. */
#ifndef CANOPY_MODEL_INTERNAL_H
#define CANOPY_MODEL_INTERNAL_H

#include "canopy.h"
#include "vectors.h"

#include <stddef.h>

#define CANOPY_MESSAGE_SIZE 512

typedef struct canopy_integrator canopy_integrator;

/* The model's integrator with its own state (integrator.h, integrators.c):
 * `state` is type->alloc's workspace for `nodes` nodes; type NULL: none. */
typedef struct canopy_stepper {
    const canopy_integrator *type;
    void *state;
    int nodes;
    size_t bytes;
} canopy_stepper;

/* The implicit hinge dashpots' conjugate-gradient workspace
 * (bending_implicit.c). */
typedef struct canopy_hinge_solver canopy_hinge_solver;

/* Growable arrays of nodes, springs and triangles (structure of arrays). */
typedef struct canopy_nodes {
    int count, capacity;
    double *x;          /* 3*count positions */
    double *v;          /* 3*count velocities */
    double *mass;       /* lumped mass */
    double *added_mass; /* optional added mass (0 by default) */
    double *added_dir;  /* 3*count unit direction the added mass acts along
                           (0 0 0: it acts in every direction) */
    double *force_ext;  /* 3*count extra nodal forces */
    double *acc;        /* 3*count acceleration carried by HHT between steps */
    double *guide;      /* 3*count unit direction of the wire a node slides
                           on (canopy_model_set_guide); 0 0 0: none */
    unsigned char *fixed;
    unsigned char *group;
} canopy_nodes;

typedef struct canopy_springs {
    int count, capacity;
    int *ends;          /* 2*count node indices */
    double *rest;       /* rest length l0 */
    double *rest_vec;   /* 3*count rest vector x_j0 - x_i0 (Model-I) */
    double *k;          /* stiffness */
    double *c;          /* dashpot */
    unsigned char *law;
    unsigned char *group;
} canopy_springs;

typedef struct canopy_triangles {
    int count, capacity;
    int *nodes;         /* 3*count */
    double *dp;         /* pressure jump */
    double *added_mass; /* consistent added mass (inertia.c; 0 by default) */
} canopy_triangles;

/* The hinge dashpots' high-pass filter (bending_filter.c): node i's
 * stencil nodes[start[i] .. start[i+1]) is i itself, then its cloth
 * neighbours; weights are A's row i (the linear fit's value at i). */
typedef struct canopy_hinge_filter {
    int *start;         /* node count + 1 */
    int *nodes;
    double *weights;    /* at one shape, set by canopy_hinge_filter_weights */
    double *normals, *filtered, *spread; /* 3 * node count, scratch */
    int largest;        /* the largest stencil's size */
    int *slot;          /* node count, -1: scratch of the diagonal, with */
    int *touched;       /* 4 * largest */
    double *row;        /* 12 * largest */
} canopy_hinge_filter;

/* Hinges (edges shared by two triangles) for the bending dashpots, built
 * from the triangles by canopy_model_prepare when bending_damping > 0. */
typedef struct canopy_hinges {
    int count;
    int *nodes;         /* 4*count: opposite o1, opposite o2, edge p, edge q */
    double *modes;      /* 13*count: bending modes u (4 x 3) and dashpot c at
                           one shape, cached by the implicit update
                           (bending_implicit.c) */
    canopy_hinge_filter filter; /* allocated when bending_filter is on */
} canopy_hinges;

/* Saved state for checkpoint/restore and for failed-step rollback. */
typedef struct canopy_state_copy {
    int valid;
    int count;          /* nodes the arrays hold */
    int triangles;      /* triangles dp holds */
    double t;
    double *x, *v, *acc; /* 3*node count */
    double *force_ext;  /* 3*node count: the nodal loads set on the model */
    double *dp;         /* triangle count: the pressure jump set on it */
    int acc_valid;
} canopy_state_copy;

struct canopy_model {
    canopy_nodes nodes;
    canopy_springs springs;
    canopy_triangles tris;
    canopy_hinges hinges;
    double bending_damping; /* decay rate of a hinge's bending [1/s] (bending.c) */
    int bending_implicit;   /* hinge dashpots as a backward-Euler velocity
                               update after each step (bending_implicit.c) */
    int bending_filter;     /* hinge dashpots on the velocity's high-pass
                               part only (bending_filter.c; implicit only) */
    double fabric_compression; /* the cloth's Model-II springs' stiffness in
                                  compression over their stiffness (1: as
                                  in tension) */
    int pressure_frozen;    /* the pressure load held over each step or
                               advance (set_pressure_frozen) */
    int pressure_held;      /* pressure_step holds the load of the step or
                               advance under way (advance.c) */

    double t;
    int acc_valid;      /* nodes.acc holds the last HHT step's acceleration */
    double gravity[3];
    double porosity_alpha, porosity_beta;
    int payload_node;

    const canopy_integrator *integrator;
    double max_omega_dt;
    double hht_alpha;
    double implicit_tol;
    int implicit_max_iter;
    double speed_limit;

    canopy_state_copy checkpoint; /* user checkpoint */
    canopy_state_copy rollback;   /* entry state of step/advance */

    /* Workspaces, each owned by what uses it and sized to the node count
     * by canopy_model_prepare. */
    canopy_stepper stepper;            /* the integrator's */
    canopy_hinge_solver *hinge_solver; /* the implicit hinge dashpots'
                                          (NULL unless they are on) */
    canopy_vectors bound_sums;         /* canopy_model_frequency_bound's
                                          per-node sums (one vector) */
    canopy_vectors pressure_step;      /* the pressure load's nodal forces
                                          held over a step (one vector) */

    int prepared;               /* topology validated, workspaces allocated */
    int directional_added_mass; /* some node's added mass has a direction */
    int triangle_added_mass;    /* some triangle has a consistent added mass
                                   (set_triangle_added_mass, inertia.c) */
    char message[CANOPY_MESSAGE_SIZE];
};

/* Record a failure on the handle; returns `status` (printf-style message). */
canopy_status canopy_fail(canopy_model *model, canopy_status status,
                          const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* Format into a caller's message buffer; returns `status`. */
canopy_status canopy_format_message(char *buffer, size_t size,
                                    canopy_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
/* Clear the handle's message (a successful call). */
void canopy_clear_message(canopy_model *model);
/* canopy_fail for calls that take a const handle (getters): the message is
 * not part of the model's state. Every rejection of a non-NULL handle goes
 * through canopy_fail or this, so its message is always the call's own. */
canopy_status canopy_reject(const canopy_model *model, canopy_status status,
                            const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Validate masses and topology, (re)allocate the workspaces. */
canopy_status canopy_model_prepare(canopy_model *model);

/* Forces (3*n) at positions x, velocities v: springs, dashpots, gravity,
 * pressure (the held load while pressure_held), extra loads. Fixed nodes
 * get their force too (a reaction). */
void canopy_forces(const canopy_model *model, const double *x, const double *v,
                   double *f);
/* Add the pressure jumps' load on the shape x to f (3*n). */
void canopy_pressure_forces(const canopy_model *model, const double *x,
                            double *f);
/* Hinge dashpots (bending.c): build the hinges from the triangles; add
 * their forces to f; add C w to y (w at fixed nodes counts as zero, fixed
 * rows untouched); add each node's Gershgorin row sum of C to
 * sum[stride * i]. */
canopy_status canopy_hinges_build(canopy_model *model);
void canopy_hinge_forces(const canopy_model *model, const double *x,
                         const double *v, double *f);
void canopy_hinge_tangent_damping(const canopy_model *model, const double *x,
                                  const double *w, double *y);
void canopy_hinge_damping_sums(const canopy_model *model, const double *x,
                               double *sum, int stride);
/* Bending modes u (4 x 3) and dashpot c of hinge k at x; returns 0 (and
 * leaves u, c unset) for a degenerate hinge. */
int canopy_hinge_modes(const canopy_model *model, const double *x, int k,
                       double u[4][3], double *c);
/* y += scale c (u.w) u for hinge k with modes u and dashpot c; with
 * free_only, fixed nodes' w count as zero and their rows are left alone. */
void canopy_hinge_apply(const canopy_model *model, int k, const double u[4][3],
                        double c, const double *w, double *y, double scale,
                        int free_only);
/* The high-pass filter (bending_filter.c): build the stencils from the
 * cloth edges (pairs of nodes, n_edges of them); set A's weights at x;
 * out = (I - A) w; out = (I - A)^T z; add scale (U F P)_kj^2 (hinge k's
 * row of U F P with modes u, squared per component) to diag at every free
 * node j it touches. */
canopy_status canopy_hinge_filter_build(canopy_model *model, const int *edges,
                                        int n_edges);
void canopy_hinge_filter_free(canopy_hinge_filter *filter);
void canopy_hinge_filter_weights(canopy_model *model, const double *x);
void canopy_hinge_filter_apply(const canopy_model *model, const double *w,
                               double *out);
void canopy_hinge_filter_apply_transpose(const canopy_model *model,
                                         const double *z, double *out);
void canopy_hinge_filter_add_diagonal(canopy_model *model, int k,
                                      const double u[4][3], double scale,
                                      double *diag);
/* f += the hinge dashpots' forces at the model's state, as the implicit
 * update applies them (filtered if the filter is on). */
void canopy_hinge_damping_implicit_forces(canopy_model *model, double *f);
/* The implicit hinge dashpots' workspace (bending_implicit.c): prepare
 * makes it when they are on (bending_implicit and hinges), sized to the
 * node count, and drops it otherwise; on failure CANOPY_ERR_MEMORY with the
 * handle's message, and the model keeps the one it had. destroy frees it
 * and sets *solver to NULL (NULL: no-op); bytes: its size (NULL: 0). */
canopy_status canopy_hinge_solver_prepare(canopy_model *model);
void canopy_hinge_solver_destroy(canopy_hinge_solver **solver);
size_t canopy_hinge_solver_bytes(const canopy_hinge_solver *solver);
/* With bending_implicit: v <- (M + h C)^-1 M v at the current positions
 * (bending_implicit.c, with the model's hinge solver);
 * CANOPY_ERR_DIVERGED if the solve fails. */
canopy_status canopy_hinge_damping_implicit_update(canopy_model *model,
                                                   double h);
/* Accelerations (3*n): forces over effective mass; zero at fixed nodes. */
void canopy_accelerations(const canopy_model *model, const double *x,
                          const double *v, double *a);
/* y = K u (tangent stiffness at x, 3*n). With clamp, the geometric term of
 * compressed springs is dropped so K stays positive semi-definite. Fixed
 * nodes' rows and columns are zero. v (may be NULL: the dashpots count as
 * idle) tells which lines carry tension (canopy_line_tension). */
void canopy_tangent_stiffness(const canopy_model *model, const double *x,
                              const double *v, const double *u, double *y,
                              int clamp);
/* y = C u (dashpot tangent at x, velocities v as above). */
void canopy_tangent_damping(const canopy_model *model, const double *x,
                            const double *v, const double *u, double *y);
/* Does node i's added mass act along one direction only? */
static inline int canopy_added_mass_directional(const canopy_model *m, int i)
{
    const double *d = m->nodes.added_dir + 3 * i;
    return d[0] != 0.0 || d[1] != 0.0 || d[2] != 0.0;
}

/* Effective mass of node i: mass + added mass, or for a directional added
 * mass the smallest inertia, the mass alone (what bounds the stable step). */
static inline double canopy_effective_mass(const canopy_model *m, int i)
{
    return m->nodes.mass[i]
         + (canopy_added_mass_directional(m, i) ? 0.0 : m->nodes.added_mass[i]);
}

/* y = M_i u for node i's inertia M_i = m_i I + m_a d d^T (directional added
 * mass) or (m_i + m_a) I; u, y: 3 doubles. */
static inline void canopy_inertia_apply(const canopy_model *m, int i,
                                        const double *u, double *y)
{
    const double mi = canopy_effective_mass(m, i);
    y[0] = mi * u[0]; y[1] = mi * u[1]; y[2] = mi * u[2];
    if (canopy_added_mass_directional(m, i)) {
        const double *d = m->nodes.added_dir + 3 * i;
        const double s = m->nodes.added_mass[i] *
                         (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]);
        y[0] += s * d[0]; y[1] += s * d[1]; y[2] += s * d[2];
    }
}

/* The diagonal of node i's inertia M_i (3 doubles): m_i + m_a d_k^2 for a
 * directional added mass, else m_i + m_a. */
static inline void canopy_inertia_diagonal(const canopy_model *m, int i,
                                           double *diag)
{
    const double ma = m->nodes.added_mass[i];
    const int directional = canopy_added_mass_directional(m, i);
    const double *d = m->nodes.added_dir + 3 * i;
    for (int k = 0; k < 3; ++k)
        diag[k] = m->nodes.mass[i] + (directional ? ma * d[k] * d[k] : ma);
}

/* f <- M_i^-1 f for node i (Sherman-Morrison for the directional added
 * mass: (m I + m_a d d^T)^-1 f = (f - m_a / (m + m_a) (d.f) d) / m). */
static inline void canopy_inertia_solve(const canopy_model *m, int i,
                                        double *f)
{
    if (canopy_added_mass_directional(m, i)) {
        const double *d = m->nodes.added_dir + 3 * i;
        const double ma = m->nodes.added_mass[i];
        const double s = ma / (m->nodes.mass[i] + ma) *
                         (d[0] * f[0] + d[1] * f[1] + d[2] * f[2]);
        f[0] -= s * d[0]; f[1] -= s * d[1]; f[2] -= s * d[2];
    }
    const double inv = 1.0 / canopy_effective_mass(m, i);
    f[0] *= inv; f[1] *= inv; f[2] *= inv;
}

/* The nodes' inertia as a whole (inertia.c): the per-node masses above and
 * the triangles' consistent added mass, sum over t of
 * (added_mass[t] / 9) 1_t 1_t^T in every direction. y = M u over all
 * nodes (3n doubles; the fixed nodes' rows too, which callers ignore). */
void canopy_inertia_apply_all(const canopy_model *m, const double *u,
                              double *y);
/* diag = the diagonal of that M (3n doubles): each node's own
 * (canopy_inertia_diagonal) plus the sum over its triangles of
 * added_mass[t] / 9, in each direction. */
void canopy_inertia_diagonal_all(const canopy_model *m, double *diag);

/* Whether node i slides on a guide (canopy_model_set_guide). */
static inline int canopy_guided(const canopy_model *m, int i)
{
    const double *e = m->nodes.guide + 3 * i;
    return e[0] != 0.0 || e[1] != 0.0 || e[2] != 0.0;
}

/* w <- e (e.w) at a guided node i (its component along the guide e);
 * other nodes' w unchanged. */
static inline void canopy_guide_project(const canopy_model *m, int i,
                                        double *w)
{
    if (!canopy_guided(m, i)) return;
    const double *e = m->nodes.guide + 3 * i;
    const double s = e[0] * w[0] + e[1] * w[1] + e[2] * w[2];
    w[0] = s * e[0]; w[1] = s * e[1]; w[2] = s * e[2];
}

/* f <- node i's acceleration under force f: M_i^-1 f for a free node; on
 * a guide e the motion along it, e (e.f) / (e.M_i e) (the guide takes the
 * rest of f). */
static inline void canopy_node_acceleration(const canopy_model *m, int i,
                                            double *f)
{
    if (!canopy_guided(m, i)) {
        canopy_inertia_solve(m, i, f);
        return;
    }
    const double *e = m->nodes.guide + 3 * i;
    double me[3];
    canopy_inertia_apply(m, i, e, me);
    const double s = (e[0] * f[0] + e[1] * f[1] + e[2] * f[2]) /
                     (e[0] * me[0] + e[1] * me[1] + e[2] * me[2]);
    f[0] = s * e[0]; f[1] = s * e[1]; f[2] = s * e[2];
}

/* State copies. */
canopy_status canopy_state_save(canopy_model *model, canopy_state_copy *copy);
void canopy_state_load(canopy_model *model, const canopy_state_copy *copy);
void canopy_state_free(canopy_state_copy *copy);

/* Triangle helpers. area_normal = 1/2 (xb - xa) x (xc - xa); inline, as
 * the pressure load evaluates it for every triangle at every force
 * evaluation. */
static inline void canopy_triangle_area_normal(const double *x, const int *tri,
                                               double area_normal[3])
{
    const double *a = x + 3 * tri[0], *b = x + 3 * tri[1], *c = x + 3 * tri[2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    area_normal[0] = 0.5 * (u[1] * w[2] - u[2] * w[1]);
    area_normal[1] = 0.5 * (u[2] * w[0] - u[0] * w[2]);
    area_normal[2] = 0.5 * (u[0] * w[1] - u[1] * w[0]);
}

/* Check a node / spring / triangle index; on failure sets the message. */
canopy_status canopy_check_node(canopy_model *model, int node,
                                const char *what);

/* The factor on spring k's stiffness while it is shorter than its rest
 * length: the cloth's compression ratio for its Model-II springs
 * (canopy_model_set_fabric_compression), 1 for every other Model-II
 * spring. Tension-only and Model-I springs are handled by their laws. */
static inline double canopy_compression_factor(const canopy_model *m, int k)
{
    return m->springs.group[k] == CANOPY_GROUP_FABRIC ? m->fabric_compression
                                                      : 1.0;
}

/* Spring k's stiffness at the given stretch l - l0: k, times the
 * compression factor for a compressed Model-II spring. */
static inline double canopy_spring_stiffness(const canopy_model *m, int k,
                                             double stretch)
{
    return stretch < 0.0 && m->springs.law[k] == CANOPY_SPRING_MODEL_II
               ? canopy_compression_factor(m, k) * m->springs.k[k]
               : m->springs.k[k];
}

/* Tension of a tension-only spring (a line) with stiffness k, dashpot c,
 * stretch l - l0 and stretch rate dl/dt: its spring-dashpot force clipped
 * at zero, T = max(0, k (l - l0) + c dl/dt). A line never pushes, and T is
 * continuous in l and dl/dt, so an implicit step's residual has no jump where
 * a line goes taut (with the dashpot switched on at l = l0, Newton cycles
 * there). The dashpot engages up to (c/k) dl/dt before the line is taut: the
 * distance its ends cover in the damping time c/k, about 2e-5 s for the
 * tutorials' lines. Without a dashpot, T = k max(l - l0, 0). */
static inline double canopy_line_tension(double k, double c, double stretch,
                                         double rate)
{
    const double T = k * stretch + c * rate;
    return T > 0.0 ? T : 0.0;
}

#endif /* CANOPY_MODEL_INTERNAL_H */

/* canopy.h — public C API of libcanopy, the spring–mass parachute structure.
 *
 * This header is the manual. It is laid out in the order a program calls it:
 * status codes, constants, the model handle and how to build it (by hand or
 * with the geometry builders), time integration, the coupling calls a fluid
 * solver makes every time step, diagnostics, HDF5/XDMF output, and reading
 * output files back (restart, initial states).
 *
 * Conventions (they hold for every function below)
 * - Handles are opaque. `*_create(..., &out)` makes one, `*_destroy(&h)` frees
 *   it and sets it to NULL; destroying NULL is a harmless no-op.
 * - Every call that can fail returns a canopy_status. On failure the handle is
 *   unchanged (a failed time step restores the state it started from) and
 *   canopy_model_message() / canopy_output_message() says what went wrong,
 *   naming the bad argument or index. Nothing is printed, nothing aborts.
 * - Arrays cross the ABI as `double *` plus an explicit count; vectors are xyz
 *   interleaved (node i is x[3*i], x[3*i+1], x[3*i+2]); indices are 0-based.
 *   A count that does not match the model is an error, not a truncation.
 * - SI units throughout: m, kg, s, N, Pa.
 * - No global state: separate handles may be used from separate threads.
 *   (Output goes through the HDF5 library, which serialises itself only when
 *   it was built thread-safe; do not write two outputs from two threads with
 *   Debian's serial HDF5.)
 *
 * Minimal example: a canopy with lines and payload, loaded by a constant
 * pressure jump, written for ParaView.
 *
 *     canopy_model *m = NULL;
 *     canopy_model_create(&m);
 *     canopy_circular_spec c = canopy_circular_spec_default();
 *     c.diameter = 2.134; c.edge_length = 0.1; c.n_attachments = 16;
 *     int skirt[16], payload;
 *     canopy_build_circular(m, &c, skirt);
 *     canopy_lines_spec l = canopy_lines_spec_default();
 *     l.line_length = 2.0; l.payload_mass = 5.398;
 *     canopy_build_suspension_lines(m, skirt, 16, &l, &payload);
 *     canopy_model_set_integrator(m, "rk4");
 *     int nt = canopy_model_triangle_count(m);
 *     double *dp = calloc(nt, sizeof *dp);    // fill with 40 Pa
 *     for (int t = 0; t < nt; ++t) dp[t] = 40.0;
 *     canopy_model_set_pressure_jump(m, dp, nt);
 *     canopy_output *o = NULL;
 *     canopy_output_create(m, "drop", CANOPY_OUTPUT_CREATE, &o);
 *     for (int s = 0; s < 100; ++s) {
 *         if (canopy_model_advance(m, 1e-3, NULL) != CANOPY_OK) {
 *             fprintf(stderr, "%s\n", canopy_model_message(m)); break;
 *         }
 *         canopy_output_write(o, m);
 *     }
 *     canopy_output_destroy(&o);
 *     canopy_model_destroy(&m);
 */
#ifndef CANOPY_H
#define CANOPY_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CANOPY_VERSION_MAJOR 0
#define CANOPY_VERSION_MINOR 1
#define CANOPY_VERSION_PATCH 0

/* ------------------------------------------------------------------------ */
/* Status codes. One list, so that codes, names and descriptions cannot drift. */

#define CANOPY_STATUS_LIST(X)                                                   \
    X(CANOPY_OK,               0, "success")                                    \
    X(CANOPY_ERR_ARGUMENT,     1, "invalid argument")                           \
    X(CANOPY_ERR_RANGE,        2, "index or count out of range")                \
    X(CANOPY_ERR_MEMORY,       3, "out of memory")                              \
    X(CANOPY_ERR_UNKNOWN_NAME, 4, "unknown name")                               \
    X(CANOPY_ERR_STATE,        5, "model not valid for this operation")         \
    X(CANOPY_ERR_DIVERGED,     6, "time step diverged; state restored")         \
    X(CANOPY_ERR_NOT_CONVERGED,7, "implicit solve did not converge; state restored") \
    X(CANOPY_ERR_IO,           8, "file input/output failed")                   \
    X(CANOPY_ERR_FORMAT,       9, "file does not match the model")

typedef enum canopy_status {
#define CANOPY_STATUS_ENUM_(name, code, text) name = code,
    CANOPY_STATUS_LIST(CANOPY_STATUS_ENUM_)
#undef CANOPY_STATUS_ENUM_
    CANOPY_STATUS_COUNT_
} canopy_status;

/* "CANOPY_ERR_RANGE" etc.; "CANOPY_UNKNOWN_STATUS" for a value not listed. */
const char *canopy_status_name(canopy_status status);
/* One-line description of the code ("index or count out of range"). */
const char *canopy_status_description(canopy_status status);

/* ------------------------------------------------------------------------ */
/* Constants. */

/* What a node or spring belongs to. Used for masses, output and diagnostics. */
typedef enum canopy_group {
    CANOPY_GROUP_FABRIC  = 0, /* canopy cloth */
    CANOPY_GROUP_TAPE    = 1, /* gore seams / radial reinforcement tapes */
    CANOPY_GROUP_LINE    = 2, /* suspension lines */
    CANOPY_GROUP_PAYLOAD = 3, /* the payload point mass */
    CANOPY_GROUP_OTHER   = 4
} canopy_group;

/* Force law of a spring between nodes i and j, l = |x_i - x_j|.
 * MODEL_II     f_i = -k (l - l0) e_ij             seed 000 eq. 2.18 (fabric)
 * MODEL_I      f_i = -k ((x_i - x_j) - d0_ij)     seed 000 eq. 2.17, d0_ij the
 *              rest vector: linear, with bending stiffness; for analysis only.
 * TENSION_ONLY f_i = -T e_ij, T = max(0, k (l - l0) + c dl/dt): a
 *              compression-free cloth or line; its spring and dashpot
 *              together never push (no force while slack, save that the
 *              dashpot engages (c/k) dl/dt before the line is taut, which
 *              keeps T continuous for the implicit integrators).
 * Every spring may carry a dashpot c acting on the relative velocity of its
 * two ends along the spring, f_i = c ((v_j - v_i)·e) e: internal impulse only
 * (the seed's impulse method, seed 000 §2.9), so rigid motion is undamped. */
typedef enum canopy_spring_law {
    CANOPY_SPRING_MODEL_II     = 0,
    CANOPY_SPRING_MODEL_I      = 1,
    CANOPY_SPRING_TENSION_ONLY = 2
} canopy_spring_law;

/* ------------------------------------------------------------------------ */
/* The model handle. */

typedef struct canopy_model canopy_model;

/* Make an empty model: no nodes, gravity (0, 0, -9.81), integrator "rk4",
 * max omega*dt 0.1, speed limit 1e4 m/s, porosity alpha = beta = 0. */
canopy_status canopy_model_create(canopy_model **out);
/* Free the model and set *model to NULL. NULL or *model == NULL: no-op. */
void canopy_model_destroy(canopy_model **model);
/* Message of the last failed call on this handle ("" if none). Valid until
 * the next call on the handle. */
const char *canopy_model_message(const canopy_model *model);

/* --- Building by hand ---------------------------------------------------- */

/* Add a node at x with lumped mass `mass` (>= 0; a free node needs a positive
 * total mass before the first step). *index_out (may be NULL) receives its
 * index. Velocity starts at zero, the node is free. */
canopy_status canopy_model_add_node(canopy_model *model, const double x[3],
                                    double mass, canopy_group group,
                                    int *index_out);
/* Add mass (>= 0) to a node: the lumped-mass model sums element shares. */
canopy_status canopy_model_add_node_mass(canopy_model *model, int node,
                                         double mass);
/* Hold a node fixed (1) or release it (0). A fixed node keeps its velocity
 * (normally zero) and ignores forces. */
canopy_status canopy_model_set_fixed(canopy_model *model, int node, int fixed);
/* Put a node on a guide: a straight frictionless wire through its current
 * position along axis (any length; NULL or 0 0 0 takes it off). It then
 * moves along the wire alone, with the acceleration e (e.F) / (e.M e) for
 * e = axis / |axis|, F its force and M its inertia; the wire takes the
 * rest of F. Its velocity (and carried acceleration) across the wire is
 * removed now. A guided node must not be fixed, and the integrator must
 * not be kang (canopy_model_prepare says so). Like set_fixed, this drops
 * the checkpoint. */
canopy_status canopy_model_set_guide(canopy_model *model, int node,
                                     const double axis[3]);
/* A node's guide direction (unit length), 0 0 0 when it has none. */
canopy_status canopy_model_get_guide(const canopy_model *model, int node,
                                     double axis[3]);

/* Add a spring i–j. Rest length (and, for MODEL_I, rest vector) = the nodes'
 * current separation, which must be positive (seed 000 Model-II: rest length
 * of each edge = its initial length). stiffness > 0 [N/m], damping >= 0
 * [N s/m]. */
canopy_status canopy_model_add_spring(canopy_model *model, int i, int j,
                                      double stiffness, double damping,
                                      canopy_spring_law law, canopy_group group,
                                      int *index_out);
/* Override a spring's rest length (> 0). */
canopy_status canopy_model_set_rest_length(canopy_model *model, int spring,
                                           double rest_length);

/* Add a canopy triangle a, b, c (distinct nodes). Its unit normal is
 * (x_b - x_a) x (x_c - x_a) normalised; a pressure jump dp > 0 pushes it
 * along that normal (dp = p_minus - p_plus, seed 000 eq. 2.27). Triangles
 * carry no mass by themselves: builders add it to the nodes. */
canopy_status canopy_model_add_triangle(canopy_model *model, int a, int b,
                                        int c, int *index_out);

/* Gravity vector [m/s^2]. Default (0, 0, -9.81). */
canopy_status canopy_model_set_gravity(canopy_model *model, const double g[3]);
/* The gravity vector [m/s^2]; CANOPY_ERR_ARGUMENT for a NULL argument. */
canopy_status canopy_model_get_gravity(const canopy_model *model, double g[3]);

/* Darcy–Forchheimer porosity of the canopy cloth (seed 002 eqs. 6–10):
 * the seepage velocity w through the cloth satisfies dp = alpha w + beta w|w|,
 * alpha >= 0 [Pa s/m], beta >= 0 [Pa s^2/m^2]. Both zero: impermeable. */
canopy_status canopy_model_set_porosity(canopy_model *model, double alpha,
                                        double beta);

/* Name the payload node (used by diagnostics and output); -1 clears it. */
canopy_status canopy_model_set_payload_node(canopy_model *model, int node);

/* --- Building with the geometry builders ---------------------------------
 * Builders add nodes, springs and triangles to a model (which may already
 * hold other parts), with masses from the material densities: a fabric node
 * gets areal density x 1/3 of each adjacent triangle's area, a line node half
 * of each adjacent segment's linear density x length. Triangulations are
 * homogeneous and near-equilateral with the given target edge length. */

/* Material of a family of springs. */
typedef struct canopy_material {
    double stiffness;   /* spring constant k [N/m]; if 0, derived from modulus */
    double modulus;     /* fabric: 2-D modulus E*t [N/m], k = (sqrt(3)/2) E t
                           (triangular spring lattice, NOTES §3); lines/tapes:
                           E*A [N], k = E A / l0 per segment */
    double density;     /* fabric: areal [kg/m^2]; lines/tapes: linear [kg/m];
                           >= 0 (0: add node masses yourself) */
    double damping;     /* dashpot on relative velocity along spring [N s/m] */
    canopy_spring_law law;
} canopy_material;

/* Nylon canopy cloth (0.0373 kg/m^2, k = 5000 N/m, light damping). */
canopy_material canopy_material_fabric_default(void);
/* Suspension line (0.01 kg/m, E A = 5000 N, tension only). */
canopy_material canopy_material_line_default(void);

/* Circular canopy as a surface of revolution: flat (height 0) or parabolic,
 * z = apex_z - height (r/R)^2 (seed 000 eq. 5.4), with an optional vent and
 * an optional extended skirt. The axis is the vertical through `center`,
 * which is the apex, or the centre of the vent opening (in the vent's plane)
 * when there is a vent; the rim r = R lies `height (1 - (r_vent/R)^2)` below
 * it. An extended skirt (skirt_length > 0) is a band of cloth beyond the rim,
 * a conical frustum of slant `skirt_length` from the rim down and inwards to
 * the hem of diameter `skirt_diameter` (R - skirt_diameter/2 < skirt_length):
 * the hem, where the lines attach, is narrower than the rim, as in extended-
 * skirt canopies (Knacke, Parachute Recovery Systems Design Manual, 1991,
 * Table 5-1). Rings of nodes start at angle 0
 * and hold a multiple of n_attachments nodes, so the attachments (and
 * gores) sit on nodes; rings too small for that keep a symmetric count:
 * near the apex (radial tapes then end at the apex node) and near a vent
 * without radial tapes (its edge ring has at least 6 nodes). With radial
 * tapes the gore rings reach the vent, narrowing with the gores. */
typedef struct canopy_circular_spec {
    double diameter;       /* horizontal rim diameter 2R (without an extended
                              skirt the skirt; flat: constructed) */
    double vent_diameter;  /* 0: no vent */
    double height;         /* apex above the rim; 0: flat */
    double skirt_length;   /* extended skirt's slant length; 0: none */
    double skirt_diameter; /* extended skirt's hem diameter, > 0 and in
                              (diameter - 2 skirt_length, diameter); used only
                              when skirt_length > 0 */
    double edge_length;    /* target triangle edge length */
    double center[3];
    int n_attachments;     /* suspension line attachment points on the skirt */
    int radial_tapes;      /* 1: tapes from each attachment to vent/apex */
    canopy_material fabric;
    canopy_material tape;
} canopy_circular_spec;
canopy_circular_spec canopy_circular_spec_default(void);
/* attach_out (n_attachments ints, may be NULL): skirt (hem) nodes at angles
 * 2 pi k / n_attachments, k = 0..n-1. */
canopy_status canopy_build_circular(canopy_model *model,
                                    const canopy_circular_spec *spec,
                                    int *attach_out);

/* Flat cross canopy: two crossed rectangles of length `span` and width
 * `arm_width` in the plane z = center[2]; normal +z. The mesh has the
 * cross's quarter-turn symmetry (a square centre of right triangles, four
 * arms alike with their node rows across them), so no pair of arms folds
 * more easily than the other; edge_length is a target, the attachments on
 * each tip may make the spacing across the arms finer. */
typedef struct canopy_cross_spec {
    double span;
    double arm_width;
    double edge_length;
    double center[3];
    int n_attachments;     /* multiple of 4: spread evenly along the 4 arm-tip
                              edges, corners included; attach_out ordered
                              counter-clockwise from the +x tip */
    canopy_material fabric;
} canopy_cross_spec;
canopy_cross_spec canopy_cross_spec_default(void);
canopy_status canopy_build_cross(canopy_model *model,
                                 const canopy_cross_spec *spec,
                                 int *attach_out);

/* Flat rectangular cloth [0, width] x [0, length] in the x–y plane, shifted
 * by `origin`; normal +z. */
typedef struct canopy_rectangle_spec {
    double width;
    double length;
    double edge_length;
    double origin[3];
    canopy_material fabric;
} canopy_rectangle_spec;
canopy_rectangle_spec canopy_rectangle_spec_default(void);
canopy_status canopy_build_rectangle(canopy_model *model,
                                     const canopy_rectangle_spec *spec);

/* A chord of n_segments equal springs from `start` to `end`. If first_node
 * >= 0 the chord starts at that existing node (start is then ignored).
 * *last_node_out (may be NULL) receives the node at `end`. */
canopy_status canopy_build_chord(canopy_model *model, const double start[3],
                                 const double end[3], int n_segments,
                                 const canopy_material *material,
                                 canopy_group group, int first_node,
                                 int *last_node_out);

/* Suspension lines from each attachment node to one confluence node on the
 * canopy axis below them, at distance line_length from every attachment
 * (which must exceed the attachments' radius). The confluence node carries
 * payload_mass and becomes the payload node. */
typedef struct canopy_lines_spec {
    double line_length;
    double edge_length;    /* target segment length */
    double payload_mass;
    canopy_material line;
} canopy_lines_spec;
canopy_lines_spec canopy_lines_spec_default(void);
canopy_status canopy_build_suspension_lines(canopy_model *model,
                                            const int *attach, int n_attach,
                                            const canopy_lines_spec *spec,
                                            int *payload_node_out);

/* --- Sizes and state ----------------------------------------------------- */

int canopy_model_node_count(const canopy_model *model);
int canopy_model_spring_count(const canopy_model *model);
int canopy_model_triangle_count(const canopy_model *model);
double canopy_model_time(const canopy_model *model);
canopy_status canopy_model_set_time(canopy_model *model, double t);

/* Positions / velocities of all nodes: 3*n doubles, n = node count. */
canopy_status canopy_model_get_positions(const canopy_model *model, double *x,
                                         int n);
canopy_status canopy_model_set_positions(canopy_model *model, const double *x,
                                         int n);
canopy_status canopy_model_get_velocities(const canopy_model *model, double *v,
                                          int n);
/* A guided node (canopy_model_set_guide) keeps only the part of the
 * velocity along its guide; so does its acceleration state below. */
canopy_status canopy_model_set_velocities(canopy_model *model, const double *v,
                                          int n);
/* Integrator state beyond (t, x, v): newmark and hht end each step with
 * the acceleration a_{n+1} of their equation (M + added mass) a = F, and
 * hht carries it into the next step (3*n doubles). The implicit hinge
 * dashpots' velocity update after the step leaves it as it is. *valid = 0
 * when there is none (any other integrator, or after positions/velocities
 * were set). Output stores it and canopy_model_read_state restores it, so
 * restarts are exact. */
canopy_status canopy_model_get_acceleration_state(const canopy_model *model,
                                                  double *a, int n,
                                                  int *valid);
canopy_status canopy_model_set_acceleration_state(canopy_model *model,
                                                  const double *a, int n,
                                                  int valid);
/* The whole motion state at once, exactly as given, as
 * canopy_model_read_state loads it from a file: time t, positions x,
 * velocities v and, when acc_valid, the integrator's carried acceleration
 * acc (3*n doubles each; acc may be NULL when acc_valid is 0). For a copy
 * of another model's state (its get_* values: a parallel run's ranks), so
 * a guided node's vectors are not projected onto its guide again, which
 * would change their last bits. Every value is checked (finite, counts)
 * before anything changes; on failure the model is unchanged. */
canopy_status canopy_model_set_state(canopy_model *model, double t,
                                     const double *x, const double *v,
                                     const double *acc, int acc_valid,
                                     int n);
/* Node masses (n doubles) and fixed flags (n ints). */
canopy_status canopy_model_get_masses(const canopy_model *model, double *mass,
                                      int n);
canopy_status canopy_model_get_fixed(const canopy_model *model, int *fixed,
                                     int n);
/* Node groups (n ints, canopy_group values). */
canopy_status canopy_model_get_node_groups(const canopy_model *model,
                                           int *group, int n);
/* Springs: 2*ns node indices; rest lengths and stiffnesses (ns doubles each,
 * either pointer may be NULL). */
canopy_status canopy_model_get_springs(const canopy_model *model, int *ends,
                                       double *rest_length, double *stiffness,
                                       int ns);
/* Spring groups (ns ints). */
canopy_status canopy_model_get_spring_groups(const canopy_model *model,
                                             int *group, int ns);
/* Triangles: 3*nt node indices. */
canopy_status canopy_model_get_triangles(const canopy_model *model, int *tri,
                                         int nt);

/* ------------------------------------------------------------------------ */
/* Time integration. */

/* Select the integrator by name (all share one force evaluation):
 *   "euler"            explicit Euler, order 1 (seed 002 eq. 12)
 *   "euler-cromer"     symplectic Euler, order 1 (seed 002 eqs. 15-16)
 *   "euler-richardson" midpoint, order 2 (seed 002 eqs. 17-22)
 *   "heun"             improved Euler / predictor-corrector, order 2
 *                      (seed 002 eqs. 23-24, seed 000 eq. 4.6)
 *   "verlet"           velocity Verlet, order 2 (seed 002 eqs. 37-40)
 *   "rk4"              classic Runge-Kutta, order 4 (seed 000 ch. 4)
 *   "newmark"          Newmark-beta, average acceleration (beta 1/4, gamma
 *                      1/2), implicit, order 2 (seed 002 eqs. 25-26)
 *   "hht"              Hilber-Hughes-Taylor alpha, implicit, order 2
 *                      (seed 002 eq. 41)
 *   "kang"             Kang et al.'s approximate implicit update, order 1
 *                      (seed 002 eqs. 52-57)
 * An unknown name fails with CANOPY_ERR_UNKNOWN_NAME and the message lists
 * the valid names. */
canopy_status canopy_model_set_integrator(canopy_model *model,
                                          const char *name);
const char *canopy_model_integrator(const canopy_model *model);
/* The built-in integrators, for listing: count, name(i), formal order(i). */
int canopy_integrator_count(void);
const char *canopy_integrator_name(int i);
int canopy_integrator_order(int i);

/* The sub-step of canopy_model_advance satisfies Lambda*dt <= max_omega_dt,
 * Lambda the per-node eigen-frequency bound below. Default 0.1 (seed 000
 * Table 5.1: RK4 at omega dt = 0.1 is accurate). Implicit integrators are
 * stable beyond 1 and may be given a larger value. */
canopy_status canopy_model_set_max_omega_dt(canopy_model *model, double value);
/* HHT alpha in [-1/3, 0] (default -0.1); 0 is Newmark average acceleration. */
canopy_status canopy_model_set_hht_alpha(canopy_model *model, double alpha);
/* Newton tolerance (relative residual, finite and > 0, default 1e-10) and
 * iteration limit (1 to 1000, default 25) of the implicit integrators. */
canopy_status canopy_model_set_implicit_controls(canopy_model *model,
                                                 double tolerance,
                                                 int max_iterations);
/* Bending dashpots (hinge damping): every edge shared by two triangles
 * damps the rate of its dihedral angle theta with the force
 *   f_i = -c (dtheta/dt) dtheta/dx_i,  c = rate / sum_a (|dtheta/dx_a|^2 / m_a)
 * over the hinge's four nodes a (fixed nodes left out; m_a their own
 * masses, without any added mass, so every free node needs one:
 * CANOPY_ERR_STATE otherwise), so that each
 * hinge's bending, on its own, decays at `rate` [1/s] whatever the
 * triangles' size. Rigid motion and in-plane motion are not damped; the
 * out-of-plane flapping of single triangles, which the springs' dashpots
 * (along the springs) leave undamped, is. rate >= 0; default 0 (none).
 * The frequency bound includes it unless it is implicit (below). */
canopy_status canopy_model_set_bending_damping(canopy_model *model,
                                               double rate);
/* implicit != 0: the hinge dashpots leave the force evaluation and act
 * after every (sub-)step h of any integrator as the backward-Euler update
 *   (M + h C) v' = M v,   C = sum over hinges of c u u^T at the new shape
 * (Lie splitting, first order in h for the dashpots; solved by conjugate
 * gradients). M is the nodes' own mass: an added mass (set_added_mass)
 * acts in the integrator's equation only, so a caller that balances it
 * there with the step's end acceleration (get_acceleration_state) removes
 * it from the whole step. It only dissipates, keeps linear and angular
 * momentum and is
 * stable for any h, so the frequency bound leaves the hinges out: a large
 * rate no longer shortens the stable step. Default 0 (explicit). The
 * forces of canopy_model_get_forces include the dashpots either way. */
canopy_status canopy_model_set_bending_damping_implicit(canopy_model *model,
                                                        int implicit);
int canopy_model_bending_damping_implicit(const canopy_model *model);
/* high_pass != 0: the hinge dashpots act on P v = v - A v only, the cloth
 * velocity's deviation from its local linear fit (A v at node i: the
 * least-squares fit a + g.xi of v over node i and its cloth neighbours in
 * i's tangent plane, evaluated at i), with the damping matrix P^T F C F P
 * (F: the fixed nodes, which do not move, left out).
 * P w ~ (k h)^2 w for a smooth field of wavenumber k on cloth edges h,
 * so a smooth bending decays at ~ rate (k h)^8 instead of ~ rate (k h)^4,
 * while single triangles' flapping still decays at about `rate`: the
 * dashpots regularise the mesh scale and leave the canopy's shape changes.
 * Still only dissipative; linear momentum is kept, angular momentum up to
 * the O(h^2 curvature) part of a rotation the tangent-plane fit misses.
 * Needs the implicit hinge dashpots (canopy_model_prepare fails
 * otherwise). Default 0. */
canopy_status canopy_model_set_bending_damping_filter(canopy_model *model,
                                                      int high_pass);

/* The cloth's Model-II springs (group CANOPY_GROUP_FABRIC) take `ratio`
 * times their stiffness while shorter than their rest length:
 *   f_i = +r k (l - l0) e  for l < l0,  +k (l - l0) e  otherwise,
 * energy r k (l - l0)^2 / 2 in compression; their dashpots are unchanged.
 * Real cloth buckles into wrinkles under a small compressive load; on a
 * mesh coarser than the wrinkles a spring that resists compression as
 * stiffly as tension holds a canopy's skirt out (hoop compression), and
 * one that does not resist it at all (tension-only) leaves the slack
 * cloth nothing to hold it. ratio in [0, 1]; default 1 (Model-II as in
 * seed 000 eq. 2.18). Other groups' springs are not affected. */
canopy_status canopy_model_set_fabric_compression(canopy_model *model,
                                                  double ratio);

/* The pressure jump's load dp A n / 3 per triangle node (set_pressure_jump)
 * on the shape the nodes have when a step or an advance starts, held over
 * its sub-steps (frozen != 0), or on the shape of every force evaluation
 * (0, the default: a follower load). A fluid solver sees the cloth once a
 * time step, so within the step its load is a force, not a pressure that
 * turns with the cloth: a follower load turns with each triangle, also
 * with the folds finer than the fluid's cells, where a triangle that has
 * folded over is pushed further over. Outside step and advance (e.g.
 * canopy_model_get_forces) the load follows the current shape either way. */
canopy_status canopy_model_set_pressure_frozen(canopy_model *model,
                                               int frozen);
int canopy_model_pressure_frozen(const canopy_model *model);

/* Runaway detection: a step that leaves any node faster than this [m/s]
 * fails with CANOPY_ERR_DIVERGED (as does any NaN/Inf). Default 1e4;
 * pass INFINITY to check only for NaN/Inf. */
canopy_status canopy_model_set_speed_limit(canopy_model *model, double vmax);

/* Eigen-frequency bound (seed 000 eq. 3.5, Gershgorin): for node i with
 * effective mass m_i (mass + added mass), stiffness sum K_i = sum_j k_ij and
 * dashpot sum C_i = sum_j c_ij,
 *   omega_i^2 = 2 K_i / m_i,   rho_i = 2 C_i / m_i,
 *   Lambda_i  = rho_i / 2 + sqrt(rho_i^2 / 4 + omega_i^2),
 * where rho_i also holds node i's row sum of the hinge dashpots' damping
 * matrix over m_i (canopy_model_set_bending_damping; at the current shape;
 * not when they are implicit),
 * and *omega = max_i Lambda_i over free nodes (rad/s). With an integrator
 * that solves the spring dashpots implicitly ("newmark", "hht") C_i is
 * left out (rho_i holds only explicit hinge dashpots): the bound then
 * sizes the sub-steps for the fastest oscillation, which damping only
 * slows. */
canopy_status canopy_model_frequency_bound(canopy_model *model,
                                           double *omega);
/* Stable sub-step = max_omega_dt / frequency bound. */
canopy_status canopy_model_stable_step(canopy_model *model, double *dt);

/* Exactly one step of the selected integrator with step dt > 0. */
canopy_status canopy_model_step(canopy_model *model, double dt);
/* Advance by dt, sub-cycling in n = ceil(dt / stable step) equal sub-steps.
 * With an implicit integrator a sub-step whose Newton solve does not
 * converge is taken again as two halves, and so on down to 1/16 of it.
 * *substeps_out (may be NULL) receives the sub-steps taken. On any failure
 * the state is exactly as it was before the call. */
canopy_status canopy_model_advance(canopy_model *model, double dt,
                                   int *substeps_out);

/* ------------------------------------------------------------------------ */
/* Coupling with a fluid solver. Loads are inputs that stay until changed. */

/* Pressure jump per triangle [Pa], nt doubles (see add_triangle for sign). */
canopy_status canopy_model_set_pressure_jump(canopy_model *model,
                                             const double *dp, int nt);
canopy_status canopy_model_get_pressure_jump(const canopy_model *model,
                                             double *dp, int nt);
/* Extra nodal forces [N] (3*n doubles), e.g. line drag or a fictitious force. */
canopy_status canopy_model_set_nodal_forces(canopy_model *model,
                                            const double *f, int n);
/* Optional lumped added mass per node [kg] (n doubles, >= 0): extra inertia in
 * the structure's equations, a stabiliser for strongly coupled iterations. */
canopy_status canopy_model_set_added_mass(canopy_model *model,
                                          const double *added_mass, int n);
/* Lumped added mass acting along one direction per node: node i's inertia
 * becomes m_i I + added_mass[i] d_i d_i^T, d_i = direction[3i..3i+2]
 * normalised (3*n doubles); a zero direction makes that node's added mass
 * act in every direction, as set_added_mass. For a membrane in a fluid
 * (the air resists motion normal to the cloth, not along it). Replaces the
 * values of set_added_mass (which in turn clears the directions). The
 * explicit integrators, newmark and hht take it (the implicit ones solve
 * with the full 3x3 inertia); advancing with kang, whose update assumes a
 * scalar mass, fails with CANOPY_ERR_STATE. The stable sub-step is bounded
 * with the smallest inertia, m_i alone. */
canopy_status canopy_model_set_directional_added_mass(canopy_model *model,
                                                      const double *added_mass,
                                                      const double *direction,
                                                      int n);
/* Optional added mass spread consistently over the triangles (nt doubles
 * >= 0, nt the triangle count): triangle t moving with its nodes' mean
 * acceleration has the inertia added_mass[t], in every direction:
 *   (M_a a)_i = sum over i's triangles t of (added_mass[t] / 9)
 *               (a_p + a_q + a_r)   (p, q, r: t's nodes),
 * beside the nodes' own masses and any per-node added mass. A uniform
 * acceleration meets a third of each adjacent triangle's value, as a
 * lumped added mass would; a motion whose mean over every triangle is zero
 * (the node-scale modes) meets none. It couples the nodes, so it needs
 * integrator newmark or hht: canopy_model_advance fails with
 * CANOPY_ERR_STATE under any other while some value is positive. All
 * zero: none (the default). */
canopy_status canopy_model_set_triangle_added_mass(canopy_model *model,
                                                  const double *added_mass,
                                                  int nt);

/* Triangle markers: centroids (3*nt), unit normals (3*nt), areas (nt) and
 * velocities (3*nt, mean of the vertex velocities). Any pointer may be NULL. */
canopy_status canopy_model_get_triangle_geometry(const canopy_model *model,
                                                 double *centroid,
                                                 double *normal, double *area,
                                                 int nt);
canopy_status canopy_model_get_triangle_velocities(const canopy_model *model,
                                                   double *velocity, int nt);
/* Normal velocity the fluid must have at each triangle (nt doubles): the
 * canopy's own normal velocity plus the porous seepage velocity w solving
 * dp = alpha w + beta w|w| for the triangle's current dp. */
canopy_status canopy_model_get_normal_velocities(const canopy_model *model,
                                                 double *vn, int nt);
/* The seepage velocity for a given dp under the model's porosity. */
double canopy_model_seepage_velocity(const canopy_model *model, double dp);

/* Strong coupling: checkpoint saves time, positions, velocities, the
 * integrator's carried acceleration and the loads set on the model (the
 * pressure jump and the nodal forces); restore returns to all of them (any
 * number of times), so that a state written after a restore is the
 * checkpoint's, loads included; commit drops the checkpoint. Restore
 * without a checkpoint fails with CANOPY_ERR_STATE. */
canopy_status canopy_model_checkpoint(canopy_model *model);
canopy_status canopy_model_restore(canopy_model *model);
canopy_status canopy_model_commit(canopy_model *model);

/* ------------------------------------------------------------------------ */
/* Diagnostics. */

typedef struct canopy_energies {
    double kinetic;       /* sum 1/2 m |v|^2 (node masses, no added mass) */
    double spring;        /* elastic energy of all springs */
    double gravity;       /* -sum m g.x */
    double total;         /* kinetic + spring + gravity */
} canopy_energies;
canopy_status canopy_model_energies(const canopy_model *model,
                                    canopy_energies *e);
/* Total area of all canopy triangles [m^2]. */
canopy_status canopy_model_canopy_area(const canopy_model *model,
                                       double *area);
/* Projected diameter: twice the largest distance of a canopy-triangle node
 * from the axis through the canopy centroid along gravity (z if g = 0). */
canopy_status canopy_model_projected_diameter(const canopy_model *model,
                                              double *diameter);
/* Position and velocity of the payload node (CANOPY_ERR_STATE if none). */
canopy_status canopy_model_payload_state(const canopy_model *model,
                                         double x[3], double v[3]);
/* Current total force on every node (3*n doubles): springs, dashpots,
 * gravity, pressure and extra loads. At a fixed node this is the load the
 * structure puts on its support. */
canopy_status canopy_model_get_forces(canopy_model *model, double *f, int n);
/* Spring tension k (l - l0) (+ dashpot) per spring, ns doubles. */
canopy_status canopy_model_get_tensions(const canopy_model *model, double *T,
                                        int ns);
/* Largest eigen-frequency [rad/s] of the system linearised about the current
 * state (Lanczos on M^-1/2 K M^-1/2 over free nodes); *residual receives the
 * Ritz residual norm of omega^2 (an error bar). */
canopy_status canopy_model_max_frequency(canopy_model *model, double *omega,
                                         double *residual);
/* Bytes of heap memory held by the model. */
size_t canopy_model_memory_bytes(const canopy_model *model);

/* ------------------------------------------------------------------------ */
/* Output: HDF5 time series + XDMF sidecar that ParaView opens.
 *
 * `path` without extension; writes path.h5 and path.xdmf. HDF5 layout:
 *   /mesh  attributes nodes, springs, triangles, lines (non-fabric springs)
 *   /mesh/triangles      nt x 3 int    /mesh/springs        ns x 2 int
 *   /mesh/spring_rest_length, /mesh/spring_stiffness   ns doubles
 *   /mesh/spring_group   ns int        /mesh/node_group     n int
 *   /mesh/node_mass      n double      /mesh/node_fixed     n int
 *   /mesh/cells          XDMF mixed topology (triangles, then every
 *                        non-fabric spring as a 2-node line)
 *   /steps/NNNNNN        attributes time, acc_valid; datasets x, v, f_ext,
 *                        acc (n x 3), dp (nt), tension (ns), cell_dp,
 *                        cell_tension (per XDMF cell; a triangle's tension
 *                        is the mean of its edge springs'); written by
 *                        canopy_output_write_framed also x_frame (n x 3)
 *                        and frame_origin (3)
 * The .xdmf is a temporal collection, one grid per step, the topology
 * written once and referenced; it is (re)written through a temporary file
 * and rename() after every step, so a killed run still opens. It appears
 * with the first step (an empty collection would not open). path-frame.xdmf
 * is the same over the steps that hold x_frame, with that geometry. */
typedef struct canopy_output canopy_output;
typedef enum canopy_output_mode {
    CANOPY_OUTPUT_CREATE = 0, /* new file (replaces an existing one) */
    CANOPY_OUTPUT_APPEND = 1  /* continue an existing file (missing:
                                 CANOPY_ERR_IO; other model: CANOPY_ERR_FORMAT);
                                 steps later than the model's time are dropped */
} canopy_output_mode;

/* Errors of create are reported on the model's message. A failed create
 * leaves path.h5 and path.xdmf as they were (CREATE writes the new file
 * under a temporary name and renames it when complete; APPEND reads the
 * file before it opens it for writing). A path whose .h5 another
 * canopy_output has open is refused (CANOPY_ERR_IO). */
canopy_status canopy_output_create(canopy_model *model, const char *path,
                                   canopy_output_mode mode,
                                   canopy_output **out);
/* Append the model's current state as a new step. */
canopy_status canopy_output_write(canopy_output *output,
                                  const canopy_model *model);
/* The same, and the step also holds the positions seen from a moving frame
 * (a mesh that follows the payload) whose origin is `origin` (in the
 * model's frame) at the step's time: datasets x_frame (n x 3, x - origin)
 * and frame_origin (3). The sidecar path-frame.xdmf shows the steps that
 * hold them, with x_frame as their geometry: the canopy where the moving
 * frame's fields are. */
canopy_status canopy_output_write_framed(canopy_output *output,
                                         const canopy_model *model,
                                         const double origin[3]);
int canopy_output_step_count(const canopy_output *output);
const char *canopy_output_message(const canopy_output *output);
void canopy_output_destroy(canopy_output **output);

/* Restart: load time, positions, velocities, pressure jumps, nodal forces
 * and the integrator's carried acceleration of step number `step` (the
 * NNNNNN of its group; -1: the last) of path.h5 into a model built the same
 * way. Counts are checked (CANOPY_ERR_FORMAT); a missing or unreadable file
 * is CANOPY_ERR_IO, an unknown step CANOPY_ERR_RANGE; on failure the model
 * is unchanged. Continuing with the same loads and integrator reproduces
 * the uninterrupted run exactly. */
canopy_status canopy_model_read_state(canopy_model *model, const char *path,
                                      int step);

/* --- Reading an output file ----------------------------------------------
 * A reader knows one output file (path.h5 as canopy_output writes it): its
 * mesh counts and its steps, sorted by their numbers and addressed by index
 * 0 .. step_count - 1 (not by the NNNNNN of their groups). open reads the
 * step list once and closes the file; every later call opens it again,
 * read-only and without HDF5 file locking, so a file another handle is
 * writing can be read. A call that fails says why on
 * canopy_reader_message() (naming the file) and changes neither the reader
 * nor the model it was given.
 *
 *     canopy_reader *r = NULL;
 *     canopy_reader_create(&r);
 *     int s;
 *     if (canopy_reader_open(r, "postProcessing/canopy/canopy") != CANOPY_OK ||
 *         canopy_reader_find_step(r, 1.25, 1e-6, &s) != CANOPY_OK ||
 *         canopy_reader_read_state(r, s, model) != CANOPY_OK)
 *         fprintf(stderr, "%s\n", canopy_reader_message(r));
 *     canopy_reader_destroy(&r);
 */
typedef struct canopy_reader canopy_reader;

/* Make a reader with no file open. Fails only for a NULL out
 * (CANOPY_ERR_ARGUMENT) or out of memory (CANOPY_ERR_MEMORY, *out NULL). */
canopy_status canopy_reader_create(canopy_reader **out);
/* Free the reader and set *reader to NULL. NULL or *reader == NULL: no-op. */
void canopy_reader_destroy(canopy_reader **reader);
/* Message of the last failed call on this reader ("" if none). */
const char *canopy_reader_message(const canopy_reader *reader);

/* Open path.h5 (`path` without extension, as for canopy_output_create):
 * read its /mesh counts and its steps (number and time). A missing or
 * unreadable file is CANOPY_ERR_IO; a file without /mesh counts, or with a
 * step group lacking a finite scalar 'time', CANOPY_ERR_FORMAT. A file
 * without steps opens with a step count of 0. On failure the reader keeps
 * the file it had open before, if any. */
canopy_status canopy_reader_open(canopy_reader *reader, const char *path);
/* Steps of the open file (0 when none is open or reader is NULL). */
int canopy_reader_step_count(const canopy_reader *reader);
/* Step `index`: the NNNNNN of its group into *number and its time [s] into
 * *time (either may be NULL). CANOPY_ERR_STATE with no file open,
 * CANOPY_ERR_RANGE for an index outside 0 .. step_count - 1. */
canopy_status canopy_reader_step(canopy_reader *reader, int index,
                                 int *number, double *time);
/* The step whose time is nearest `time` among those within `tolerance`
 * (>= 0, finite) of it, into *index; of two equally near, the lower index.
 * None within the tolerance: CANOPY_ERR_RANGE, the message giving the
 * file's time range and its nearest step. */
canopy_status canopy_reader_find_step(canopy_reader *reader, double time,
                                      double tolerance, int *index);
/* Load step `index` into a model built the same way, as
 * canopy_model_read_state does (time, positions, velocities, pressure jumps,
 * nodal forces, the integrator's carried acceleration), after checking that
 * the file holds the model's structure: the counts of nodes, springs,
 * triangles and lines, every triangle's vertices and spring's ends, and the
 * rest lengths to 1e-9 relative; any difference is CANOPY_ERR_FORMAT naming
 * the file and the first thing that differs. A value in the step that is not
 * finite is CANOPY_ERR_FORMAT. On failure the model is unchanged (its
 * message too: the reason is on the reader's). */
canopy_status canopy_reader_read_state(canopy_reader *reader, int index,
                                       canopy_model *model);
/* The same checks, but only the motion is loaded: positions, and velocities
 * plus velocity_offset (3 doubles added to every node's; NULL: none), as
 * canopy_model_set_positions and canopy_model_set_velocities would set them
 * (a guided node's velocity projected on its wire, the carried acceleration
 * dropped). The model's time, loads and checkpoint are kept. For a state
 * made by another run (a folded canopy) to start from. */
canopy_status canopy_reader_read_motion(canopy_reader *reader, int index,
                                        canopy_model *model,
                                        const double velocity_offset[3]);
/* The extra nodal forces [N] (canopy_model_set_nodal_forces) step `index`
 * was written with, into f (3*n doubles); n must be the file's node count
 * (CANOPY_ERR_RANGE otherwise). f is untouched on failure. */
canopy_status canopy_reader_get_nodal_forces(canopy_reader *reader, int index,
                                             double *f, int n);

#ifdef __cplusplus
}
#endif

#endif /* CANOPY_H */

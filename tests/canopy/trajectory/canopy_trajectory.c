/* canopy_trajectory.c — prints every integrator's trajectory on a small parachute as hex floats, so two builds of libcanopy can be compared bit for bit. */
#include "canopy.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Usage: canopy-trajectory [SCRATCH_DIR] > trajectory.txt
 *
 * Runs, through the public API only (so it links against any version of the
 * library), each built-in integrator on a coarse 7 ft flat circular canopy
 * with lines and payload under a pressure jump, then the cases that reach
 * the other code paths: hinge dashpots explicit, implicit and filtered;
 * directional added mass and a guide with newmark/hht; a carried HHT
 * acceleration through checkpoint/restore and through an HDF5 restart
 * (written in SCRATCH_DIR, default /tmp); the implicit sub-step halving.
 * After every outer step it prints the status, sub-steps, time and a 64-bit
 * FNV-1a hash of the raw bytes of x, v and the acceleration state; at the end
 * of each case every value with %a. Two builds whose arithmetic is the same
 * print identical files (compare with cmp). Exit status 0 unless a call the
 * cases rely on fails unexpectedly. */

static uint64_t fnv1a(uint64_t h, const void *data, size_t bytes)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < bytes; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

typedef struct snapshot {
    int n, acc_valid;
    double t;
    double *x, *v, *a;
} snapshot;

static int take(const canopy_model *m, snapshot *s)
{
    s->n = canopy_model_node_count(m);
    s->t = canopy_model_time(m);
    size_t bytes = 3 * sizeof(double) * (size_t)s->n;
    s->x = realloc(s->x, bytes);
    s->v = realloc(s->v, bytes);
    s->a = realloc(s->a, bytes);
    if (!s->x || !s->v || !s->a) return 0;
    return canopy_model_get_positions(m, s->x, s->n) == CANOPY_OK &&
           canopy_model_get_velocities(m, s->v, s->n) == CANOPY_OK &&
           canopy_model_get_acceleration_state(m, s->a, s->n, &s->acc_valid) ==
               CANOPY_OK;
}

static uint64_t hash(const snapshot *s)
{
    size_t bytes = 3 * sizeof(double) * (size_t)s->n;
    uint64_t h = 14695981039346656037ull;
    h = fnv1a(h, &s->t, sizeof s->t);
    h = fnv1a(h, s->x, bytes);
    h = fnv1a(h, s->v, bytes);
    h = fnv1a(h, &s->acc_valid, sizeof s->acc_valid);
    if (s->acc_valid) h = fnv1a(h, s->a, bytes);
    return h;
}

static void dump(const char *label, const snapshot *s)
{
    printf("%s: final t %a acc_valid %d\n", label, s->t, s->acc_valid);
    for (int i = 0; i < 3 * s->n; ++i)
        printf("%d %a %a %a\n", i, s->x[i], s->v[i],
               s->acc_valid ? s->a[i] : 0.0);
}

/* A coarse 7 ft flat circular canopy, 8 lines, payload; dp on the cloth. */
static canopy_model *parachute(const char *integrator, int *payload)
{
    canopy_model *m = NULL;
    if (canopy_model_create(&m) != CANOPY_OK) return NULL;
    canopy_circular_spec c = canopy_circular_spec_default();
    c.diameter = 2.134;
    c.edge_length = 0.3;
    c.n_attachments = 8;
    int skirt[8];
    canopy_lines_spec l = canopy_lines_spec_default();
    l.line_length = 2.0;
    l.edge_length = 0.5;
    l.payload_mass = 5.398;
    if (canopy_build_circular(m, &c, skirt) != CANOPY_OK ||
        canopy_build_suspension_lines(m, skirt, 8, &l, payload) != CANOPY_OK ||
        canopy_model_set_integrator(m, integrator) != CANOPY_OK) {
        canopy_model_destroy(&m);
        return NULL;
    }
    const int nt = canopy_model_triangle_count(m);
    double *dp = malloc(sizeof(double) * (size_t)(nt > 0 ? nt : 1));
    for (int t = 0; t < nt; ++t) dp[t] = 40.0 + 0.5 * (t % 7);
    canopy_model_set_pressure_jump(m, dp, nt);
    free(dp);
    canopy_model_set_porosity(m, 250.0, 0.0);
    return m;
}

/* Advance `steps` outer steps of dt, printing each one's hash. */
static int run(const char *label, canopy_model *m, int steps, double dt,
               snapshot *s)
{
    for (int k = 0; k < steps; ++k) {
        int sub = -1;
        canopy_status st = canopy_model_advance(m, dt, &sub);
        if (!take(m, s)) return 0;
        printf("%s step %d: %s sub %d t %a hash %016llx\n", label, k,
               canopy_status_name(st), st == CANOPY_OK ? sub : -1, s->t,
               (unsigned long long)hash(s));
        if (st != CANOPY_OK) printf("%s message: %s\n", label,
                                    canopy_model_message(m));
    }
    return 1;
}

static int bound(const char *label, canopy_model *m)
{
    double omega = 0.0, h = 0.0;
    if (canopy_model_frequency_bound(m, &omega) != CANOPY_OK ||
        canopy_model_stable_step(m, &h) != CANOPY_OK)
        return 0;
    printf("%s: omega bound %a stable step %a\n", label, omega, h);
    return 1;
}

static int every_integrator(snapshot *s)
{
    for (int i = 0; i < canopy_integrator_count(); ++i) {
        const char *name = canopy_integrator_name(i);
        int payload = -1;
        canopy_model *m = parachute(name, &payload);
        if (m == NULL) return 0;
        const int implicit = strcmp(name, "newmark") == 0 ||
                             strcmp(name, "hht") == 0 ||
                             strcmp(name, "kang") == 0;
        canopy_model_set_max_omega_dt(m, implicit ? 2.0 : 0.3);
        char label[64];
        snprintf(label, sizeof label, "plain/%s", name);
        if (!bound(label, m) || !run(label, m, 12, 1e-3, s)) {
            canopy_model_destroy(&m);
            return 0;
        }
        dump(label, s);
        canopy_model_destroy(&m);
    }
    return 1;
}

/* Hinge dashpots: explicit with verlet, implicit with rk4, newmark and hht,
 * implicit and filtered with hht and rk4. */
static int hinges(snapshot *s)
{
    static const struct { const char *name; int implicit, filter; } cases[] = {
        {"verlet", 0, 0}, {"rk4", 1, 0}, {"newmark", 1, 0}, {"hht", 1, 0},
        {"hht", 1, 1},    {"rk4", 1, 1},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        int payload = -1;
        canopy_model *m = parachute(cases[c].name, &payload);
        if (m == NULL) return 0;
        canopy_model_set_bending_damping(m, 200.0);
        canopy_model_set_bending_damping_implicit(m, cases[c].implicit);
        canopy_model_set_bending_damping_filter(m, cases[c].filter);
        canopy_model_set_max_omega_dt(
            m, strcmp(cases[c].name, "rk4") && strcmp(cases[c].name, "verlet")
                   ? 2.0 : 0.3);
        char label[64];
        snprintf(label, sizeof label, "hinges/%s/implicit%d/filter%d",
                 cases[c].name, cases[c].implicit, cases[c].filter);
        if (!bound(label, m) || !run(label, m, 10, 1e-3, s)) {
            canopy_model_destroy(&m);
            return 0;
        }
        dump(label, s);
        canopy_model_destroy(&m);
    }
    return 1;
}

/* Directional added mass on the cloth, the payload on a vertical guide. */
static int added_mass_and_guide(snapshot *s)
{
    static const char *names[] = {"newmark", "hht", "rk4"};
    for (int c = 0; c < 3; ++c) {
        int payload = -1;
        canopy_model *m = parachute(names[c], &payload);
        if (m == NULL) return 0;
        const int n = canopy_model_node_count(m);
        double *ma = calloc((size_t)n, sizeof(double));
        double *dir = calloc(3 * (size_t)n, sizeof(double));
        int *groups = calloc((size_t)n, sizeof(int));
        canopy_model_get_node_groups(m, groups, n);
        for (int i = 0; i < n; ++i)
            if (groups[i] == CANOPY_GROUP_FABRIC) {
                ma[i] = 0.01;
                dir[3 * i + 2] = 1.0;
                dir[3 * i] = 0.1 * (i % 3);
            }
        canopy_model_set_directional_added_mass(m, ma, dir, n);
        const double axis[3] = {0.0, 0.0, 1.0};
        canopy_model_set_guide(m, payload, axis);
        canopy_model_set_bending_damping(m, 100.0);
        canopy_model_set_bending_damping_implicit(m, 1);
        free(ma); free(dir); free(groups);
        canopy_model_set_max_omega_dt(m, c < 2 ? 2.0 : 0.3);
        char label[64];
        snprintf(label, sizeof label, "addedmass-guide/%s", names[c]);
        if (!run(label, m, 10, 1e-3, s)) {
            canopy_model_destroy(&m);
            return 0;
        }
        dump(label, s);
        canopy_model_destroy(&m);
    }
    return 1;
}

/* HHT's carried acceleration through checkpoint/restore (the repeated step
 * must hash as the first try) and an HDF5 write + read_state. */
static int checkpoint_and_restart(snapshot *s, const char *dir)
{
    int payload = -1;
    canopy_model *m = parachute("hht", &payload);
    if (m == NULL) return 0;
    canopy_model_set_bending_damping(m, 100.0);
    canopy_model_set_bending_damping_implicit(m, 1);
    canopy_model_set_max_omega_dt(m, 2.0);
    int ok = run("restart/hht/warm", m, 5, 1e-3, s);
    for (int k = 0; ok && k < 3; ++k) {
        ok = canopy_model_checkpoint(m) == CANOPY_OK &&
             run("restart/hht/trial", m, 1, 1e-3, s) &&
             canopy_model_restore(m) == CANOPY_OK &&
             run("restart/hht/again", m, 1, 1e-3, s) &&
             canopy_model_commit(m) == CANOPY_OK;
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/canopy-trajectory-restart", dir);
    canopy_output *o = NULL;
    ok = ok && canopy_output_create(m, path, CANOPY_OUTPUT_CREATE, &o) ==
                   CANOPY_OK &&
         canopy_output_write(o, m) == CANOPY_OK;
    canopy_output_destroy(&o);
    ok = ok && run("restart/hht/continued", m, 4, 1e-3, s);
    if (ok) dump("restart/hht/continued", s);
    canopy_model_destroy(&m);
    if (!ok) return 0;

    canopy_model *r = parachute("hht", &payload);
    if (r == NULL) return 0;
    canopy_model_set_bending_damping(r, 100.0);
    canopy_model_set_bending_damping_implicit(r, 1);
    canopy_model_set_max_omega_dt(r, 2.0);
    ok = canopy_model_read_state(r, path, -1) == CANOPY_OK &&
         run("restart/hht/restarted", r, 4, 1e-3, s);
    if (!ok)
        fprintf(stderr, "restart: %s\n", canopy_model_message(r));
    if (ok) dump("restart/hht/restarted", s);
    canopy_model_destroy(&r);
    return ok;
}

/* Newton held to a few iterations: the advance halves its sub-steps; held
 * too tightly, it fails and restores the state. */
static int halving(snapshot *s)
{
    static const struct { const char *name, *what; double tol; int iter; }
        cases[] = {{"newmark", "halving", 1e-8, 3},
                   {"hht", "halving", 1e-8, 3},
                   {"newmark", "failing", 1e-13, 2},
                   {"hht", "failing", 1e-13, 2}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        int payload = -1;
        canopy_model *m = parachute(cases[c].name, &payload);
        if (m == NULL) return 0;
        canopy_model_set_implicit_controls(m, cases[c].tol, cases[c].iter);
        canopy_model_set_max_omega_dt(m, 20.0);
        char label[64];
        snprintf(label, sizeof label, "%s/%s", cases[c].what, cases[c].name);
        int ok = run(label, m, cases[c].iter == 3 ? 6 : 2, 2e-3, s);
        if (ok) dump(label, s);
        canopy_model_destroy(&m);
        if (!ok) return 0;
    }
    return 1;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "/tmp";
    snapshot s = {0};
    int ok = every_integrator(&s) && hinges(&s) && added_mass_and_guide(&s) &&
             checkpoint_and_restart(&s, dir) && halving(&s);
    free(s.x); free(s.v); free(s.a);
    if (!ok) fprintf(stderr, "canopy-trajectory: a case failed to set up\n");
    return ok ? 0 : 1;
}

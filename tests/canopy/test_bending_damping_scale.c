/* test_bending_damping_scale.c — how strongly the hinge dashpots damp a smooth bending of the cloth against its flapping at the mesh scale, with and without their high-pass filter. */
#include "test.h"

#include <math.h>
#include <stdlib.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* A pinned 1 m x 1 m rectangle of edge h (no gravity, hinge dashpots of
 * `rate`, explicit) moving out of plane with v_z = shape(x, y). Returns the
 * rate at which the dashpots take out the kinetic energy, as an amplitude
 * decay rate lambda = -P / (2 E_kin), P = sum f . v (the springs stay at
 * rest and their dashpots act along the springs, to which this velocity
 * is normal: the hinge dashpots are the only force). -1 on failure. */
static double decay_rate(double h, double rate, int smooth, int high_pass)
{
    canopy_model *m = NULL;
    double lambda = -1.0;
    if (canopy_model_create(&m)) return -1.0;
    canopy_rectangle_spec r = canopy_rectangle_spec_default();
    r.width = 1.0;
    r.length = 1.0;
    r.edge_length = h;
    const double g[3] = {0.0, 0.0, 0.0};
    canopy_status st = canopy_build_rectangle(m, &r);
    if (!st) st = canopy_model_set_gravity(m, g);
    if (!st) st = canopy_model_set_bending_damping(m, rate);
    if (!st && high_pass) st = canopy_model_set_bending_damping_implicit(m, 1);
    if (!st) st = canopy_model_set_bending_damping_filter(m, high_pass);
    const int n = canopy_model_node_count(m);
    double *x = malloc(sizeof(double) * 3 * (size_t)n);
    double *v = calloc(3 * (size_t)n, sizeof(double));
    double *f = malloc(sizeof(double) * 3 * (size_t)n);
    double *mass = malloc(sizeof(double) * (size_t)n);
    if (!x || !v || !f || !mass) st = CANOPY_ERR_MEMORY;
    if (!st) st = canopy_model_get_positions(m, x, n);
    if (!st) st = canopy_model_get_masses(m, mass, n);
    for (int i = 0; i < n && !st; ++i) {
        const double px = x[3 * i], py = x[3 * i + 1];
        if (px < 1e-9 || py < 1e-9 || px > 1.0 - 1e-9 || py > 1.0 - 1e-9) {
            st = canopy_model_set_fixed(m, i, 1);
            continue;
        }
        /* the lowest bending mode of the pinned square, or every other
         * node up and down (flapping at the mesh scale) */
        v[3 * i + 2] = smooth ? sin(M_PI * px) * sin(M_PI * py)
                              : ((i % 2) ? 1.0 : -1.0);
    }
    if (!st) st = canopy_model_set_velocities(m, v, n);
    if (!st) st = canopy_model_get_forces(m, f, n);
    if (!st) {
        double power = 0.0, kinetic = 0.0;
        for (int i = 0; i < n; ++i) {
            power += f[3 * i + 2] * v[3 * i + 2];
            kinetic += 0.5 * mass[i] * v[3 * i + 2] * v[3 * i + 2];
        }
        lambda = -power / (2.0 * kinetic);
    }
    free(x);
    free(v);
    free(f);
    free(mass);
    canopy_model_destroy(&m);
    return lambda;
}

/* The dashpot damps a hinge's own bending at `rate`, but a smooth bending
 * of wavenumber k bends each hinge by only ~ k^2 h^2 of what it moves the
 * nodes, and neighbouring hinges' forces nearly cancel: the smooth mode
 * decays at C rate (k h)^4 (a fourth difference of the velocity, like a
 * bending stiffness). Asserted: halving h divides the smooth mode's decay
 * by 16 to within 15 % (the next terms are O((k h)^2) = 20 % and 5 % of
 * the leading one at h = 0.1 and 0.05 m, k = sqrt(2) pi), and the flapping
 * decays at 1-10 times `rate` (each node is a corner of several hinges:
 * six edges of its own and the edges opposite it). The printed C turns a dashpot rate into the
 * damping of a canopy's breathing (docs/validation.md). */
CANOPY_TEST(bending_damping_falls_as_the_fourth_power_of_the_scale)
{
    const double rate = 1e4;
    const double k = sqrt(2.0) * M_PI;
    const double hs[3] = {0.2, 0.1, 0.05};
    double smooth[3], flap[3];
    for (int j = 0; j < 3; ++j) {
        smooth[j] = decay_rate(hs[j], rate, 1, 0);
        flap[j] = decay_rate(hs[j], rate, 0, 0);
        ASSERT_TRUE(smooth[j] > 0.0);
        ASSERT_TRUE(flap[j] > 0.0);
        printf("  h = %.3g m (k h = %.3g): smooth mode decays at %.4g /s "
               "(C = %.3g), flapping at %.4g /s (rate %g /s)\n",
               hs[j], k * hs[j], smooth[j],
               smooth[j] / (rate * pow(k * hs[j], 4.0)), flap[j], rate);
    }
    const double ratio = smooth[1] / smooth[2];
    printf("  smooth decay at h = 0.1 over h = 0.05: %.3g (h^4: 16)\n", ratio);
    ASSERT_TRUE(fabs(ratio / 16.0 - 1.0) < 0.15);
    for (int j = 0; j < 3; ++j) {
        ASSERT_TRUE(flap[j] > rate);
        ASSERT_TRUE(flap[j] < 10.0 * rate);
    }
}

/* With the high-pass filter the dashpots act on P v, the velocity's
 * deviation from its local linear fit: P v ~ (k h)^2 v for the smooth
 * mode, so its decay falls as (k h)^8. Asserted: halving h from 0.05 to
 * 0.025 m divides it by 256 to within 15 % (the next terms, O((k h)^2),
 * are 5 % and 1 % of the leading one there; at h = 0.1 they are 20 % and
 * the ratio 0.1 / 0.05 is printed, not asserted), and the flapping decays
 * at 1-10 times `rate` and at least half as fast as without the filter
 * (P leaves the mesh-scale motion at about its size). */
CANOPY_TEST(bending_damping_high_pass_falls_as_the_eighth_power_of_the_scale)
{
    const double rate = 1e4;
    const double k = sqrt(2.0) * M_PI;
    const double hs[3] = {0.1, 0.05, 0.025};
    double smooth[3], flap[3], flap_plain[3];
    for (int j = 0; j < 3; ++j) {
        smooth[j] = decay_rate(hs[j], rate, 1, 1);
        flap[j] = decay_rate(hs[j], rate, 0, 1);
        flap_plain[j] = decay_rate(hs[j], rate, 0, 0);
        ASSERT_TRUE(smooth[j] > 0.0);
        ASSERT_TRUE(flap[j] > 0.0);
        printf("  h = %.3g m (k h = %.3g): smooth mode decays at %.4g /s "
               "(C8 = %.3g), flapping at %.4g /s (%.4g /s unfiltered)\n",
               hs[j], k * hs[j], smooth[j],
               smooth[j] / (rate * pow(k * hs[j], 8.0)), flap[j],
               flap_plain[j]);
    }
    printf("  smooth decay at h = 0.1 over h = 0.05: %.3g; at h = 0.05 over "
           "h = 0.025: %.3g (h^8: 256)\n", smooth[0] / smooth[1],
           smooth[1] / smooth[2]);
    ASSERT_TRUE(fabs(smooth[1] / smooth[2] / 256.0 - 1.0) < 0.15);
    for (int j = 0; j < 3; ++j) {
        ASSERT_TRUE(flap[j] > rate);
        ASSERT_TRUE(flap[j] < 10.0 * rate);
        ASSERT_TRUE(flap[j] > 0.5 * flap_plain[j]);
    }
}

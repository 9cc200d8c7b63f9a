/* canopy_bench.c — libcanopy benchmark: RK4 spring-force evaluations per second and memory per node. */
#include "canopy.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* Prints one line per figure: BENCH <name> <value> <unit>.
 * A flat circular canopy (C-9 size, 8.53 m) with 28 suspension lines and a
 * payload is meshed at an edge length giving about 1k, 10k and 100k nodes,
 * loaded by a uniform pressure jump, and advanced with RK4 for a fixed wall
 * time budget. A "spring evaluation" is one spring's force (with dashpot)
 * computed once; RK4 does four force evaluations per step. */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int bench(int target_nodes, double budget_s)
{
    const double diameter = 8.53, area = M_PI * diameter * diameter / 4.0;
    canopy_model *m = NULL;
    if (canopy_model_create(&m) != CANOPY_OK) return 1;
    canopy_circular_spec c = canopy_circular_spec_default();
    c.diameter = diameter;
    c.n_attachments = 28;
    c.edge_length = sqrt(2.0 * area / (sqrt(3.0) * target_nodes));
    int attach[28], payload;
    canopy_lines_spec l = canopy_lines_spec_default();
    l.line_length = 8.0;
    l.edge_length = c.edge_length * 4.0;
    l.payload_mass = 100.0;
    if (canopy_build_circular(m, &c, attach) != CANOPY_OK ||
        canopy_build_suspension_lines(m, attach, 28, &l, &payload) != CANOPY_OK ||
        canopy_model_set_integrator(m, "rk4") != CANOPY_OK) {
        fprintf(stderr, "canopy-bench: %s\n", canopy_model_message(m));
        canopy_model_destroy(&m);
        return 1;
    }
    const int nt = canopy_model_triangle_count(m);
    double *dp = malloc(sizeof(double) * (size_t)nt);
    for (int t = 0; t < nt; ++t) dp[t] = 30.0;
    canopy_model_set_pressure_jump(m, dp, nt);
    free(dp);
    const int n = canopy_model_node_count(m), ns = canopy_model_spring_count(m);
    double dt;
    canopy_model_stable_step(m, &dt);
    /* Warm up (allocates work space), then time whole steps. */
    canopy_model_step(m, dt);
    long steps = 0;
    const double t0 = now();
    double t1 = t0;
    while (t1 - t0 < budget_s) {
        for (int k = 0; k < 10; ++k)
            if (canopy_model_step(m, dt) != CANOPY_OK) {
                fprintf(stderr, "canopy-bench: %s\n", canopy_model_message(m));
                canopy_model_destroy(&m);
                return 1;
            }
        steps += 10;
        t1 = now();
    }
    const double secs = t1 - t0;
    const double evals = 4.0 * (double)ns * (double)steps / secs;
    char name[64];
    snprintf(name, sizeof name, "rk4_spring_evals_per_s_%dk_nodes",
             target_nodes / 1000);
    printf("BENCH %s %.4g evals/s\n", name, evals);
    snprintf(name, sizeof name, "rk4_step_ns_per_node_%dk_nodes",
             target_nodes / 1000);
    printf("BENCH %s %.4g ns\n", name, 1e9 * secs / (double)steps / n);
    snprintf(name, sizeof name, "memory_bytes_per_node_%dk_nodes",
             target_nodes / 1000);
    printf("BENCH %s %.1f bytes\n", name,
           (double)canopy_model_memory_bytes(m) / n);
    printf("#     (%d nodes, %d springs, %d triangles, %ld RK4 steps in %.2f s)\n",
           n, ns, nt, steps, secs);
    fflush(stdout);
    canopy_model_destroy(&m);
    return 0;
}

int main(int argc, char **argv)
{
    const double budget = argc > 1 ? atof(argv[1]) : 3.0;
    if (!(budget > 0.0)) {
        fprintf(stderr, "usage: canopy-bench [seconds per size > 0]\n");
        return 2;
    }
    int rc = 0;
    rc |= bench(1000, budget);
    rc |= bench(10000, budget);
    rc |= bench(100000, budget);
    return rc;
}

/* canopyDropDemo.c — structure-only drop of a 7 ft flat circular parachute under a quasi-steady pressure stand-in, written as HDF5 + XDMF for ParaView. */
#include "canopy.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The case (NOTES §4, seed 000 ch. 5): 7 ft flat circular canopy, 2.134 m
 * constructed diameter, 16 suspension lines of 2 m, payload 5.398 kg, nylon
 * cloth 0.0373 kg/m^2. It starts flat and at rest and falls under gravity.
 *
 * The load is a STAND-IN FOR THE FLUID, NOT A PREDICTION: a quasi-steady
 * pressure jump on each triangle from its own normal velocity,
 *     dp = -1/2 rho Cp vn |vn|,   vn = (triangle velocity) . (unit normal),
 * rho = 1.2 kg/m^3, Cp = 2 (Newtonian impact theory: Cp = 2 sin^2 of the
 * incidence). A triangle moving along its normal is pushed back; for the
 * flat canopy falling at speed V this is dp = 1/2 rho Cp V^2 on every
 * triangle. (That same dp taken from the payload's speed and applied
 * uniformly has no restoring moment: the canopy tips over, slides sideways
 * and speeds up. The local form always dissipates energy and keeps the
 * canopy above the payload.) The default case settles at about 6.7 m/s with
 * a projected diameter of about 0.7 of the constructed one within 2 s. The
 * fluid solver (canopyPimpleFoam) replaces this load. */

#define AIR_DENSITY        1.2      /* kg/m^3 */
#define PRESSURE_COEFF     2.0      /* Cp of the stand-in load */
#define OUTER_STEP         1e-3     /* s, the step a fluid solver would take */
#define CANOPY_DIAMETER    2.134    /* m */
#define N_LINES            16
#define LINE_LENGTH        2.0      /* m */
#define PAYLOAD_MASS       5.398    /* kg */
#define FABRIC_DENSITY     0.0373   /* kg/m^2 */
#define PROGRESS_SECONDS   2.0      /* wall time between progress lines */

typedef struct options {
    const char *prefix;
    double end_time;
    double edge_length;
    double write_interval;
    int quiet;
    int frame;
} options;

static void usage(FILE *f)
{
    fprintf(f,
        "Usage: canopyDropDemo [-o outputPrefix] [-t endTime] [-h edgeLength]"
        " [-w writeInterval] [-f] [-q]\n"
        "Structure-only drop of a 7 ft flat circular parachute (2.134 m, 16 "
        "lines of 2 m,\n"
        "5.398 kg payload) under a quasi-steady pressure stand-in for the "
        "fluid.\n"
        "  -o outputPrefix   output path without extension: writes "
        "<prefix>.h5 and\n"
        "                    <prefix>.xdmf (default: drop; the directory must "
        "exist)\n"
        "  -t endTime        simulated time [s] (default 3)\n"
        "  -h edgeLength     canopy triangle edge length [m] (default 0.1)\n"
        "  -w writeInterval  simulated time between outputs [s] (default "
        "0.01),\n"
        "                    rounded to whole steps of %g s\n"
        "  -f                also write each step in the frame that follows "
        "the payload\n"
        "                    (<prefix>-frame.xdmf: the payload at the "
        "origin)\n"
        "  -q                quiet: no progress lines, only the summary\n",
        OUTER_STEP);
}

/* A positive finite number, or 0 with a message. */
static int parse_positive(const char *text, const char *what, double *value)
{
    char *end = NULL;
    double v = strtod(text, &end);
    if (end == text || *end != '\0' || !isfinite(v) || !(v > 0.0)) {
        fprintf(stderr, "canopyDropDemo: %s '%s' is not a positive number\n",
                what, text);
        return 0;
    }
    *value = v;
    return 1;
}

static int parse_options(int argc, char **argv, options *o)
{
    o->prefix = "drop";
    o->end_time = 3.0;
    o->edge_length = 0.1;
    o->write_interval = 0.01;
    o->quiet = 0;
    o->frame = 0;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "-q") == 0) {
            o->quiet = 1;
            continue;
        }
        if (strcmp(a, "-f") == 0) {
            o->frame = 1;
            continue;
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-help") == 0) {
            usage(stdout);
            exit(0);
        }
        if (a[0] != '-' || a[1] == '\0' || a[2] != '\0' ||
            strchr("othw", a[1]) == NULL) {
            fprintf(stderr, "canopyDropDemo: unknown argument '%s'\n", a);
            return 0;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "canopyDropDemo: option %s needs a value\n", a);
            return 0;
        }
        const char *value = argv[++i];
        switch (a[1]) {
        case 'o':
            if (value[0] == '\0') {
                fprintf(stderr, "canopyDropDemo: empty output prefix\n");
                return 0;
            }
            o->prefix = value;
            break;
        case 't':
            if (!parse_positive(value, "end time (-t)", &o->end_time)) return 0;
            break;
        case 'h':
            if (!parse_positive(value, "edge length (-h)", &o->edge_length))
                return 0;
            if (o->edge_length > 0.5 * CANOPY_DIAMETER) {
                fprintf(stderr, "canopyDropDemo: edge length %g m is larger "
                        "than the canopy radius\n", o->edge_length);
                return 0;
            }
            break;
        case 'w':
            if (!parse_positive(value, "write interval (-w)",
                                &o->write_interval))
                return 0;
            break;
        default:
            return 0;
        }
    }
    if (o->end_time / OUTER_STEP > 1e8) {
        fprintf(stderr, "canopyDropDemo: end time %g s needs more than 1e8 "
                "steps\n", o->end_time);
        return 0;
    }
    return 1;
}

static double wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Report a library failure and stop (the last good state is on disk). */
static int fail(const char *what, const char *message)
{
    fprintf(stderr, "canopyDropDemo: %s failed: %s\n", what, message);
    return 1;
}

typedef struct demo {
    canopy_model *model;
    canopy_output *output;
    double *dp, *normal, *velocity;   /* per triangle: 1, 3, 3 doubles */
    int nt;
    double up[3];        /* unit vector against gravity */
} demo;

static void demo_free(demo *d)
{
    canopy_output_destroy(&d->output);
    canopy_model_destroy(&d->model);
    free(d->dp);
    free(d->normal);
    free(d->velocity);
}

static canopy_status build(demo *d, double edge_length)
{
    canopy_status st = canopy_model_create(&d->model);
    if (st != CANOPY_OK) return st;
    canopy_model *m = d->model;
    canopy_circular_spec c = canopy_circular_spec_default();
    c.diameter = CANOPY_DIAMETER;
    c.height = 0.0;                 /* flat */
    c.vent_diameter = 0.0;
    c.edge_length = edge_length;
    c.center[0] = c.center[1] = c.center[2] = 0.0;
    c.n_attachments = N_LINES;
    c.fabric.density = FABRIC_DENSITY;
    int skirt[N_LINES], payload;
    if ((st = canopy_build_circular(m, &c, skirt)) != CANOPY_OK) return st;
    canopy_lines_spec l = canopy_lines_spec_default();
    l.line_length = LINE_LENGTH;
    l.payload_mass = PAYLOAD_MASS;
    /* Line segments no shorter than the cloth's edges: the line nodes'
     * frequency bound then stays at or below the cloth's. */
    l.edge_length = edge_length > 0.1 ? edge_length : 0.1;
    if ((st = canopy_build_suspension_lines(m, skirt, N_LINES, &l,
                                            &payload)) != CANOPY_OK)
        return st;
    if ((st = canopy_model_set_integrator(m, "rk4")) != CANOPY_OK) return st;

    d->nt = canopy_model_triangle_count(m);
    d->dp = calloc((size_t)d->nt, sizeof *d->dp);
    d->normal = malloc(sizeof(double) * 3 * (size_t)d->nt);
    d->velocity = malloc(sizeof(double) * 3 * (size_t)d->nt);
    if (d->dp == NULL || d->normal == NULL || d->velocity == NULL)
        return CANOPY_ERR_MEMORY;
    const double g[3] = {0.0, 0.0, -9.81};
    if ((st = canopy_model_set_gravity(m, g)) != CANOPY_OK) return st;
    const double gl = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    for (int k = 0; k < 3; ++k) d->up[k] = -g[k] / gl;
    return CANOPY_OK;
}

/* Descent speed of the payload [m/s], positive downwards. */
static double descent_speed(const demo *d)
{
    double v[3] = {0.0, 0.0, 0.0};
    canopy_model_payload_state(d->model, NULL, v);
    return -(v[0] * d->up[0] + v[1] * d->up[1] + v[2] * d->up[2]);
}

static canopy_status set_stand_in_load(demo *d)
{
    canopy_status st = canopy_model_get_triangle_geometry(d->model, NULL,
                                                          d->normal, NULL,
                                                          d->nt);
    if (st == CANOPY_OK)
        st = canopy_model_get_triangle_velocities(d->model, d->velocity,
                                                  d->nt);
    if (st != CANOPY_OK) return st;
    const double q = 0.5 * AIR_DENSITY * PRESSURE_COEFF;
    for (int t = 0; t < d->nt; ++t) {
        const double *n = d->normal + 3 * t, *v = d->velocity + 3 * t;
        const double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
        d->dp[t] = -q * vn * fabs(vn);
    }
    return canopy_model_set_pressure_jump(d->model, d->dp, d->nt);
}

static double projected_diameter(const demo *d)
{
    double D = NAN;
    canopy_model_projected_diameter(d->model, &D);
    return D;
}

static void format_duration(char *buf, size_t size, double s)
{
    if (!isfinite(s) || s < 0.0) snprintf(buf, size, "?");
    else if (s < 90.0) snprintf(buf, size, "%.0f s", s);
    else snprintf(buf, size, "%.0f min %02.0f s", floor(s / 60.0),
                  fmod(s, 60.0));
}

/* One output step; with frame, also in the frame that follows the payload
 * (origin at the payload node). */
static canopy_status write_step(canopy_output *out, const canopy_model *m,
                                int frame)
{
    if (!frame) return canopy_output_write(out, m);
    double origin[3];
    canopy_status st = canopy_model_payload_state(m, origin, NULL);
    return st != CANOPY_OK ? st : canopy_output_write_framed(out, m, origin);
}

int main(int argc, char **argv)
{
    options opt;
    if (!parse_options(argc, argv, &opt)) {
        usage(stderr);
        return 2;
    }
    const double t0_wall = wall_seconds();
    demo d;
    memset(&d, 0, sizeof d);
    canopy_status st = build(&d, opt.edge_length);
    if (st != CANOPY_OK) {
        int rc = fail("building the model",
                      d.model ? canopy_model_message(d.model)
                              : canopy_status_description(st));
        demo_free(&d);
        return rc;
    }
    canopy_model *m = d.model;
    const int n = canopy_model_node_count(m);
    double *mass = malloc(sizeof(double) * (size_t)n);
    double total_mass = 0.0;
    if (mass != NULL && canopy_model_get_masses(m, mass, n) == CANOPY_OK)
        for (int i = 0; i < n; ++i) total_mass += mass[i];
    free(mass);
    double sub_dt = 0.0;
    if ((st = canopy_model_stable_step(m, &sub_dt)) != CANOPY_OK) {
        int rc = fail("the stable step", canopy_model_message(m));
        demo_free(&d);
        return rc;
    }
    const long steps = lround(ceil(opt.end_time / OUTER_STEP - 1e-9));
    long write_every = lround(opt.write_interval / OUTER_STEP);
    if (write_every < 1) write_every = 1;

    if (!opt.quiet) {
        printf("canopyDropDemo: 7 ft flat circular canopy, %d nodes, %d "
               "springs, %d triangles, %.3f kg in all\n", n,
               canopy_model_spring_count(m), d.nt, total_mass);
        printf("  %ld steps of %g s to t = %g s, rk4 sub-steps of <= %.3g s "
               "(%.0f per step), output every %ld steps\n", steps, OUTER_STEP,
               (double)steps * OUTER_STEP, sub_dt, ceil(OUTER_STEP / sub_dt),
               write_every);
        printf("  load: dp = -1/2 rho Cp vn|vn| per triangle (rho %g, Cp %g)"
               " - a stand-in for the fluid, not a prediction\n",
               AIR_DENSITY, PRESSURE_COEFF);
        fflush(stdout);
    }

    if ((st = canopy_output_create(m, opt.prefix, CANOPY_OUTPUT_CREATE,
                                   &d.output)) != CANOPY_OK) {
        int rc = fail("creating the output", canopy_model_message(m));
        demo_free(&d);
        return rc;
    }
    if ((st = write_step(d.output, m, opt.frame)) != CANOPY_OK) {
        int rc = fail("writing the output", canopy_output_message(d.output));
        demo_free(&d);
        return rc;
    }

    const double t_start = wall_seconds();
    double last_report = t_start;
    int substeps = 0;
    for (long s = 1; s <= steps; ++s) {
        if ((st = set_stand_in_load(&d)) != CANOPY_OK ||
            (st = canopy_model_advance(m, OUTER_STEP, &substeps)) != CANOPY_OK) {
            fprintf(stderr, "canopyDropDemo: step %ld (t = %g s) failed: %s\n"
                    "  the last good state is step %d of %s.h5\n", s,
                    canopy_model_time(m), canopy_model_message(m),
                    canopy_output_step_count(d.output) - 1, opt.prefix);
            demo_free(&d);
            return 1;
        }
        if (s % write_every == 0 || s == steps) {
            if ((st = write_step(d.output, m, opt.frame)) != CANOPY_OK) {
                int rc = fail("writing the output",
                              canopy_output_message(d.output));
                demo_free(&d);
                return rc;
            }
        }
        const double now = wall_seconds();
        if (!opt.quiet && (now - last_report >= PROGRESS_SECONDS || s == steps)) {
            const double frac = (double)s / (double)steps;
            char eta[32];
            format_duration(eta, sizeof eta,
                            (now - t_start) * (1.0 - frac) / frac);
            printf("  t = %.3f s  %5.1f %%  left %-10s descent %6.3f m/s  "
                   "projected diameter %.3f m\n", canopy_model_time(m),
                   100.0 * frac, eta, descent_speed(&d),
                   projected_diameter(&d));
            fflush(stdout);
            last_report = now;
        }
    }

    const double wall = wall_seconds() - t0_wall;
    char took[32];
    format_duration(took, sizeof took, wall);
    const char *slash = strrchr(opt.prefix, '/');
    printf("\ncanopyDropDemo: done\n"
           "  simulated             %.3f s in %ld steps of %g s (%d rk4 "
           "sub-steps each), wall %s\n"
           "  final descent speed   %.3f m/s (stand-in load, not a "
           "prediction)\n"
           "  projected diameter    %.3f m (constructed %.3f m)\n"
           "  steps written         %d\n"
           "  output files          %s.h5, %s.xdmf\n"
           "  open %s.xdmf in ParaView%s\n",
           canopy_model_time(m), steps, OUTER_STEP, substeps, took,
           descent_speed(&d), projected_diameter(&d), CANOPY_DIAMETER,
           canopy_output_step_count(d.output), opt.prefix, opt.prefix,
           opt.prefix, slash ? "" : " (in this directory)");
    demo_free(&d);
    return 0;
}

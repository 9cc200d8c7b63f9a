/* spectrum.c — largest eigen-frequency of the linearised spring system by Lanczos iteration. */
#include "model_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The linearised equations M dx'' = -K dx (seed 000 eqs. 3.3 and 3.12) have
 * frequencies omega^2 = eigenvalues of S = M^-1/2 K M^-1/2 over the free
 * nodes' degrees of freedom. Lanczos with full re-orthogonalisation finds the
 * largest one; the Ritz residual |S y - theta y| bounds its error. */

typedef struct lanczos_space {
    int nfree, dim;
    int *free_nodes;
    double *inv_sqrt_m;   /* per free node */
    double *full_in, *full_out; /* 3*n */
} lanczos_space;

static void apply_S(const canopy_model *m, const lanczos_space *sp,
                    const double *q, double *out)
{
    const int n = m->nodes.count;
    memset(sp->full_in, 0, 3 * sizeof(double) * (size_t)n);
    for (int f = 0; f < sp->nfree; ++f)
        for (int d = 0; d < 3; ++d)
            sp->full_in[3 * sp->free_nodes[f] + d] = q[3 * f + d] * sp->inv_sqrt_m[f];
    canopy_tangent_stiffness(m, m->nodes.x, NULL, sp->full_in, sp->full_out, 0);
    for (int f = 0; f < sp->nfree; ++f)
        for (int d = 0; d < 3; ++d)
            out[3 * f + d] = sp->full_out[3 * sp->free_nodes[f] + d] * sp->inv_sqrt_m[f];
}

static double dot(int n, const double *a, const double *b)
{
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += a[i] * b[i];
    return s;
}

/* Number of eigenvalues of the tridiagonal (a, b) below x (Sturm sequence). */
static int sturm_count(int k, const double *a, const double *b, double x)
{
    int count = 0;
    double d = 1.0;
    for (int i = 0; i < k; ++i) {
        const double off = i > 0 ? b[i - 1] * b[i - 1] : 0.0;
        d = a[i] - x - (i > 0 ? off / d : 0.0);
        if (d == 0.0) d = -1e-300;
        if (d < 0.0) ++count;
    }
    return count;
}

static double largest_eigenvalue(int k, const double *a, const double *b)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < k; ++i) {
        const double r = (i > 0 ? fabs(b[i - 1]) : 0.0) +
                         (i < k - 1 ? fabs(b[i]) : 0.0);
        if (a[i] - r < lo) lo = a[i] - r;
        if (a[i] + r > hi) hi = a[i] + r;
    }
    for (int it = 0; it < 200 && hi - lo > 1e-15 * fmax(fabs(hi), fabs(lo)); ++it) {
        const double mid = 0.5 * (lo + hi);
        if (sturm_count(k, a, b, mid) == k) hi = mid; else lo = mid;
    }
    return 0.5 * (lo + hi);
}

/* Eigenvector of the tridiagonal for eigenvalue theta by inverse iteration. */
static void tridiagonal_eigenvector(int k, const double *a, const double *b,
                                    double theta, double *s, double *work)
{
    double *c = work, *dd = work + k;
    const double shift = theta + 1e-10 * fmax(fabs(theta), 1e-300);
    for (int i = 0; i < k; ++i) s[i] = 1.0;
    for (int pass = 0; pass < 3; ++pass) {
        /* Thomas algorithm on (T - shift I) z = s. */
        for (int i = 0; i < k; ++i) {
            double diag = a[i] - shift;
            if (i > 0) {
                diag -= b[i - 1] * c[i - 1];
                dd[i] = s[i] - b[i - 1] * dd[i - 1];
            } else {
                dd[i] = s[i];
            }
            if (diag == 0.0) diag = 1e-300;
            c[i] = i < k - 1 ? b[i] / diag : 0.0;
            dd[i] /= diag;
        }
        for (int i = k - 1; i >= 0; --i)
            s[i] = dd[i] - (i < k - 1 ? c[i] * s[i + 1] : 0.0);
        const double norm = sqrt(dot(k, s, s));
        for (int i = 0; i < k; ++i) s[i] /= norm;
    }
}

canopy_status canopy_model_max_frequency(canopy_model *model, double *omega,
                                         double *residual)
{
    if (model == NULL) return CANOPY_ERR_ARGUMENT;
    if (omega == NULL)
        return canopy_fail(model, CANOPY_ERR_ARGUMENT,
                           "max_frequency: omega is NULL");
    canopy_status st = canopy_model_prepare(model);
    if (st != CANOPY_OK) return st;
    const int n = model->nodes.count;
    lanczos_space sp = {0};
    sp.free_nodes = malloc(sizeof(int) * (size_t)n);
    sp.inv_sqrt_m = malloc(sizeof(double) * (size_t)n);
    sp.full_in = malloc(3 * sizeof(double) * (size_t)n);
    sp.full_out = malloc(3 * sizeof(double) * (size_t)n);
    double *Q = NULL, *alpha = NULL, *beta = NULL, *w = NULL, *s = NULL,
           *y = NULL, *Sy = NULL;
    if (!sp.free_nodes || !sp.inv_sqrt_m || !sp.full_in || !sp.full_out) {
        st = canopy_fail(model, CANOPY_ERR_MEMORY, "max_frequency: no memory");
        goto done;
    }
    for (int i = 0; i < n; ++i)
        if (!model->nodes.fixed[i]) {
            sp.inv_sqrt_m[sp.nfree] = 1.0 / sqrt(canopy_effective_mass(model, i));
            sp.free_nodes[sp.nfree++] = i;
        }
    sp.dim = 3 * sp.nfree;
    if (sp.dim == 0) {
        *omega = 0.0;
        if (residual) *residual = 0.0;
        goto done;
    }
    const int N = sp.dim;
    int kmax = N < 300 ? N : 300;
    const int mem_cap = (int)(25000000 / N);   /* Q at most ~200 MB */
    if (kmax > mem_cap) kmax = mem_cap > 10 ? mem_cap : 10;
    Q = malloc(sizeof(double) * (size_t)N * (size_t)(kmax + 1));
    alpha = calloc((size_t)kmax, sizeof(double));
    beta = calloc((size_t)kmax, sizeof(double));
    w = malloc(sizeof(double) * (size_t)N);
    s = malloc(sizeof(double) * (size_t)(3 * kmax));
    y = malloc(sizeof(double) * (size_t)N);
    Sy = malloc(sizeof(double) * (size_t)N);
    if (!Q || !alpha || !beta || !w || !s || !y || !Sy) {
        st = canopy_fail(model, CANOPY_ERR_MEMORY, "max_frequency: no memory "
                         "for %d Lanczos vectors of %d", kmax, N);
        goto done;
    }
    /* Deterministic pseudo-random start vector. */
    unsigned long long seed = 0x9E3779B97F4A7C15ull;
    for (int i = 0; i < N; ++i) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        Q[i] = (double)(seed >> 11) / 9007199254740992.0 - 0.5;
    }
    double nrm = sqrt(dot(N, Q, Q));
    for (int i = 0; i < N; ++i) Q[i] /= nrm;

    int k = 0;
    double theta = 0.0, theta_prev = -1.0;
    for (int j = 0; j < kmax; ++j) {
        double *qj = Q + (size_t)j * N;
        apply_S(model, &sp, qj, w);
        alpha[j] = dot(N, w, qj);
        for (int pass = 0; pass < 2; ++pass)       /* full re-orthogonalisation */
            for (int i = 0; i <= j; ++i) {
                const double *qi = Q + (size_t)i * N;
                const double h = dot(N, w, qi);
                for (int c = 0; c < N; ++c) w[c] -= h * qi[c];
            }
        k = j + 1;
        beta[j] = sqrt(dot(N, w, w));
        if ((k % 10 == 0) || k == kmax) {
            theta = largest_eigenvalue(k, alpha, beta);
            if (fabs(theta - theta_prev) <= 1e-13 * fabs(theta)) break;
            theta_prev = theta;
        }
        if (beta[j] <= 1e-14 * fabs(alpha[j]) || j + 1 == kmax) break;
        double *qn = Q + (size_t)(j + 1) * N;
        for (int c = 0; c < N; ++c) qn[c] = w[c] / beta[j];
    }
    theta = largest_eigenvalue(k, alpha, beta);
    tridiagonal_eigenvector(k, alpha, beta, theta, s, s + kmax);
    for (int c = 0; c < N; ++c) y[c] = 0.0;
    for (int i = 0; i < k; ++i) {
        const double *qi = Q + (size_t)i * N;
        for (int c = 0; c < N; ++c) y[c] += s[i] * qi[c];
    }
    nrm = sqrt(dot(N, y, y));
    for (int c = 0; c < N; ++c) y[c] /= nrm;
    apply_S(model, &sp, y, Sy);
    theta = dot(N, y, Sy);                         /* Rayleigh quotient */
    for (int c = 0; c < N; ++c) Sy[c] -= theta * y[c];
    *omega = sqrt(fmax(theta, 0.0));
    if (residual) *residual = sqrt(dot(N, Sy, Sy));
    canopy_clear_message(model);
done:
    free(sp.free_nodes); free(sp.inv_sqrt_m); free(sp.full_in); free(sp.full_out);
    free(Q); free(alpha); free(beta); free(w); free(s); free(y); free(Sy);
    return st;
}

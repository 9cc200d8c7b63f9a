/* test_integrator_state.c — each integrator's own state is made afresh when the integrator or the node count changes: a switched or grown model steps exactly as a fresh one from the same state. */
#include "test.h"
#include "test_membrane_fixture.h"

enum { N = 6, NN = N * N + 1, STEPS = 3 };

/* The membrane under a pressure jump, implicit hinge dashpots on (their
 * own workspace is remade too). */
static canopy_status make_model(canopy_model **m, const char *integrator)
{
    canopy_status st = canopy_model_create(m);
    if (st) return st;
    if ((st = membrane_fixture(*m, N, 0.1, 500.0, 0.05, 0.01))) return st;
    const int nt = canopy_model_triangle_count(*m);
    double dp[2 * (N - 1) * (N - 1)];
    for (int t = 0; t < nt; ++t) dp[t] = 20.0 + 0.1 * t;
    if ((st = canopy_model_set_pressure_jump(*m, dp, nt)) ||
        (st = canopy_model_set_bending_damping(*m, 50.0)) ||
        (st = canopy_model_set_bending_damping_implicit(*m, 1)))
        return st;
    return canopy_model_set_integrator(*m, integrator);
}

typedef struct state {
    int n, acc_valid;
    double t, x[3 * NN], v[3 * NN], a[3 * NN];
} state;

static canopy_status get_state(const canopy_model *m, state *s)
{
    canopy_status st;
    s->n = canopy_model_node_count(m);
    s->t = canopy_model_time(m);
    if ((st = canopy_model_get_positions(m, s->x, s->n)) ||
        (st = canopy_model_get_velocities(m, s->v, s->n)))
        return st;
    return canopy_model_get_acceleration_state(m, s->a, s->n, &s->acc_valid);
}

/* Positions and velocities first: setting them invalidates the carried
 * acceleration, which comes last. */
static canopy_status set_state(canopy_model *m, const state *s)
{
    canopy_status st;
    if ((st = canopy_model_set_time(m, s->t)) ||
        (st = canopy_model_set_positions(m, s->x, s->n)) ||
        (st = canopy_model_set_velocities(m, s->v, s->n)))
        return st;
    return canopy_model_set_acceleration_state(m, s->a, s->n, s->acc_valid);
}

static int same_state(const state *p, const state *q)
{
    const size_t bytes = 3 * sizeof(double) * (size_t)p->n;
    return p->n == q->n && p->t == q->t && p->acc_valid == q->acc_valid &&
           memcmp(p->x, q->x, bytes) == 0 && memcmp(p->v, q->v, bytes) == 0 &&
           (!p->acc_valid || memcmp(p->a, q->a, bytes) == 0);
}

static void advance(canopy_model *m, int steps)
{
    for (int s = 0; s < steps; ++s)
        ASSERT_OK(m, canopy_model_advance(m, 2e-3, NULL));
}

/* a: `from` for STEPS steps, then `to`; b: a fresh model given a's state
 * at the switch, `to` from the start. They must agree bit for bit, and hold
 * the same memory (the first integrator's state is gone). */
static void check_switch(const char *from, const char *to)
{
    canopy_model *a = NULL, *b = NULL;
    state *sa = calloc(1, sizeof *sa), *sb = calloc(1, sizeof *sb);
    ASSERT_TRUE(sa != NULL && sb != NULL);
    if (sa == NULL || sb == NULL) goto done;
    ASSERT_OK(a, make_model(&a, from));
    ASSERT_OK(b, make_model(&b, to));
    advance(a, STEPS);
    ASSERT_OK(a, get_state(a, sa));
    ASSERT_OK(a, canopy_model_set_integrator(a, to));
    ASSERT_OK(b, set_state(b, sa));
    advance(a, STEPS);
    advance(b, STEPS);
    ASSERT_OK(a, get_state(a, sa));
    ASSERT_OK(b, get_state(b, sb));
    if (!same_state(sa, sb))
        CANOPY_TEST_FAIL_("%s then %s differs from %s alone", from, to, to);
    ASSERT_TRUE(sa->t > 0.0);
    ASSERT_TRUE(canopy_model_memory_bytes(a) == canopy_model_memory_bytes(b));
done:
    free(sa);
    free(sb);
    canopy_model_destroy(&a);
    canopy_model_destroy(&b);
}

CANOPY_TEST(integrator_state_switch)
{
    const int count = canopy_integrator_count();
    for (int i = 0; i < count; ++i)
        for (int j = 0; j < count; ++j)
            check_switch(canopy_integrator_name(i), canopy_integrator_name(j));
}

/* a: STEPS steps, then a node on a spring below the membrane's centre,
 * then STEPS more; b: built with that node and spring (a's rest length),
 * given a's state after the node was added. */
static void check_resize(const char *integrator)
{
    canopy_model *a = NULL, *b = NULL;
    state *sa = calloc(1, sizeof *sa), *sb = calloc(1, sizeof *sb);
    ASSERT_TRUE(sa != NULL && sb != NULL);
    if (sa == NULL || sb == NULL) goto done;
    ASSERT_OK(a, make_model(&a, integrator));
    ASSERT_OK(b, make_model(&b, integrator));
    const int centre = (N / 2) * N + N / 2;
    const double below[3] = {0.3, 0.3, -0.2};
    int node = -1, spring = -1;
    advance(a, STEPS);
    ASSERT_OK(a, canopy_model_add_node(a, below, 0.05, CANOPY_GROUP_PAYLOAD,
                                       &node));
    ASSERT_OK(a, canopy_model_add_spring(a, centre, node, 200.0, 0.01,
                                         CANOPY_SPRING_TENSION_ONLY,
                                         CANOPY_GROUP_LINE, &spring));
    ASSERT_OK(b, canopy_model_add_node(b, below, 0.05, CANOPY_GROUP_PAYLOAD,
                                       NULL));
    ASSERT_OK(b, canopy_model_add_spring(b, centre, node, 200.0, 0.01,
                                         CANOPY_SPRING_TENSION_ONLY,
                                         CANOPY_GROUP_LINE, NULL));
    const int ns = canopy_model_spring_count(a);
    double *rest = malloc(sizeof(double) * (size_t)ns);
    ASSERT_TRUE(rest != NULL);
    if (rest == NULL) goto done;
    canopy_status st = canopy_model_get_springs(a, NULL, rest, NULL, ns);
    if (st == CANOPY_OK)
        st = canopy_model_set_rest_length(b, spring, rest[spring]);
    free(rest);
    ASSERT_OK(b, st);
    ASSERT_OK(a, get_state(a, sa));
    ASSERT_OK(b, set_state(b, sa));
    advance(a, STEPS);
    advance(b, STEPS);
    ASSERT_OK(a, get_state(a, sa));
    ASSERT_OK(b, get_state(b, sb));
    if (!same_state(sa, sb))
        CANOPY_TEST_FAIL_("%s: a node added after stepping differs from one "
                          "there from the start", integrator);
    ASSERT_TRUE(sa->x[3 * node + 2] != below[2]); /* the new node moved */
done:
    free(sa);
    free(sb);
    canopy_model_destroy(&a);
    canopy_model_destroy(&b);
}

CANOPY_TEST(integrator_state_resize)
{
    for (int i = 0; i < canopy_integrator_count(); ++i)
        check_resize(canopy_integrator_name(i));
}

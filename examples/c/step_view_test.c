/* The header's inline lpe_view_step / lpe_view_is_dead against the calls they stand for,
 * lpe_step / lpe_is_dead: the same status and state on every state x class of DFA sets
 * (every table index and past it, padding classes, classes out of range, wrap-around
 * state ids), of lazy sets (every state reached, foreign ids) and of an OSL set, and on
 * NULL arguments. Exits 1 on the first disagreement. Run by examples/c/build.sh.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>

#include "lpe.h"

static int failures = 0;

static void check(lpe_status s, const char *what) {
    if (s != LPE_OK) {
        fprintf(stderr, "%s: %s\n", what, lpe_status_message((uint32_t)s));
        exit(1);
    }
}

/* Steps taken by the table and by the fallback call, so that the test knows it ran both. */
struct counts {
    size_t table, fallback;
};

/* One state x class: inline and call agree on status and state, and on is_dead. */
static void agree(const char *set_name, const lpe_step_view *view, uint32_t state,
                  uint32_t cls, struct counts *n) {
    lpe_state inline_s = {state}, call_s = {state};
    lpe_class c = {cls};
    lpe_status inline_st = lpe_view_step(view, &inline_s, c);
    lpe_status call_st = lpe_step(view->set, &call_s, c);
    if (inline_st != call_st || inline_s.opaque != call_s.opaque) {
        if (failures++ < 10)
            fprintf(stderr,
                    "%s: state %" PRIu32 " class %" PRIu32 ": inline %d -> %" PRIu32
                    ", lpe_step %d -> %" PRIu32 "\n",
                    set_name, state, cls, (int)inline_st, inline_s.opaque, (int)call_st,
                    call_s.opaque);
    }
    if (cls < view->class_count && (uint32_t)(state + cls) < view->table_len)
        n->table++;
    else
        n->fallback++;
    lpe_state s = {state};
    bool inline_dead = true, call_dead = false;
    lpe_status a = lpe_view_is_dead(view, &s, &inline_dead);
    lpe_status b = lpe_is_dead(view->set, &s, &call_dead);
    if (a != b || inline_dead != call_dead) {
        if (failures++ < 10)
            fprintf(stderr, "%s: is_dead of state %" PRIu32 ": inline %d/%d, call %d/%d\n",
                    set_name, state, (int)a, (int)inline_dead, (int)b, (int)call_dead);
    }
}

/* Classes to try: every class, the padding up to the next power of two and past it, and
 * the largest ids. */
static void each_class(const char *set_name, const lpe_step_view *view, uint32_t state,
                       struct counts *n) {
    uint32_t classes = (uint32_t)view->class_count;
    for (uint32_t c = 0; c < 2 * classes + 2; c++) agree(set_name, view, state, c, n);
    agree(set_name, view, state, UINT32_MAX, n);
    agree(set_name, view, state, UINT32_MAX - 1, n);
}

static lpe_set *compile(size_t count, const char **exprs, uint32_t dialect,
                        const lpe_options *o) {
    static const char *names[] = {"a0", "a1", "a2", "a3", "a4", "a5", "a6", "a7"};
    lpe_set *set = NULL;
    lpe_error *err = NULL;
    if (lpe_set_compile(names, exprs, count, dialect, NULL, o, &set, &err)) {
        fprintf(stderr, "compile: %s\n", lpe_error_message(err));
        exit(1);
    }
    return set;
}

/* A DFA set: every table index (states and the ids between them), then ids past the
 * table and near UINT32_MAX, where `state + class` wraps. */
static void dfa_set(const char *set_name, lpe_set *set) {
    lpe_step_view view;
    check(lpe_set_step_view(set, &view), "lpe_set_step_view");
    struct counts n = {0, 0};
    if (view.table == NULL || view.table_len == 0) {
        fprintf(stderr, "%s: expected a DFA table\n", set_name);
        failures++;
        return;
    }
    for (size_t i = 0; i < view.table_len + 70; i++)
        each_class(set_name, &view, (uint32_t)i, &n);
    uint32_t far[] = {UINT32_MAX, UINT32_MAX - 1, UINT32_MAX - (uint32_t)view.class_count,
                      (uint32_t)view.table_len * 2};
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++)
        each_class(set_name, &view, far[i], &n);
    if (n.table == 0 || n.fallback == 0) {
        fprintf(stderr, "%s: only one branch ran (%zu table, %zu fallback)\n", set_name,
                n.table, n.fallback);
        failures++;
    }
    printf("%s: %zu classes, %zu table entries: %zu table steps, %zu fallbacks agree\n",
           set_name, view.class_count, view.table_len, n.table, n.fallback);
    lpe_set_free(set);
}

/* A lazy set: no table; every state reached from the start (breadth first, up to a
 * bound), then ids the set never handed out. */
static void lazy_set(const char *set_name, lpe_set *set) {
    lpe_step_view view;
    check(lpe_set_step_view(set, &view), "lpe_set_step_view");
    struct counts n = {0, 0};
    if (view.table != NULL || view.table_len != 0) {
        fprintf(stderr, "%s: a lazy set has no table\n", set_name);
        failures++;
    }
    enum { MAX_STATES = 400 };
    uint32_t seen[MAX_STATES];
    size_t count = 0;
    seen[count++] = view.start.opaque;
    for (size_t at = 0; at < count; at++) {
        each_class(set_name, &view, seen[at], &n);
        for (uint32_t c = 0; c < view.class_count; c++) {
            lpe_state s = {seen[at]};
            check(lpe_step(set, &s, (lpe_class){c}), "lpe_step");
            size_t k = 0;
            while (k < count && seen[k] != s.opaque) k++;
            if (k == count && count < MAX_STATES) seen[count++] = s.opaque;
        }
    }
    uint32_t foreign[] = {0, 987654, UINT32_MAX};
    for (size_t i = 0; i < sizeof foreign / sizeof foreign[0]; i++)
        each_class(set_name, &view, foreign[i], &n);
    printf("%s: %zu classes, lazy, %zu states: %zu steps agree\n", set_name,
           view.class_count, count, n.fallback);
    if (n.table != 0) failures++;
    lpe_set_free(set);
}

int main(void) {
    const char *basic[] = {"directDiffuse", "indirectDiffuse", "subsurface",
                           "directSpecular", "indirectSpecular", "transmissive",
                           "emissive", "caustics"};
    const char *labels[] = {"C<RD'floor'>.*<L.'key'>", "C.*D{2,3}[<L.>O]", "CS+L"};
    /* `^`: state 0 of the lazy set is not dead (the complement matches on). */
    const char *algebra[] = {"^(C.*D.*L)", "C.*L - CSL"};
    lpe_options lazy = lpe_options_default();
    lazy.dfa_budget = 0;

    dfa_set("basic", compile(8, basic, LPE_DIALECT_RENDERMAN, NULL));
    dfa_set("labels", compile(3, labels, LPE_DIALECT_RENDERMAN, NULL));
    dfa_set("algebra", compile(2, algebra, LPE_DIALECT_RENDERMAN, NULL));
    lpe_options osl = lpe_options_default();
    osl.osl_registered = "events=U;scatters=Y";
    const char *osl_rules[] = {"C<RD>L", "CDY+U", "C<R[^D]>*L"};
    dfa_set("osl", compile(3, osl_rules, LPE_DIALECT_OSL, &osl));
    lazy_set("basic lazy", compile(8, basic, LPE_DIALECT_RENDERMAN, &lazy));
    lazy_set("algebra lazy", compile(2, algebra, LPE_DIALECT_RENDERMAN, &lazy));

    /* NULL arguments: the same status as the calls. */
    lpe_set *set = compile(1, basic, LPE_DIALECT_RENDERMAN, NULL);
    lpe_step_view view;
    check(lpe_set_step_view(set, &view), "lpe_set_step_view");
    lpe_state s = view.start;
    lpe_class c0 = {0};
    bool dead;
    if (lpe_view_step(NULL, &s, c0) != LPE_ERR_NULL || lpe_view_step(&view, NULL, c0) !=
            LPE_ERR_NULL || lpe_view_is_dead(NULL, &s, &dead) != LPE_ERR_NULL ||
        lpe_view_is_dead(&view, NULL, &dead) != LPE_ERR_NULL ||
        lpe_view_is_dead(&view, &s, NULL) != LPE_ERR_NULL ||
        lpe_set_step_view(NULL, &view) != LPE_ERR_NULL ||
        lpe_set_step_view(set, NULL) != LPE_ERR_NULL) {
        fprintf(stderr, "NULL arguments: not LPE_ERR_NULL\n");
        failures++;
    }
    lpe_set_free(set);

    if (failures) {
        fprintf(stderr, "%d disagreements\n", failures);
        return 1;
    }
    printf("inline step and lpe_step agree\n");
    return 0;
}

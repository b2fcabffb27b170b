/* A step through the C ABI against a step from Rust, same set, same class sequences, same
 * run. Rows, each stepping the four paths of `cargo bench -p lpe-bench --bench step`
 * (30 vertices, the basic AOVs, classes computed beforehand) from the start state and
 * summing the final state ids:
 *   rust         AovSet::step_class in a Rust loop inside the library
 *                (lpe_bench_rust_loop, a bench-only export: the loop a renderer linking
 *                lpe directly runs)
 *   inline       the header's lpe_view_step, inlined into this loop
 *   lpe_step     one call per vertex
 *   lpe_step_n   one call per path
 * Each trial times every row in turn; the table gives per row the median over trials of
 * the time per 4 paths, and of its ratio to the rust row of the same trial. A second
 * block does the same on the set compiled lazily (dfa_budget 0), where the inline step
 * falls back to lpe_step. Exits 1 if the rows' final states disagree.
 *
 * Usage: examples/c/build/step_bench [REPS [TRIALS]]   (defaults 200000 and 15)
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime under -std=c99 */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "lpe.h"

/* Bench-only export of liblpe_capi (not in the header): steps the paths `reps` times
 * from Rust, adds the final state ids to *checksum, returns the nanoseconds taken. */
uint64_t lpe_bench_rust_loop(const lpe_set *set, const lpe_class *classes,
                             const size_t *lens, size_t path_count, uint64_t reps,
                             uint64_t *checksum);

enum { PATHS = 4, MAX_VERTICES = 16, ROWS = 4, MAX_TRIALS = 99 };

static const char *const PATH_TEXT[PATHS][MAX_VERTICES] = {
    {"C", "RD2'floor'", "RS1", "TS8", "TS8", "RD1", "L'key'"},
    {"C", "RS1", "RD1'wall'", "RD1", "RD1", "RD1", "O'glow'"},
    {"C", "TS8", "TS8", "RD2'floor'", "RS1", "RD1", "L'fill'"},
    {"C", "RD1", "RD1", "RD1", "RD1", "RS1", "RS1", "L"},
};

struct paths {
    lpe_class classes[PATHS * MAX_VERTICES]; /* concatenated */
    size_t lens[PATHS];
    size_t steps;
};

static const char *const ROW_NAME[ROWS] = {"rust AovSet::step_class", "inline lpe_view_step",
                                           "lpe_step per vertex", "lpe_step_n per path"};

static void check(lpe_status s, const char *what) {
    if (s != LPE_OK) {
        fprintf(stderr, "%s: %s\n", what, lpe_status_message((uint32_t)s));
        exit(1);
    }
}

static double now_ns(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

/* The C rows, one loop each (no per-path dispatch): the final states' sum. */
static uint64_t inline_rows(const lpe_step_view *shared, const struct paths *p,
                            uint64_t reps) {
    /* A local copy, as the README advises: nothing the loop stores can alias it. */
    const lpe_step_view view = *shared;
    uint64_t acc = 0;
    for (uint64_t r = 0; r < reps; r++) {
        const lpe_class *c = p->classes;
        for (int i = 0; i < PATHS; i++) {
            lpe_state s = view.start;
            for (size_t k = 0; k < p->lens[i]; k++) lpe_view_step(&view, &s, c[k]);
            acc += s.opaque;
            c += p->lens[i];
        }
    }
    return acc;
}

static uint64_t call_rows(const lpe_step_view *view, const struct paths *p, uint64_t reps) {
    const lpe_set *set = view->set;
    lpe_state start = view->start;
    uint64_t acc = 0;
    for (uint64_t r = 0; r < reps; r++) {
        const lpe_class *c = p->classes;
        for (int i = 0; i < PATHS; i++) {
            lpe_state s = start;
            for (size_t k = 0; k < p->lens[i]; k++) lpe_step(set, &s, c[k]);
            acc += s.opaque;
            c += p->lens[i];
        }
    }
    return acc;
}

static uint64_t call_n_rows(const lpe_step_view *view, const struct paths *p, uint64_t reps) {
    const lpe_set *set = view->set;
    lpe_state start = view->start;
    uint64_t acc = 0;
    for (uint64_t r = 0; r < reps; r++) {
        const lpe_class *c = p->classes;
        for (int i = 0; i < PATHS; i++) {
            lpe_state s = start;
            lpe_step_n(set, &s, c, p->lens[i]);
            acc += s.opaque;
            c += p->lens[i];
        }
    }
    return acc;
}

/* Runs row `row` `reps` times over the paths; returns nanoseconds, adds the final states
 * to *sum. */
static double run(int row, const lpe_step_view *view, const struct paths *p, uint64_t reps,
                  uint64_t *sum) {
    if (row == 0)
        return (double)lpe_bench_rust_loop(view->set, p->classes, p->lens, PATHS, reps, sum);
    double t0 = now_ns();
    uint64_t acc = row == 1   ? inline_rows(view, p, reps)
                   : row == 2 ? call_rows(view, p, reps)
                              : call_n_rows(view, p, reps);
    double ns = now_ns() - t0;
    *sum += acc;
    return ns;
}

/* Where the timed rows' sums go, so that no row's work is optimized away. */
static volatile uint64_t sink_out;

static int by_value(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *xs, int n) {
    qsort(xs, (size_t)n, sizeof *xs, by_value);
    return n % 2 ? xs[n / 2] : (xs[n / 2 - 1] + xs[n / 2]) / 2;
}

/* Benchmarks one set; returns 0 when every row reaches the same states. */
static int bench(const char *title, const lpe_set *set, uint64_t reps, int trials) {
    struct paths p;
    memset(&p, 0, sizeof p);
    for (int i = 0; i < PATHS; i++) {
        size_t n = 0;
        while (n < MAX_VERTICES && PATH_TEXT[i][n] != NULL) {
            check(lpe_classify_text(set, PATH_TEXT[i][n], &p.classes[p.steps + n]),
                  PATH_TEXT[i][n]);
            n++;
        }
        p.lens[i] = n;
        p.steps += n;
    }
    lpe_step_view view;
    check(lpe_set_step_view(set, &view), "lpe_set_step_view");

    /* One pass each: the rows must agree before their times mean anything. */
    uint64_t sums[ROWS];
    for (int row = 0; row < ROWS; row++) {
        sums[row] = 0;
        run(row, &view, &p, 1, &sums[row]);
        if (sums[row] != sums[0]) {
            fprintf(stderr, "%s: %s reaches other states than the rust row\n", title,
                    ROW_NAME[row]);
            return 1;
        }
    }

    static double ns[ROWS][MAX_TRIALS], ratio[ROWS][MAX_TRIALS];
    uint64_t sink = 0;
    for (int row = 0; row < ROWS; row++) run(row, &view, &p, reps / 10 + 1, &sink); /* warm */
    for (int t = 0; t < trials; t++) {
        for (int row = 0; row < ROWS; row++)
            ns[row][t] = run(row, &view, &p, reps, &sink) / (double)reps;
        for (int row = 0; row < ROWS; row++) ratio[row][t] = ns[row][t] / ns[0][t];
    }
    sink_out = sink;
    printf("%s (%zu steps per 4 paths, %llu reps, median of %d trials)\n", title, p.steps,
           (unsigned long long)reps, trials);
    printf("| row | ns per 4 paths | ns per step | vs rust (same trial) |\n");
    printf("|---|---|---|---|\n");
    for (int row = 0; row < ROWS; row++) {
        double m = median(ns[row], trials);
        printf("| %s | %.1f | %.2f | %.2fx |\n", ROW_NAME[row], m, m / (double)p.steps,
               median(ratio[row], trials));
    }
    return 0;
}

int main(int argc, char **argv) {
    uint64_t reps = argc > 1 ? strtoull(argv[1], NULL, 10) : 200000;
    int trials = argc > 2 ? atoi(argv[2]) : 15;
    if (reps == 0 || trials < 1 || trials > MAX_TRIALS) {
        fprintf(stderr, "usage: step_bench [REPS>0 [TRIALS 1-%d]]\n", MAX_TRIALS);
        return 2;
    }
    const char *names[] = {"directDiffuse", "indirectDiffuse",  "subsurface",  "directSpecular",
                           "indirectSpecular", "transmissive", "emissive"};
    const char *exprs[] = {"C<RD>[<L.>O]", "C<RD>.+[<L.>O]", "C<TD>.*[<L.>O]",
                           "C<RS>[<L.>O]", "C<RS>.+[<L.>O]", "C<TS>.*[<L.>O]",
                           "C[<L.>O]"};
    lpe_options lazy = lpe_options_default();
    lazy.dfa_budget = 0;
    const lpe_options *options[] = {NULL, &lazy};
    const char *titles[] = {"basic AOVs, DFA", "basic AOVs, lazy DFA (dfa_budget 0)"};
    int status = 0;
    for (int i = 0; i < 2; i++) {
        lpe_set *set = NULL;
        lpe_error *err = NULL;
        if (lpe_set_compile(names, exprs, 7, LPE_DIALECT_RENDERMAN, NULL, options[i], &set,
                            &err)) {
            fprintf(stderr, "%s\n", lpe_error_message(err));
            return 1;
        }
        status |= bench(titles[i], set, reps, trials);
        if (i == 0) printf("\n");
        lpe_set_free(set);
    }
    return status;
}

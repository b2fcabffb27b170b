/* The renderer loop of the lpe crate docs (lpe::matcher), in C: compile the AOVs once,
 * classify every material lobe, light and the camera once, take the set's step view,
 * then per path one inline lpe_view_step per vertex and lpe_matches at every light
 * sample.
 *
 * Build (see .ci/run):  cc -std=c99 -Icapi/include examples/c/render_loop.c \
 *                          target/release/liblpe_capi.a -lpthread -ldl -lm
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>

#include "lpe.h"

static void check(lpe_status s, const char *what) {
    if (s != LPE_OK) {
        fprintf(stderr, "%s: %s\n", what, lpe_status_message((uint32_t)s));
        exit(1);
    }
}

static lpe_class classify(const lpe_set *set, char type, char event, uint8_t lobe,
                          const char *label) {
    lpe_vertex v = {(uint8_t)type, (uint8_t)event, lobe, label};
    lpe_class c;
    check(lpe_classify(set, &v, &c), "lpe_classify");
    return c;
}

/* Prints the AOVs a light sample at state `s` lands in. */
static void print_hits(const lpe_set *set, const lpe_state *s, int bounce) {
    uint64_t mask[4];
    size_t count = 0;
    check(lpe_matches(set, s, mask, 4, &count), "lpe_matches");
    printf("bounce %d:", bounce);
    for (size_t i = 0; i < lpe_set_len(set); i++)
        if (mask[i / 64] >> (i % 64) & 1) printf(" %s", lpe_set_name(set, i));
    printf(" (%zu)\n", count);
}

int main(void) {
    /* Scene load: compile every AOV into one automaton. */
    const char *names[] = {"directDiffuse", "indirectDiffuse", "emissive", "caustics"};
    const char *exprs[] = {"directDiffuse", "indirectDiffuse", "emissive", "caustics"};
    lpe_set *set = NULL;
    lpe_error *err = NULL;
    if (lpe_set_compile(names, exprs, 4, LPE_DIALECT_RENDERMAN, NULL, NULL, &set, &err)) {
        fprintf(stderr, "%s\n", lpe_error_message(err));
        lpe_error_free(err);
        return 1;
    }
    printf("%zu AOVs, %zu warnings\n", lpe_set_len(set), lpe_set_warning_count(set));

    /* Classify every material lobe, light and the camera once. */
    lpe_class camera = classify(set, 'C', 0, 0, NULL);
    lpe_class floor_diffuse = classify(set, 'R', 'D', 2, "floor");
    lpe_class glass_specular = classify(set, 'T', 'S', 8, "glass");
    lpe_class key_light = classify(set, 'L', 0, 0, "key");

    /* The step view: the header's inline step reads the set's table through it. */
    lpe_step_view view;
    check(lpe_set_step_view(set, &view), "lpe_set_step_view");

    /* Per path: one step per vertex (inline, no call while the set's DFA answers); the
     * state is a plain value, copied to branch off a light sample at each bounce
     * (next-event estimation). */
    lpe_class bounces[] = {floor_diffuse, glass_specular};
    lpe_state s = view.start;
    check(lpe_view_step(&view, &s, camera), "lpe_view_step");
    for (int b = 0; b < 2; b++) {
        check(lpe_view_step(&view, &s, bounces[b]), "lpe_view_step");
        bool dead = false;
        check(lpe_view_is_dead(&view, &s, &dead), "lpe_view_is_dead");
        if (dead) break; /* no AOV can match any continuation */
        lpe_state sample = s;
        check(lpe_view_step(&view, &sample, key_light), "lpe_view_step");
        print_hits(set, &sample, b + 1);
    }

    /* Errors name the AOV and the byte. */
    const char *bad_names[] = {"ok", "key"};
    const char *bad_exprs[] = {"C.L", "C<L'key'>"};
    lpe_set *bad = NULL;
    lpe_status st = lpe_set_compile(bad_names, bad_exprs, 2, LPE_DIALECT_RENDERMAN, NULL,
                                    NULL, &bad, &err);
    printf("bad set: status %d, AOV %" PRId64 ", byte %" PRId64 ", set %s\n", (int)st,
           lpe_error_aov(err), lpe_error_position(err), bad ? "built" : "NULL");
    lpe_error_free(err);
    /* Out-of-range classes are refused, the state left alone. */
    lpe_class nowhere = {(uint32_t)lpe_set_class_count(set)};
    printf("foreign class: %s\n",
           lpe_status_message((uint32_t)lpe_view_step(&view, &s, nowhere)));
    lpe_set_free(set);
    return 0;
}

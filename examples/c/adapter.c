/* The external-matcher protocol (docs/protocol.md) over lpe's C ABI: what a renderer
 * team writes to put its own matcher under `lpe-check diff --external`. Here the matcher
 * is lpe itself, reached only through lpe.h, so the run tests the whole C path in both
 * dialects: compile (OSL: under the registered labels; under the renderer profile a
 * request names, through lpe_options.renderer), classify (RenderMan: from
 * vertex text; OSL: from each vertex's symbols, as an OSL renderer would), start,
 * step through a cache of the adapter's own, matches.
 *
 * The JSON reading is minimal on purpose: the requests come from lpe-check, one object
 * per line, so a small recursive reader of strings, numbers, arrays and objects does.
 *
 * Build (see .ci/run):  cc -std=c99 -Icapi/include examples/c/adapter.c \
 *                          target/release/liblpe_capi.a -lpthread -ldl -lm
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lpe.h"

/* ---- JSON: just what the requests use ------------------------------------------ */

typedef struct {
    const char *p;
    int ok;
} reader;

static void skip_ws(reader *r) {
    while (*r->p == ' ' || *r->p == '\t' || *r->p == '\r' || *r->p == '\n') r->p++;
}

static void put_utf8(char **o, unsigned long c) {
    char *q = *o;
    if (c < 0x80) {
        *q++ = (char)c;
    } else if (c < 0x800) {
        *q++ = (char)(0xC0 | c >> 6);
        *q++ = (char)(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        *q++ = (char)(0xE0 | c >> 12);
        *q++ = (char)(0x80 | (c >> 6 & 0x3F));
        *q++ = (char)(0x80 | (c & 0x3F));
    } else {
        *q++ = (char)(0xF0 | c >> 18);
        *q++ = (char)(0x80 | (c >> 12 & 0x3F));
        *q++ = (char)(0x80 | (c >> 6 & 0x3F));
        *q++ = (char)(0x80 | (c & 0x3F));
    }
    *o = q;
}

static unsigned long hex4(reader *r) {
    unsigned long v = 0;
    for (int i = 0; i < 4; i++) {
        char c = *r->p++;
        v <<= 4;
        if (c >= '0' && c <= '9') v |= (unsigned long)(c - '0');
        else if (c >= 'a' && c <= 'f') v |= (unsigned long)(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F') v |= (unsigned long)(c - 'A' + 10);
        else { r->ok = 0; return 0; }
    }
    return v;
}

/* A string value, decoded into a fresh NUL-terminated buffer (the caller frees it). */
static char *read_string(reader *r) {
    skip_ws(r);
    if (*r->p != '"') { r->ok = 0; return NULL; }
    r->p++;
    char *out = malloc(strlen(r->p) + 1), *o = out;
    while (r->ok && *r->p && *r->p != '"') {
        char c = *r->p++;
        if (c != '\\') { *o++ = c; continue; }
        c = *r->p++;
        switch (c) {
        case 'n': *o++ = '\n'; break;
        case 't': *o++ = '\t'; break;
        case 'r': *o++ = '\r'; break;
        case 'b': *o++ = '\b'; break;
        case 'f': *o++ = '\f'; break;
        case 'u': {
            unsigned long u = hex4(r);
            if (u >= 0xD800 && u < 0xDC00 && r->p[0] == '\\' && r->p[1] == 'u') {
                r->p += 2;
                u = 0x10000 + ((u - 0xD800) << 10) + (hex4(r) - 0xDC00);
            }
            put_utf8(&o, u);
            break;
        }
        default: *o++ = c; /* \" \\ \/ */
        }
    }
    if (*r->p != '"') r->ok = 0; else r->p++;
    *o = 0;
    return out;
}

static void skip_value(reader *r);

/* Calls `member` for every key of an object, the reader positioned at its value. */
static void read_object(reader *r, void (*member)(reader *, const char *, void *), void *ctx) {
    skip_ws(r);
    if (*r->p != '{') { r->ok = 0; return; }
    r->p++;
    skip_ws(r);
    if (*r->p == '}') { r->p++; return; }
    while (r->ok) {
        char *key = read_string(r);
        skip_ws(r);
        if (*r->p != ':') r->ok = 0; else r->p++;
        if (r->ok) member(r, key, ctx);
        free(key);
        skip_ws(r);
        if (*r->p == ',') { r->p++; continue; }
        if (*r->p == '}') { r->p++; return; }
        r->ok = 0;
    }
}

/* Calls `item` for every element of an array. */
static void read_array(reader *r, void (*item)(reader *, void *), void *ctx) {
    skip_ws(r);
    if (*r->p != '[') { r->ok = 0; return; }
    r->p++;
    skip_ws(r);
    if (*r->p == ']') { r->p++; return; }
    while (r->ok) {
        item(r, ctx);
        skip_ws(r);
        if (*r->p == ',') { r->p++; continue; }
        if (*r->p == ']') { r->p++; return; }
        r->ok = 0;
    }
}

static void skip_member(reader *r, const char *key, void *ctx) { (void)key; (void)ctx; skip_value(r); }
static void skip_item(reader *r, void *ctx) { (void)ctx; skip_value(r); }

static void skip_value(reader *r) {
    skip_ws(r);
    if (*r->p == '"') free(read_string(r));
    else if (*r->p == '{') read_object(r, skip_member, NULL);
    else if (*r->p == '[') read_array(r, skip_item, NULL);
    else if (strchr("-0123456789tfn", *r->p) && *r->p) {
        while (*r->p && !strchr(",}] \t\r\n", *r->p)) r->p++;
    } else r->ok = 0;
}

/* A JSON string literal on stdout. */
static void write_string(const char *s) {
    putchar('"');
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') printf("\\%c", c);
        else if (c < 0x20) printf("\\u%04x", c);
        else putchar(c);
    }
    putchar('"');
}

/* ---- the request ----------------------------------------------------------------- */

typedef struct {
    size_t n, cap;
    char **items;
} strings;

static void push(strings *s, char *x) {
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 16;
        s->items = realloc(s->items, s->cap * sizeof *s->items);
    }
    s->items[s->n++] = x;
}

static void clear(strings *s) {
    for (size_t i = 0; i < s->n; i++) free(s->items[i]);
    s->n = 0;
}

typedef struct {
    char *id, *op, *dialect, *renderer;
    strings names, exprs, paths, events, scatters;
} request;

static void aov_member(reader *r, const char *key, void *ctx) {
    request *q = ctx;
    if (!strcmp(key, "name")) push(&q->names, read_string(r));
    else if (!strcmp(key, "expr")) push(&q->exprs, read_string(r));
    else skip_value(r);
}

static void aov_item(reader *r, void *ctx) { read_object(r, aov_member, ctx); }
static void path_item(reader *r, void *ctx) { push(&((request *)ctx)->paths, read_string(r)); }
static void string_item(reader *r, void *ctx) { push(ctx, read_string(r)); }

static void registered_member(reader *r, const char *key, void *ctx) {
    request *q = ctx;
    if (!strcmp(key, "events")) read_array(r, string_item, &q->events);
    else if (!strcmp(key, "scatters")) read_array(r, string_item, &q->scatters);
    else skip_value(r);
}

static void request_member(reader *r, const char *key, void *ctx) {
    request *q = ctx;
    if (!strcmp(key, "id")) {
        /* Kept as text and echoed back as it came. */
        skip_ws(r);
        const char *start = r->p;
        skip_value(r);
        free(q->id);
        q->id = malloc((size_t)(r->p - start) + 1);
        memcpy(q->id, start, (size_t)(r->p - start));
        q->id[r->p - start] = 0;
    } else if (!strcmp(key, "op")) { free(q->op); q->op = read_string(r); }
    else if (!strcmp(key, "dialect")) { free(q->dialect); q->dialect = read_string(r); }
    else if (!strcmp(key, "renderer")) { free(q->renderer); q->renderer = read_string(r); }
    else if (!strcmp(key, "aovs")) read_array(r, aov_item, q);
    else if (!strcmp(key, "paths")) read_array(r, path_item, q);
    else if (!strcmp(key, "registered")) read_object(r, registered_member, q);
    else skip_value(r);
}

/* ---- matching through the C ABI -------------------------------------------------- */

static lpe_set *set = NULL;
static lpe_cache *cache = NULL; /* this thread's lazy-DFA cache for `set` */
static lpe_options options;
static int osl = 0; /* the dialect of `hello`: 1 for OSL */

/* The next RenderMan vertex of `*p` (vertices separated by spaces; labels in quotes may
 * hold spaces) into `vertex`, classified. 0 on a bad vertex. */
static int renderman_vertex(const char **p, char *vertex, lpe_class *c) {
    size_t n = 0;
    int quoted = 0;
    while (**p && (quoted || **p != ' ')) {
        if (**p == '\'') quoted = !quoted;
        vertex[n++] = *(*p)++;
    }
    vertex[n] = 0;
    return lpe_classify_text(set, vertex, c) == LPE_OK;
}

/* The next OSL vertex of `*p` (symbols separated by commas: `~` is NONE, a label is bare
 * or in quotes with '' for a quote), its symbols decoded into `buf`, classified from
 * them. 0 on a bad vertex. */
static int osl_vertex(const char **p, char *buf, const char **symbols, lpe_class *c) {
    size_t count = 0;
    for (;;) {
        const char *q = *p;
        if (*q == '~') {
            symbols[count++] = NULL; /* NONE, as OSL's null ustring */
            q++;
        } else {
            symbols[count++] = buf;
            if (*q == '\'') {
                for (q++;; q++) {
                    if (!*q) return 0;
                    if (*q == '\'' && q[1] != '\'') break;
                    if (*q == '\'') q++;
                    *buf++ = *q;
                }
                q++;
            } else {
                if (!*q || *q == ',' || *q == ' ') return 0;
                while (*q && !strchr(" ,~'", *q)) *buf++ = *q++;
            }
            *buf++ = 0;
        }
        *p = q;
        if (**p != ',') break;
        (*p)++;
    }
    if (**p && **p != ' ') return 0;
    return lpe_classify_symbols(set, symbols, count, c) == LPE_OK;
}

/* Steps a path written in the dialect's text form and prints the names of the AOVs it
 * lands in as a JSON array. 0 on a bad vertex. */
static int match_path(const char *path, uint64_t *mask, size_t words) {
    lpe_state s;
    if (lpe_start(set, &s) != LPE_OK) return 0;
    size_t len = strlen(path);
    char *buf = malloc(2 * len + 2);
    const char **symbols = malloc((len + 1) * sizeof *symbols);
    const char *p = path;
    int ok = 1;
    while (ok && *p) {
        if (*p == ' ') { p++; continue; }
        lpe_class c;
        ok = (osl ? osl_vertex(&p, buf, symbols, &c) : renderman_vertex(&p, buf, &c)) &&
             lpe_step_with(set, cache, &s, c) == LPE_OK;
    }
    free(buf);
    free(symbols);
    if (!ok || lpe_matches_with(set, cache, &s, mask, words, NULL) != LPE_OK) return 0;
    putchar('[');
    int first = 1;
    for (size_t i = 0; i < lpe_set_len(set); i++) {
        if (mask[i / 64] >> (i % 64) & 1) {
            if (!first) putchar(',');
            write_string(lpe_set_name(set, i));
            first = 0;
        }
    }
    putchar(']');
    return 1;
}

/* The `registered` lists as lpe_options.osl_registered text, `events=A,B;scatters=Y`
 * (NULL when nothing is registered); the caller frees it. */
static char *registration(const request *q) {
    if (!q->events.n && !q->scatters.n) return NULL;
    size_t len = sizeof "events=;scatters=";
    for (size_t i = 0; i < q->events.n; i++) len += strlen(q->events.items[i]) + 1;
    for (size_t i = 0; i < q->scatters.n; i++) len += strlen(q->scatters.items[i]) + 1;
    char *out = malloc(len), *o = out;
    const strings *lists[2] = {&q->events, &q->scatters};
    const char *keys[2] = {"events=", "scatters="};
    for (int k = 0; k < 2; k++) {
        if (!lists[k]->n) continue;
        if (o != out) *o++ = ';';
        o += sprintf(o, "%s", keys[k]);
        for (size_t i = 0; i < lists[k]->n; i++)
            o += sprintf(o, "%s%s", i ? "," : "", lists[k]->items[i]);
    }
    *o = 0;
    return out;
}

static void answer(request *q) {
    const char *id = q->id ? q->id : "null";
    if (!q->op) {
        printf("{\"id\":%s,\"ok\":false,\"unsupported\":\"no op\"}\n", id);
    } else if (!strcmp(q->op, "hello")) {
        int renderman = q->dialect && !strcmp(q->dialect, "renderman");
        osl = q->dialect && !strcmp(q->dialect, "osl");
        if (renderman || osl)
            printf("{\"id\":%s,\"ok\":true,\"protocol\":1,\"name\":\"lpe C ABI adapter\"}\n", id);
        else
            printf("{\"id\":%s,\"ok\":false,\"unsupported\":\"dialects: renderman, osl\"}\n", id);
    } else if (!strcmp(q->op, "compile")) {
        lpe_cache_free(cache);
        lpe_set_free(set);
        cache = NULL;
        set = NULL;
        lpe_error *err = NULL;
        size_t n = q->names.n < q->exprs.n ? q->names.n : q->exprs.n;
        lpe_options opts = options;
        char *registered = osl ? registration(q) : NULL;
        opts.osl_registered = registered;
        opts.renderer = q->renderer; /* NULL: none named */
        lpe_status st = lpe_set_compile((const char *const *)q->names.items,
                                        (const char *const *)q->exprs.items, n,
                                        osl ? LPE_DIALECT_OSL : LPE_DIALECT_RENDERMAN, NULL,
                                        &opts, &set, &err);
        free(registered);
        if (st == LPE_OK) cache = lpe_cache_new(set);
        if (st == LPE_OK) {
            printf("{\"id\":%s,\"ok\":true}\n", id);
        } else if (st == LPE_ERR_PARSE) {
            printf("{\"id\":%s,\"ok\":false,\"error\":{\"message\":", id);
            write_string(lpe_error_message(err));
            printf(",\"aov\":%" PRId64 ",\"position\":%" PRId64 "}}\n", lpe_error_aov(err),
                   lpe_error_position(err));
        } else {
            /* Over a size limit: not a language error, so not a disagreement. */
            printf("{\"id\":%s,\"ok\":false,\"unsupported\":", id);
            write_string(err ? lpe_error_message(err) : lpe_status_message((uint32_t)st));
            printf("}\n");
        }
        lpe_error_free(err);
    } else if (!strcmp(q->op, "match")) {
        size_t words = set ? lpe_set_mask_words(set) : 0;
        uint64_t *mask = calloc(words ? words : 1, sizeof *mask);
        printf("{\"id\":%s,\"ok\":true,\"matches\":[", id);
        for (size_t i = 0; i < q->paths.n; i++) {
            if (i) putchar(',');
            if (!set || !match_path(q->paths.items[i], mask, words)) printf("[]");
        }
        printf("]}\n");
        free(mask);
    } else if (!strcmp(q->op, "quit")) {
        printf("{\"id\":%s,\"ok\":true}\n", id);
    } else {
        printf("{\"id\":%s,\"ok\":false,\"unsupported\":", id);
        write_string(q->op);
        printf("}\n");
    }
    fflush(stdout);
}

int main(int argc, char **argv) {
    /* --dfa-budget BYTES: a renderer's compile options (0: step the bitset NFA). */
    options = lpe_options_default();
    for (int i = 1; i + 1 < argc; i++)
        if (!strcmp(argv[i], "--dfa-budget")) options.dfa_budget = (size_t)strtoull(argv[++i], NULL, 10);
    size_t cap = 1 << 16;
    char *line = malloc(cap);
    request q;
    memset(&q, 0, sizeof q);
    for (;;) {
        /* One request per line, however long. */
        size_t n = 0;
        int c;
        while ((c = getchar()) != EOF && c != '\n') {
            if (n + 1 == cap) line = realloc(line, cap *= 2);
            line[n++] = (char)c;
        }
        if (c == EOF && n == 0) break;
        line[n] = 0;
        clear(&q.names);
        clear(&q.exprs);
        clear(&q.paths);
        clear(&q.events);
        clear(&q.scatters);
        /* A renderer holds for the compile request that names it only. */
        free(q.renderer);
        q.renderer = NULL;
        reader r = {line, 1};
        read_object(&r, request_member, &q);
        if (!r.ok) {
            printf("{\"id\":null,\"ok\":false,\"unsupported\":\"unreadable request\"}\n");
            fflush(stdout);
            continue;
        }
        answer(&q);
        if (q.op && !strcmp(q.op, "quit")) break;
    }
    lpe_cache_free(cache);
    lpe_set_free(set);
    return 0;
}

/*
 * C test of the nyquist C API (capi/include/nyquist.h, libnyquist_capi.a).
 *
 * Built and run by capi/tests/c_program.rs (cc -std=c99 -Wall -Wextra -Werror), which
 * computes the same lines from the nyquist crate and compares them exactly. Each line is a
 * key followed by values: floats as the hex of their IEEE bits (exact), integers in decimal,
 * and status codes. The program exits 1 (with a message on stderr) if a call that must
 * succeed does not.
 */
#include "nyquist.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHECK(call)                                                                    \
    do {                                                                               \
        NyqStatus s_ = (call);                                                         \
        if (s_ != NYQ_OK) {                                                            \
            fprintf(stderr, "%s:%d: %s returned %d (%s)\n", __FILE__, __LINE__, #call, \
                    (int)s_, nyq_status_message((uint32_t)s_));                        \
            exit(1);                                                                   \
        }                                                                              \
    } while (0)

static void put_floats(const float *v, size_t n) {
    for (size_t i = 0; i < n; i++) {
        uint32_t u;
        memcpy(&u, &v[i], sizeof u);
        printf(" %08" PRIx32, u);
    }
    printf("\n");
}

static void put_double(double d) {
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    printf(" %016" PRIx64 "\n", u);
}

static void put_status(const char *key, NyqStatus s) { printf("err %s %d\n", key, (int)s); }

/* ---- radical inverses ------------------------------------------------------------------ */

static void radical(void) {
    static const uint32_t dims[] = {0, 0, 0, 1, 2, 7, 1023};
    static const uint64_t idx[] = {0, 1, 5, 5, 1234567, (uint64_t)1 << 40, UINT64_MAX};
    for (size_t i = 0; i < sizeof dims / sizeof dims[0]; i++) {
        uint32_t d = dims[i];
        uint64_t a = idx[i];
        float f;
        double g;
        CHECK(nyq_radical_inverse(d, a, &f));
        printf("ri %" PRIu32 " %" PRIu64, d, a);
        put_floats(&f, 1);
        CHECK(nyq_radical_inverse_f64(d, a, &g));
        printf("ri64 %" PRIu32 " %" PRIu64, d, a);
        put_double(g);
        CHECK(nyq_folded_radical_inverse(d, a, &f));
        printf("folded %" PRIu32 " %" PRIu64, d, a);
        put_floats(&f, 1);
        CHECK(nyq_folded_radical_inverse_f64(d, a, &g));
        printf("folded64 %" PRIu32 " %" PRIu64, d, a);
        put_double(g);
        CHECK(nyq_scrambled_radical_inverse(d, a, 42, &f));
        printf("scrambled %" PRIu32 " %" PRIu64, d, a);
        put_floats(&f, 1);
        CHECK(nyq_scrambled_radical_inverse_f64(d, a, 42, &g));
        printf("scrambled64 %" PRIu32 " %" PRIu64, d, a);
        put_double(g);
    }
    uint32_t p;
    CHECK(nyq_prime(0, &p));
    printf("prime 0 %" PRIu32 "\n", p);
    CHECK(nyq_prime(1023, &p));
    printf("prime 1023 %" PRIu32 "\n", p);
    float buf[8];
    CHECK(nyq_fill_radical_inverse(3, 1000, buf, 8));
    printf("fill_ri 3 1000");
    put_floats(buf, 8);
    uint64_t inv;
    CHECK(nyq_inverse_radical_inverse(1, 5, 2, &inv));
    printf("inverse_ri 1 5 2 %" PRIu64 "\n", inv);
}

/* ---- sequences ------------------------------------------------------------------------- */

static void sequences(void) {
    const NyqSequence seqs[] = {
        {NYQ_SEQ_VAN_DER_CORPUT, 1, 0, 0, 0},  {NYQ_SEQ_HALTON, 3, 0, 0, 0},
        {NYQ_SEQ_HALTON_ZAREMBA, 3, 0, 0, 0},  {NYQ_SEQ_HALTON_SCRAMBLED, 3, 0, 42, 0},
        {NYQ_SEQ_HAMMERSLEY, 3, 16, 0, 0},     {NYQ_SEQ_HAMMERSLEY_ZAREMBA, 2, 16, 0, 0},
        {NYQ_SEQ_SOBOL, 4, 0, 0, 0},           {NYQ_SEQ_SOBOL_SCRAMBLED, 4, 0, 7, 0},
        {NYQ_SEQ_ZERO_TWO, 2, 0, 0, 0},        {NYQ_SEQ_ZERO_TWO_SCRAMBLED, 2, 0, 9, 0},
    };
    static const uint64_t idx[] = {0, 1, 7, 13, 0};
    for (size_t s = 0; s < sizeof seqs / sizeof seqs[0]; s++) {
        const NyqSequence *q = &seqs[s];
        for (size_t i = 0; i < 4; i++) {
            float v[8];
            for (uint32_t d = 0; d < q->dims; d++) {
                CHECK(nyq_sequence_sample(q, idx[i], d, &v[d]));
            }
            printf("seq %" PRIu32 " %" PRIu64, q->kind, idx[i]);
            put_floats(v, q->dims);
        }
        double g;
        CHECK(nyq_sequence_sample_f64(q, 13, q->dims - 1, &g));
        printf("seq64 %" PRIu32 " 13", q->kind);
        put_double(g);
        float buf[16]; /* four points of up to four dimensions */
        uint64_t n = 0;
        size_t len = 4 * (size_t)q->dims;
        if (len > sizeof buf / sizeof buf[0]) {
            fprintf(stderr, "seqfill: %zu floats do not fit the buffer\n", len);
            exit(1);
        }
        CHECK(nyq_sequence_fill(q, 5, q->dims, buf, len, &n));
        printf("seqfill %" PRIu32 " %" PRIu64, q->kind, n);
        put_floats(buf, len);
        CHECK(nyq_sequence_point_count(q, &n));
        printf("seqcount %" PRIu32 " %" PRIu64 "\n", q->kind, n);
    }
    /* The Halton functions: the last three of 300 dimensions, and four points of three. */
    static const uint64_t far[] = {0, 13, 4000000000u, UINT64_MAX};
    for (size_t i = 0; i < 4; i++) {
        float v[3];
        for (uint32_t d = 0; d < 3; d++) {
            CHECK(nyq_halton_sample(300, far[i], 297 + d, &v[d]));
        }
        printf("halton %" PRIu64, far[i]);
        put_floats(v, 3);
    }
    float hb[12];
    uint64_t hn = 0;
    CHECK(nyq_halton_fill(5, 3, hb, 12, &hn));
    printf("haltonfill %" PRIu64, hn);
    put_floats(hb, 12);
}

/* ---- stratify -------------------------------------------------------------------------- */

static void stratify(void) {
    float buf[16];
    CHECK(nyq_stratified_1d(buf, 7, true, 3));
    printf("strat1d jittered");
    put_floats(buf, 7);
    CHECK(nyq_stratified_1d(buf, 4, false, 3));
    printf("strat1d centred");
    put_floats(buf, 4);
    CHECK(nyq_stratified_2d(buf, 12, 3, 2, true, 5));
    printf("strat2d jittered");
    put_floats(buf, 12);
    uint32_t n = 0;
    CHECK(nyq_latin_hypercube(buf, 15, 3, 2, &n));
    printf("lhs %" PRIu32, n);
    put_floats(buf, 15);
    for (int i = 0; i < 6; i++) {
        buf[i] = (float)i;
    }
    CHECK(nyq_shuffle(buf, 6, 3, 2, 4));
    printf("shuffle");
    put_floats(buf, 6);
}

/* ---- samplers -------------------------------------------------------------------------- */

/* Prints what sampler `s` gives (under `label`, `seed`) and destroys it. */
static void sampler_values(const char *label, uint64_t seed, NyqSampler *s) {
    uint32_t spp = 0;
    CHECK(nyq_sampler_samples_per_pixel(s, &spp));
    float v[8];
    CHECK(nyq_sampler_start_pixel_sample(s, 3, 5, 2, 0));
    CHECK(nyq_sampler_get_pixel_2d(s, &v[0]));
    CHECK(nyq_sampler_get_1d(s, &v[2]));
    CHECK(nyq_sampler_get_2d(s, &v[3]));
    printf("sampler %s %" PRIu64 " %" PRIu32, label, seed, spp);
    put_floats(v, 5);
    NyqSampler *c = NULL;
    CHECK(nyq_sampler_clone(s, &c));
    CHECK(nyq_sampler_start_pixel_sample(c, 9, 2, 11, 6));
    CHECK(nyq_sampler_get_array_1d(c, &v[0], 4));
    CHECK(nyq_sampler_get_array_2d(c, &v[4], 4));
    printf("arrays %s %" PRIu64, label, seed);
    put_floats(v, 8);
    NyqCameraSample cs;
    CHECK(nyq_sampler_camera_sample(s, 7, 1, 3, &cs));
    printf("camera %s %" PRIu64, label, seed);
    float cv[5] = {cs.p_film[0], cs.p_film[1], cs.lens[0], cs.lens[1], cs.time};
    put_floats(cv, 5);
    nyq_sampler_destroy(c);
    nyq_sampler_destroy(s);
}

static void samplers(void) {
    static const char *names[] = {"random",     "uniform",  "stratified",
                                  "halton",     "hammersley", "zero-two",
                                  "sobol",      "best-candidate", "adaptive",
                                  "owen-sobol", "owen-sobol-bn", "zsobol", "pmj02",
                                  "pmj02-bn", "bluenoise-dithered", "fibonacci",
                                  "r2", "korobov", "lattice-bn"};
    static const uint64_t seeds[] = {0, 7};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        for (size_t j = 0; j < 2; j++) {
            NyqSampler *s = NULL;
            CHECK(nyq_sampler_create(names[k], 16, 16, 16, seeds[j], &s));
            sampler_values(names[k], seeds[j], s);
        }
    }
    /* The per-kind constructor, which must give the named sampler's values. */
    for (size_t j = 0; j < 2; j++) {
        NyqSampler *s = NULL;
        CHECK(nyq_sampler_create_owen_sobol(16, 16, 16, seeds[j], &s));
        sampler_values("owen-sobol-by-kind", seeds[j], s);
    }
}

/* ---- filters --------------------------------------------------------------------------- */

static const float probes[][2] = {{0.0f, 0.0f}, {0.3f, -1.1f}, {1.7f, 0.2f}, {-0.45f, 0.05f}};

static void filter_values(const char *label, const NyqFilter *f) {
    float r[2], integral, w[3 * 4];
    CHECK(nyq_filter_radius(f, r));
    CHECK(nyq_filter_integral(f, &integral));
    for (size_t i = 0; i < 4; i++) {
        CHECK(nyq_filter_eval(f, probes[i][0], probes[i][1], &w[3 * i]));
        CHECK(nyq_filter_lookup(f, NYQ_INTERP_NEAREST, probes[i][0], probes[i][1], &w[3 * i + 1]));
        CHECK(nyq_filter_lookup(f, NYQ_INTERP_LINEAR, probes[i][0], probes[i][1], &w[3 * i + 2]));
    }
    printf("filter %s", label);
    put_floats(r, 2);
    printf("integral %s", label);
    put_floats(&integral, 1);
    printf("weights %s", label);
    put_floats(w, 12);
    NyqFilterSample fs;
    float pdf;
    CHECK(nyq_filter_sample(f, 0.3f, 0.7f, &fs));
    CHECK(nyq_filter_pdf(f, fs.offset[0], fs.offset[1], &pdf));
    float sv[4] = {fs.offset[0], fs.offset[1], fs.weight, pdf};
    printf("fsample %s", label);
    put_floats(sv, 4);
}

typedef struct Cone {
    float scale;
    int calls;
} Cone;

/* A plugin filter: a scaled cone of radius 1.5, zero outside. */
static float cone_eval(void *user, float x, float y) {
    Cone *c = (Cone *)user;
    c->calls++;
    float v = c->scale * (1.0f - (x * x + y * y) / 2.25f);
    return v > 0.0f ? v : 0.0f;
}

static void filters(void) {
    static const char *specs[] = {"box", "triangle", "gaussian:sigma=0.5",
                                  "mitchell:b=0.5,c=0.25", "lanczos"};
    for (size_t i = 0; i < sizeof specs / sizeof specs[0]; i++) {
        NyqFilter *f = NULL;
        CHECK(nyq_filter_create(specs[i], &f));
        filter_values(specs[i], f);
        nyq_filter_destroy(f);
    }
    Cone cone = {2.0f, 0};
    NyqFilter *f = NULL;
    CHECK(nyq_filter_create_callback(cone_eval, &cone, 1.5f, 1.5f, &f));
    int calls = cone.calls;
    filter_values("cone", f);
    /* Tabulated once: lookups never call back. */
    printf("cone calls after lookups %s\n", cone.calls == calls && calls > 0 ? "unchanged" : "CHANGED");
    nyq_filter_destroy(f);
}

/* ---- pixel statistics ------------------------------------------------------------------ */

static void put_doubles(const double *v, size_t n) {
    for (size_t i = 0; i < n; i++) {
        uint64_t u;
        memcpy(&u, &v[i], sizeof u);
        printf(" %016" PRIx64, u);
    }
    printf("\n");
}

/* Sample k of pixel p: filter weight and value, exact in binary so Rust forms the same. */
static void stats_sample(int p, int k, double *weight, double value[3]) {
    *weight = (double)((k * 3 + p) % 5) / 4.0 - 0.25;
    value[0] = (double)((k * 7 + p) % 11) / 8.0;
    value[1] = 2.0 - value[0];
    value[2] = (double)(k % 3);
}

/* Four pixels, 16 samples each, added by two "threads" (samples 0..9 and 9..16) and merged,
 * the way a renderer with its own film would keep them. */
static void pixel_stats(void) {
    NyqPixelStats a[4], b[4];
    memset(a, 0, sizeof a);
    memset(b, 0, sizeof b);
    for (int p = 0; p < 4; p++) {
        for (int k = 0; k < 16; k++) {
            double w, v[3];
            stats_sample(p, k, &w, v);
            CHECK(nyq_pixel_stats_add(k < 9 ? &a[p] : &b[p], (uint64_t)k, w, v));
        }
        CHECK(nyq_pixel_stats_merge(&a[p], &b[p]));
        const NyqPixelStats *s = &a[p];
        printf("stats %d", p);
        double fields[15];
        memcpy(fields, s->sum, sizeof s->sum);
        fields[3] = s->weight;
        fields[4] = s->weight2_sum;
        memcpy(fields + 5, s->mean, sizeof s->mean);
        memcpy(fields + 8, s->deviation_sum, sizeof s->deviation_sum);
        memcpy(fields + 11, s->half_b_sum, sizeof s->half_b_sum);
        fields[14] = s->half_b_weight;
        put_doubles(fields, 15);
        NyqEstimate e;
        CHECK(nyq_pixel_stats_estimate(s, &e));
        printf("estimate %d %d %d", p, (int)e.has_variance, (int)e.has_halves);
        double est[12];
        memcpy(est, e.value, sizeof e.value);
        memcpy(est + 3, e.variance, sizeof e.variance);
        memcpy(est + 6, e.half_a, sizeof e.half_a);
        memcpy(est + 9, e.half_b, sizeof e.half_b);
        put_doubles(est, 12);
        double r[2];
        CHECK(nyq_pixel_stats_relative_error(s, NYQ_ERROR_HALVES, 0.01, &r[0]));
        CHECK(nyq_pixel_stats_relative_error(s, NYQ_ERROR_VARIANCE, 0.01, &r[1]));
        printf("relerr %d", p);
        put_doubles(r, 2);
    }
    uint32_t h[8];
    for (uint64_t i = 0; i < 8; i++) {
        CHECK(nyq_sample_half(i * 5 + ((uint64_t)1 << 40), &h[i]));
    }
    printf("halves");
    for (int i = 0; i < 8; i++) {
        printf(" %" PRIu32, h[i]);
    }
    printf("\n");
    /* Domains: an owen-sobol sample's domain, four light samples split from it, a branch. */
    NyqSampler *os = NULL;
    NyqDomain root, sub;
    float dv[2 * 4 + 2];
    CHECK(nyq_sampler_create("owen-sobol", 64, 64, 16, 7, &os));
    CHECK(nyq_sampler_start_pixel_sample(os, 3, 5, 2, 0));
    CHECK(nyq_sampler_domain(os, &root));
    for (uint32_t k = 0; k < 4; k++) {
        CHECK(nyq_domain_split(root, 1, 4, k, &sub));
        CHECK(nyq_domain_get_2d(sub, 0, &dv[2 * k]));
    }
    CHECK(nyq_domain_branch(root, 2, &sub));
    CHECK(nyq_domain_get_1d(sub, 1030, &dv[8]));
    CHECK(nyq_domain_chain(root, 3, 1, &sub));
    CHECK(nyq_domain_get_1d(sub, 0, &dv[9]));
    printf("domain");
    put_floats(dv, 10);
    put_status("domain_random", nyq_sampler_domain(NULL, &root));
    nyq_sampler_destroy(os);
    NyqPixelStats bad = a[0];
    bad.weight2_sum = -1.0;
    double v[3] = {1.0, 1.0, 1.0}, r;
    put_status("stats_nan_weight", nyq_pixel_stats_add(&a[0], 0, NAN, v));
    put_status("stats_null_value", nyq_pixel_stats_add(&a[0], 0, 1.0, NULL));
    put_status("stats_bad_struct", nyq_pixel_stats_merge(&a[0], &bad));
    put_status("stats_bad_kind", nyq_pixel_stats_relative_error(&a[0], 7, 0.0, &r));
    put_status("stats_negative_floor", nyq_pixel_stats_relative_error(&a[0], 0, -1.0, &r));
}

/* ---- error codes ----------------------------------------------------------------------- */

/* nyq_blue_tile: each blue-noise sampler's tile, a few entries, whether its keys are a
   permutation of 0 .. 16383, whether the entry past the tile was left alone, and the statuses
   of bad calls. */
static uint32_t blue_tile_buf[NYQ_BLUE_TILE_ENTRIES + 1];
static unsigned char blue_key_seen[NYQ_BLUE_TILE_ENTRIES];

static void blue_tiles(void) {
    const char *names[4] = {"owen-sobol-bn", "pmj02-bn", "lattice-bn", "LATTICE-BN"};
    for (int k = 0; k < 4; ++k) {
        blue_tile_buf[NYQ_BLUE_TILE_ENTRIES] = 0xdeadbeefu;
        CHECK(nyq_blue_tile(names[k], blue_tile_buf, NYQ_BLUE_TILE_ENTRIES + 1));
        memset(blue_key_seen, 0, sizeof blue_key_seen);
        int permutation = 1;
        for (size_t i = 0; i < NYQ_BLUE_TILE_ENTRIES; ++i) {
            uint32_t key = blue_tile_buf[i] >> 8;
            if (key >= NYQ_BLUE_TILE_ENTRIES || blue_key_seen[key]) permutation = 0;
            else blue_key_seen[key] = 1;
        }
        printf("blue %s %" PRIu32 " %" PRIu32 " %" PRIu32 " %" PRIu32 " %d %d\n", names[k],
               blue_tile_buf[0], blue_tile_buf[127], blue_tile_buf[77 * 128 + 5],
               blue_tile_buf[NYQ_BLUE_TILE_ENTRIES - 1], permutation,
               blue_tile_buf[NYQ_BLUE_TILE_ENTRIES] == 0xdeadbeefu);
    }
    put_status("blue_null_name", nyq_blue_tile(NULL, blue_tile_buf, NYQ_BLUE_TILE_ENTRIES));
    put_status("blue_null_out", nyq_blue_tile("pmj02-bn", NULL, NYQ_BLUE_TILE_ENTRIES));
    put_status("blue_bad_name", nyq_blue_tile("owen-sobol", blue_tile_buf, NYQ_BLUE_TILE_ENTRIES));
    put_status("blue_short", nyq_blue_tile("pmj02-bn", blue_tile_buf, NYQ_BLUE_TILE_ENTRIES - 1));
    put_status("blue_zero", nyq_blue_tile("pmj02-bn", blue_tile_buf, 0));
}

static int ignore_eval_calls;
static float never_called(void *user, float x, float y) {
    (void)user;
    (void)x;
    (void)y;
    ignore_eval_calls++;
    return 1.0f;
}

static void errors(void) {
    float f = 0.0f, buf[8];
    uint64_t n64;
    uint32_t n32;
    put_status("ri_null_out", nyq_radical_inverse(0, 1, NULL));
    put_status("ri_dim_1024", nyq_radical_inverse(1024, 1, &f));
    put_status("ri64_null_out", nyq_radical_inverse_f64(0, 1, NULL));
    put_status("scrambled_dim", nyq_scrambled_radical_inverse(5000, 1, 1, &f));
    put_status("fill_ri_zero", nyq_fill_radical_inverse(0, 0, buf, 0));
    put_status("fill_ri_null", nyq_fill_radical_inverse(0, 0, NULL, 4));

    NyqSequence halton = {NYQ_SEQ_HALTON, 2, 0, 0, 0};
    NyqSequence bad_kind = {99, 2, 0, 0, 0};
    NyqSequence zero_dims = {NYQ_SEQ_SOBOL, 0, 0, 0, 0};
    NyqSequence sobol_big = {NYQ_SEQ_SOBOL, 2000, 0, 0, 0};
    NyqSequence hammersley = {NYQ_SEQ_HAMMERSLEY, 2, 16, 0, 0};
    NyqSequence hammersley0 = {NYQ_SEQ_HAMMERSLEY, 2, 0, 0, 0};
    NyqSequence vdc2 = {NYQ_SEQ_VAN_DER_CORPUT, 2, 0, 0, 0};
    put_status("seq_null_seq", nyq_sequence_sample(NULL, 0, 0, &f));
    put_status("seq_null_out", nyq_sequence_sample(&halton, 0, 0, NULL));
    put_status("seq_bad_kind", nyq_sequence_sample(&bad_kind, 0, 0, &f));
    put_status("seq_zero_dims", nyq_sequence_sample(&zero_dims, 0, 0, &f));
    put_status("seq_sobol_2000", nyq_sequence_sample(&sobol_big, 1ull << 40, 1500, &f));
    put_status("seq_dim_past", nyq_sequence_sample(&halton, 0, 2, &f));
    put_status("seq_index_past", nyq_sequence_sample(&hammersley, 16, 0, &f));
    put_status("seq_hammersley_n0", nyq_sequence_sample(&hammersley0, 0, 0, &f));
    put_status("seq_vdc_dims2", nyq_sequence_sample(&vdc2, 0, 0, &f));
    put_status("seq64_null", nyq_sequence_sample_f64(&halton, 0, 0, NULL));
    put_status("fill_zero_len", nyq_sequence_fill(&halton, 0, 2, buf, 0, &n64));
    put_status("fill_odd_len", nyq_sequence_fill(&halton, 0, 2, buf, 5, &n64));
    put_status("fill_null_written", nyq_sequence_fill(&halton, 0, 2, buf, 4, NULL));
    put_status("fill_dims0", nyq_sequence_fill(&halton, 0, 0, buf, 4, &n64));
    put_status("fill_dims_past", nyq_sequence_fill(&halton, 0, 3, buf, 6, &n64));
    put_status("fill_past_end", nyq_sequence_fill(&hammersley, 14, 2, buf, 8, &n64));

    put_status("strat1d_null", nyq_stratified_1d(NULL, 4, true, 0));
    put_status("strat1d_zero", nyq_stratified_1d(buf, 0, true, 0));
    put_status("strat2d_len", nyq_stratified_2d(buf, 8, 3, 2, true, 0));
    put_status("strat2d_nx0", nyq_stratified_2d(buf, 8, 0, 2, true, 0));
    put_status("lhs_dims0", nyq_latin_hypercube(buf, 8, 0, 0, &n32));
    put_status("lhs_len", nyq_latin_hypercube(buf, 7, 3, 0, &n32));
    put_status("lhs_null_written", nyq_latin_hypercube(buf, 6, 3, 0, NULL));
    put_status("shuffle_long", nyq_shuffle(buf, 8, 3, 2, 0));
    put_status("shuffle_short", nyq_shuffle(buf, 4, 3, 2, 0));

    NyqSampler *s = NULL;
    put_status("sampler_bad_name", nyq_sampler_create("no-such-sampler", 8, 8, 4, 0, &s));
    put_status("sampler_null_name", nyq_sampler_create(NULL, 8, 8, 4, 0, &s));
    put_status("sampler_null_out", nyq_sampler_create("random", 8, 8, 4, 0, NULL));
    put_status("sampler_spp0", nyq_sampler_create("random", 8, 8, 0, 0, &s));
    put_status("sampler_width0", nyq_sampler_create("sobol", 0, 8, 4, 0, &s));
    put_status("sampler_above_limit", nyq_sampler_create("best-candidate", 8, 8, 5000, 0, &s));
    put_status("sampler_bad_utf8", nyq_sampler_create("\xff", 8, 8, 4, 0, &s));
    put_status("sampler_null_handle", nyq_sampler_get_1d(NULL, &f));
    put_status("sampler_start_null", nyq_sampler_start_pixel_sample(NULL, 0, 0, 0, 0));
    CHECK(nyq_sampler_create("random", 8, 8, 4, 0, &s));
    put_status("sampler_get2d_null_out", nyq_sampler_get_2d(s, NULL));
    put_status("sampler_array2d_odd", nyq_sampler_get_array_2d(s, buf, 3));
    put_status("sampler_array1d_zero", nyq_sampler_get_array_1d(s, buf, 0));
    put_status("sampler_report_zero", nyq_sampler_report(s, 0, 0, 0, buf, 0));
    nyq_sampler_destroy(s);
    nyq_sampler_destroy(NULL);

    NyqFilter *flt = NULL;
    put_status("filter_bad_number", nyq_filter_create("mitchell:b=x", &flt));
    put_status("filter_unknown", nyq_filter_create("no-such-filter", &flt));
    put_status("filter_empty", nyq_filter_create("", &flt));
    put_status("filter_bad_radius", nyq_filter_create("box:radius=-1", &flt));
    put_status("filter_null_spec", nyq_filter_create(NULL, &flt));
    put_status("filter_null_out", nyq_filter_create("box", NULL));
    put_status("callback_null_eval", nyq_filter_create_callback(NULL, NULL, 1.0f, 1.0f, &flt));
    put_status("callback_nan_radius", nyq_filter_create_callback(never_called, NULL, NAN, 1.0f, &flt));
    put_status("callback_zero_radius", nyq_filter_create_callback(never_called, NULL, 1.0f, 0.0f, &flt));
    put_status("callback_huge_radius", nyq_filter_create_callback(never_called, NULL, 2000.0f, 1.0f, &flt));
    printf("callback_rejected_calls %d\n", ignore_eval_calls);
    CHECK(nyq_filter_create("box", &flt));
    put_status("lookup_bad_interp", nyq_filter_lookup(flt, 5, 0.0f, 0.0f, &f));
    put_status("lookup_null_out", nyq_filter_lookup(flt, NYQ_INTERP_LINEAR, 0.0f, 0.0f, NULL));
    put_status("eval_null_filter", nyq_filter_eval(NULL, 0.0f, 0.0f, &f));
    put_status("sample_null_out", nyq_filter_sample(flt, 0.5f, 0.5f, NULL));
    nyq_filter_destroy(flt);
    nyq_filter_destroy(NULL);

    printf("message %s\n", nyq_status_message(NYQ_ERR_PARSE));
    printf("message %s\n", nyq_status_message(1000));
    printf("version %s\n", nyq_version());
}

int main(void) {
    radical();
    sequences();
    stratify();
    samplers();
    filters();
    pixel_stats();
    blue_tiles();
    errors();
    printf("done\n");
    return 0;
}

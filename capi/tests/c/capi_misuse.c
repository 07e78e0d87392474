/* Misuses the nyquist C API on purpose: null handles and out-pointers, zero and wrong lengths,
 * misaligned buffers, out-of-range enums and specs, and a double destroy through the documented
 * guard (destroy, set the handle to NULL, destroy again: null is a no-op). Every call must return
 * the documented status and leave its outputs untouched; built with -fsanitize=address,undefined
 * the run must produce no sanitizer report. Prints "misuse ok" and exits 0 when every check
 * holds; otherwise prints the failing check and exits 1. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "nyquist.h"

static int failures = 0;

#define EXPECT(call, want)                                                                    \
    do {                                                                                      \
        NyqStatus got_ = (call);                                                              \
        if (got_ != (want)) {                                                                 \
            printf("FAIL line %d: %s returned %d, want %d\n", __LINE__, #call, (int)got_,     \
                   (int)(want));                                                              \
            failures++;                                                                       \
        }                                                                                     \
    } while (0)

#define UNTOUCHED(cond)                                                                       \
    do {                                                                                      \
        if (!(cond)) {                                                                        \
            printf("FAIL line %d: output written on error: %s\n", __LINE__, #cond);           \
            failures++;                                                                       \
        }                                                                                     \
    } while (0)

static float zero_filter(void *user, float x, float y) {
    (void)user;
    (void)x;
    (void)y;
    return 0.0f;
}

int main(void) {
    /* Storage for misaligned float pointers: one byte past a float boundary. */
    union {
        float f[64];
        unsigned char bytes[256];
    } store;
    memset(&store, 0, sizeof store);
    float *misaligned = (float *)(void *)(store.bytes + 1);
    float buf[64];
    float x = -1.0f;
    double d = -1.0;
    uint32_t u = 12345u;
    uint64_t written = 777u;

    /* Null out-pointers and handles. */
    EXPECT(nyq_radical_inverse(0, 1, NULL), NYQ_ERR_NULL);
    EXPECT(nyq_radical_inverse_f64(0, 1, NULL), NYQ_ERR_NULL);
    EXPECT(nyq_prime(0, NULL), NYQ_ERR_NULL);
    EXPECT(nyq_filter_create(NULL, NULL), NYQ_ERR_NULL);
    EXPECT(nyq_filter_eval(NULL, 0.0f, 0.0f, &x), NYQ_ERR_NULL);
    EXPECT(nyq_filter_integral(NULL, &x), NYQ_ERR_NULL);
    EXPECT(nyq_filter_create_callback(NULL, NULL, 1.0f, 1.0f, NULL), NYQ_ERR_NULL);
    EXPECT(nyq_sampler_get_1d(NULL, &x), NYQ_ERR_NULL);
    EXPECT(nyq_sampler_samples_per_pixel(NULL, &u), NYQ_ERR_NULL);
    EXPECT(nyq_sampler_clone(NULL, NULL), NYQ_ERR_NULL);
    EXPECT(nyq_sequence_sample(NULL, 0, 0, &x), NYQ_ERR_NULL);
    EXPECT(nyq_sequence_fill(NULL, 0, 2, buf, 64, &written), NYQ_ERR_NULL);
    UNTOUCHED(x == -1.0f && u == 12345u && written == 777u);
    nyq_filter_destroy(NULL); /* documented no-ops */
    nyq_sampler_destroy(NULL);

    /* Zero and wrong lengths. */
    EXPECT(nyq_fill_radical_inverse(0, 0, buf, 0), NYQ_ERR_ZERO_SIZE);
    EXPECT(nyq_stratified_1d(buf, 0, true, 1), NYQ_ERR_ZERO_SIZE);
    EXPECT(nyq_stratified_2d(buf, 7, 2, 2, true, 1), NYQ_ERR_BUFFER); /* 2 × 2 points need 8 */
    NyqSequence halton = {NYQ_SEQ_HALTON, 2, 0, 0, 0};
    EXPECT(nyq_sequence_fill(&halton, 0, 2, buf, 3, &written), NYQ_ERR_BUFFER); /* not a multiple */
    UNTOUCHED(written == 777u);

    /* Misaligned buffers and out-pointers. */
    EXPECT(nyq_radical_inverse(0, 1, misaligned), NYQ_ERR_BUFFER);
    EXPECT(nyq_radical_inverse_f64(0, 1, (double *)(void *)(store.bytes + 4)), NYQ_ERR_BUFFER);
    EXPECT(nyq_fill_radical_inverse(0, 0, misaligned, 8), NYQ_ERR_BUFFER);
    EXPECT(nyq_stratified_1d(misaligned, 8, true, 1), NYQ_ERR_BUFFER);
    EXPECT(nyq_sequence_fill(&halton, 0, 2, misaligned, 8, &written), NYQ_ERR_BUFFER);
    for (size_t i = 0; i < sizeof store.bytes; i++) {
        if (store.bytes[i] != 0) {
            printf("FAIL: a misaligned buffer was written at byte %zu\n", i);
            failures++;
            break;
        }
    }

    /* Out-of-range values. */
    EXPECT(nyq_radical_inverse(1024, 1, &x), NYQ_ERR_OUT_OF_RANGE);
    EXPECT(nyq_radical_inverse_f64(5000, 1, &d), NYQ_ERR_OUT_OF_RANGE);
    NyqSequence bad_kind = {999, 2, 0, 0, 0};
    EXPECT(nyq_sequence_sample(&bad_kind, 0, 0, &x), NYQ_ERR_OUT_OF_RANGE);
    UNTOUCHED(x == -1.0f && d == -1.0);

    /* Specs and names that do not parse; radii outside the range. */
    NyqFilter *filter = NULL;
    EXPECT(nyq_filter_create("mitchell:b=", &filter), NYQ_ERR_PARSE);
    EXPECT(nyq_filter_create("no-such-filter", &filter), NYQ_ERR_PARSE);
    EXPECT(nyq_filter_create_callback(zero_filter, NULL, 0.0f / 0.0f, 1.0f, &filter),
           NYQ_ERR_NON_FINITE);
    EXPECT(nyq_filter_create_callback(zero_filter, NULL, 5000.0f, 1.0f, &filter),
           NYQ_ERR_OUT_OF_RANGE);
    UNTOUCHED(filter == NULL);
    NyqSampler *sampler = NULL;
    EXPECT(nyq_sampler_create("no-such-sampler", 4, 4, 4, 1, &sampler), NYQ_ERR_PARSE);
    EXPECT(nyq_sampler_create("stratified", 0, 4, 4, 1, &sampler), NYQ_ERR_ZERO_SIZE);
    UNTOUCHED(sampler == NULL);

    /* A real handle: bad interpolation, then a double destroy through the guard. */
    EXPECT(nyq_filter_create("mitchell", &filter), NYQ_OK);
    EXPECT(nyq_filter_lookup(filter, 7, 0.0f, 0.0f, &x), NYQ_ERR_OUT_OF_RANGE);
    EXPECT(nyq_filter_eval(filter, 0.0f, 0.0f, misaligned), NYQ_ERR_BUFFER);
    nyq_filter_destroy(filter);
    filter = NULL;
    nyq_filter_destroy(filter);

    EXPECT(nyq_sampler_create("stratified", 4, 4, 4, 1, &sampler), NYQ_OK);
    NyqSampler *copy = NULL;
    EXPECT(nyq_sampler_clone(sampler, &copy), NYQ_OK);
    EXPECT(nyq_sampler_get_array_2d(sampler, buf, 3), NYQ_ERR_BUFFER); /* odd length for pairs */
    EXPECT(nyq_sampler_get_2d(sampler, misaligned), NYQ_ERR_BUFFER);
    nyq_sampler_destroy(sampler);
    sampler = NULL;
    nyq_sampler_destroy(sampler);
    nyq_sampler_destroy(copy);
    copy = NULL;
    nyq_sampler_destroy(copy);

    /* Every status, known or not, has a message. */
    for (uint32_t s = 0; s < 20; s++) {
        const char *m = nyq_status_message(s);
        if (m == NULL || m[0] == '\0') {
            printf("FAIL: status %u has no message\n", s);
            failures++;
        }
    }

    if (failures != 0) {
        printf("%d failures\n", failures);
        return 1;
    }
    printf("misuse ok\n");
    return 0;
}

/* The smallest use of the Owen-Sobol sampler, for scripts/c-size.sh: one handle, one 2D sample
 * printed as its bits. Linked with --gc-sections and stripped, it carries what the Owen-Sobol
 * sampler needs only. */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "nyquist.h"

int main(void) {
    NyqSampler *sampler = NULL;
    float uv[2] = {0.0f, 0.0f};
    uint32_t bits[2];
    enum NyqStatus status = nyq_sampler_create_owen_sobol(64, 64, 16, 7, &sampler);
    if (status == NYQ_OK) {
        status = nyq_sampler_start_pixel_sample(sampler, 3, 5, 2, 0);
    }
    if (status == NYQ_OK) {
        status = nyq_sampler_get_2d(sampler, uv);
    }
    nyq_sampler_destroy(sampler);
    if (status != NYQ_OK) {
        printf("error %d\n", (int)status);
        return 1;
    }
    memcpy(bits, uv, sizeof bits);
    printf("%08" PRIx32 " %08" PRIx32 "\n", bits[0], bits[1]);
    return 0;
}

/* The smallest use of the Halton sequence, for scripts/c-size.sh: one value, printed as its
 * bits. Linked with --gc-sections and stripped, it carries what nyq_halton_sample needs only. */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "nyquist.h"

int main(void) {
    float x = 0.0f;
    uint32_t bits;
    enum NyqStatus status = nyq_halton_sample(2, 3, 1, &x);
    if (status != NYQ_OK) {
        printf("error %d\n", (int)status);
        return 1;
    }
    memcpy(&bits, &x, sizeof bits);
    printf("%08" PRIx32 "\n", bits);
    return 0;
}

// The pbrt-v4 side of the peer benchmark: extern "C" loops over pbrt-v4's own samplers and
// Sobol function (src/pbrt/samplers.h, src/pbrt/util/lowdiscrepancy.h). Every loop writes its
// values to a caller buffer so that the Rust side can check them and nothing is optimised away.
#include <pbrt/samplers.h>
#include <pbrt/util/lowdiscrepancy.h>

#include <cstddef>
#include <cstdint>

namespace {

// The 5 values of a camera sample as pbrt-v4's GetCameraSample draws them (pixel 2-D, time,
// lens), without the filter's importance sampling, which nyquist's camera sample does not do
// either: film x, film y, time, lens u, lens v.
template <typename S>
void camera(S &s, int x0, int y0, int n, int spp, float *out) {
    for (int y = y0; y < y0 + n; ++y) {
        for (int x = x0; x < x0 + n; ++x) {
            for (int i = 0; i < spp; ++i) {
                const pbrt::Point2i p(x, y);
                s.StartPixelSample(p, i, 0);
                const pbrt::Point2f film = s.GetPixel2D();
                const pbrt::Float time = s.Get1D();
                const pbrt::Point2f lens = s.Get2D();
                out[0] = float(x) + film.x;
                out[1] = float(y) + film.y;
                out[2] = time;
                out[3] = lens.x;
                out[4] = lens.y;
                out += 5;
            }
        }
    }
}

}  // namespace

extern "C" {

// HaltonSampler with RandomizeStrategy::PermuteDigits over a `res` x `res` image.
void *peer_pbrt_v4_halton_new(int spp, int res, int seed) {
    return new pbrt::HaltonSampler(spp, pbrt::Point2i(res, res),
                                   pbrt::RandomizeStrategy::PermuteDigits, seed);
}

void peer_pbrt_v4_halton_free(void *s) { delete static_cast<pbrt::HaltonSampler *>(s); }

void peer_pbrt_v4_halton_camera(void *s, int x0, int y0, int n, int spp, float *out) {
    camera(*static_cast<pbrt::HaltonSampler *>(s), x0, y0, n, spp, out);
}

// ZSobolSampler with RandomizeStrategy::FastOwen over a `res` x `res` image.
void *peer_pbrt_v4_zsobol_new(int spp, int res, int seed) {
    return new pbrt::ZSobolSampler(spp, pbrt::Point2i(res, res),
                                   pbrt::RandomizeStrategy::FastOwen, seed);
}

void peer_pbrt_v4_zsobol_free(void *s) { delete static_cast<pbrt::ZSobolSampler *>(s); }

void peer_pbrt_v4_zsobol_camera(void *s, int x0, int y0, int n, int spp, float *out) {
    camera(*static_cast<pbrt::ZSobolSampler *>(s), x0, y0, n, spp, out);
}

// SobolSample(index, dimension, NoRandomizer) for every index and dimensions 0..dims,
// index-major.
void peer_pbrt_v4_sobol(const uint32_t *index, size_t n, int dims, float *out) {
    for (size_t k = 0; k < n; ++k) {
        for (int d = 0; d < dims; ++d) {
            *out++ = pbrt::SobolSample(int64_t(index[k]), d, pbrt::NoRandomizer());
        }
    }
}

// RadicalInverse(d, a) (util/lowdiscrepancy.h: one digit loop, the base read at run time) for
// every index and d in 0..dims, index-major.
void peer_pbrt_v4_radical_inverse(const uint64_t *index, size_t n, int dims, float *out) {
    for (size_t k = 0; k < n; ++k) {
        for (int d = 0; d < dims; ++d) {
            *out++ = pbrt::RadicalInverse(d, index[k]);
        }
    }
}

// PMJ02BNSampler and its table (src/pbrt/util/pmj02tables.cpp and bluenoise.cpp, or the
// substitutes peers/build.rs writes where the snapshot lacks them).
void *peer_pbrt_v4_pmj02bn_new(int spp, int seed) {
    return new pbrt::PMJ02BNSampler(spp, seed);
}

void peer_pbrt_v4_pmj02bn_free(void *s) { delete static_cast<pbrt::PMJ02BNSampler *>(s); }

void peer_pbrt_v4_pmj02bn_camera(void *s, int x0, int y0, int n, int spp, float *out) {
    camera(*static_cast<pbrt::PMJ02BNSampler *>(s), x0, y0, n, spp, out);
}

// GetPMJ02BNSample(0, i): the table read of pbrt-v4's first pmj02bn set, 2 floats per index.
void peer_pbrt_v4_pmj02bn_lookup(const uint32_t *index, size_t n, float *out) {
    for (size_t k = 0; k < n; ++k) {
        const pbrt::Point2f p = pbrt::GetPMJ02BNSample(0, int(index[k]));
        out[2 * k] = p.x;
        out[2 * k + 1] = p.y;
    }
}

}  // extern "C"

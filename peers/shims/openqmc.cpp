// The OpenQMC side of the peer benchmark: extern "C" loops over OpenQMC's own samplers and
// lookup functions (include/oqmc, header-only). Every loop writes its values to a caller buffer
// so that the Rust side can check them and nothing is optimised away.
#include <oqmc/float.h>
#include <oqmc/oqmc.h>
#include <oqmc/lookup.h>
#include <oqmc/owen.h>
#include <oqmc/pmj.h>
#include <oqmc/stochastic.h>

#include <cstddef>
#include <cstdint>

extern "C" {

// The PMJ sampler's cache (`PmjSampler::cacheSize` bytes, initialised by OpenQMC).
void *peer_oqmc_pmj_cache_new() {
    void *cache = new char[oqmc::PmjSampler::cacheSize];
    oqmc::PmjSampler::initialiseCache(cache);
    return cache;
}

void peer_oqmc_pmj_cache_free(void *cache) { delete[] static_cast<char *>(cache); }

// Camera samples of `nx` x `ny` pixels from (x0, y0), `spp` each: the pixel domain's 2-D draw
// (image sample) and a derived domain's 3-D draw (time, lens). Writes 5 floats per sample:
// film x, film y, time, lens u, lens v.
void peer_oqmc_pmj_camera(const void *cache, int x0, int y0, int nx, int ny, int spp,
                          float *out) {
    for (int y = y0; y < y0 + ny; ++y) {
        for (int x = x0; x < x0 + nx; ++x) {
            for (int i = 0; i < spp; ++i) {
                const auto pixel = oqmc::PmjSampler(x, y, 0, i, cache);
                float image[2];
                pixel.drawSample<2>(image);
                float rest[3];
                pixel.newDomain(0).drawSample<3>(rest);
                out[0] = float(x) + image[0];
                out[1] = float(y) + image[1];
                out[2] = rest[0];
                out[3] = rest[1];
                out[4] = rest[2];
                out += 5;
            }
        }
    }
}

// The stochastic PMJ table OpenQMC's PMJ sampler reads: 2^16 points of 4 dimensions.
uint32_t (*peer_oqmc_pmj_table_new())[4] {
    auto table = new uint32_t[65536][4];
    oqmc::stochasticPmjInit(65536, table);
    return table;
}

void peer_oqmc_pmj_table_free(uint32_t (*table)[4]) { delete[] table; }

// The PMJ sampler's lookup core: index shuffle, table read and XOR scramble of two
// dimensions, then OpenQMC's integer-to-float conversion. Writes 2 floats per index.
void peer_oqmc_pmj_lookup_2d(const uint32_t (*table)[4], uint32_t hash, const uint32_t *index,
                             size_t n, float *out) {
    for (size_t k = 0; k < n; ++k) {
        uint32_t s[2];
        oqmc::shuffledScrambledLookup<4, 2>(index[k], hash, table, s);
        out[2 * k] = oqmc::uintToFloat(s[0]);
        out[2 * k + 1] = oqmc::uintToFloat(s[1]);
    }
}

// Owen-scrambled Sobol, four dimensions per seed: for each index in 0..n_points and each seed
// (one per set of four dimensions), OpenQMC's shuffled, scrambled Sobol value. Writes 4 floats
// per (index, seed), index-major.
void peer_oqmc_sobol_4d(uint32_t n_points, const uint32_t *seeds, uint32_t n_seeds, float *out) {
    for (uint32_t i = 0; i < n_points; ++i) {
        for (uint32_t s = 0; s < n_seeds; ++s) {
            uint32_t v[4];
            oqmc::shuffledScrambledSobol<4>(i, seeds[s], v);
            for (int d = 0; d < 4; ++d) {
                out[d] = oqmc::uintToFloat(v[d]);
            }
            out += 4;
        }
    }
}

} // extern "C"

// Screen-space blue noise: the four values of one domain's `drawSample<4>` for `spp` samples
// of each of `nx` x `ny` pixels from (0, 0) in frame `frame`, for OpenQMC's samplers by kind
// (0 SobolBn, 1 PmjBn, 2 LatticeBn, 3 Sobol, 4 Pmj, 5 Lattice). Domain 0 is the pixel's own
// domain; domain `d > 0` is `newDomain(d)`. Writes 4 floats per sample, pixel-major.
template <typename Sampler>
static void bn_draw(int nx, int ny, int frame, int spp, int domain, float *out) {
    char *cache = new char[Sampler::cacheSize];
    Sampler::initialiseCache(cache);
    for (int y = 0; y < ny; ++y) {
        for (int x = 0; x < nx; ++x) {
            for (int i = 0; i < spp; ++i) {
                auto s = Sampler(x, y, frame, i, cache);
                if (domain > 0) {
                    s = s.newDomain(domain);
                }
                s.template drawSample<4>(out);
                out += 4;
            }
        }
    }
    delete[] cache;
}

extern "C" int peer_oqmc_bn_draw(int kind, int nx, int ny, int frame, int spp, int domain,
                                 float *out) {
    switch (kind) {
    case 0: bn_draw<oqmc::SobolBnSampler>(nx, ny, frame, spp, domain, out); return 0;
    case 1: bn_draw<oqmc::PmjBnSampler>(nx, ny, frame, spp, domain, out); return 0;
    case 2: bn_draw<oqmc::LatticeBnSampler>(nx, ny, frame, spp, domain, out); return 0;
    case 3: bn_draw<oqmc::SobolSampler>(nx, ny, frame, spp, domain, out); return 0;
    case 4: bn_draw<oqmc::PmjSampler>(nx, ny, frame, spp, domain, out); return 0;
    case 5: bn_draw<oqmc::LatticeSampler>(nx, ny, frame, spp, domain, out); return 0;
    default: return 1;
    }
}

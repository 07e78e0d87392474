// Parity of gpu/cpp/nyquist.hpp with the Rust core, run by capi/tests/cpp_header.rs:
//
//   parity EXPECTED_FILE [--quick]
//
// 1. Samplers and sequences the C API builds (`nyq_sampler_create` by name,
//    `nyq_sequence_sample`): random (pixel, sample index, dimension, seed) queries drawn here,
//    each answered by libnyquist_capi.a and by the header, compared bit for bit.
//    The blue-noise samplers take their tiles from the C API too (`nyq_blue_tile`).
// 2. Configurations the C API cannot name (other scrambles, frames, the Owen-Sobol sequence):
//    the Rust test wrote the queries and the core's answers to EXPECTED_FILE; the header must
//    reproduce every value.
//
// Prints one line per configuration with its value count; on the first mismatch prints the
// configuration, the query and both values' bits, and exits 1.
#include <cinttypes>
#include <cstdio>
#include <string>
#include <cstdlib>
#include <cstring>

#include "nyquist.h"
#include "nyquist.hpp"

namespace {

using namespace nyquist;

/// SplitMix64: the queries' source (independent of the header's hashes).
struct Rng {
    std::uint64_t s;
    std::uint64_t next() {
        s += 0x9e3779b97f4a7c15ull;
        std::uint64_t z = s;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    std::uint32_t below(std::uint32_t n) {
        return static_cast<std::uint32_t>((next() >> 32) % n);
    }
};

struct Query {
    std::uint32_t px, py, index, dim;
};

/// Pixels small, medium and anywhere in u32; indices inside the pixel's spp, a few times past
/// it, and anywhere; dimensions mostly small, some past 1024 and some next to u32::MAX.
Query draw(Rng& r, std::uint32_t spp) {
    Query q{};
    const std::uint32_t pick = static_cast<std::uint32_t>(r.next());
    const std::uint32_t sizes[3] = {64, 4096, 0};
    const std::uint32_t size = sizes[pick % 3];
    q.px = size ? r.below(size) : static_cast<std::uint32_t>(r.next());
    q.py = size ? r.below(size) : static_cast<std::uint32_t>(r.next());
    switch ((pick >> 8) & 3) {
        case 0: q.index = r.below(spp); break;
        case 1: q.index = r.below(spp > 0x3fffffffu ? 0xffffffffu : 4 * spp); break;
        case 2: q.index = r.below(65536); break;
        default: q.index = static_cast<std::uint32_t>(r.next()); break;
    }
    switch ((pick >> 16) & 7) {
        case 0: case 1: case 2: case 3: q.dim = r.below(8); break;
        case 4: case 5: q.dim = r.below(64); break;
        case 6: q.dim = r.below(2100); break;
        default: q.dim = 0xffffffffu - r.below(4); break;
    }
    return q;
}

bool same(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::uint32_t bits(float x) {
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

const char* const kValueNames[14] = {
    "get_1d", "get_2d[0]", "get_2d[1]", "get_pixel_2d[0]", "get_pixel_2d[1]", "get_1d (2nd)",
    "get_2d[0] (2nd)", "get_2d[1] (2nd)", "camera p_film[0]", "camera p_film[1]", "camera time",
    "camera lens[0]", "camera lens[1]", "get_1d after camera"};

/// The 14 values one query gives: after start_pixel_sample, get_1d, get_2d, get_pixel_2d,
/// get_1d, get_2d; then camera_sample and one get_1d.
template <class S>
void header_values(S& s, const Query& q, float out[14]) {
    s.start_pixel_sample(q.px, q.py, q.index, q.dim);
    out[0] = s.get_1d();
    Float2 v = s.get_2d();
    out[1] = v.v[0];
    out[2] = v.v[1];
    v = s.get_pixel_2d();
    out[3] = v.v[0];
    out[4] = v.v[1];
    out[5] = s.get_1d();
    v = s.get_2d();
    out[6] = v.v[0];
    out[7] = v.v[1];
    const CameraSample c = s.camera_sample(q.px, q.py, q.index);
    out[8] = c.p_film[0];
    out[9] = c.p_film[1];
    out[10] = c.time;
    out[11] = c.lens[0];
    out[12] = c.lens[1];
    out[13] = s.get_1d();
}

bool ok(NyqStatus s, const char* what) {
    if (s != NYQ_OK) {
        std::printf("MISMATCH: %s returned status %d\n", what, static_cast<int>(s));
        return false;
    }
    return true;
}

bool capi_values(NyqSampler* h, const Query& q, float out[14]) {
    bool good = ok(nyq_sampler_start_pixel_sample(h, q.px, q.py, q.index, q.dim), "start");
    good = good && ok(nyq_sampler_get_1d(h, &out[0]), "get_1d");
    good = good && ok(nyq_sampler_get_2d(h, &out[1]), "get_2d");
    good = good && ok(nyq_sampler_get_pixel_2d(h, &out[3]), "get_pixel_2d");
    good = good && ok(nyq_sampler_get_1d(h, &out[5]), "get_1d");
    good = good && ok(nyq_sampler_get_2d(h, &out[6]), "get_2d");
    NyqCameraSample c{};
    good = good && ok(nyq_sampler_camera_sample(h, q.px, q.py, q.index, &c), "camera_sample");
    out[8] = c.p_film[0];
    out[9] = c.p_film[1];
    out[10] = c.time;
    out[11] = c.lens[0];
    out[12] = c.lens[1];
    good = good && ok(nyq_sampler_get_1d(h, &out[13]), "get_1d");
    return good;
}

bool compare14(const char* label, const Query& q, const float want[14], const float got[14]) {
    for (int k = 0; k < 14; ++k) {
        if (!same(want[k], got[k])) {
            std::printf(
                "MISMATCH %s: pixel (%" PRIu32 ", %" PRIu32 ") sample %" PRIu32 " dim %" PRIu32
                ": %s core %08" PRIx32 " (%.9g) header %08" PRIx32 " (%.9g)\n",
                label, q.px, q.py, q.index, q.dim, kValueNames[k], bits(want[k]),
                static_cast<double>(want[k]), bits(got[k]), static_cast<double>(got[k]));
            return false;
        }
    }
    return true;
}

std::uint64_t g_total = 0;

/// Queries per C API sampler configuration: 8 configurations × 9000 × 14 values ≥ 10⁶ per
/// sampler. `--quick` divides every C API count by `g_scale` (the second build's run).
constexpr std::uint32_t kQueries = 9000;
std::uint32_t g_scale = 1;

/// Keeps query `q` of sampler `name` where the header follows the core (docs/c.md): the core's
/// ZSobol and Sobol samplers continue past their spp, its PMJ(0,2) sampler past 2^16 samples,
/// and its Owen-Sobol, Sobol and Halton samplers pad from dimension 1024 on, where the header
/// still wraps. A query reads its dimension and the five after it.
void restrict_to_the_headers_domain(const char* name, std::uint32_t spp, Query& q) {
    const std::string n = name;
    if (n == "zsobol" || n == "sobol") q.index %= spp;
    if (n == "pmj02") q.index &= 0xffffu;
    if (n == "owen-sobol" || n == "sobol" || n == "halton") q.dim %= 1000u;
}

/// Sampler `name` of the C API against the header's `cpp`, over `queries` random queries.
template <class S>
bool capi_sampler(const char* name, std::uint32_t w, std::uint32_t h, std::uint32_t spp,
                  std::uint64_t seed, S cpp, std::uint32_t queries, Rng& rng) {
    char label[160];
    std::snprintf(label, sizeof label, "%s %" PRIu32 "x%" PRIu32 " spp %" PRIu32 " seed %" PRIu64,
                  name, w, h, spp, seed);
    if (!cpp.valid()) {
        std::printf("MISMATCH %s: the header's sampler is not valid\n", label);
        return false;
    }
    NyqSampler* handle = nullptr;
    if (!ok(nyq_sampler_create(name, w, h, spp, seed, &handle), label)) return false;
    std::uint32_t capi_spp = 0;
    nyq_sampler_samples_per_pixel(handle, &capi_spp);
    bool good = capi_spp == cpp.samples_per_pixel();
    if (!good)
        std::printf("MISMATCH %s: spp core %" PRIu32 " header %" PRIu32 "\n", label, capi_spp,
                    cpp.samples_per_pixel());
    for (std::uint32_t n = 0; good && n < queries; ++n) {
        Query q = draw(rng, capi_spp);
        restrict_to_the_headers_domain(name, capi_spp, q);
        float want[14], got[14];
        good = capi_values(handle, q, want);
        header_values(cpp, q, got);
        good = good && compare14(label, q, want, got);
    }
    nyq_sampler_destroy(handle);
    if (good) g_total += 14ull * queries;
    return good;
}

/// Accumulates value counts per sampler family and prints them.
struct Tally {
    const char* name;
    std::uint64_t before;
    explicit Tally(const char* n) : name(n), before(g_total) {}
    void print() const {
        std::printf("%s: %" PRIu64 " values equal\n", name, g_total - before);
    }
};

// ---------------------------------------------------------------------------------------------
// Part 1: the C API.

bool owen_sobol_capi(Rng& rng) {
    Tally t("owen-sobol (C API)");
    const std::uint32_t spps[4] = {1, 16, 64, 1000};
    for (std::uint32_t k = 0; k < 8; ++k) {
        const std::uint64_t seed = k < 2 ? k : rng.next();
        const std::uint32_t spp = spps[k % 4];
        if (!capi_sampler("owen-sobol", 64, 64, spp, seed, OwenSobolSampler<>(spp, seed), kQueries / g_scale, rng))
            return false;
    }
    t.print();
    return true;
}

bool zsobol_capi(Rng& rng) {
    Tally t("zsobol fast-owen (C API)");
    struct Config {
        std::uint32_t w, h, spp;
    };
    const Config configs[4] = {{64, 64, 16}, {1920, 1080, 8}, {3, 1, 1}, {4096, 2160, 256}};
    for (std::uint32_t k = 0; k < 8; ++k) {
        const Config c = configs[k % 4];
        const std::uint64_t seed = k < 2 ? k : rng.next();
        if (!capi_sampler("zsobol", c.w, c.h, c.spp, seed,
                          ZSobolSampler(c.w, c.h, c.spp, Scramble::FastOwen, seed), kQueries / g_scale, rng))
            return false;
    }
    t.print();
    return true;
}

bool sobol_capi(Rng& rng) {
    Tally t("sobol none/permute-digits (C API)");
    struct Config {
        std::uint32_t w, h, spp;
    };
    const Config configs[4] = {{64, 48, 16}, {1024, 1024, 64}, {3, 1, 1}, {16384, 16384, 16}};
    for (std::uint32_t k = 0; k < 8; ++k) {
        const Config c = configs[k % 4];
        const std::uint64_t seed = k < 4 ? 0 : rng.next();
        if (!capi_sampler("sobol", c.w, c.h, c.spp, seed, SobolSampler<>(c.w, c.h, c.spp, seed), kQueries / g_scale,
                          rng))
            return false;
    }
    t.print();
    return true;
}

/// `nyq_sequence_fill` of `seq` (whole points, every dimension) against the header's
/// `sample(index, dim)`, until `values` values are compared; `points` is the set's point count
/// (0: unbounded). Runs start at random indices, small and large.
template <class F>
bool sequence_capi(const char* label, const NyqSequence& seq, std::uint64_t points, F sample,
                   std::uint32_t values, Rng& rng) {
    static float buf[4096];
    const std::uint32_t dims = seq.dims;
    std::uint64_t run = 4096 / dims;
    if (points != 0 && run > points) run = points;
    for (std::uint32_t done = 0, n = 0; done < values; ++n) {
        std::uint64_t first = (n & 1) ? rng.next() >> (n & 2 ? 0 : 32) : rng.below(4096);
        if (points != 0) first %= points - run + 1;
        else if (first > ~std::uint64_t{0} - run) first -= run;
        std::uint64_t written = 0;
        if (!ok(nyq_sequence_fill(&seq, first, dims, buf, static_cast<std::size_t>(run * dims),
                                  &written),
                label))
            return false;
        for (std::uint64_t k = 0; k < run; ++k)
            for (std::uint32_t d = 0; d < dims; ++d) {
                const float want = buf[k * dims + d];
                const float got = sample(first + k, d);
                if (!same(want, got)) {
                    std::printf("MISMATCH %s (dims %" PRIu32 " points %" PRIu64 " seed %" PRIu64
                                "): index %" PRIu64 " dim %" PRIu32 " core %08" PRIx32
                                " header %08" PRIx32 "\n",
                                label, dims, seq.points, seq.seed, first + k, d, bits(want),
                                bits(got));
                    return false;
                }
            }
        done += static_cast<std::uint32_t>(run * dims);
        g_total += run * dims;
    }
    return true;
}

bool sobol_sequence_capi(Rng& rng) {
    Tally t("Sobol sequence (C API nyq_sequence_fill)");
    for (std::uint32_t k = 0; k < 4; ++k) {
        NyqSequence seq{};
        seq.kind = k < 2 ? NYQ_SEQ_SOBOL : NYQ_SEQ_SOBOL_SCRAMBLED;
        seq.dims = k % 2 ? 1024 : 3;
        seq.seed = k < 3 ? k : rng.next();
        const Sobol<1024> s = k < 2 ? Sobol<1024>::plain() : Sobol<1024>::with_digital_shift(seq.seed);
        if (!sequence_capi("Sobol", seq, std::uint64_t{1} << 32,
                           [&](std::uint64_t i, std::uint32_t d) { return s.sample(i, d); }, 260000 / g_scale,
                           rng))
            return false;
    }
    t.print();
    return true;
}

bool random_capi(Rng& rng) {
    Tally t("random (C API)");
    for (std::uint32_t k = 0; k < 8; ++k) {
        const std::uint64_t seed = k < 2 ? k : rng.next();
        const std::uint32_t spp = k % 2 ? 16 : 1;
        if (!capi_sampler("random", 8, 8, spp, seed, RandomSampler(spp, seed), kQueries / g_scale, rng)) return false;
    }
    t.print();
    return true;
}

bool stratified_capi(Rng& rng) {
    Tally t("stratified + uniform (C API)");
    const std::uint32_t sides[4] = {1, 4, 7, 32};
    for (std::uint32_t k = 0; k < 8; ++k) {
        const std::uint64_t seed = k < 2 ? k : rng.next();
        const std::uint32_t side = sides[k % 4];
        const bool jittered = k < 4 || k == 7;
        if (!capi_sampler(jittered ? "stratified" : "uniform", 8, 8, side * side, seed,
                          StratifiedSampler(side, side, jittered, seed), kQueries / g_scale, rng))
            return false;
    }
    t.print();
    return true;
}

bool lattice_capi(Rng& rng) {
    const char* names[3] = {"fibonacci", "r2", "korobov"};
    const std::uint32_t spps[4] = {1, 20, 64, 1000};
    for (std::uint32_t which = 0; which < 3; ++which) {
        char label[64];
        std::snprintf(label, sizeof label, "%s (C API)", names[which]);
        Tally t(label);
        for (std::uint32_t k = 0; k < 8; ++k) {
            const std::uint64_t seed = k < 2 ? k : rng.next();
            const std::uint32_t spp = spps[k % 4];
            const LatticeSampler s = which == 0   ? LatticeSampler::fibonacci(spp, seed)
                                     : which == 1 ? LatticeSampler::r2(spp, seed)
                                                  : LatticeSampler::korobov(spp, seed);
            if (!capi_sampler(names[which], 8, 8, spp, seed, s, kQueries / g_scale, rng)) return false;
        }
        t.print();
    }
    return true;
}

bool lattice_sequences_capi(Rng& rng) {
    Tally t("Fibonacci, R2, Korobov sequences (C API nyq_sequence_fill)");
    for (std::uint32_t k = 0; k < 4; ++k) {
        NyqSequence seq{};
        const bool rotated = k % 2 != 0;
        seq.kind = rotated ? NYQ_SEQ_FIBONACCI_ROTATED : NYQ_SEQ_FIBONACCI;
        seq.dims = 2;
        seq.points = detail::fibonacci(10 + 20 * k);
        seq.seed = rotated ? rng.next() : 0;
        Lattice l = Lattice::fibonacci_at_least(seq.points);
        if (rotated) l = l.rotated_by(seq.seed);
        if (!sequence_capi("Fibonacci", seq, seq.points,
                           [&](std::uint64_t i, std::uint32_t d) { return l.sample(i, d); }, 100000 / g_scale,
                           rng))
            return false;
        seq.kind = rotated ? NYQ_SEQ_RD_ROTATED : NYQ_SEQ_RD;
        seq.points = 0;
        Lattice r = Lattice::r2();
        if (rotated) r = r.rotated_by(seq.seed);
        if (!sequence_capi("R2", seq, 0, [&](std::uint64_t i, std::uint32_t d) { return r.sample(i, d); },
                           100000 / g_scale, rng))
            return false;
        seq.kind = NYQ_SEQ_KOROBOV;
        seq.dims = k % 2 ? 1024 : 8;
        seq.points = k < 2 ? 1021 : (std::uint64_t{1} << 40) + 15;
        seq.multiplier = k < 2 ? 76 : 0x1234567891ull;  // coprime to the points
        const Lattice kor = Lattice::korobov(seq.points, seq.multiplier, seq.dims);
        if (!sequence_capi("Korobov", seq, seq.points,
                           [&](std::uint64_t i, std::uint32_t d) { return kor.sample(i, d); }, 100000 / g_scale,
                           rng))
            return false;
    }
    t.print();
    return true;
}

bool halton_capi(Rng& rng) {
    Tally t("halton, permute-digits (C API)");
    struct Config {
        std::uint32_t w, h, spp;
    };
    const Config configs[4] = {{64, 48, 16}, {1920, 1080, 64}, {3, 1, 1}, {16384, 16384, 65536}};
    for (std::uint32_t k = 0; k < 8; ++k) {
        const Config c = configs[k % 4];
        const std::uint64_t seed = k < 4 ? 0 : rng.next();
        const Scramble how = Scramble::PermuteDigits;
        if (!capi_sampler("halton", c.w, c.h, c.spp, seed, HaltonSampler<>(c.w, c.h, c.spp, how, seed),
                          kQueries / g_scale, rng))
            return false;
    }
    t.print();
    return true;
}

bool halton_sequence_capi(Rng& rng) {
    Tally t("Halton sequence (C API nyq_sequence_fill)");
    const std::uint32_t dim_counts[2] = {1024, 7};
    for (std::uint32_t dims : dim_counts) {
        NyqSequence seq{};
        seq.kind = NYQ_SEQ_HALTON;
        seq.dims = dims;
        const Halton<1024> h;
        if (!sequence_capi("Halton", seq, 0,
                           [&](std::uint64_t i, std::uint32_t d) { return h.sample(i, d); }, 600000 / g_scale,
                           rng))
            return false;
    }
    t.print();
    return true;
}

bool pmj02_capi(Rng& rng) {
    Tally t("pmj02 (C API)");
    const std::uint32_t spps[4] = {1, 16, 1000, 65536};
    for (std::uint32_t k = 0; k < 8; ++k) {
        const std::uint64_t seed = k < 2 ? k : rng.next();
        const std::uint32_t spp = spps[k % 4];
        if (!capi_sampler("pmj02", 8, 8, spp, seed, Pmj02Sampler(spp, seed), kQueries / g_scale, rng)) return false;
    }
    t.print();
    return true;
}

/// The blue-noise samplers' tiles, from the C API (`nyq_blue_tile`), in the order of
/// `kBlueNames`.
const char* const kBlueNames[3] = {"owen-sobol-bn", "pmj02-bn", "lattice-bn"};
std::uint32_t g_blue_tiles[3][kBlueTileEntries];

bool load_blue_tiles() {
    for (int f = 0; f < 3; ++f)
        if (!ok(nyq_blue_tile(kBlueNames[f], g_blue_tiles[f], kBlueTileEntries), kBlueNames[f]))
            return false;
    return true;
}

template <class S>
bool blue_capi_family(std::uint32_t f, Rng& rng) {
    char label[64];
    std::snprintf(label, sizeof label, "%s (C API)", kBlueNames[f]);
    Tally t(label);
    const std::uint32_t spps[4] = {1, 16, 64, 1000};
    for (std::uint32_t k = 0; k < 8; ++k) {
        const std::uint64_t seed = k < 2 ? k : rng.next();
        const std::uint32_t spp = spps[k % 4];
        if (!capi_sampler(kBlueNames[f], 8, 8, spp, seed, S(spp, seed, g_blue_tiles[f]), kQueries / g_scale, rng))
            return false;
    }
    t.print();
    return true;
}

/// docs/gpu.md's blue-noise example, as written there (the pixel and index are the example's
/// free names), held to the C API's sampler.
bool blue_docs_example() {
    const std::uint32_t px = 300, py = 7, sample_index = 5;
    static std::uint32_t tile[nyquist::kBlueTileEntries];
    nyq_blue_tile("pmj02-bn", tile, nyquist::kBlueTileEntries);      // NYQ_OK
    nyquist::Pmj02BlueSampler b(/*spp*/ 16, /*seed*/ 7, tile, /*frame*/ 0);
    nyquist::CameraSample cb = b.camera_sample(px, py, sample_index);
    NyqSampler* h = nullptr;
    NyqCameraSample c{};
    bool good = b.valid() && ok(nyq_sampler_create("pmj02-bn", 8, 8, 16, 7, &h), "docs example") &&
                ok(nyq_sampler_camera_sample(h, px, py, sample_index, &c), "docs example");
    nyq_sampler_destroy(h);
    good = good && same(c.p_film[0], cb.p_film[0]) && same(c.p_film[1], cb.p_film[1]) &&
           same(c.time, cb.time) && same(c.lens[0], cb.lens[0]) && same(c.lens[1], cb.lens[1]);
    if (!good) std::printf("MISMATCH: docs/gpu.md's blue-noise example\n");
    return good;
}

bool blue_capi(Rng& rng) {
    return load_blue_tiles() && blue_docs_example() && blue_capi_family<OwenSobolBlueSampler>(0, rng) &&
           blue_capi_family<Pmj02BlueSampler>(1, rng) && blue_capi_family<LatticeBlueSampler>(2, rng);
}

// ---------------------------------------------------------------------------------------------
// Part 2: the expected file.

struct Reader {
    std::FILE* f;
    bool u32(std::uint32_t& v) { return std::fread(&v, sizeof v, 1, f) == 1; }
    bool u64(std::uint64_t& v) { return std::fread(&v, sizeof v, 1, f) == 1; }
    bool floats(float* v, std::size_t n) { return std::fread(v, sizeof(float), n, f) == n; }
};

enum Kind : std::uint32_t {
    kOwenSobolSampler = 0,
    kZSobolSampler = 1,
    kSobolSampler = 2,
    kHaltonSampler = 3,
    kBlueNoiseSampler = 4,  // `dims` names the family: 0 owen-sobol-bn, 1 pmj02-bn, 2 lattice-bn
    kOwenSobolSequence = 10,
    kPmj02Sequence = 11,
};

const char* scramble_name(std::uint32_t s) {
    const char* names[4] = {"none", "permute-digits", "fast-owen", "owen"};
    return s < 4 ? names[s] : "?";
}

template <class S>
bool file_sampler(Reader& in, const char* label, S s, std::uint32_t count) {
    if (!s.valid()) {
        std::printf("MISMATCH %s: the header's sampler is not valid\n", label);
        return false;
    }
    for (std::uint32_t n = 0; n < count; ++n) {
        Query q{};
        float want[14], got[14];
        if (!in.u32(q.px) || !in.u32(q.py) || !in.u32(q.index) || !in.u32(q.dim) ||
            !in.floats(want, 14)) {
            std::printf("MISMATCH %s: expected file truncated\n", label);
            return false;
        }
        header_values(s, q, got);
        if (!compare14(label, q, want, got)) return false;
    }
    g_total += 14ull * count;
    return true;
}

template <std::uint32_t N>
bool file_owen_sobol_sequence(Reader& in, const char* label, std::uint64_t seed, std::uint32_t count) {
    const OwenSobol<N> s = OwenSobol<N>::make(seed);
    for (std::uint32_t n = 0; n < count; ++n) {
        std::uint32_t index = 0, dim = 0;
        float want[5];
        if (!in.u32(index) || !in.u32(dim) || !in.floats(want, 5)) {
            std::printf("MISMATCH %s: expected file truncated\n", label);
            return false;
        }
        const Float4 four = s.sample_4d(index, dim);
        const float got[5] = {s.sample(index, dim), four.v[0], four.v[1], four.v[2], four.v[3]};
        for (int k = 0; k < 5; ++k)
            if (!same(want[k], got[k])) {
                std::printf("MISMATCH %s: index %" PRIu32 " dim %" PRIu32 " %s core %08" PRIx32
                            " header %08" PRIx32 "\n",
                            label, index, dim, k == 0 ? "sample" : "sample_4d", bits(want[k]),
                            bits(got[k]));
                return false;
            }
    }
    g_total += 5ull * count;
    return true;
}

bool file_pmj02_sequence(Reader& in, const char* label, bool scrambled, std::uint64_t seed,
                         std::uint32_t count) {
    const Pmj02 s = scrambled ? Pmj02::make_scrambled(seed) : Pmj02::plain();
    for (std::uint32_t n = 0; n < count; ++n) {
        std::uint32_t index = 0, dim = 0;
        float want = 0;
        if (!in.u32(index) || !in.u32(dim) || !in.floats(&want, 1)) {
            std::printf("MISMATCH %s: expected file truncated\n", label);
            return false;
        }
        const float got = s.sample(index, dim);
        if (!same(want, got)) {
            std::printf("MISMATCH %s: index %" PRIu32 " dim %" PRIu32 " core %08" PRIx32
                        " header %08" PRIx32 "\n",
                        label, index, dim, bits(want), bits(got));
            return false;
        }
    }
    g_total += count;
    return true;
}

bool expected_file(const char* path) {
    std::FILE* f = std::fopen(path, "rb");
    if (!f) {
        std::printf("MISMATCH: cannot open %s\n", path);
        return false;
    }
    Reader in{f};
    bool good = true;
    std::uint32_t kind = 0;
    std::uint64_t families[16] = {};
    while (good && in.u32(kind)) {
        std::uint32_t scramble = 0, w = 0, h = 0, spp = 0, frame = 0, dims = 0, count = 0;
        std::uint64_t seed = 0;
        good = in.u32(scramble) && in.u32(w) && in.u32(h) && in.u32(spp) && in.u32(frame) &&
               in.u32(dims) && in.u64(seed) && in.u32(count);
        if (!good) break;
        char label[200];
        std::snprintf(label, sizeof label,
                      "kind %" PRIu32 " scramble %s %" PRIu32 "x%" PRIu32 " spp %" PRIu32
                      " frame %" PRIu32 " dims %" PRIu32 " seed %" PRIu64,
                      kind, scramble_name(scramble), w, h, spp, frame, dims, seed);
        const Scramble how = static_cast<Scramble>(scramble);
        const std::uint64_t before = g_total;
        switch (kind) {
            case kOwenSobolSampler:
                good = file_sampler(in, label, OwenSobolSampler<>(spp, seed, frame), count);
                break;
            case kZSobolSampler:
                good = file_sampler(in, label, ZSobolSampler(w, h, spp, how, seed), count);
                break;
            case kSobolSampler:
                good = file_sampler(in, label, SobolSampler<>(w, h, spp, how, seed), count);
                break;
            case kHaltonSampler:
                good = file_sampler(in, label, HaltonSampler<>(w, h, spp, how, seed), count);
                break;
            case kBlueNoiseSampler: {
                const std::uint32_t* tile = dims < 3 ? g_blue_tiles[dims] : nullptr;
                if (dims == 0) good = file_sampler(in, label, OwenSobolBlueSampler(spp, seed, tile, frame), count);
                else if (dims == 1) good = file_sampler(in, label, Pmj02BlueSampler(spp, seed, tile, frame), count);
                else good = file_sampler(in, label, LatticeBlueSampler(spp, seed, tile, frame), count);
                break;
            }
            case kPmj02Sequence:
                good = file_pmj02_sequence(in, label, scramble != 0, seed, count);
                break;
            case kOwenSobolSequence:
                if (dims == 1024) good = file_owen_sobol_sequence<1024>(in, label, seed, count);
                else if (dims == 5) good = file_owen_sobol_sequence<5>(in, label, seed, count);
                else {
                    std::printf("MISMATCH %s: no instantiation for these dims\n", label);
                    good = false;
                }
                break;
            default:
                std::printf("MISMATCH: unknown kind %" PRIu32 " in the expected file\n", kind);
                good = false;
        }
        families[kind < 16 ? kind : 15] += g_total - before;
    }
    std::fclose(f);
    const char* names[16] = {"owen-sobol frames 1+ (core)", "zsobol none/permute-digits/owen (core)",
                             "sobol fast-owen/owen (core)", "halton fast-owen/owen (core)",
                             "owen-sobol-bn, pmj02-bn, lattice-bn frames 1+ (core)"};
    names[10] = "OwenSobol sequence sample + sample_4d (core)";
    names[11] = "Pmj02 sequence plain + scrambled (core)";
    for (int k = 0; k < 16; ++k)
        if (families[k] && names[k]) std::printf("%s: %" PRIu64 " values equal\n", names[k], families[k]);
    return good;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3 || (argc == 3 && std::strcmp(argv[2], "--quick") != 0)) {
        std::printf("usage: parity EXPECTED_FILE [--quick]\n");
        return 2;
    }
    if (argc == 3) g_scale = 8;
    Rng rng{0x6e7971756973740aull};
    const bool good = owen_sobol_capi(rng) && zsobol_capi(rng) && sobol_capi(rng) &&
                      sobol_sequence_capi(rng) && random_capi(rng) &&
                      stratified_capi(rng) && lattice_capi(rng) && lattice_sequences_capi(rng) &&
                      halton_capi(rng) && halton_sequence_capi(rng) && pmj02_capi(rng) &&
                      blue_capi(rng) && expected_file(argv[1]);
    std::printf("%s: %" PRIu64 " values compared\n", good ? "parity ok" : "parity FAILED", g_total);
    return good ? 0 : 1;
}

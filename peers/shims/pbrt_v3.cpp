// The pbrt-v3 side of the peer benchmark: extern "C" functions over pbrt-v3's own film tile
// (core/film.h, core/film.cpp), filters (filters/*.cpp), RNG and Shuffle (core/rng.h,
// core/sampling.h) and radical inverse (core/lowdiscrepancy.cpp). Loops write to caller buffers so the Rust side can check the values.
#include "film.h"
#include "lowdiscrepancy.h"
#include "filters/box.h"
#include "filters/mitchell.h"
#include "filters/sinc.h"
#include "rng.h"
#include "sampling.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>

using pbrt::Float;

extern "C" {

pbrt::Filter *peer_pbrt_v3_mitchell_new(float rx, float ry, float b, float c) {
    return new pbrt::MitchellFilter(pbrt::Vector2f(rx, ry), b, c);
}

pbrt::Filter *peer_pbrt_v3_box_new(float rx, float ry) {
    return new pbrt::BoxFilter(pbrt::Vector2f(rx, ry));
}

pbrt::Filter *peer_pbrt_v3_lanczos_new(float rx, float ry, float tau) {
    return new pbrt::LanczosSincFilter(pbrt::Vector2f(rx, ry), tau);
}

void peer_pbrt_v3_filter_free(pbrt::Filter *f) { delete f; }

// Filter::Evaluate through the virtual call pbrt-v3 makes, for `n` points (x, y pairs).
void peer_pbrt_v3_filter_evaluate(const pbrt::Filter *f, const float *xy, size_t n,
                                  float *out) {
    for (size_t k = 0; k < n; ++k) {
        out[k] = f->Evaluate(pbrt::Point2f(xy[2 * k], xy[2 * k + 1]));
    }
}

// A `res` x `res` Film (whole crop window) owning `filter`, and its tile over the whole film
// as Film::GetFilmTile makes it.
pbrt::Film *peer_pbrt_v3_film_new(pbrt::Filter *filter, int res) {
    return new pbrt::Film(pbrt::Point2i(res, res),
                          pbrt::Bounds2f(pbrt::Point2f(0, 0), pbrt::Point2f(1, 1)),
                          std::unique_ptr<pbrt::Filter>(filter), 35.f, "", 1.f);
}

void peer_pbrt_v3_film_free(pbrt::Film *film) { delete film; }

pbrt::FilmTile *peer_pbrt_v3_tile_new(pbrt::Film *film, int res) {
    return film->GetFilmTile(pbrt::Bounds2i(pbrt::Point2i(0, 0), pbrt::Point2i(res, res)))
        .release();
}

void peer_pbrt_v3_tile_free(pbrt::FilmTile *tile) { delete tile; }

// FilmTile::AddSample of `n` samples (film positions and RGB radiances), weight 1.
void peer_pbrt_v3_tile_add(pbrt::FilmTile *tile, const float *p, const float *rgb, size_t n) {
    for (size_t k = 0; k < n; ++k) {
        tile->AddSample(pbrt::Point2f(p[2 * k], p[2 * k + 1]),
                        pbrt::Spectrum::FromRGB(rgb + 3 * k), 1.f);
    }
}

// A tile pixel: the RGB contribution sums and the filter weight sum.
void peer_pbrt_v3_tile_pixel(const pbrt::FilmTile *tile, int x, int y, float out[4]) {
    const pbrt::FilmTilePixel &px = tile->GetPixel(pbrt::Point2i(x, y));
    Float rgb[3];
    px.contribSum.ToRGB(rgb);
    out[0] = rgb[0];
    out[1] = rgb[1];
    out[2] = rgb[2];
    out[3] = px.filterWeightSum;
}

// A 16 x 16 table of `filter` over one quadrant of its support, sampled at cell centres as
// pbrt-v3's Film fills its filter table, and read for `n` offsets (x, y pairs, inside the
// support) the way FilmTile::AddSample indexes it. The table and the index arithmetic are
// written here: pbrt-v3 has no lookup function apart from AddSample.
struct Table {
    Float weights[16 * 16];
    pbrt::Vector2f invRadius;
};

Table *peer_pbrt_v3_table_new(const pbrt::Filter *filter) {
    auto *t = new Table;
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            pbrt::Point2f p((x + 0.5f) * filter->radius.x / 16, (y + 0.5f) * filter->radius.y / 16);
            t->weights[16 * y + x] = filter->Evaluate(p);
        }
    }
    t->invRadius = filter->invRadius;
    return t;
}

void peer_pbrt_v3_table_free(Table *t) { delete t; }

void peer_pbrt_v3_table_lookup(const Table *t, const float *xy, size_t n, float *out) {
    for (size_t k = 0; k < n; ++k) {
        const Float fx = std::abs(xy[2 * k] * t->invRadius.x * 16);
        const Float fy = std::abs(xy[2 * k + 1] * t->invRadius.y * 16);
        const int ix = std::min(int(std::floor(fx)), 15);
        const int iy = std::min(int(std::floor(fy)), 15);
        out[k] = t->weights[iy * 16 + ix];
    }
}

// RadicalInverse(d, a) (core/lowdiscrepancy.cpp: a switch over the bases, each a digit loop
// with its base a compile-time constant) for every index and d in 0..dims, index-major.
void peer_pbrt_v3_radical_inverse(const uint64_t *index, size_t n, int dims, float *out) {
    for (size_t k = 0; k < n; ++k) {
        for (int d = 0; d < dims; ++d) {
            *out++ = pbrt::RadicalInverse(d, index[k]);
        }
    }
}

// pbrt-v3's PCG32 RNG on sequence `seq`, and Shuffle of `count` blocks of `dims` floats.
pbrt::RNG *peer_pbrt_v3_rng_new(uint64_t seq) { return new pbrt::RNG(seq); }

void peer_pbrt_v3_rng_free(pbrt::RNG *rng) { delete rng; }

void peer_pbrt_v3_shuffle(pbrt::RNG *rng, float *buf, int count, int dims) {
    pbrt::Shuffle(buf, count, dims, *rng);
}

}  // extern "C"

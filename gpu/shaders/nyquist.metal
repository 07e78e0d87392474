// language: metal2.0
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct _mslBufferSizes {
    uint size0;
    uint size1;
    uint size2;
    uint size4;
    uint size5;
};

struct NyqCameraSample {
    metal::float2 p_film;
    metal::float2 lens;
    float time;
    char _pad3[4];
};
typedef uint type_4[1];
struct NyqSobol {
    uint dims;
    uint scrambled;
    metal::uint2 seed;
};
struct NyqSobolSampler {
    uint spp;
    uint m;
    uint scramble;
    char _pad3[4];
    metal::uint2 seed;
    char _pad4[8];
    metal::uint4 inverse0_;
    metal::uint4 inverse1_;
    metal::uint4 inverse2_;
    metal::uint4 inverse3_;
    metal::uint4 inverse4_;
    metal::uint4 inverse5_;
    metal::uint4 inverse6_;
    metal::uint4 inverse7_;
    metal::uint2 shift;
    uint index;
    uint dim;
};
struct type_7 {
    metal::uint2 inner[32];
};
struct type_8 {
    uint inner[32];
};
struct NyqOwenSobol {
    uint dims;
    uint shuffle_seed;
    uint key;
};
struct NyqOwenSobolSampler {
    metal::uint2 seed;
    uint frame;
    uint key;
    uint r;
    uint dim;
};
struct type_12 {
    float inner[5];
};
struct type_13 {
    uint inner[24];
};
struct NyqZSobolSampler {
    uint spp;
    uint log2_spp;
    uint log2_res;
    uint scramble;
    metal::uint2 seed;
    uint digits;
    uint sample_digits;
    uint odd;
    uint morton;
    uint dim;
    char _pad10[4];
};
struct NyqPcg32_ {
    metal::uint2 state;
};
struct NyqRandomSampler {
    metal::uint2 seed;
    metal::uint2 base;
    NyqPcg32_ rng;
    uint dim;
    char _pad4[4];
};
struct type_17 {
    metal::uint2 inner[2];
};
struct NyqLatticeSampler {
    uint lattice;
    uint n;
    uint g;
    char _pad3[4];
    metal::uint2 seed;
    metal::uint2 pixel;
    uint index;
    uint dim;
};
struct NyqLattice {
    uint lattice;
    uint n;
    uint g;
    uint dims;
    uint rotated;
    char _pad5[4];
    metal::uint2 seed;
};
struct type_21 {
    uint inner[5];
};
struct NyqPermutation {
    uint n;
    uint mask;
    uint half_;
    uint third;
    uint key;
    uint key2_;
    uint offset;
    char _pad7[4];
    metal::uint2 table;
};
struct NyqStratifiedSampler {
    uint xs;
    uint ys;
    uint spp;
    char _pad3[4];
    metal::packed_float3 inv;
    uint jitter;
    metal::uint2 seed;
    metal::uint2 pixel_key;
    metal::uint2 sample_key;
    uint index;
    uint dim;
};
struct type_24 {
    uint inner[16];
};
struct NyqPmj02_ {
    uint scrambled;
    char _pad1[4];
    metal::uint2 keys;
};
struct NyqPmj02Sampler {
    metal::uint2 seed;
    metal::uint2 pixel_key;
    uint index_rev;
    uint dim;
};
struct NyqRounding {
    metal::uint4 x;
    int e;
    uint sticky;
    uint twice;
    uint below;
};
struct NyqFraction {
    metal::uint4 num;
    metal::uint4 den;
    uint twice;
    uint below;
    char _pad4[8];
};
struct NyqHalton {
    uint dims;
    uint scramble;
    metal::uint2 seed;
};
struct NyqHaltonSampler {
    uint spp;
    uint scramble;
    metal::uint2 seed;
    metal::uint2 exponents;
    metal::uint2 scales;
    uint stride;
    char _pad6[4];
    metal::uint2 basis;
    metal::uint2 index;
    uint dim;
    char _pad9[4];
};
struct NyqBlueSampler {
    metal::uint2 seed;
    uint frame;
    char _pad2[4];
    metal::uint2 pixel;
    uint index;
    uint dim;
    metal::uint2 key;
    metal::uint2 prepared;
};
struct NyqFillJob {
    uint kind;
    uint scramble;
    uint spp;
    uint frame;
    metal::uint2 seed;
    metal::uint2 resolution;
    uint dims;
    uint implicit;
    uint first;
    uint count;
    uint lattice;
    uint generator;
    uint pad0_;
    uint pad1_;
};
typedef metal::uint4 type_28[1];
constant uint NYQ_SCRAMBLE_NONE = 0u;
constant uint NYQ_SCRAMBLE_PERMUTE_DIGITS = 1u;
constant uint NYQ_SCRAMBLE_FAST_OWEN = 2u;
constant uint NYQ_SCRAMBLE_OWEN = 3u;
constant uint NYQ_SOBOL_DIMS = 1024u;
constant type_13 NYQ_PERMUTATIONS_4_ = type_13 {{228u, 180u, 216u, 120u, 156u, 108u, 225u, 177u, 201u, 57u, 141u, 45u, 210u, 114u, 198u, 54u, 78u, 30u, 147u, 99u, 135u, 39u, 75u, 27u}};
constant metal::uint2 NYQ_PCG_MULTIPLIER = metal::uint2(1284865837u, 1481765933u);
constant metal::uint2 NYQ_RANDOM_INCREMENT = metal::uint2(2665069115u, 1250683170u);
constant uint NYQ_LATTICE_FIBONACCI = 0u;
constant uint NYQ_LATTICE_KOROBOV = 1u;
constant uint NYQ_LATTICE_R2_ = 2u;
constant type_17 NYQ_R2_ALPHA = type_17 {{metal::uint2(44445696u, 3242174889u), metal::uint2(3349051392u, 2447445413u)}};
constant type_8 NYQ_SMALL_PERMUTATIONS = type_8 {{16u, 1u, 528u, 288u, 513u, 33u, 258u, 18u, 12816u, 8976u, 12576u, 4896u, 8496u, 4656u, 12801u, 8961u, 12321u, 801u, 8241u, 561u, 12546u, 4866u, 12306u, 786u, 4146u, 306u, 8451u, 4611u, 8211u, 531u, 4131u, 291u}};
constant uint NYQ_JITTERED = 0u;
constant uint NYQ_CENTERED = 1u;
constant metal::uint2 NYQ_DIM_STEP = metal::uint2(2135587861u, 2654435769u);
constant metal::uint2 NYQ_JITTER_STEP = metal::uint2(668265295u, 3266489917u);
constant uint NYQ_PMJ02_TABLE_SEED = 0u;
constant uint NYQ_LCG_A = 747796405u;
constant uint NYQ_LCG_C = 2891336453u;
constant type_24 NYQ_PMJ02_XOR_X = type_24 {{0u, 0u, 2u, 6u, 6u, 14u, 54u, 78u, 22u, 46u, 630u, 1742u, 1814u, 3118u, 12406u, 16590u}};
constant type_24 NYQ_PMJ02_XOR_Y = type_24 {{0u, 1u, 3u, 3u, 7u, 27u, 39u, 11u, 23u, 315u, 871u, 907u, 1559u, 6203u, 8295u, 139u}};
constant uint NYQ_HALTON_WORDS = 24u;
constant uint NYQ_BELOW_ONE_BITS = 1065353215u;
constant uint NYQ_PRIME_COUNT = 1024u;
constant metal::uint2 NYQ_OWEN_TAG_UNIFORM = metal::uint2(1599426121u, 1331119438u);
constant metal::uint2 NYQ_OWEN_TAG_AFFINE = metal::uint2(1598113350u, 1331119438u);
constant metal::uint2 NYQ_OWEN_LEVEL_STEP = metal::uint2(2135587861u, 2654435769u);
constant metal::uint2 NYQ_OWEN_PREFIX_MUL = metal::uint2(656542357u, 1367130551u);
constant uint NYQ_BLUE_OWEN_SOBOL = 0u;
constant uint NYQ_BLUE_PMJ02_ = 1u;
constant uint NYQ_BLUE_LATTICE = 2u;
constant uint NYQ_BLUE_TILE_SIZE = 128u;
constant metal::uint4 NYQ_LATTICE_BN_GENERATOR = metal::uint4(1u, 364981u, 245389u, 97823u);
constant uint NYQ_FILL_OWEN_SOBOL_SAMPLER = 0u;
constant uint NYQ_FILL_ZSOBOL_SAMPLER = 1u;
constant uint NYQ_FILL_RANDOM_SAMPLER = 2u;
constant uint NYQ_FILL_LATTICE_SAMPLER = 3u;
constant uint NYQ_FILL_STRATIFIED_SAMPLER = 4u;
constant uint NYQ_FILL_PMJ02_SAMPLER = 5u;
constant uint NYQ_FILL_SOBOL_SAMPLER = 6u;
constant uint NYQ_FILL_HALTON_SAMPLER = 7u;
constant uint NYQ_FILL_OWEN_SOBOL_BN_SAMPLER = 8u;
constant uint NYQ_FILL_PMJ02_BN_SAMPLER = 9u;
constant uint NYQ_FILL_LATTICE_BN_SAMPLER = 10u;
constant uint NYQ_FILL_SOBOL = 16u;
constant uint NYQ_FILL_OWEN_SOBOL = 17u;
constant uint NYQ_FILL_PMJ02_ = 18u;
constant uint NYQ_FILL_HALTON = 19u;
constant uint NYQ_FILL_LATTICE = 20u;

metal::uint2 nyq_mul_wide(
    uint a,
    uint b
) {
    uint a0_ = a & 65535u;
    uint a1_ = a >> 16u;
    uint b0_ = b & 65535u;
    uint b1_ = b >> 16u;
    uint p00_ = a0_ * b0_;
    uint p01_ = a0_ * b1_;
    uint p10_ = a1_ * b0_;
    uint p11_ = a1_ * b1_;
    uint mid = ((p00_ >> 16u) + (p01_ & 65535u)) + (p10_ & 65535u);
    return metal::uint2((p00_ & 65535u) | (mid << 16u), ((p11_ + (p01_ >> 16u)) + (p10_ >> 16u)) + (mid >> 16u));
}

metal::uint2 nyq_mul64_(
    metal::uint2 a_1,
    metal::uint2 b_1
) {
    metal::uint2 _e4 = nyq_mul_wide(a_1.x, b_1.x);
    return metal::uint2(_e4.x, (_e4.y + (a_1.x * b_1.y)) + (a_1.y * b_1.x));
}

metal::uint2 nyq_add64_(
    metal::uint2 a_2,
    metal::uint2 b_2
) {
    uint low_1 = a_2.x + b_2.x;
    return metal::uint2(low_1, (a_2.y + b_2.y) + ((low_1 < a_2.x) ? 1u : 0u));
}

metal::uint2 nyq_shr64_(
    metal::uint2 a_3,
    uint s_11
) {
    return metal::uint2((a_3.x >> s_11) | (a_3.y << (32u - s_11)), a_3.y >> s_11);
}

metal::uint2 nyq_shl64_(
    metal::uint2 a_4,
    uint s_12
) {
    return metal::uint2(a_4.x << s_12, (a_4.y << s_12) | (a_4.x >> (32u - s_12)));
}

metal::uint2 nyq_u64_(
    uint x
) {
    return metal::uint2(x, 0u);
}

uint nyq_mix32_(
    uint x_in
) {
    uint x_1 = {};
    x_1 = x_in;
    uint _e2 = x_1;
    uint _e3 = x_1;
    x_1 = _e2 ^ (_e3 >> 16u);
    uint _e7 = x_1;
    x_1 = _e7 * 2146121005u;
    uint _e10 = x_1;
    uint _e11 = x_1;
    x_1 = _e10 ^ (_e11 >> 15u);
    uint _e15 = x_1;
    x_1 = _e15 * 2221713035u;
    uint _e18 = x_1;
    uint _e19 = x_1;
    return _e18 ^ (_e19 >> 16u);
}

metal::uint2 nyq_mix64_(
    metal::uint2 x_in_1
) {
    metal::uint2 x_2 = {};
    x_2 = x_in_1;
    metal::uint2 _e2 = x_2;
    metal::uint2 _e3 = x_2;
    metal::uint2 _e5 = nyq_shr64_(_e3, 30u);
    x_2 = _e2 ^ _e5;
    metal::uint2 _e7 = x_2;
    metal::uint2 _e11 = nyq_mul64_(_e7, metal::uint2(484763065u, 3210233709u));
    x_2 = _e11;
    metal::uint2 _e12 = x_2;
    metal::uint2 _e13 = x_2;
    metal::uint2 _e15 = nyq_shr64_(_e13, 27u);
    x_2 = _e12 ^ _e15;
    metal::uint2 _e17 = x_2;
    metal::uint2 _e21 = nyq_mul64_(_e17, metal::uint2(321982955u, 2496678331u));
    x_2 = _e21;
    metal::uint2 _e22 = x_2;
    metal::uint2 _e23 = x_2;
    metal::uint2 _e25 = nyq_shr64_(_e23, 31u);
    return _e22 ^ _e25;
}

metal::uint2 nyq_hash2_(
    metal::uint2 a_5,
    metal::uint2 b_3
) {
    metal::uint2 golden = metal::uint2(2135587861u, 2654435769u);
    metal::uint2 golden2_ = metal::uint2(4271175722u, 1013904242u);
    metal::uint2 _e8 = nyq_add64_(a_5, golden);
    metal::uint2 _e9 = nyq_mix64_(_e8);
    metal::uint2 _e10 = nyq_add64_(b_3, golden2_);
    metal::uint2 _e12 = nyq_mix64_(_e9 ^ _e10);
    return _e12;
}

metal::uint2 nyq_hash4_(
    metal::uint2 a_6,
    metal::uint2 b_4,
    metal::uint2 c,
    metal::uint2 d
) {
    metal::uint2 golden_1 = metal::uint2(2135587861u, 2654435769u);
    metal::uint2 _e7 = nyq_hash2_(golden_1, a_6);
    metal::uint2 _e8 = nyq_hash2_(_e7, b_4);
    metal::uint2 _e9 = nyq_hash2_(_e8, c);
    metal::uint2 _e10 = nyq_hash2_(_e9, d);
    return _e10;
}

float nyq_fraction_to_f32_(
    uint v
) {
    return static_cast<float>(v >> 8u) * 0.000000059604645;
}

uint nyq_round_up_pow2_(
    uint n
) {
    return (n <= 1u) ? 1u : (1u << (32u - metal::clz(n - 1u)));
}

float nyq_rev_to_f32_(
    uint w_rev
) {
    float _e2 = nyq_fraction_to_f32_(metal::reverse_bits(w_rev));
    return _e2;
}

uint nyq_shr(
    uint x_3,
    uint s_13
) {
    return (s_13 >= 32u) ? 0u : (x_3 >> (s_13 & 31u));
}

float nyq_film_coordinate(
    uint pixel,
    float offset
) {
    float base_2 = static_cast<float>(pixel);
    float x_26 = base_2 + offset;
    float edge = base_2 + 1.0;
    if (x_26 < edge) {
        return x_26;
    }
    float below = as_type<float>(as_type<uint>(edge) - 1u);
    return (below >= base_2) ? below : base_2;
}

uint nyq_lk_hash(
    uint x_rev,
    uint seed
) {
    uint x_4 = {};
    x_4 = x_rev ^ (x_rev * 1025551850u);
    uint _e6 = x_4;
    x_4 = (_e6 + seed) * ((seed >> 16u) | 1u);
    uint _e13 = x_4;
    uint _e14 = x_4;
    x_4 = _e13 ^ (_e14 * 89287766u);
    uint _e18 = x_4;
    uint _e19 = x_4;
    x_4 = _e18 ^ (_e19 * 1403136100u);
    uint _e23 = x_4;
    return _e23;
}

uint nyq_fast_owen_scramble(
    uint x_5,
    uint seed_1
) {
    uint _e5 = nyq_mix32_(seed_1 ^ 1779033703u);
    uint _e6 = nyq_lk_hash(metal::reverse_bits(x_5), _e5);
    return metal::reverse_bits(_e6);
}

uint nyq_nested_uniform_shuffle(
    uint index,
    uint seed_2
) {
    uint _e2 = nyq_fast_owen_scramble(index, seed_2);
    return _e2;
}

uint nyq_owen_scramble(
    uint x_6,
    uint seed_3
) {
    uint out = {};
    uint k_6 = 0u;
    uint _e4 = nyq_mix32_(seed_3 ^ 3144134277u);
    out = x_6;
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e41 = k_6;
            k_6 = _e41 + 1u;
        }
        loop_init = false;
        uint _e8 = k_6;
        if (_e8 < 32u) {
        } else {
            break;
        }
        {
            uint _e12 = k_6;
            uint _e18 = k_6;
            uint prefix = (_e18 == 0u) ? 0u : (x_6 >> ((32u - _e12) & 31u));
            uint _e23 = k_6;
            metal::uint2 word = metal::uint2((1u << _e23) | prefix, _e4);
            metal::uint2 _e27 = nyq_mix64_(word);
            if ((_e27.y >> 31u) == 1u) {
                uint _e33 = out;
                uint _e36 = k_6;
                out = _e33 ^ (1u << (31u - _e36));
            }
        }
    }
    uint _e43 = out;
    return _e43;
}

uint nyq_scramble_u32_(
    uint x_7,
    uint seed_4,
    uint how
) {
    switch(how) {
        case 1u: {
            uint _e5 = nyq_mix32_(seed_4 ^ 1013904242u);
            return x_7 ^ _e5;
        }
        case 2u: {
            uint _e7 = nyq_fast_owen_scramble(x_7, seed_4);
            return _e7;
        }
        case 3u: {
            uint _e8 = nyq_owen_scramble(x_7, seed_4);
            return _e8;
        }
        default: {
            return x_7;
        }
    }
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % metal::select(rhs, 1u, rhs == 0u);
}

uint nyq_sobol_u32_(
    uint index_1,
    uint dim,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint v_1 = 0u;
    uint bits = {};
    uint base_3 = naga_mod(dim, NYQ_SOBOL_DIMS) * 32u;
    bits = index_1;
    uint2 loop_bound_1 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e9 = bits;
        if (_e9 != 0u) {
        } else {
            break;
        }
        {
            uint _e12 = v_1;
            uint _e14 = bits;
            uint _e18 = nyq_sobol_matrices[base_3 + metal::ctz(_e14)];
            v_1 = _e12 ^ _e18;
            uint _e20 = bits;
            uint _e21 = bits;
            bits = _e20 & (_e21 - 1u);
        }
    }
    uint _e25 = v_1;
    return _e25;
}

uint nyq_sobol_rev(
    uint r,
    uint dim_1,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = nyq_sobol_u32_(metal::reverse_bits(r), dim_1, nyq_sobol_matrices, _buffer_sizes);
    return metal::reverse_bits(_e3);
}

NyqSobol nyq_sobol(
    uint dims,
    bool scrambled,
    metal::uint2 seed_5
) {
    return NyqSobol {dims, scrambled ? 1u : 0u, seed_5};
}

uint nyq_sobol_sample_u32_(
    NyqSobol s_14,
    uint index_2,
    uint dim_2,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint shift = 0u;
    uint d_9 = naga_mod(dim_2, s_14.dims);
    if (s_14.scrambled != 0u) {
        metal::uint2 _e11 = nyq_u64_(d_9);
        metal::uint2 _e12 = nyq_hash2_(s_14.seed, _e11);
        shift = _e12.y;
    }
    uint _e14 = nyq_sobol_u32_(index_2, d_9, nyq_sobol_matrices, _buffer_sizes);
    uint _e15 = shift;
    return _e14 ^ _e15;
}

float nyq_sobol_sample(
    NyqSobol s_15,
    uint index_3,
    uint dim_3,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = nyq_sobol_sample_u32_(s_15, index_3, dim_3, nyq_sobol_matrices, _buffer_sizes);
    float _e4 = nyq_fraction_to_f32_(_e3);
    return _e4;
}

uint nyq_top(
    uint v_2,
    uint bits_1
) {
    return (bits_1 == 0u) ? 0u : (v_2 >> ((32u - bits_1) & 31u));
}

NyqSobolSampler nyq_sobol_sampler(
    metal::uint2 resolution,
    uint spp_requested,
    uint scramble,
    metal::uint2 seed_in,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint2 seed_6 = {};
    metal::uint2 shift_1 = metal::uint2(0u, 0u);
    type_7 rows = {};
    uint c_1 = 0u;
    uint i = {};
    uint i_1 = 0u;
    uint col = 0u;
    uint pivot = {};
    uint r_1 = {};
    uint r_2 = {};
    bool local = {};
    type_8 inverse = {};
    uint i_2 = 0u;
    uint r_3 = {};
    uint _e4 = nyq_round_up_pow2_(spp_requested);
    uint side = metal::max(resolution.x, resolution.y);
    uint m_5 = 32u - metal::clz(side - 1u);
    seed_6 = seed_in;
    if (scramble == NYQ_SCRAMBLE_NONE) {
        seed_6 = metal::uint2(0u, 0u);
    }
    if (scramble == NYQ_SCRAMBLE_PERMUTE_DIGITS) {
        uint mask = (m_5 == 0u) ? 4294967295u : (4294967295u >> (m_5 & 31u));
        metal::uint2 _e33 = seed_6;
        metal::uint2 _e35 = nyq_u64_(0u);
        metal::uint2 _e36 = nyq_hash2_(_e33, _e35);
        metal::uint2 _e39 = seed_6;
        metal::uint2 _e41 = nyq_u64_(1u);
        metal::uint2 _e42 = nyq_hash2_(_e39, _e41);
        shift_1 = metal::uint2(_e36.x & mask, _e42.x & mask);
    }
    uint n_8 = 2u * m_5;
    uint2 loop_bound_2 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_2 == uint2(0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e111 = c_1;
            c_1 = _e111 + 1u;
        }
        loop_init_1 = false;
        uint _e51 = c_1;
        if (_e51 < n_8) {
        } else {
            break;
        }
        {
            uint _e54 = c_1;
            uint _e57 = nyq_sobol_u32_(1u << _e54, 0u, nyq_sobol_matrices, _buffer_sizes);
            uint _e58 = nyq_top(_e57, m_5);
            uint _e60 = c_1;
            uint _e63 = nyq_sobol_u32_(1u << _e60, 1u, nyq_sobol_matrices, _buffer_sizes);
            uint _e64 = nyq_top(_e63, m_5);
            metal::uint2 image_bits = metal::uint2(_e58 | (_e64 << (m_5 & 31u)), (m_5 == 0u) ? 0u : (_e64 >> ((32u - m_5) & 31u)));
            i = 0u;
            uint2 loop_bound_3 = uint2(4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (metal::all(loop_bound_3 == uint2(0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e108 = i;
                    i = _e108 + 1u;
                }
                loop_init_2 = false;
                uint _e81 = i;
                if (_e81 < n_8) {
                } else {
                    break;
                }
                {
                    uint _e84 = i;
                    uint _e87 = i;
                    uint _e91 = i;
                    uint bit = ((_e91 >= 32u) ? (image_bits.y >> (_e87 - 32u)) : (image_bits.x >> _e84)) & 1u;
                    if (bit == 1u) {
                        uint _e99 = i;
                        uint _e102 = rows.inner[_e99].x;
                        uint _e104 = c_1;
                        rows.inner[_e99].x = _e102 | (1u << _e104);
                    }
                }
            }
        }
    }
    uint2 loop_bound_4 = uint2(4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (metal::all(loop_bound_4 == uint2(0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e126 = i_1;
            i_1 = _e126 + 1u;
        }
        loop_init_3 = false;
        uint _e115 = i_1;
        if (_e115 < n_8) {
        } else {
            break;
        }
        {
            uint _e117 = i_1;
            uint _e120 = rows.inner[_e117].y;
            uint _e122 = i_1;
            rows.inner[_e117].y = _e120 | (1u << _e122);
        }
    }
    uint2 loop_bound_5 = uint2(4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (metal::all(loop_bound_5 == uint2(0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e194 = col;
            col = _e194 + 1u;
        }
        loop_init_4 = false;
        uint _e130 = col;
        if (_e130 < n_8) {
        } else {
            break;
        }
        {
            uint _e132 = col;
            pivot = _e132;
            uint _e134 = col;
            r_1 = _e134;
            uint2 loop_bound_6 = uint2(4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (metal::all(loop_bound_6 == uint2(0u))) { break; }
                loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e150 = r_1;
                    r_1 = _e150 + 1u;
                }
                loop_init_5 = false;
                uint _e136 = r_1;
                if (_e136 < n_8) {
                } else {
                    break;
                }
                {
                    uint _e138 = r_1;
                    uint _e141 = rows.inner[_e138].x;
                    uint _e142 = col;
                    if (((_e141 >> _e142) & 1u) == 1u) {
                        uint _e148 = r_1;
                        pivot = _e148;
                        break;
                    }
                }
            }
            uint _e152 = col;
            metal::uint2 t_6 = rows.inner[_e152];
            uint _e155 = col;
            uint _e157 = pivot;
            metal::uint2 _e159 = rows.inner[_e157];
            rows.inner[_e155] = _e159;
            uint _e160 = pivot;
            rows.inner[_e160] = t_6;
            r_2 = 0u;
            uint2 loop_bound_7 = uint2(4294967295u);
            bool loop_init_6 = true;
            while(true) {
                if (metal::all(loop_bound_7 == uint2(0u))) { break; }
                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                if (!loop_init_6) {
                    uint _e191 = r_2;
                    r_2 = _e191 + 1u;
                }
                loop_init_6 = false;
                uint _e164 = r_2;
                if (_e164 < n_8) {
                } else {
                    break;
                }
                {
                    uint _e166 = r_2;
                    uint _e167 = col;
                    if (_e166 != _e167) {
                        uint _e171 = r_2;
                        uint _e174 = rows.inner[_e171].x;
                        uint _e175 = col;
                        local = ((_e174 >> _e175) & 1u) == 1u;
                    } else {
                        local = false;
                    }
                    bool _e182 = local;
                    if (_e182) {
                        uint _e183 = r_2;
                        metal::uint2 _e185 = rows.inner[_e183];
                        uint _e186 = col;
                        metal::uint2 _e188 = rows.inner[_e186];
                        rows.inner[_e183] = _e185 ^ _e188;
                    }
                }
            }
        }
    }
    uint2 loop_bound_8 = uint2(4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (metal::all(loop_bound_8 == uint2(0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e226 = i_2;
            i_2 = _e226 + 1u;
        }
        loop_init_7 = false;
        uint _e199 = i_2;
        if (_e199 < n_8) {
        } else {
            break;
        }
        {
            r_3 = 0u;
            uint2 loop_bound_9 = uint2(4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (metal::all(loop_bound_9 == uint2(0u))) { break; }
                loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e223 = r_3;
                    r_3 = _e223 + 1u;
                }
                loop_init_8 = false;
                uint _e203 = r_3;
                if (_e203 < n_8) {
                } else {
                    break;
                }
                {
                    uint _e205 = i_2;
                    uint _e208 = rows.inner[_e205].y;
                    uint _e209 = r_3;
                    if (((_e208 >> _e209) & 1u) == 1u) {
                        uint _e215 = r_3;
                        uint _e217 = inverse.inner[_e215];
                        uint _e219 = i_2;
                        inverse.inner[_e215] = _e217 | (1u << _e219);
                    }
                }
            }
        }
    }
    uint _e229 = inverse.inner[0];
    uint _e231 = inverse.inner[1];
    uint _e233 = inverse.inner[2];
    uint _e235 = inverse.inner[3];
    metal::uint4 v0_ = metal::uint4(_e229, _e231, _e233, _e235);
    uint _e238 = inverse.inner[4];
    uint _e240 = inverse.inner[5];
    uint _e242 = inverse.inner[6];
    uint _e244 = inverse.inner[7];
    metal::uint4 v1_ = metal::uint4(_e238, _e240, _e242, _e244);
    uint _e247 = inverse.inner[8];
    uint _e249 = inverse.inner[9];
    uint _e251 = inverse.inner[10];
    uint _e253 = inverse.inner[11];
    metal::uint4 v2_ = metal::uint4(_e247, _e249, _e251, _e253);
    uint _e256 = inverse.inner[12];
    uint _e258 = inverse.inner[13];
    uint _e260 = inverse.inner[14];
    uint _e262 = inverse.inner[15];
    metal::uint4 v3_ = metal::uint4(_e256, _e258, _e260, _e262);
    uint _e265 = inverse.inner[16];
    uint _e267 = inverse.inner[17];
    uint _e269 = inverse.inner[18];
    uint _e271 = inverse.inner[19];
    metal::uint4 v4_ = metal::uint4(_e265, _e267, _e269, _e271);
    uint _e274 = inverse.inner[20];
    uint _e276 = inverse.inner[21];
    uint _e278 = inverse.inner[22];
    uint _e280 = inverse.inner[23];
    metal::uint4 v5_ = metal::uint4(_e274, _e276, _e278, _e280);
    uint _e283 = inverse.inner[24];
    uint _e285 = inverse.inner[25];
    uint _e287 = inverse.inner[26];
    uint _e289 = inverse.inner[27];
    metal::uint4 v6_ = metal::uint4(_e283, _e285, _e287, _e289);
    uint _e292 = inverse.inner[28];
    uint _e294 = inverse.inner[29];
    uint _e296 = inverse.inner[30];
    uint _e298 = inverse.inner[31];
    metal::uint4 v7_ = metal::uint4(_e292, _e294, _e296, _e298);
    metal::uint2 _e300 = seed_6;
    metal::uint2 _e301 = shift_1;
    return NyqSobolSampler {_e4, m_5, scramble, {}, _e300, {}, v0_, v1_, v2_, v3_, v4_, v5_, v6_, v7_, _e301, 0u, 0u};
}

uint nyq_sobol_sampler_invert(
    thread NyqSobolSampler& s_16,
    uint t_in
) {
    uint low = 0u;
    uint t = {};
    metal::uint4 four = {};
    t = t_in;
    uint2 loop_bound_10 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_10 == uint2(0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        uint _e5 = t;
        if (_e5 != 0u) {
        } else {
            break;
        }
        {
            uint _e8 = t;
            uint k_19 = metal::ctz(_e8);
            four = metal::uint4 {};
            switch(k_19 >> 2u) {
                case 0u: {
                    metal::uint4 _e15 = s_16.inverse0_;
                    four = _e15;
                    break;
                }
                case 1u: {
                    metal::uint4 _e17 = s_16.inverse1_;
                    four = _e17;
                    break;
                }
                case 2u: {
                    metal::uint4 _e19 = s_16.inverse2_;
                    four = _e19;
                    break;
                }
                case 3u: {
                    metal::uint4 _e21 = s_16.inverse3_;
                    four = _e21;
                    break;
                }
                case 4u: {
                    metal::uint4 _e23 = s_16.inverse4_;
                    four = _e23;
                    break;
                }
                case 5u: {
                    metal::uint4 _e25 = s_16.inverse5_;
                    four = _e25;
                    break;
                }
                case 6u: {
                    metal::uint4 _e27 = s_16.inverse6_;
                    four = _e27;
                    break;
                }
                default: {
                    metal::uint4 _e29 = s_16.inverse7_;
                    four = _e29;
                    break;
                }
            }
            uint _e30 = low;
            uint _e34 = four[k_19 & 3u];
            low = _e30 ^ _e34;
            uint _e36 = t;
            uint _e37 = t;
            t = _e36 & (_e37 - 1u);
        }
    }
    uint _e41 = low;
    return _e41;
}

uint nyq_sobol_sampler_index(
    thread NyqSobolSampler& s_17,
    metal::uint2 pixel_1,
    uint sample_index,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint m_6 = s_17.m;
    uint _e6 = s_17.spp;
    uint si = naga_mod(sample_index, _e6);
    uint high = ((2u * m_6) >= 32u) ? 0u : (si << ((2u * m_6) & 31u));
    uint mask_1 = (m_6 == 0u) ? 0u : (4294967295u >> ((32u - m_6) & 31u));
    uint want = (pixel_1.x & mask_1) | ((pixel_1.y & mask_1) << (m_6 & 31u));
    uint _e38 = nyq_sobol_u32_(high, 0u, nyq_sobol_matrices, _buffer_sizes);
    uint _e39 = nyq_top(_e38, m_6);
    uint _e41 = nyq_sobol_u32_(high, 1u, nyq_sobol_matrices, _buffer_sizes);
    uint _e42 = nyq_top(_e41, m_6);
    uint have = _e39 | (_e42 << (m_6 & 31u));
    uint _e48 = nyq_sobol_sampler_invert(s_17, want ^ have);
    return high | _e48;
}

float nyq_sobol_sampler_value(
    thread NyqSobolSampler& s_18,
    uint dim_4,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint v_3 = {};
    bool local_1 = {};
    bool local_2 = {};
    uint d_10 = naga_mod(dim_4, NYQ_SOBOL_DIMS);
    metal::uint2 seed_35 = s_18.seed;
    uint _e7 = s_18.index;
    uint _e8 = nyq_sobol_u32_(_e7, d_10, nyq_sobol_matrices, _buffer_sizes);
    v_3 = _e8;
    uint how_3 = s_18.scramble;
    if (!((how_3 == NYQ_SCRAMBLE_FAST_OWEN))) {
        local_1 = how_3 == NYQ_SCRAMBLE_OWEN;
    } else {
        local_1 = true;
    }
    bool _e20 = local_1;
    if (_e20) {
        uint _e21 = v_3;
        uint _e22 = v_3;
        uint _e24 = s_18.m;
        if (d_10 < 2u) {
            uint _e33 = s_18.m;
            local_2 = _e33 < 32u;
        } else {
            local_2 = false;
        }
        bool _e37 = local_2;
        uint w_1 = _e37 ? (_e22 << (_e24 & 31u)) : _e21;
        metal::uint2 _e39 = nyq_u64_(d_10);
        metal::uint2 _e40 = nyq_hash2_(seed_35, _e39);
        uint _e42 = nyq_scramble_u32_(w_1, _e40.y, how_3);
        float _e43 = nyq_fraction_to_f32_(_e42);
        return _e43;
    }
    if (d_10 < 2u) {
        uint _e46 = v_3;
        uint _e49 = s_18.shift[d_10];
        uint _e52 = s_18.m;
        v_3 = (_e46 ^ _e49) << _e52;
    } else {
        if (how_3 == NYQ_SCRAMBLE_PERMUTE_DIGITS) {
            uint _e56 = v_3;
            metal::uint2 _e57 = nyq_u64_(d_10);
            metal::uint2 _e58 = nyq_hash2_(seed_35, _e57);
            v_3 = _e56 ^ _e58.x;
        }
    }
    uint _e61 = v_3;
    float _e62 = nyq_fraction_to_f32_(_e61);
    return _e62;
}

void nyq_sobol_sampler_start(
    thread NyqSobolSampler& s_19,
    metal::uint2 pixel_2,
    uint sample_index_1,
    uint dim_5,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = nyq_sobol_sampler_index(s_19, pixel_2, sample_index_1, nyq_sobol_matrices, _buffer_sizes);
    s_19.index = _e5;
    s_19.dim = dim_5;
    return;
}

float nyq_sobol_sampler_get_1d(
    thread NyqSobolSampler& s_20,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_11 = s_20.dim;
    s_20.dim = d_11 + 1u;
    float _e6 = nyq_sobol_sampler_value(s_20, d_11, nyq_sobol_matrices, _buffer_sizes);
    return _e6;
}

metal::float2 nyq_sobol_sampler_get_2d(
    thread NyqSobolSampler& s_21,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_12 = s_21.dim;
    s_21.dim = d_12 + 2u;
    float _e6 = nyq_sobol_sampler_value(s_21, d_12, nyq_sobol_matrices, _buffer_sizes);
    float _e9 = nyq_sobol_sampler_value(s_21, d_12 + 1u, nyq_sobol_matrices, _buffer_sizes);
    return metal::float2(_e6, _e9);
}

metal::float2 nyq_sobol_sampler_get_pixel_2d(
    thread NyqSobolSampler& s_22,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = s_22.dim;
    s_22.dim = metal::max(_e3, 2u);
    float _e7 = nyq_sobol_sampler_value(s_22, 0u, nyq_sobol_matrices, _buffer_sizes);
    float _e9 = nyq_sobol_sampler_value(s_22, 1u, nyq_sobol_matrices, _buffer_sizes);
    return metal::float2(_e7, _e9);
}

NyqCameraSample nyq_sobol_sampler_camera_sample(
    thread NyqSobolSampler& s_23,
    metal::uint2 pixel_3,
    uint sample_index_2,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    nyq_sobol_sampler_start(s_23, pixel_3, sample_index_2, 0u, nyq_sobol_matrices, _buffer_sizes);
    metal::float2 _e4 = nyq_sobol_sampler_get_pixel_2d(s_23, nyq_sobol_matrices, _buffer_sizes);
    float _e5 = nyq_sobol_sampler_get_1d(s_23, nyq_sobol_matrices, _buffer_sizes);
    metal::float2 _e6 = nyq_sobol_sampler_get_2d(s_23, nyq_sobol_matrices, _buffer_sizes);
    float _e9 = nyq_film_coordinate(pixel_3.x, _e4.x);
    float _e12 = nyq_film_coordinate(pixel_3.y, _e4.y);
    metal::float2 film = metal::float2(_e9, _e12);
    return NyqCameraSample {film, _e6, _e5};
}

uint nyq_dim_seed(
    uint key,
    uint dim_6
) {
    uint _e5 = nyq_mix32_(key ^ (dim_6 * 2654435769u));
    return _e5;
}

uint nyq_shuffle_rev(
    uint index_4,
    uint shuffle_seed
) {
    uint _e3 = nyq_lk_hash(0u, shuffle_seed);
    uint fix = _e3 & 65535u;
    uint _e7 = nyq_lk_hash(metal::reverse_bits(index_4), shuffle_seed);
    return _e7 ^ fix;
}

uint nyq_owen_sobol_rev(
    uint r_4,
    uint dim_7,
    uint dim_seed,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e5 = nyq_sobol_rev(r_4, naga_mod(dim_7, NYQ_SOBOL_DIMS), nyq_sobol_matrices, _buffer_sizes);
    uint _e6 = nyq_lk_hash(_e5, dim_seed);
    return _e6;
}

NyqOwenSobol nyq_owen_sobol(
    uint dims_1,
    metal::uint2 seed_7
) {
    metal::uint2 _e3 = nyq_u64_(1331119438u);
    metal::uint2 _e4 = nyq_hash2_(seed_7, _e3);
    uint _e6 = nyq_mix32_(_e4.y);
    return NyqOwenSobol {dims_1, _e6, _e4.x};
}

uint nyq_owen_sobol_sample_u32_(
    NyqOwenSobol s_24,
    uint index_5,
    uint dim_8,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_13 = naga_mod(dim_8, s_24.dims);
    uint _e6 = nyq_shuffle_rev(index_5, s_24.shuffle_seed);
    uint _e8 = nyq_dim_seed(s_24.key, d_13);
    uint _e9 = nyq_owen_sobol_rev(_e6, d_13, _e8, nyq_sobol_matrices, _buffer_sizes);
    return metal::reverse_bits(_e9);
}

float nyq_owen_sobol_sample(
    NyqOwenSobol s_25,
    uint index_6,
    uint dim_9,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = nyq_owen_sobol_sample_u32_(s_25, index_6, dim_9, nyq_sobol_matrices, _buffer_sizes);
    float _e4 = nyq_fraction_to_f32_(_e3);
    return _e4;
}

metal::float4 nyq_owen_sobol_sample_4d(
    NyqOwenSobol s_26,
    uint index_7,
    uint first_dim,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float4 out_1 = {};
    uint k_7 = 0u;
    uint _e4 = nyq_shuffle_rev(index_7, s_26.shuffle_seed);
    uint2 loop_bound_11 = uint2(4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (metal::all(loop_bound_11 == uint2(0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e22 = k_7;
            k_7 = _e22 + 1u;
        }
        loop_init_9 = false;
        uint _e8 = k_7;
        if (_e8 < 4u) {
        } else {
            break;
        }
        {
            uint _e11 = k_7;
            uint d_14 = naga_mod(first_dim + _e11, s_26.dims);
            uint _e15 = k_7;
            uint _e18 = nyq_dim_seed(s_26.key, d_14);
            uint _e19 = nyq_owen_sobol_rev(_e4, d_14, _e18, nyq_sobol_matrices, _buffer_sizes);
            float _e20 = nyq_rev_to_f32_(_e19);
            out_1[_e15] = _e20;
        }
    }
    metal::float4 _e24 = out_1;
    return _e24;
}

NyqOwenSobolSampler nyq_owen_sobol_sampler(
    metal::uint2 seed_8,
    uint frame
) {
    return NyqOwenSobolSampler {seed_8, frame, 0u, 0u, 0u};
}

void nyq_owen_sobol_start(
    thread NyqOwenSobolSampler& s_27,
    metal::uint2 pixel_4,
    uint sample_index_3,
    uint dim_10
) {
    metal::uint2 _e5 = nyq_u64_(pixel_4.x);
    metal::uint2 _e7 = nyq_u64_(pixel_4.y);
    uint _e9 = s_27.frame;
    metal::uint2 _e10 = nyq_u64_(_e9);
    metal::uint2 _e12 = s_27.seed;
    metal::uint2 _e13 = nyq_hash4_(_e5, _e7, _e10, _e12);
    s_27.key = _e13.x;
    uint _e18 = nyq_mix32_(_e13.y);
    uint _e19 = nyq_shuffle_rev(sample_index_3, _e18);
    s_27.r = _e19;
    s_27.dim = dim_10;
    return;
}

float nyq_owen_sobol_value(
    thread NyqOwenSobolSampler& s_28,
    uint dim_11,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = s_28.r;
    uint _e5 = s_28.key;
    uint _e6 = nyq_dim_seed(_e5, dim_11);
    uint _e7 = nyq_owen_sobol_rev(_e3, dim_11, _e6, nyq_sobol_matrices, _buffer_sizes);
    float _e8 = nyq_rev_to_f32_(_e7);
    return _e8;
}

float nyq_owen_sobol_get_1d(
    thread NyqOwenSobolSampler& s_29,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_15 = s_29.dim;
    s_29.dim = d_15 + 1u;
    float _e6 = nyq_owen_sobol_value(s_29, d_15, nyq_sobol_matrices, _buffer_sizes);
    return _e6;
}

metal::float2 nyq_owen_sobol_get_2d(
    thread NyqOwenSobolSampler& s_30,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_16 = s_30.dim;
    s_30.dim = d_16 + 2u;
    float _e6 = nyq_owen_sobol_value(s_30, d_16, nyq_sobol_matrices, _buffer_sizes);
    float _e9 = nyq_owen_sobol_value(s_30, d_16 + 1u, nyq_sobol_matrices, _buffer_sizes);
    return metal::float2(_e6, _e9);
}

metal::float2 nyq_owen_sobol_get_pixel_2d(
    thread NyqOwenSobolSampler& s_31,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = s_31.dim;
    s_31.dim = metal::max(_e3, 2u);
    float _e7 = nyq_owen_sobol_value(s_31, 0u, nyq_sobol_matrices, _buffer_sizes);
    float _e9 = nyq_owen_sobol_value(s_31, 1u, nyq_sobol_matrices, _buffer_sizes);
    return metal::float2(_e7, _e9);
}

NyqCameraSample nyq_owen_sobol_camera_sample(
    thread NyqOwenSobolSampler& s_32,
    metal::uint2 pixel_5,
    uint sample_index_4,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    type_12 v_4 = {};
    uint d_1 = 0u;
    nyq_owen_sobol_start(s_32, pixel_5, sample_index_4, 0u);
    uint2 loop_bound_12 = uint2(4294967295u);
    bool loop_init_10 = true;
    while(true) {
        if (metal::all(loop_bound_12 == uint2(0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_10) {
            uint _e15 = d_1;
            d_1 = _e15 + 1u;
        }
        loop_init_10 = false;
        uint _e7 = d_1;
        if (_e7 < 5u) {
        } else {
            break;
        }
        {
            uint _e10 = d_1;
            uint _e12 = d_1;
            float _e13 = nyq_owen_sobol_value(s_32, _e12, nyq_sobol_matrices, _buffer_sizes);
            v_4.inner[_e10] = _e13;
        }
    }
    s_32.dim = 5u;
    float _e21 = v_4.inner[0];
    float _e22 = nyq_film_coordinate(pixel_5.x, _e21);
    float _e25 = v_4.inner[1];
    float _e26 = nyq_film_coordinate(pixel_5.y, _e25);
    metal::float2 p_2 = metal::float2(_e22, _e26);
    float _e29 = v_4.inner[3];
    float _e31 = v_4.inner[4];
    float _e34 = v_4.inner[2];
    return NyqCameraSample {p_2, metal::float2(_e29, _e31), _e34};
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / metal::select(rhs, 1u, rhs == 0u);
}

NyqZSobolSampler nyq_zsobol_sampler(
    metal::uint2 resolution_1,
    uint spp_requested_1,
    uint scramble_1,
    metal::uint2 seed_9
) {
    uint _e4 = nyq_round_up_pow2_(spp_requested_1);
    uint side_1 = metal::max(resolution_1.x, resolution_1.y);
    uint log2_res = 32u - metal::clz(side_1 - 1u);
    uint log2_spp = metal::ctz(_e4);
    uint bits_3 = (2u * log2_res) + log2_spp;
    return NyqZSobolSampler {_e4, log2_spp, log2_res, scramble_1, seed_9, naga_div(bits_3, 2u), naga_div(log2_spp, 2u), log2_spp & 1u, 0u, 0u};
}

uint nyq_spread(
    uint x_in_2
) {
    uint x_8 = {};
    x_8 = x_in_2 & 65535u;
    uint _e4 = x_8;
    uint _e5 = x_8;
    x_8 = (_e4 | (_e5 << 8u)) & 16711935u;
    uint _e11 = x_8;
    uint _e12 = x_8;
    x_8 = (_e11 | (_e12 << 4u)) & 252645135u;
    uint _e18 = x_8;
    uint _e19 = x_8;
    x_8 = (_e18 | (_e19 << 2u)) & 858993459u;
    uint _e25 = x_8;
    uint _e26 = x_8;
    return (_e25 | (_e26 << 1u)) & 1431655765u;
}

uint nyq_zsobol_morton(
    NyqZSobolSampler s_33,
    metal::uint2 pixel_6
) {
    uint mask_2 = (s_33.log2_res == 0u) ? 0u : (4294967295u >> ((32u - s_33.log2_res) & 31u));
    uint _e16 = nyq_spread(pixel_6.x & mask_2);
    uint _e19 = nyq_spread(pixel_6.y & mask_2);
    return _e16 | (_e19 << 1u);
}

uint nyq_one_of_24_(
    uint h
) {
    metal::uint2 _e2 = nyq_mul_wide(h, 24u);
    return _e2.y;
}

metal::uint2 nyq_zsobol_dim_key(
    metal::uint2 seed_10,
    uint dim_12
) {
    metal::uint2 _e6 = nyq_hash2_(seed_10, metal::uint2(dim_12 ^ 1329745740u, 23123u));
    return _e6;
}

uint nyq_zsobol_pixel_node(
    uint higher,
    metal::uint2 key_1
) {
    metal::uint2 _e4 = nyq_shr64_(key_1, 16u);
    uint _e7 = nyq_mix32_(higher ^ _e4.x);
    uint _e8 = nyq_one_of_24_(_e7);
    return NYQ_PERMUTATIONS_4_.inner[_e8];
}

uint nyq_permuted_digit(
    uint perm,
    uint digit,
    uint shift_2
) {
    return ((perm >> (2u * digit)) & 3u) << shift_2;
}

metal::uint2 nyq_zsobol_pixel_word(
    uint pixel_morton,
    metal::uint2 key_2
) {
    metal::uint2 _e3 = nyq_shl64_(key_2, 17u);
    metal::uint2 rotated_1 = _e3 | metal::uint2(key_2.y >> 15u, 0u);
    metal::uint2 _e10 = nyq_u64_(pixel_morton);
    metal::uint2 _e12 = nyq_mix64_(_e10 ^ rotated_1);
    return _e12;
}

metal::uint2 nyq_zsobol_nested_word(
    metal::uint2 w,
    uint higher_1,
    uint shift_3
) {
    metal::uint2 tag = metal::uint2((higher_1 << 6u) | shift_3, higher_1 >> 26u);
    metal::uint2 _e12 = nyq_mul64_(tag, metal::uint2(2135587861u, 2654435769u));
    metal::uint2 _e17 = nyq_mul64_(w ^ _e12, metal::uint2(3516067075u, 3518319154u));
    return _e17;
}

uint nyq_zsobol_index(
    NyqZSobolSampler s_34,
    uint morton,
    metal::uint2 key_3
) {
    uint index_8 = 0u;
    uint i_3 = {};
    uint i_4 = {};
    i_3 = s_34.digits;
    uint2 loop_bound_13 = uint2(4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (metal::all(loop_bound_13 == uint2(0u))) { break; }
        loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e28 = i_3;
            i_3 = _e28 - 1u;
        }
        loop_init_11 = false;
        uint _e7 = i_3;
        if (_e7 > s_34.sample_digits) {
        } else {
            break;
        }
        {
            uint _e11 = i_3;
            uint shift_5 = (2u * (_e11 - 1u)) + s_34.odd;
            uint digit_2 = (morton >> shift_5) & 3u;
            uint _e20 = index_8;
            uint _e23 = nyq_shr(morton, shift_5 + 2u);
            uint _e24 = nyq_zsobol_pixel_node(_e23, key_3);
            uint _e25 = nyq_permuted_digit(_e24, digit_2, shift_5);
            index_8 = _e20 | _e25;
        }
    }
    uint _e31 = nyq_shr(morton, s_34.log2_spp);
    metal::uint2 _e32 = nyq_zsobol_pixel_word(_e31, key_3);
    uint sample = morton & (s_34.spp - 1u);
    i_4 = s_34.sample_digits;
    uint2 loop_bound_14 = uint2(4294967295u);
    bool loop_init_12 = true;
    while(true) {
        if (metal::all(loop_bound_14 == uint2(0u))) { break; }
        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
        if (!loop_init_12) {
            uint _e64 = i_4;
            i_4 = _e64 - 1u;
        }
        loop_init_12 = false;
        uint _e39 = i_4;
        if (_e39 > 0u) {
        } else {
            break;
        }
        {
            uint _e43 = i_4;
            uint shift_6 = (2u * (_e43 - 1u)) + s_34.odd;
            uint digit_3 = (sample >> shift_6) & 3u;
            uint _e54 = nyq_shr(sample, shift_6 + 2u);
            metal::uint2 _e55 = nyq_zsobol_nested_word(_e32, _e54, shift_6);
            uint _e57 = nyq_one_of_24_(_e55.y);
            uint _e58 = index_8;
            uint _e61 = nyq_permuted_digit(NYQ_PERMUTATIONS_4_.inner[_e57], digit_3, shift_6);
            index_8 = _e58 | _e61;
        }
    }
    if (s_34.odd == 1u) {
        uint _e69 = index_8;
        metal::uint2 _e75 = nyq_zsobol_nested_word(_e32, sample >> 1u, 0u);
        index_8 = _e69 | ((sample & 1u) ^ (_e75.y >> 31u));
    }
    uint _e81 = index_8;
    return _e81;
}

uint nyq_zsobol_sequence_index(
    NyqZSobolSampler s_35,
    metal::uint2 pixel_7,
    uint sample_index_5,
    uint dim_13
) {
    uint _e4 = nyq_zsobol_morton(s_35, pixel_7);
    uint morton_1 = (_e4 << s_35.log2_spp) | (sample_index_5 & (s_35.spp - 1u));
    metal::uint2 _e13 = nyq_zsobol_dim_key(s_35.seed, dim_13);
    uint _e14 = nyq_zsobol_index(s_35, morton_1, _e13);
    return _e14;
}

uint nyq_zsobol_dim0_(
    uint index_9,
    uint seed_11,
    uint how_1
) {
    if (how_1 == NYQ_SCRAMBLE_FAST_OWEN) {
        uint _e5 = nyq_lk_hash(index_9, seed_11);
        return metal::reverse_bits(_e5);
    }
    uint _e8 = nyq_scramble_u32_(metal::reverse_bits(index_9), seed_11, how_1);
    return _e8;
}

float nyq_zsobol_value_1d(
    thread NyqZSobolSampler& s_36,
    uint dim_14
) {
    metal::uint2 _e3 = s_36.seed;
    metal::uint2 _e4 = nyq_zsobol_dim_key(_e3, dim_14);
    NyqZSobolSampler _e5 = s_36;
    uint _e7 = s_36.morton;
    uint _e8 = nyq_zsobol_index(_e5, _e7, _e4);
    uint _e11 = s_36.scramble;
    uint _e12 = nyq_zsobol_dim0_(_e8, _e4.x, _e11);
    float _e13 = nyq_fraction_to_f32_(_e12);
    return _e13;
}

metal::float2 nyq_zsobol_value_2d(
    thread NyqZSobolSampler& s_37,
    uint dim_15,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint y = {};
    metal::uint2 _e3 = s_37.seed;
    metal::uint2 _e4 = nyq_zsobol_dim_key(_e3, dim_15);
    NyqZSobolSampler _e5 = s_37;
    uint _e7 = s_37.morton;
    uint _e8 = nyq_zsobol_index(_e5, _e7, _e4);
    uint _e11 = s_37.scramble;
    uint _e12 = nyq_zsobol_dim0_(_e8, _e4.x, _e11);
    uint _e15 = s_37.scramble;
    if (_e15 == NYQ_SCRAMBLE_FAST_OWEN) {
        uint _e19 = nyq_sobol_u32_(_e8, 1u, nyq_sobol_matrices, _buffer_sizes);
        uint _e22 = nyq_lk_hash(metal::reverse_bits(_e19), _e4.y);
        y = metal::reverse_bits(_e22);
    } else {
        uint _e25 = nyq_sobol_u32_(_e8, 1u, nyq_sobol_matrices, _buffer_sizes);
        uint _e28 = s_37.scramble;
        uint _e29 = nyq_scramble_u32_(_e25, _e4.y, _e28);
        y = _e29;
    }
    float _e30 = nyq_fraction_to_f32_(_e12);
    uint _e31 = y;
    float _e32 = nyq_fraction_to_f32_(_e31);
    return metal::float2(_e30, _e32);
}

void nyq_zsobol_start(
    thread NyqZSobolSampler& s_38,
    metal::uint2 pixel_8,
    uint sample_index_6,
    uint dim_16
) {
    NyqZSobolSampler _e5 = s_38;
    uint _e6 = nyq_zsobol_morton(_e5, pixel_8);
    uint _e8 = s_38.log2_spp;
    uint _e11 = s_38.spp;
    s_38.morton = (_e6 << _e8) | (sample_index_6 & (_e11 - 1u));
    s_38.dim = dim_16;
    return;
}

float nyq_zsobol_get_1d(
    thread NyqZSobolSampler& s_39
) {
    uint d_17 = s_39.dim;
    s_39.dim = d_17 + 1u;
    float _e6 = nyq_zsobol_value_1d(s_39, d_17);
    return _e6;
}

metal::float2 nyq_zsobol_get_2d(
    thread NyqZSobolSampler& s_40,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_18 = s_40.dim;
    s_40.dim = d_18 + 2u;
    metal::float2 _e6 = nyq_zsobol_value_2d(s_40, d_18, nyq_sobol_matrices, _buffer_sizes);
    return _e6;
}

metal::float2 nyq_zsobol_get_pixel_2d(
    thread NyqZSobolSampler& s_41,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = s_41.dim;
    s_41.dim = metal::max(_e3, 2u);
    metal::float2 _e7 = nyq_zsobol_value_2d(s_41, 0u, nyq_sobol_matrices, _buffer_sizes);
    return _e7;
}

NyqCameraSample nyq_zsobol_camera_sample(
    thread NyqZSobolSampler& s_42,
    metal::uint2 pixel_9,
    uint sample_index_7,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    nyq_zsobol_start(s_42, pixel_9, sample_index_7, 0u);
    metal::float2 _e5 = nyq_zsobol_value_2d(s_42, 0u, nyq_sobol_matrices, _buffer_sizes);
    float _e7 = nyq_zsobol_value_1d(s_42, 2u);
    metal::float2 _e9 = nyq_zsobol_value_2d(s_42, 3u, nyq_sobol_matrices, _buffer_sizes);
    s_42.dim = 5u;
    float _e14 = nyq_film_coordinate(pixel_9.x, _e5.x);
    float _e17 = nyq_film_coordinate(pixel_9.y, _e5.y);
    metal::float2 film_1 = metal::float2(_e14, _e17);
    return NyqCameraSample {film_1, _e9, _e7};
}

NyqPcg32_ nyq_pcg32_(
    metal::uint2 state
) {
    metal::uint2 _e2 = nyq_add64_(state, NYQ_RANDOM_INCREMENT);
    metal::uint2 _e4 = nyq_mul64_(_e2, NYQ_PCG_MULTIPLIER);
    metal::uint2 _e6 = nyq_add64_(_e4, NYQ_RANDOM_INCREMENT);
    return NyqPcg32_ {_e6};
}

uint nyq_pcg32_next(
    thread NyqPcg32_& g
) {
    metal::uint2 old = g.state;
    metal::uint2 _e5 = nyq_mul64_(old, NYQ_PCG_MULTIPLIER);
    metal::uint2 _e7 = nyq_add64_(_e5, NYQ_RANDOM_INCREMENT);
    g.state = _e7;
    metal::uint2 _e9 = nyq_shr64_(old, 18u);
    metal::uint2 _e12 = nyq_shr64_(_e9 ^ old, 27u);
    uint x_27 = _e12.x;
    uint rot = old.y >> 27u;
    return (x_27 >> rot) | (x_27 << ((32u - rot) & 31u));
}

void nyq_pcg32_advance(
    thread NyqPcg32_& g_1,
    uint delta
) {
    metal::uint2 acc_mult = metal::uint2(1u, 0u);
    metal::uint2 acc_plus = metal::uint2(0u, 0u);
    metal::uint2 cur_mult = NYQ_PCG_MULTIPLIER;
    metal::uint2 cur_plus = NYQ_RANDOM_INCREMENT;
    uint d_2 = {};
    d_2 = delta;
    uint2 loop_bound_15 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_15 == uint2(0u))) { break; }
        loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
        uint _e15 = d_2;
        if (_e15 > 0u) {
        } else {
            break;
        }
        {
            uint _e18 = d_2;
            if ((_e18 & 1u) != 0u) {
                metal::uint2 _e23 = acc_mult;
                metal::uint2 _e24 = cur_mult;
                metal::uint2 _e25 = nyq_mul64_(_e23, _e24);
                acc_mult = _e25;
                metal::uint2 _e26 = acc_plus;
                metal::uint2 _e27 = cur_mult;
                metal::uint2 _e28 = nyq_mul64_(_e26, _e27);
                metal::uint2 _e29 = cur_plus;
                metal::uint2 _e30 = nyq_add64_(_e28, _e29);
                acc_plus = _e30;
            }
            metal::uint2 _e31 = cur_mult;
            metal::uint2 _e35 = nyq_add64_(_e31, metal::uint2(1u, 0u));
            metal::uint2 _e36 = cur_plus;
            metal::uint2 _e37 = nyq_mul64_(_e35, _e36);
            cur_plus = _e37;
            metal::uint2 _e38 = cur_mult;
            metal::uint2 _e39 = cur_mult;
            metal::uint2 _e40 = nyq_mul64_(_e38, _e39);
            cur_mult = _e40;
            uint _e41 = d_2;
            d_2 = _e41 >> 1u;
        }
    }
    metal::uint2 _e45 = acc_mult;
    metal::uint2 _e47 = g_1.state;
    metal::uint2 _e48 = nyq_mul64_(_e45, _e47);
    metal::uint2 _e49 = acc_plus;
    metal::uint2 _e50 = nyq_add64_(_e48, _e49);
    g_1.state = _e50;
    return;
}

metal::uint2 nyq_hash3_(
    metal::uint2 a_7,
    metal::uint2 b_5,
    metal::uint2 c_2
) {
    metal::uint2 _e3 = nyq_hash2_(a_7, b_5);
    metal::uint2 _e7 = nyq_add64_(c_2, metal::uint2(2111796287u, 3668340012u));
    metal::uint2 _e9 = nyq_mix64_(_e3 ^ _e7);
    return _e9;
}

NyqRandomSampler nyq_random_sampler(
    metal::uint2 seed_12
) {
    return NyqRandomSampler {seed_12, metal::uint2(0u, 0u), NyqPcg32_ {metal::uint2(0u, 0u)}, 0u};
}

NyqPcg32_ nyq_random_at(
    thread NyqRandomSampler& s_43,
    uint dim_17
) {
    NyqPcg32_ g_2 = {};
    metal::uint2 _e3 = s_43.base;
    NyqPcg32_ _e4 = nyq_pcg32_(_e3);
    g_2 = _e4;
    if (dim_17 != 0u) {
        nyq_pcg32_advance(g_2, dim_17);
    }
    NyqPcg32_ _e8 = g_2;
    return _e8;
}

void nyq_random_start(
    thread NyqRandomSampler& s_44,
    metal::uint2 pixel_10,
    uint sample_index_8,
    uint dim_18
) {
    metal::uint2 _e5 = s_44.seed;
    metal::uint2 _e7 = nyq_u64_(1918987876u);
    metal::uint2 _e8 = nyq_hash3_(pixel_10, _e5, _e7);
    metal::uint2 golden_2 = metal::uint2(2135587861u, 2654435769u);
    metal::uint2 _e13 = nyq_u64_(sample_index_8);
    metal::uint2 _e14 = nyq_mul64_(_e13, golden_2);
    metal::uint2 _e16 = nyq_mix64_(_e8 ^ _e14);
    s_44.base = _e16;
    s_44.dim = dim_18;
    NyqPcg32_ _e19 = nyq_random_at(s_44, dim_18);
    s_44.rng = _e19;
    return;
}

float nyq_random_get_1d(
    thread NyqRandomSampler& s_45
) {
    NyqPcg32_ g_3 = {};
    NyqPcg32_ _e2 = s_45.rng;
    g_3 = _e2;
    uint _e4 = nyq_pcg32_next(g_3);
    float _e5 = nyq_fraction_to_f32_(_e4);
    NyqPcg32_ _e7 = g_3;
    s_45.rng = _e7;
    uint _e9 = s_45.dim;
    s_45.dim = _e9 + 1u;
    uint _e13 = s_45.dim;
    if (_e13 == 0u) {
        NyqPcg32_ _e18 = nyq_random_at(s_45, 0u);
        s_45.rng = _e18;
    }
    return _e5;
}

metal::float2 nyq_random_get_2d(
    thread NyqRandomSampler& s_46
) {
    float _e1 = nyq_random_get_1d(s_46);
    float _e2 = nyq_random_get_1d(s_46);
    return metal::float2(_e1, _e2);
}

metal::float2 nyq_random_get_pixel_2d(
    thread NyqRandomSampler& s_47
) {
    NyqPcg32_ g_4 = {};
    uint _e2 = s_47.dim;
    if (_e2 == 0u) {
        metal::float2 _e5 = nyq_random_get_2d(s_47);
        return _e5;
    }
    NyqPcg32_ _e7 = nyq_random_at(s_47, 0u);
    g_4 = _e7;
    uint _e9 = nyq_pcg32_next(g_4);
    float _e10 = nyq_fraction_to_f32_(_e9);
    uint _e11 = nyq_pcg32_next(g_4);
    float _e12 = nyq_fraction_to_f32_(_e11);
    metal::float2 p_3 = metal::float2(_e10, _e12);
    uint _e15 = s_47.dim;
    if (_e15 < 2u) {
        s_47.dim = 2u;
        NyqPcg32_ _e21 = g_4;
        s_47.rng = _e21;
    }
    return p_3;
}

NyqCameraSample nyq_random_camera_sample(
    thread NyqRandomSampler& s_48,
    metal::uint2 pixel_11,
    uint sample_index_9
) {
    nyq_random_start(s_48, pixel_11, sample_index_9, 0u);
    metal::float2 _e4 = nyq_random_get_pixel_2d(s_48);
    float _e5 = nyq_random_get_1d(s_48);
    metal::float2 _e6 = nyq_random_get_2d(s_48);
    float _e9 = nyq_film_coordinate(pixel_11.x, _e4.x);
    float _e12 = nyq_film_coordinate(pixel_11.y, _e4.y);
    metal::float2 film_2 = metal::float2(_e9, _e12);
    return NyqCameraSample {film_2, _e6, _e5};
}

uint nyq_mod64_(
    metal::uint2 x_9,
    uint n_1
) {
    uint r_5 = 0u;
    uint i_5 = 0u;
    bool local_3 = {};
    uint2 loop_bound_16 = uint2(4294967295u);
    bool loop_init_13 = true;
    while(true) {
        if (metal::all(loop_bound_16 == uint2(0u))) { break; }
        loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
        if (!loop_init_13) {
            uint _e42 = i_5;
            i_5 = _e42 + 1u;
        }
        loop_init_13 = false;
        uint _e6 = i_5;
        if (_e6 < 64u) {
        } else {
            break;
        }
        {
            uint _e11 = i_5;
            uint word_1 = (_e11 < 32u) ? x_9.y : x_9.x;
            uint _e16 = i_5;
            uint bit_1 = (word_1 >> (31u - (_e16 & 31u))) & 1u;
            uint _e23 = r_5;
            uint carry = _e23 >> 31u;
            uint _e26 = r_5;
            r_5 = (_e26 << 1u) | bit_1;
            if (!((carry == 1u))) {
                uint _e35 = r_5;
                local_3 = _e35 >= n_1;
            } else {
                local_3 = true;
            }
            bool _e38 = local_3;
            if (_e38) {
                uint _e39 = r_5;
                r_5 = _e39 - n_1;
            }
        }
    }
    uint _e44 = r_5;
    return _e44;
}

metal::uint2 nyq_fixed_ratio(
    uint num,
    uint den
) {
    uint r_6 = {};
    metal::uint2 q = metal::uint2(0u, 0u);
    uint i_6 = 0u;
    bool local_4 = {};
    r_6 = num;
    uint2 loop_bound_17 = uint2(4294967295u);
    bool loop_init_14 = true;
    while(true) {
        if (metal::all(loop_bound_17 == uint2(0u))) { break; }
        loop_bound_17 -= uint2(loop_bound_17.y == 0u, 1u);
        if (!loop_init_14) {
            uint _e37 = i_6;
            i_6 = _e37 + 1u;
        }
        loop_init_14 = false;
        uint _e9 = i_6;
        if (_e9 < 64u) {
        } else {
            break;
        }
        {
            uint _e12 = r_6;
            uint carry_1 = _e12 >> 31u;
            uint _e15 = r_6;
            r_6 = _e15 << 1u;
            metal::uint2 _e18 = q;
            metal::uint2 _e20 = nyq_shl64_(_e18, 1u);
            q = _e20;
            if (!((carry_1 == 1u))) {
                uint _e26 = r_6;
                local_4 = _e26 >= den;
            } else {
                local_4 = true;
            }
            bool _e29 = local_4;
            if (_e29) {
                uint _e30 = r_6;
                r_6 = _e30 - den;
                uint _e33 = q.x;
                q.x = _e33 | 1u;
            }
        }
    }
    metal::uint2 _e39 = q;
    return _e39;
}

float nyq_fixed_to_f32_(
    metal::uint2 x_10
) {
    return static_cast<float>(x_10.y >> 8u) * 0.000000059604645;
}

NyqLatticeSampler nyq_lattice_sampler(
    uint lattice,
    uint n_2,
    uint g_5,
    metal::uint2 seed_13
) {
    return NyqLatticeSampler {lattice, n_2, g_5, {}, seed_13, metal::uint2(0u, 0u), 0u, 0u};
}

float nyq_lattice_value(
    thread NyqLatticeSampler& s_49,
    uint dim_19
) {
    metal::uint2 base = {};
    uint g_6 = {};
    uint n_9 = s_49.n;
    uint _e5 = s_49.index;
    uint k_20 = naga_mod(_e5, n_9);
    uint component = naga_mod(dim_19, 2u);
    uint _e11 = s_49.lattice;
    switch(_e11) {
        case 2u: {
            metal::uint2 _e15 = nyq_u64_(k_20);
            metal::uint2 _e18 = nyq_mul64_(_e15, NYQ_R2_ALPHA.inner[component]);
            metal::uint2 _e19 = nyq_add64_(metal::uint2(0u, 2147483648u), _e18);
            base = _e19;
            break;
        }
        default: {
            uint _e21 = s_49.g;
            g_6 = _e21;
            if (component == 0u) {
                g_6 = naga_mod(1u, n_9);
            }
            uint _e27 = g_6;
            metal::uint2 _e28 = nyq_mul_wide(k_20, _e27);
            uint _e29 = nyq_mod64_(_e28, n_9);
            metal::uint2 _e30 = nyq_fixed_ratio(_e29, n_9);
            base = _e30;
            break;
        }
    }
    metal::uint2 _e32 = s_49.pixel;
    metal::uint2 _e35 = nyq_u64_(naga_div(dim_19, 2u));
    metal::uint2 _e37 = s_49.seed;
    metal::uint2 _e38 = nyq_hash3_(_e32, _e35, _e37);
    metal::uint2 _e39 = base;
    metal::uint2 _e40 = nyq_u64_(component);
    metal::uint2 _e41 = nyq_hash2_(_e38, _e40);
    metal::uint2 _e42 = nyq_add64_(_e39, _e41);
    float _e43 = nyq_fixed_to_f32_(_e42);
    return _e43;
}

void nyq_lattice_start(
    thread NyqLatticeSampler& s_50,
    metal::uint2 pixel_12,
    uint sample_index_10,
    uint dim_20
) {
    s_50.pixel = pixel_12;
    s_50.index = sample_index_10;
    s_50.dim = dim_20;
    return;
}

float nyq_lattice_get_1d(
    thread NyqLatticeSampler& s_51
) {
    uint d_19 = s_51.dim;
    s_51.dim = d_19 + 1u;
    float _e6 = nyq_lattice_value(s_51, d_19);
    return _e6;
}

metal::float2 nyq_lattice_get_2d(
    thread NyqLatticeSampler& s_52
) {
    uint d_20 = s_52.dim;
    s_52.dim = d_20 + 2u;
    float _e6 = nyq_lattice_value(s_52, d_20);
    float _e9 = nyq_lattice_value(s_52, d_20 + 1u);
    return metal::float2(_e6, _e9);
}

metal::float2 nyq_lattice_get_pixel_2d(
    thread NyqLatticeSampler& s_53
) {
    uint _e3 = s_53.dim;
    s_53.dim = metal::max(_e3, 2u);
    float _e7 = nyq_lattice_value(s_53, 0u);
    float _e9 = nyq_lattice_value(s_53, 1u);
    return metal::float2(_e7, _e9);
}

NyqCameraSample nyq_lattice_camera_sample(
    thread NyqLatticeSampler& s_54,
    metal::uint2 pixel_13,
    uint sample_index_11
) {
    nyq_lattice_start(s_54, pixel_13, sample_index_11, 0u);
    metal::float2 _e4 = nyq_lattice_get_pixel_2d(s_54);
    float _e5 = nyq_lattice_get_1d(s_54);
    metal::float2 _e6 = nyq_lattice_get_2d(s_54);
    float _e9 = nyq_film_coordinate(pixel_13.x, _e4.x);
    float _e12 = nyq_film_coordinate(pixel_13.y, _e4.y);
    metal::float2 film_3 = metal::float2(_e9, _e12);
    return NyqCameraSample {film_3, _e6, _e5};
}

uint nyq_pow_mod(
    uint b_6,
    uint e_in,
    uint n_3
) {
    uint base_1 = {};
    uint r_7 = {};
    uint e = {};
    base_1 = naga_mod(b_6, n_3);
    r_7 = naga_mod(1u, n_3);
    e = e_in;
    uint2 loop_bound_18 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_18 == uint2(0u))) { break; }
        loop_bound_18 -= uint2(loop_bound_18.y == 0u, 1u);
        uint _e9 = e;
        if (_e9 > 0u) {
        } else {
            break;
        }
        {
            uint _e12 = e;
            if ((_e12 & 1u) == 1u) {
                uint _e17 = r_7;
                uint _e18 = base_1;
                metal::uint2 _e19 = nyq_mul_wide(_e17, _e18);
                uint _e20 = nyq_mod64_(_e19, n_3);
                r_7 = _e20;
            }
            uint _e21 = base_1;
            uint _e22 = base_1;
            metal::uint2 _e23 = nyq_mul_wide(_e21, _e22);
            uint _e24 = nyq_mod64_(_e23, n_3);
            base_1 = _e24;
            uint _e25 = e;
            e = _e25 >> 1u;
        }
    }
    uint _e28 = r_7;
    return _e28;
}

NyqLattice nyq_lattice(
    uint lattice_1,
    uint n_4,
    uint g_7,
    uint dims_2,
    bool rotated,
    metal::uint2 seed_14
) {
    return NyqLattice {lattice_1, n_4, g_7, dims_2, rotated ? 1u : 0u, {}, seed_14};
}

metal::uint2 nyq_lattice_fixed(
    NyqLattice l,
    uint index_10,
    uint dim_21
) {
    metal::uint2 shift_4 = metal::uint2(0u, 0u);
    uint g_8 = {};
    uint d_21 = naga_mod(dim_21, l.dims);
    if (l.rotated != 0u) {
        metal::uint2 _e13 = nyq_u64_(d_21);
        metal::uint2 _e14 = nyq_hash2_(l.seed, _e13);
        shift_4 = _e14;
    }
    if (l.lattice == NYQ_LATTICE_R2_) {
        metal::uint2 _e21 = shift_4;
        metal::uint2 start = (l.rotated != 0u) ? _e21 : metal::uint2(0u, 2147483648u);
        metal::uint2 _e26 = nyq_u64_(index_10);
        metal::uint2 _e31 = nyq_mul64_(_e26, NYQ_R2_ALPHA.inner[d_21 & 1u]);
        metal::uint2 _e32 = nyq_add64_(start, _e31);
        return _e32;
    }
    g_8 = l.g;
    if (d_21 == 0u) {
        g_8 = naga_mod(1u, l.n);
    } else {
        if (d_21 > 1u) {
            uint _e44 = nyq_pow_mod(l.g, d_21, l.n);
            g_8 = _e44;
        }
    }
    uint _e47 = g_8;
    metal::uint2 _e48 = nyq_mul_wide(naga_mod(index_10, l.n), _e47);
    uint _e50 = nyq_mod64_(_e48, l.n);
    metal::uint2 _e52 = nyq_fixed_ratio(_e50, l.n);
    metal::uint2 _e53 = shift_4;
    metal::uint2 _e54 = nyq_add64_(_e52, _e53);
    return _e54;
}

float nyq_lattice_sample(
    NyqLattice l_1,
    uint index_11,
    uint dim_22
) {
    metal::uint2 _e3 = nyq_lattice_fixed(l_1, index_11, dim_22);
    float _e4 = nyq_fixed_to_f32_(_e3);
    return _e4;
}

metal::uint2 nyq_fixed_to_f64_bits(
    metal::uint2 x_11
) {
    bool local_5 = {};
    metal::uint2 frac = {};
    metal::uint2 _e2 = nyq_shr64_(x_11, 11u);
    if (_e2.x == 0u) {
        local_5 = _e2.y == 0u;
    } else {
        local_5 = false;
    }
    bool _e12 = local_5;
    if (_e12) {
        return metal::uint2(0u, 0u);
    }
    uint e_2 = (_e2.y != 0u) ? (63u - metal::clz(_e2.y)) : (31u - metal::clz(_e2.x));
    frac = _e2;
    uint s_103 = 52u - e_2;
    if (s_103 >= 32u) {
        frac = metal::uint2(0u, _e2.x << (s_103 - 32u));
    } else {
        if (s_103 > 0u) {
            metal::uint2 _e41 = nyq_shl64_(_e2, s_103);
            frac = _e41;
        }
    }
    uint _e43 = frac.x;
    uint _e45 = frac.y;
    return metal::uint2(_e43, (_e45 & 1048575u) | (((1023u + e_2) - 53u) << 20u));
}

float nyq_u32_to_f32_(
    uint x_12
) {
    uint m = {};
    bool local_6 = {};
    bool local_7 = {};
    if (x_12 < 16777216u) {
        return static_cast<float>(x_12);
    }
    uint top = 31u - metal::clz(x_12);
    uint drop = top - 23u;
    m = x_12 >> drop;
    uint rest_1 = x_12 & ((1u << drop) - 1u);
    uint half_ = 1u << (drop - 1u);
    if (!((rest_1 > half_))) {
        if (rest_1 == half_) {
            uint _e27 = m;
            local_7 = (_e27 & 1u) == 1u;
        } else {
            local_7 = false;
        }
        bool _e33 = local_7;
        local_6 = _e33;
    } else {
        local_6 = true;
    }
    bool _e35 = local_6;
    if (_e35) {
        uint _e36 = m;
        m = _e36 + 1u;
    }
    uint _e43 = m;
    return as_type<float>((((top + 127u) << 23u) + _e43) - 8388608u);
}

float nyq_recip_f32_(
    float x_13
) {
    uint r_8 = 16777216u;
    uint q_1 = 0u;
    uint i_7 = 0u;
    bool local_8 = {};
    bool local_9 = {};
    uint bits_4 = as_type<uint>(x_13);
    uint m_7 = (bits_4 & 8388607u) | 8388608u;
    int e_3 = as_type<int>(as_type<uint>(static_cast<int>(bits_4 >> 23u)) - as_type<uint>(127));
    if (m_7 == 8388608u) {
        return as_type<float>(static_cast<uint>(as_type<int>(as_type<uint>(127) - as_type<uint>(e_3))) << 23u);
    }
    uint2 loop_bound_19 = uint2(4294967295u);
    bool loop_init_15 = true;
    while(true) {
        if (metal::all(loop_bound_19 == uint2(0u))) { break; }
        loop_bound_19 -= uint2(loop_bound_19.y == 0u, 1u);
        if (!loop_init_15) {
            uint _e42 = i_7;
            i_7 = _e42 + 1u;
        }
        loop_init_15 = false;
        uint _e25 = i_7;
        if (_e25 < 25u) {
        } else {
            break;
        }
        {
            uint _e28 = q_1;
            q_1 = _e28 << 1u;
            uint _e31 = r_8;
            if (_e31 >= m_7) {
                uint _e33 = r_8;
                r_8 = _e33 - m_7;
                uint _e35 = q_1;
                q_1 = _e35 | 1u;
            }
            uint _e38 = r_8;
            r_8 = _e38 << 1u;
        }
    }
    uint _e44 = q_1;
    uint round = _e44 & 1u;
    uint _e47 = q_1;
    q_1 = _e47 >> 1u;
    if (round == 1u) {
        uint _e54 = r_8;
        if (!((_e54 != 0u))) {
            uint _e60 = q_1;
            local_9 = (_e60 & 1u) == 1u;
        } else {
            local_9 = true;
        }
        bool _e66 = local_9;
        local_8 = _e66;
    } else {
        local_8 = false;
    }
    bool _e68 = local_8;
    if (_e68) {
        uint _e69 = q_1;
        q_1 = _e69 + 1u;
    }
    uint _e79 = q_1;
    return as_type<float>(((static_cast<uint>(as_type<int>(as_type<uint>(as_type<int>(as_type<uint>(127) - as_type<uint>(e_3))) - as_type<uint>(1))) << 23u) + _e79) - 8388608u);
}

metal::uint3 nyq_mul64x32_(
    metal::uint2 r_9,
    uint k_8
) {
    metal::uint2 _e3 = nyq_mul_wide(r_9.x, k_8);
    metal::uint2 _e5 = nyq_mul_wide(r_9.y, k_8);
    metal::uint2 _e9 = nyq_add64_(_e5, metal::uint2(_e3.y, 0u));
    return metal::uint3(_e3.x, _e9.x, _e9.y);
}

uint nyq_nibble(
    metal::uint2 t_1,
    uint s_55
) {
    return (((s_55 >= 32u) ? t_1.y : t_1.x) >> (s_55 & 31u)) & 15u;
}

metal::uint2 nyq_shl64_any(
    metal::uint2 x_14,
    uint s_56
) {
    if (s_56 == 0u) {
        return x_14;
    }
    if (s_56 >= 32u) {
        return metal::uint2(0u, x_14.x << (s_56 - 32u));
    }
    metal::uint2 _e12 = nyq_shl64_(x_14, s_56);
    return _e12;
}

metal::uint2 nyq_packed_table(
    uint n_5,
    metal::uint2 r_in
) {
    metal::uint2 t_2 = metal::uint2(1985229328u, 4275878552u);
    metal::uint2 r_10 = {};
    uint k_9 = {};
    if (n_5 <= 4u) {
        if (n_5 < 2u) {
            return metal::uint2(0u, 0u);
        }
        type_21 factorial = type_21 {{1u, 1u, 2u, 6u, 24u}};
        type_21 start_1 = type_21 {{0u, 0u, 0u, 2u, 8u}};
        metal::uint3 _e22 = nyq_mul64x32_(r_in, factorial.inner[n_5]);
        uint rank = _e22.z;
        return metal::uint2(NYQ_SMALL_PERMUTATIONS.inner[(start_1.inner[n_5] + rank) & 31u], 0u);
    }
    if (n_5 < 16u) {
        uint keep = 4u * n_5;
        if (keep < 32u) {
            uint _e43 = t_2.x;
            t_2 = metal::uint2(_e43 & ((1u << keep) - 1u), 0u);
        } else {
            uint _e52 = t_2.y;
            t_2.y = _e52 & ((1u << (keep - 32u)) - 1u);
        }
    }
    r_10 = r_in;
    k_9 = n_5;
    uint2 loop_bound_20 = uint2(4294967295u);
    bool loop_init_16 = true;
    while(true) {
        if (metal::all(loop_bound_20 == uint2(0u))) { break; }
        loop_bound_20 -= uint2(loop_bound_20.y == 0u, 1u);
        if (!loop_init_16) {
            uint _e94 = k_9;
            k_9 = _e94 - 1u;
        }
        loop_init_16 = false;
        uint _e62 = k_9;
        if (_e62 > 1u) {
        } else {
            break;
        }
        {
            metal::uint2 _e65 = r_10;
            uint _e66 = k_9;
            metal::uint3 _e67 = nyq_mul64x32_(_e65, _e66);
            uint j_1 = _e67.z;
            r_10 = _e67.xy;
            uint _e71 = k_9;
            uint hi = 4u * (_e71 - 1u);
            uint lo = 4u * j_1;
            metal::uint2 _e77 = t_2;
            uint _e78 = nyq_nibble(_e77, hi);
            metal::uint2 _e79 = t_2;
            uint _e80 = nyq_nibble(_e79, lo);
            uint x_28 = (_e78 ^ _e80) & 15u;
            metal::uint2 _e84 = t_2;
            metal::uint2 _e87 = nyq_shl64_any(metal::uint2(x_28, 0u), hi);
            metal::uint2 _e90 = nyq_shl64_any(metal::uint2(x_28, 0u), lo);
            t_2 = _e84 ^ (_e87 | _e90);
        }
    }
    metal::uint2 _e96 = t_2;
    return _e96;
}

NyqPermutation nyq_permutation(
    uint n_in,
    uint seed_15
) {
    uint n_10 = metal::max(n_in, 1u);
    if (n_10 <= 16u) {
        metal::uint2 _e10 = nyq_mix64_(metal::uint2(seed_15 ^ 2242054355u, 608135816u));
        metal::uint2 _e11 = nyq_packed_table(n_10, _e10);
        return NyqPermutation {n_10, 0u, 0u, 0u, 0u, 0u, 0u, {}, _e11};
    }
    uint mask_3 = 4294967295u >> metal::clz(n_10 - 1u);
    uint bits_5 = 32u - metal::clz(mask_3);
    uint _e29 = nyq_mix32_(seed_15 ^ 1540483477u);
    uint _e32 = nyq_mix32_(_e29 + 1759714724u);
    uint _e35 = nyq_mix32_(_e32 ^ 625341585u);
    metal::uint2 _e36 = nyq_mul_wide(_e35, n_10);
    uint offset_3 = _e36.y;
    return NyqPermutation {n_10, mask_3, metal::max(naga_div(bits_5 + 1u, 2u), 1u), metal::max(naga_div(bits_5, 3u), 1u), _e29, _e32, offset_3, {}, metal::uint2(0u, 0u)};
}

uint nyq_permutation_apply(
    NyqPermutation p,
    uint i_8
) {
    uint x_15 = {};
    bool local_10 = {};
    uint n_11 = p.n;
    if (n_11 <= 16u) {
        uint _e11 = nyq_nibble(p.table, 4u * (naga_mod(i_8, n_11) & 15u));
        return _e11;
    }
    x_15 = naga_mod(i_8, n_11);
    uint2 loop_bound_21 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_21 == uint2(0u))) { break; }
        loop_bound_21 -= uint2(loop_bound_21.y == 0u, 1u);
        uint _e14 = x_15;
        x_15 = _e14 ^ (p.key & p.mask);
        uint _e19 = x_15;
        x_15 = (_e19 * 3782248765u) & p.mask;
        uint _e24 = x_15;
        uint _e25 = x_15;
        x_15 = _e24 ^ (_e25 >> p.half_);
        uint _e29 = x_15;
        x_15 = (_e29 + p.key2_) & p.mask;
        uint _e34 = x_15;
        x_15 = (_e34 * (p.key | 1u)) & p.mask;
        uint _e41 = x_15;
        uint _e42 = x_15;
        x_15 = _e41 ^ (_e42 >> p.half_);
        uint _e46 = x_15;
        x_15 = _e46 ^ ((p.key2_ >> 7u) & p.mask);
        uint _e53 = x_15;
        x_15 = (_e53 * 153742143u) & p.mask;
        uint _e58 = x_15;
        uint _e59 = x_15;
        x_15 = _e58 ^ (_e59 >> p.half_);
        uint _e63 = x_15;
        x_15 = (_e63 * (1765145193u ^ (p.key2_ & 4294967294u))) & p.mask;
        uint _e72 = x_15;
        uint _e73 = x_15;
        x_15 = _e72 ^ (_e73 >> p.third);
        uint _e77 = x_15;
        if (_e77 < n_11) {
            break;
        }
    }
    uint _e79 = x_15;
    uint q_3 = _e79 + p.offset;
    uint _e83 = x_15;
    if (!((q_3 < _e83))) {
        local_10 = q_3 >= n_11;
    } else {
        local_10 = true;
    }
    bool _e90 = local_10;
    return _e90 ? (q_3 - n_11) : q_3;
}

NyqStratifiedSampler nyq_stratified_sampler(
    uint xs,
    uint ys,
    uint jitter,
    metal::uint2 seed_16
) {
    uint spp_1 = xs * ys;
    float _e5 = nyq_u32_to_f32_(xs);
    float _e6 = nyq_recip_f32_(_e5);
    float _e7 = nyq_u32_to_f32_(ys);
    float _e8 = nyq_recip_f32_(_e7);
    float _e9 = nyq_u32_to_f32_(spp_1);
    float _e10 = nyq_recip_f32_(_e9);
    metal::float3 inv = metal::float3(_e6, _e8, _e10);
    metal::uint2 zero = metal::uint2(0u, 0u);
    return NyqStratifiedSampler {xs, ys, spp_1, {}, inv, jitter, seed_16, zero, zero, 0u, 0u};
}

uint nyq_stratified_dim_key(
    metal::uint2 pixel_key,
    uint dim_23
) {
    metal::uint2 _e2 = nyq_u64_(dim_23);
    metal::uint2 _e4 = nyq_mul64_(_e2, NYQ_DIM_STEP);
    metal::uint2 _e6 = nyq_mix64_(pixel_key ^ _e4);
    return _e6.x ^ _e6.y;
}

uint nyq_stratified_stratum(
    thread NyqStratifiedSampler& s_57,
    uint dim_24
) {
    if (dim_24 == 0u) {
        uint _e5 = s_57.index;
        uint _e7 = s_57.spp;
        return naga_mod(_e5, _e7);
    }
    uint _e10 = s_57.spp;
    metal::uint2 _e12 = s_57.pixel_key;
    uint _e13 = nyq_stratified_dim_key(_e12, dim_24);
    NyqPermutation _e14 = nyq_permutation(_e10, _e13);
    uint _e16 = s_57.index;
    uint _e17 = nyq_permutation_apply(_e14, _e16);
    return _e17;
}

metal::float2 nyq_stratified_jitters(
    thread NyqStratifiedSampler& s_58,
    uint dim_25
) {
    bool local_11 = {};
    uint _e3 = s_58.jitter;
    if (_e3 != NYQ_JITTERED) {
        return metal::float2(0.5, 0.5);
    }
    if (!((dim_25 == 2u))) {
        local_11 = dim_25 == 3u;
    } else {
        local_11 = true;
    }
    bool _e17 = local_11;
    if (_e17) {
        metal::uint2 _e19 = s_58.sample_key;
        metal::uint2 _e24 = nyq_mul64_(metal::uint2(2u, 0u), NYQ_JITTER_STEP);
        metal::uint2 _e26 = nyq_mix64_(_e19 ^ _e24);
        if (dim_25 == 2u) {
            return metal::float2(static_cast<float>((_e26.y >> 11u) & 2097151u) * 0.00000047683716, 0.5);
        }
        metal::uint2 _e40 = nyq_shr64_(_e26, 22u);
        return metal::float2(static_cast<float>(_e40.x & 2097151u) * 0.00000047683716, static_cast<float>((_e26.x >> 1u) & 2097151u) * 0.00000047683716);
    }
    metal::uint2 _e55 = s_58.sample_key;
    metal::uint2 _e56 = nyq_u64_(dim_25);
    metal::uint2 _e58 = nyq_mul64_(_e56, NYQ_JITTER_STEP);
    metal::uint2 _e60 = nyq_mix64_(_e55 ^ _e58);
    float _e62 = nyq_fraction_to_f32_(_e60.y);
    float _e64 = nyq_fraction_to_f32_(_e60.x);
    return metal::float2(_e62, _e64);
}

float nyq_below_one(
    float x_16
) {
    return metal::min(x_16, as_type<float>(1065353215u));
}

metal::float2 nyq_stratified_cell(
    thread NyqStratifiedSampler& s_59,
    uint st,
    metal::float2 j
) {
    uint _e4 = s_59.xs;
    uint cx = naga_mod(st, _e4);
    uint _e7 = s_59.xs;
    uint cy = naga_div(st, _e7);
    float _e9 = nyq_u32_to_f32_(cx);
    float _e14 = s_59.inv[0];
    float _e16 = nyq_below_one((_e9 + j.x) * _e14);
    float _e17 = nyq_u32_to_f32_(cy);
    float _e22 = s_59.inv[1];
    float _e24 = nyq_below_one((_e17 + j.y) * _e22);
    return metal::float2(_e16, _e24);
}

void nyq_stratified_start(
    thread NyqStratifiedSampler& s_60,
    metal::uint2 pixel_14,
    uint sample_index_12,
    uint dim_26
) {
    metal::uint2 _e6 = s_60.seed;
    metal::uint2 _e8 = nyq_u64_(1937011297u);
    metal::uint2 _e9 = nyq_hash3_(pixel_14, _e6, _e8);
    s_60.pixel_key = _e9;
    s_60.index = sample_index_12;
    metal::uint2 _e13 = s_60.pixel_key;
    metal::uint2 _e14 = nyq_u64_(sample_index_12);
    metal::uint2 _e16 = nyq_mul64_(_e14, NYQ_DIM_STEP);
    s_60.sample_key = _e13 ^ _e16;
    s_60.dim = dim_26;
    return;
}

float nyq_stratified_get_1d(
    thread NyqStratifiedSampler& s_61
) {
    uint d_22 = s_61.dim;
    s_61.dim = d_22 + 1u;
    uint _e6 = nyq_stratified_stratum(s_61, d_22);
    float _e7 = nyq_u32_to_f32_(_e6);
    metal::float2 _e8 = nyq_stratified_jitters(s_61, d_22);
    float _e13 = s_61.inv[2];
    float _e15 = nyq_below_one((_e7 + _e8.x) * _e13);
    return _e15;
}

metal::float2 nyq_stratified_get_2d(
    thread NyqStratifiedSampler& s_62
) {
    uint d_23 = s_62.dim;
    s_62.dim = d_23 + 2u;
    uint _e6 = nyq_stratified_stratum(s_62, d_23);
    metal::float2 _e7 = nyq_stratified_jitters(s_62, d_23);
    metal::float2 _e8 = nyq_stratified_cell(s_62, _e6, _e7);
    return _e8;
}

metal::float2 nyq_stratified_get_pixel_2d(
    thread NyqStratifiedSampler& s_63
) {
    uint _e3 = s_63.dim;
    s_63.dim = metal::max(_e3, 2u);
    uint _e7 = nyq_stratified_stratum(s_63, 0u);
    metal::float2 _e9 = nyq_stratified_jitters(s_63, 0u);
    metal::float2 _e10 = nyq_stratified_cell(s_63, _e7, _e9);
    return _e10;
}

NyqCameraSample nyq_stratified_camera_sample(
    thread NyqStratifiedSampler& s_64,
    metal::uint2 pixel_15,
    uint sample_index_13
) {
    nyq_stratified_start(s_64, pixel_15, sample_index_13, 0u);
    metal::float2 _e4 = nyq_stratified_get_pixel_2d(s_64);
    float _e5 = nyq_stratified_get_1d(s_64);
    metal::float2 _e6 = nyq_stratified_get_2d(s_64);
    float _e9 = nyq_film_coordinate(pixel_15.x, _e4.x);
    float _e12 = nyq_film_coordinate(pixel_15.y, _e4.y);
    metal::float2 film_4 = metal::float2(_e9, _e12);
    return NyqCameraSample {film_4, _e6, _e5};
}

uint nyq_rxs_m_xs(
    uint state_1
) {
    uint s_65 = {};
    s_65 = state_1;
    uint _e2 = s_65;
    uint _e3 = s_65;
    uint _e5 = s_65;
    s_65 = _e2 ^ (_e3 >> (4u + (_e5 >> 28u)));
    uint _e11 = s_65;
    s_65 = _e11 * 277803737u;
    uint _e14 = s_65;
    uint _e15 = s_65;
    return _e14 ^ (_e15 >> 22u);
}

uint nyq_lcg_draw(
    uint seed_17,
    uint m_1
) {
    uint s_66 = {};
    uint a_8 = NYQ_LCG_A;
    uint c_3 = NYQ_LCG_C;
    uint k_10 = 0u;
    s_66 = NYQ_LCG_C + seed_17;
    uint n_12 = m_1 + 1u;
    uint2 loop_bound_22 = uint2(4294967295u);
    bool loop_init_17 = true;
    while(true) {
        if (metal::all(loop_bound_22 == uint2(0u))) { break; }
        loop_bound_22 -= uint2(loop_bound_22.y == 0u, 1u);
        if (!loop_init_17) {
            uint _e38 = k_10;
            k_10 = _e38 + 1u;
        }
        loop_init_17 = false;
        uint _e13 = k_10;
        if (_e13 < 18u) {
        } else {
            break;
        }
        {
            uint _e16 = s_66;
            uint _e17 = a_8;
            uint _e18 = s_66;
            uint _e20 = c_3;
            uint _e22 = k_10;
            s_66 = (((n_12 >> _e22) & 1u) != 0u) ? ((_e17 * _e18) + _e20) : _e16;
            uint _e29 = a_8;
            uint _e32 = c_3;
            c_3 = (_e29 + 1u) * _e32;
            uint _e34 = a_8;
            uint _e35 = a_8;
            a_8 = _e34 * _e35;
        }
    }
    uint _e40 = s_66;
    uint _e41 = nyq_rxs_m_xs(_e40);
    return _e41;
}

uint nyq_pmj02_point(
    uint seed_18,
    uint index_12,
    uint dim_27
) {
    uint x_17 = 0u;
    uint known = 0u;
    uint flips = 0u;
    uint p_1 = {};
    p_1 = index_12 & 65535u;
    uint2 loop_bound_23 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_23 == uint2(0u))) { break; }
        loop_bound_23 -= uint2(loop_bound_23.y == 0u, 1u);
        uint _e12 = p_1;
        if (_e12 != 0u) {
        } else {
            break;
        }
        {
            uint _e16 = p_1;
            uint level_1 = 31u - metal::clz(_e16);
            uint swap = 2147483648u >> level_1;
            uint low_2 = swap - 1u;
            uint _e23 = x_17;
            uint _e25 = p_1;
            uint _e28 = nyq_lcg_draw(seed_18, (2u * _e25) + dim_27);
            uint _e30 = known;
            x_17 = _e23 | ((_e28 & low_2) & ~(_e30));
            uint _e34 = known;
            known = _e34 | low_2;
            uint _e36 = flips;
            flips = _e36 ^ swap;
            uint c_11 = (dim_27 == 0u) ? NYQ_PMJ02_XOR_X.inner[level_1 & 15u] : NYQ_PMJ02_XOR_Y.inner[level_1 & 15u];
            uint _e49 = p_1;
            p_1 = (_e49 - (1u << level_1)) ^ c_11;
        }
    }
    uint _e54 = x_17;
    uint _e55 = nyq_lcg_draw(seed_18, dim_27);
    uint _e56 = known;
    x_17 = _e54 | (_e55 & ~(_e56));
    uint _e60 = x_17;
    uint _e61 = flips;
    return _e60 ^ _e61;
}

NyqPmj02_ nyq_pmj02_(
    bool scrambled_1,
    metal::uint2 seed_19
) {
    metal::uint2 _e5 = nyq_hash2_(seed_19, metal::uint2(845115255u, 1886218800u));
    return NyqPmj02_ {scrambled_1 ? 1u : 0u, {}, _e5};
}

uint nyq_pmj02_sample_u32_(
    NyqPmj02_ s_67,
    uint index_13,
    uint dim_28
) {
    uint d_24 = dim_28 & 1u;
    uint _e6 = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, index_13, d_24);
    if (s_67.scrambled == 0u) {
        return _e6;
    }
    uint _e13 = nyq_lk_hash(metal::reverse_bits(_e6), s_67.keys[d_24]);
    return metal::reverse_bits(_e13);
}

float nyq_pmj02_sample(
    NyqPmj02_ s_68,
    uint index_14,
    uint dim_29
) {
    uint _e3 = nyq_pmj02_sample_u32_(s_68, index_14, dim_29);
    float _e4 = nyq_fraction_to_f32_(_e3);
    return _e4;
}

NyqPmj02Sampler nyq_pmj02_sampler(
    metal::uint2 seed_20
) {
    return NyqPmj02Sampler {seed_20, metal::uint2(0u, 0u), 0u, 0u};
}

uint nyq_reverse16_(
    uint m_2
) {
    return metal::reverse_bits(m_2 & 65535u) >> 16u;
}

metal::uint3 nyq_pmj02_keys(
    thread NyqPmj02Sampler& s_69,
    metal::uint2 request
) {
    metal::uint2 _e3 = s_69.pixel_key;
    metal::uint2 _e7 = nyq_mul64_(request, metal::uint2(2135587861u, 2654435769u));
    metal::uint2 _e9 = nyq_mix64_(_e3 ^ _e7);
    metal::uint2 _e14 = nyq_mix64_(_e9 ^ metal::uint2(1781543545u, 28781u));
    return metal::uint3(_e9.x, _e9.y, _e14.x);
}

metal::float2 nyq_pmj02_keyed_point(
    metal::uint3 k_11,
    uint i_9
) {
    uint _e4 = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, i_9, 0u);
    uint _e7 = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, i_9, 1u);
    uint _e10 = nyq_lk_hash(metal::reverse_bits(_e4), k_11.y);
    float _e11 = nyq_rev_to_f32_(_e10);
    uint _e14 = nyq_lk_hash(metal::reverse_bits(_e7), k_11.z);
    float _e15 = nyq_rev_to_f32_(_e14);
    return metal::float2(_e11, _e15);
}

uint nyq_pmj02_row(
    thread NyqPmj02Sampler& s_70,
    metal::uint3 k_12
) {
    uint _e3 = s_70.index_rev;
    uint _e5 = nyq_lk_hash(_e3, k_12.x);
    return _e5 >> 16u;
}

void nyq_pmj02_start(
    thread NyqPmj02Sampler& s_71,
    metal::uint2 pixel_16,
    uint sample_index_14,
    uint dim_30
) {
    metal::uint2 _e6 = s_71.seed;
    metal::uint2 _e10 = nyq_hash3_(pixel_16, _e6, metal::uint2(1835675698u, 112u));
    s_71.pixel_key = _e10;
    uint _e12 = nyq_reverse16_(sample_index_14);
    s_71.index_rev = _e12 << 16u;
    s_71.dim = dim_30;
    return;
}

float nyq_pmj02_get_1d(
    thread NyqPmj02Sampler& s_72
) {
    uint d_25 = s_72.dim;
    s_72.dim = d_25 + 1u;
    metal::uint2 _e6 = nyq_u64_(d_25);
    metal::uint2 _e8 = nyq_shl64_(_e6, 1u);
    metal::uint2 _e12 = nyq_add64_(_e8, metal::uint2(1u, 0u));
    metal::uint3 _e13 = nyq_pmj02_keys(s_72, _e12);
    uint _e14 = nyq_pmj02_row(s_72, _e13);
    uint _e15 = nyq_reverse16_(_e14);
    uint _e17 = nyq_lk_hash(_e15, _e13.y);
    float _e18 = nyq_rev_to_f32_(_e17);
    return _e18;
}

metal::float2 nyq_pmj02_get_2d(
    thread NyqPmj02Sampler& s_73
) {
    uint d_26 = s_73.dim;
    s_73.dim = d_26 + 2u;
    metal::uint2 _e6 = nyq_u64_(d_26);
    metal::uint2 _e8 = nyq_shl64_(_e6, 1u);
    metal::uint3 _e9 = nyq_pmj02_keys(s_73, _e8);
    if (d_26 == 0u) {
        uint _e13 = s_73.index_rev;
        uint _e16 = nyq_reverse16_(_e13 >> 16u);
        metal::float2 _e17 = nyq_pmj02_keyed_point(_e9, _e16);
        return _e17;
    }
    uint _e18 = nyq_pmj02_row(s_73, _e9);
    uint _e19 = nyq_reverse16_(_e18);
    metal::float2 _e20 = nyq_pmj02_keyed_point(_e9, _e19);
    return _e20;
}

metal::float2 nyq_pmj02_get_pixel_2d(
    thread NyqPmj02Sampler& s_74
) {
    uint _e3 = s_74.dim;
    s_74.dim = metal::max(_e3, 2u);
    metal::uint3 _e9 = nyq_pmj02_keys(s_74, metal::uint2(0u, 0u));
    uint _e11 = s_74.index_rev;
    uint _e14 = nyq_reverse16_(_e11 >> 16u);
    metal::float2 _e15 = nyq_pmj02_keyed_point(_e9, _e14);
    return _e15;
}

NyqCameraSample nyq_pmj02_camera_sample(
    thread NyqPmj02Sampler& s_75,
    metal::uint2 pixel_17,
    uint sample_index_15
) {
    nyq_pmj02_start(s_75, pixel_17, sample_index_15, 0u);
    metal::float2 _e4 = nyq_pmj02_get_pixel_2d(s_75);
    float _e5 = nyq_pmj02_get_1d(s_75);
    metal::float2 _e6 = nyq_pmj02_get_2d(s_75);
    float _e9 = nyq_film_coordinate(pixel_17.x, _e4.x);
    float _e12 = nyq_film_coordinate(pixel_17.y, _e4.y);
    metal::float2 film_5 = metal::float2(_e9, _e12);
    return NyqCameraSample {film_5, _e6, _e5};
}

metal::uint2 nyq_sub64_(
    metal::uint2 a_9,
    metal::uint2 b_7
) {
    return metal::uint2(a_9.x - b_7.x, (a_9.y - b_7.y) - ((a_9.x < b_7.x) ? 1u : 0u));
}

metal::uint3 nyq_divmod64_small(
    metal::uint2 x_18,
    uint d_3
) {
    if (x_18.y == 0u) {
        uint q_4 = naga_div(x_18.x, d_3);
        return metal::uint3(q_4, 0u, x_18.x - (q_4 * d_3));
    }
    uint t3_ = x_18.y >> 16u;
    uint q3_ = naga_div(t3_, d_3);
    uint t2_ = ((t3_ - (q3_ * d_3)) << 16u) | (x_18.y & 65535u);
    uint q2_ = naga_div(t2_, d_3);
    uint t1_1 = ((t2_ - (q2_ * d_3)) << 16u) | (x_18.x >> 16u);
    uint q1_ = naga_div(t1_1, d_3);
    uint t0_1 = ((t1_1 - (q1_ * d_3)) << 16u) | (x_18.x & 65535u);
    uint q0_ = naga_div(t0_1, d_3);
    return metal::uint3((q1_ << 16u) | q0_, (q3_ << 16u) | q2_, t0_1 - (q0_ * d_3));
}

metal::uint4 nyq_add128_(
    metal::uint4 a_10,
    metal::uint4 b_8
) {
    metal::uint4 s_104 = a_10 + b_8;
    metal::uint4 c_12 = metal::select(metal::uint4(0u), metal::uint4(1u), s_104 < a_10);
    uint t1_2 = s_104.y + c_12.x;
    uint k1_ = c_12.y + ((t1_2 < c_12.x) ? 1u : 0u);
    uint t2_1 = s_104.z + k1_;
    uint k2_ = c_12.z + ((t2_1 < k1_) ? 1u : 0u);
    return metal::uint4(s_104.x, t1_2, t2_1, s_104.w + k2_);
}

metal::uint4 nyq_sub128_(
    metal::uint4 a_11,
    metal::uint4 b_9
) {
    metal::uint4 s_105 = a_11 - b_9;
    metal::uint4 o = metal::select(metal::uint4(0u), metal::uint4(1u), a_11 < b_9);
    uint t1_3 = s_105.y - o.x;
    uint k1_1 = o.y + ((s_105.y < o.x) ? 1u : 0u);
    uint t2_2 = s_105.z - k1_1;
    uint k2_1 = o.z + ((s_105.z < k1_1) ? 1u : 0u);
    return metal::uint4(s_105.x, t1_3, t2_2, s_105.w - k2_1);
}

bool nyq_lt128_(
    metal::uint4 a_12,
    metal::uint4 b_10
) {
    if (a_12.w != b_10.w) {
        return a_12.w < b_10.w;
    }
    if (a_12.z != b_10.z) {
        return a_12.z < b_10.z;
    }
    if (a_12.y != b_10.y) {
        return a_12.y < b_10.y;
    }
    return a_12.x < b_10.x;
}

metal::uint4 nyq_mul128_u32_(
    metal::uint4 x_19,
    uint k_13
) {
    metal::uint2 _e3 = nyq_mul_wide(x_19.x, k_13);
    metal::uint2 _e5 = nyq_mul_wide(x_19.y, k_13);
    metal::uint2 _e9 = nyq_add64_(_e5, metal::uint2(_e3.y, 0u));
    metal::uint2 _e11 = nyq_mul_wide(x_19.z, k_13);
    metal::uint2 _e15 = nyq_add64_(_e11, metal::uint2(_e9.y, 0u));
    return metal::uint4(_e3.x, _e9.x, _e15.x, (x_19.w * k_13) + _e15.y);
}

metal::uint4 nyq_mul64_wide(
    metal::uint2 a_13,
    metal::uint2 b_11
) {
    metal::uint2 _e4 = nyq_mul_wide(a_13.x, b_11.x);
    metal::uint2 _e7 = nyq_mul_wide(a_13.x, b_11.y);
    metal::uint2 _e10 = nyq_mul_wide(a_13.y, b_11.x);
    metal::uint2 _e13 = nyq_mul_wide(a_13.y, b_11.y);
    metal::uint4 outer = metal::uint4(_e4.x, _e4.y, _e13.x, _e13.y);
    metal::uint4 _e24 = nyq_add128_(outer, metal::uint4(0u, _e7.x, _e7.y, 0u));
    metal::uint4 _e30 = nyq_add128_(_e24, metal::uint4(0u, _e10.x, _e10.y, 0u));
    return _e30;
}

uint nyq_clz128_(
    metal::uint4 x_20
) {
    if (x_20.w != 0u) {
        return metal::clz(x_20.w);
    }
    if (x_20.z != 0u) {
        return 32u + metal::clz(x_20.z);
    }
    if (x_20.y != 0u) {
        return 64u + metal::clz(x_20.y);
    }
    return 96u + metal::clz(x_20.x);
}

metal::uint4 nyq_shl128_(
    metal::uint4 x_21,
    uint s_76
) {
    metal::uint4 v_5 = {};
    uint k_14 = {};
    v_5 = x_21;
    k_14 = s_76;
    uint2 loop_bound_24 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_24 == uint2(0u))) { break; }
        loop_bound_24 -= uint2(loop_bound_24.y == 0u, 1u);
        uint _e4 = k_14;
        if (_e4 >= 32u) {
        } else {
            break;
        }
        {
            uint _e9 = v_5.x;
            uint _e11 = v_5.y;
            uint _e13 = v_5.z;
            v_5 = metal::uint4(0u, _e9, _e11, _e13);
            uint _e15 = k_14;
            k_14 = _e15 - 32u;
        }
    }
    uint _e18 = k_14;
    if (_e18 == 0u) {
        metal::uint4 _e21 = v_5;
        return _e21;
    }
    uint _e23 = k_14;
    uint r_14 = 32u - _e23;
    uint _e26 = v_5.x;
    uint _e27 = k_14;
    uint _e30 = v_5.y;
    uint _e31 = k_14;
    uint _e34 = v_5.x;
    uint _e38 = v_5.z;
    uint _e39 = k_14;
    uint _e42 = v_5.y;
    uint _e46 = v_5.w;
    uint _e47 = k_14;
    uint _e50 = v_5.z;
    return metal::uint4(_e26 << _e27, (_e30 << _e31) | (_e34 >> r_14), (_e38 << _e39) | (_e42 >> r_14), (_e46 << _e47) | (_e50 >> r_14));
}

uint nyq_round_bits(
    metal::uint4 x_in_3,
    int e_in_1,
    bool sticky,
    bool twice
) {
    bool local_12 = {};
    bool local_13 = {};
    uint m_3 = {};
    uint ml = {};
    uint mh = {};
    bool local_14 = {};
    bool local_15 = {};
    bool local_16 = {};
    bool local_17 = {};
    bool local_18 = {};
    bool local_19 = {};
    bool local_20 = {};
    bool local_21 = {};
    bool local_22 = {};
    if (metal::all(x_in_3 == metal::uint4(0u))) {
        return 0u;
    }
    uint _e9 = nyq_clz128_(x_in_3);
    metal::uint4 _e10 = nyq_shl128_(x_in_3, _e9);
    int e_4 = as_type<int>(as_type<uint>(e_in_1) - as_type<uint>(static_cast<int>(_e9)));
    if (!((_e10.x != 0u))) {
        local_12 = _e10.y != 0u;
    } else {
        local_12 = true;
    }
    bool _e23 = local_12;
    if (!(_e23)) {
        local_13 = sticky;
    } else {
        local_13 = true;
    }
    bool rest_2 = local_13;
    if (twice) {
        ml = (_e10.w << 21u) | (_e10.z >> 11u);
        mh = _e10.w >> 11u;
        uint r_15 = _e10.z & 2047u;
        if (!((r_15 > 1024u))) {
            if (r_15 == 1024u) {
                if (!(rest_2)) {
                    uint _e57 = ml;
                    local_16 = (_e57 & 1u) == 1u;
                } else {
                    local_16 = true;
                }
                bool _e63 = local_16;
                local_15 = _e63;
            } else {
                local_15 = false;
            }
            bool _e65 = local_15;
            local_14 = _e65;
        } else {
            local_14 = true;
        }
        bool _e67 = local_14;
        if (_e67) {
            uint _e68 = ml;
            ml = _e68 + 1u;
            uint _e71 = mh;
            uint _e74 = ml;
            mh = _e71 + ((_e74 == 0u) ? 1u : 0u);
        }
        uint _e79 = mh;
        uint _e82 = ml;
        m_3 = (_e79 << 3u) | (_e82 >> 29u);
        uint _e86 = ml;
        uint r2_ = _e86 & 536870911u;
        if (!((r2_ > 268435456u))) {
            if (r2_ == 268435456u) {
                uint _e98 = m_3;
                local_18 = (_e98 & 1u) == 1u;
            } else {
                local_18 = false;
            }
            bool _e104 = local_18;
            local_17 = _e104;
        } else {
            local_17 = true;
        }
        bool _e106 = local_17;
        if (_e106) {
            uint _e107 = m_3;
            m_3 = _e107 + 1u;
        }
    } else {
        m_3 = _e10.w >> 8u;
        uint r_16 = _e10.w & 255u;
        if (!((r_16 > 128u))) {
            if (r_16 == 128u) {
                if (!((_e10.z != 0u))) {
                    local_21 = rest_2;
                } else {
                    local_21 = true;
                }
                bool _e132 = local_21;
                if (!(_e132)) {
                    uint _e136 = m_3;
                    local_22 = (_e136 & 1u) == 1u;
                } else {
                    local_22 = true;
                }
                bool _e142 = local_22;
                local_20 = _e142;
            } else {
                local_20 = false;
            }
            bool _e144 = local_20;
            local_19 = _e144;
        } else {
            local_19 = true;
        }
        bool _e146 = local_19;
        if (_e146) {
            uint _e147 = m_3;
            m_3 = _e147 + 1u;
        }
    }
    uint _e155 = m_3;
    return ((static_cast<uint>(as_type<int>(as_type<uint>(e_4) + as_type<uint>(254))) << 23u) + _e155) - 8388608u;
}

NyqRounding nyq_divide(
    metal::uint4 num_1,
    metal::uint4 den_1,
    bool twice_1
) {
    metal::uint2 q_2 = metal::uint2(0u, 0u);
    bool sticky_1 = false;
    bool local_23 = {};
    bool local_24 = {};
    metal::uint2 r_11 = {};
    uint i_10 = 0u;
    bool local_25 = {};
    bool local_26 = {};
    bool local_27 = {};
    metal::uint4 r_12 = {};
    uint i_11 = 0u;
    uint tw = twice_1 ? 1u : 0u;
    if (metal::all(num_1 == metal::uint4(0u))) {
        return NyqRounding {metal::uint4(0u), 0, 0u, tw, 0u};
    }
    uint _e16 = nyq_clz128_(num_1);
    uint _e17 = nyq_clz128_(den_1);
    uint s_106 = _e16 - _e17;
    uint steps = twice_1 ? 55u : 26u;
    if (den_1.z == 0u) {
        local_23 = den_1.w == 0u;
    } else {
        local_23 = false;
    }
    bool _e37 = local_23;
    if (_e37) {
        local_24 = den_1.y < 2147483648u;
    } else {
        local_24 = false;
    }
    bool _e44 = local_24;
    if (_e44) {
        metal::uint2 d_27 = den_1.xy;
        metal::uint4 _e46 = nyq_shl128_(num_1, s_106);
        r_11 = _e46.xy;
        uint2 loop_bound_25 = uint2(4294967295u);
        bool loop_init_18 = true;
        while(true) {
            if (metal::all(loop_bound_25 == uint2(0u))) { break; }
            loop_bound_25 -= uint2(loop_bound_25.y == 0u, 1u);
            if (!loop_init_18) {
                uint _e109 = i_10;
                i_10 = _e109 + 1u;
            }
            loop_init_18 = false;
            uint _e51 = i_10;
            if (_e51 < steps) {
            } else {
                break;
            }
            {
                uint _e54 = q_2.x;
                uint _e58 = q_2.y;
                uint _e62 = q_2.x;
                q_2 = metal::uint2(_e54 << 1u, (_e58 << 1u) | (_e62 >> 31u));
                uint _e68 = r_11.y;
                if (!((_e68 > d_27.y))) {
                    uint _e75 = r_11.y;
                    if (_e75 == d_27.y) {
                        uint _e81 = r_11.x;
                        local_26 = _e81 >= d_27.x;
                    } else {
                        local_26 = false;
                    }
                    bool _e85 = local_26;
                    local_25 = _e85;
                } else {
                    local_25 = true;
                }
                bool _e87 = local_25;
                if (_e87) {
                    metal::uint2 _e88 = r_11;
                    metal::uint2 _e89 = nyq_sub64_(_e88, d_27);
                    r_11 = _e89;
                    uint _e91 = q_2.x;
                    q_2.x = _e91 | 1u;
                }
                uint _e95 = r_11.x;
                uint _e99 = r_11.y;
                uint _e103 = r_11.x;
                r_11 = metal::uint2(_e95 << 1u, (_e99 << 1u) | (_e103 >> 31u));
            }
        }
        uint _e112 = r_11.x;
        if (!((_e112 != 0u))) {
            uint _e119 = r_11.y;
            local_27 = _e119 != 0u;
        } else {
            local_27 = true;
        }
        bool _e123 = local_27;
        sticky_1 = _e123;
    } else {
        metal::uint4 _e124 = nyq_shl128_(num_1, s_106);
        r_12 = _e124;
        uint2 loop_bound_26 = uint2(4294967295u);
        bool loop_init_19 = true;
        while(true) {
            if (metal::all(loop_bound_26 == uint2(0u))) { break; }
            loop_bound_26 -= uint2(loop_bound_26.y == 0u, 1u);
            if (!loop_init_19) {
                uint _e186 = i_11;
                i_11 = _e186 + 1u;
            }
            loop_init_19 = false;
            uint _e128 = i_11;
            if (_e128 < steps) {
            } else {
                break;
            }
            {
                uint _e131 = q_2.x;
                uint _e135 = q_2.y;
                uint _e139 = q_2.x;
                q_2 = metal::uint2(_e131 << 1u, (_e135 << 1u) | (_e139 >> 31u));
                metal::uint4 _e144 = r_12;
                bool _e145 = nyq_lt128_(_e144, den_1);
                if (!(_e145)) {
                    metal::uint4 _e147 = r_12;
                    metal::uint4 _e148 = nyq_sub128_(_e147, den_1);
                    r_12 = _e148;
                    uint _e150 = q_2.x;
                    q_2.x = _e150 | 1u;
                }
                uint _e154 = r_12.x;
                uint _e158 = r_12.y;
                uint _e162 = r_12.x;
                uint _e167 = r_12.z;
                uint _e171 = r_12.y;
                uint _e176 = r_12.w;
                uint _e180 = r_12.z;
                r_12 = metal::uint4(_e154 << 1u, (_e158 << 1u) | (_e162 >> 31u), (_e167 << 1u) | (_e171 >> 31u), (_e176 << 1u) | (_e180 >> 31u));
            }
        }
        metal::uint4 _e188 = r_12;
        sticky_1 = metal::any(_e188 != metal::uint4(0u));
    }
    metal::uint2 _e193 = q_2;
    bool _e203 = sticky_1;
    return NyqRounding {metal::uint4(_e193, 0u, 0u), as_type<int>(as_type<uint>(1) - as_type<uint>(static_cast<int>(steps + s_106))), _e203 ? 1u : 0u, tw, 0u};
}

uint nyq_prime(
    uint dim_31,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e7 = nyq_halton_bases[NYQ_HALTON_WORDS * naga_mod(dim_31, NYQ_PRIME_COUNT)];
    return _e7;
}

NyqRounding nyq_phi_short(
    uint t_3,
    uint a_14,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint x_22 = {};
    metal::uint2 rev = metal::uint2(0u, 0u);
    uint i_12 = 0u;
    uint b_17 = nyq_halton_bases[t_3];
    uint c_13 = naga_div(35u - metal::clz(a_14), 4u) - 1u;
    uint _e19 = nyq_halton_bases[(t_3 + 2u) + naga_div(c_13, 4u)];
    uint places = (_e19 >> (8u * naga_mod(c_13, 4u))) & 255u;
    uint low_3 = nyq_halton_bases[(t_3 + 8u) + (2u * c_13)];
    uint high_1 = nyq_halton_bases[(t_3 + 9u) + (2u * c_13)];
    x_22 = a_14;
    uint2 loop_bound_27 = uint2(4294967295u);
    bool loop_init_20 = true;
    while(true) {
        if (metal::all(loop_bound_27 == uint2(0u))) { break; }
        loop_bound_27 -= uint2(loop_bound_27.y == 0u, 1u);
        if (!loop_init_20) {
            uint _e64 = i_12;
            i_12 = _e64 + 1u;
        }
        loop_init_20 = false;
        uint _e50 = i_12;
        if (_e50 < places) {
        } else {
            break;
        }
        {
            uint _e52 = x_22;
            uint q_5 = naga_div(_e52, b_17);
            metal::uint2 _e54 = rev;
            metal::uint3 _e55 = nyq_mul64x32_(_e54, b_17);
            uint _e57 = x_22;
            metal::uint2 _e62 = nyq_add64_(_e55.xy, metal::uint2(_e57 - (q_5 * b_17), 0u));
            rev = _e62;
            x_22 = q_5;
        }
    }
    metal::uint2 mantissa = metal::uint2(low_3, (high_1 & 1048575u) | 1048576u);
    int e_5 = as_type<int>(as_type<uint>(static_cast<int>((high_1 >> 20u) & 2047u)) - as_type<uint>(1075));
    metal::uint2 _e78 = rev;
    metal::uint4 _e79 = nyq_mul64_wide(_e78, mantissa);
    return NyqRounding {_e79, e_5, 0u, 1u, 0u};
}

NyqFraction nyq_phi_fraction(
    uint t_4,
    metal::uint2 a_15,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint2 x_23 = {};
    metal::uint4 num_2 = metal::uint4(0u);
    metal::uint4 den_2 = metal::uint4(1u, 0u, 0u, 0u);
    bool local_28 = {};
    uint c_4 = {};
    uint rev_1 = {};
    uint i_13 = {};
    uint b_18 = nyq_halton_bases[t_4];
    uint chunk = nyq_halton_bases[t_4 + 4u];
    uint run = nyq_halton_bases[t_4 + 5u];
    x_23 = a_15;
    uint2 loop_bound_28 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_28 == uint2(0u))) { break; }
        loop_bound_28 -= uint2(loop_bound_28.y == 0u, 1u);
        uint _e26 = x_23.x;
        if (!((_e26 != 0u))) {
            uint _e33 = x_23.y;
            local_28 = _e33 != 0u;
        } else {
            local_28 = true;
        }
        bool _e37 = local_28;
        if (_e37) {
        } else {
            break;
        }
        {
            metal::uint2 _e38 = x_23;
            metal::uint3 _e39 = nyq_divmod64_small(_e38, chunk);
            x_23 = _e39.xy;
            c_4 = _e39.z;
            rev_1 = 0u;
            i_13 = 0u;
            uint2 loop_bound_29 = uint2(4294967295u);
            bool loop_init_21 = true;
            while(true) {
                if (metal::all(loop_bound_29 == uint2(0u))) { break; }
                loop_bound_29 -= uint2(loop_bound_29.y == 0u, 1u);
                if (!loop_init_21) {
                    uint _e58 = i_13;
                    i_13 = _e58 + 1u;
                }
                loop_init_21 = false;
                uint _e47 = i_13;
                if (_e47 < run) {
                } else {
                    break;
                }
                {
                    uint _e49 = c_4;
                    uint q_6 = naga_div(_e49, b_18);
                    uint _e51 = rev_1;
                    uint _e53 = c_4;
                    rev_1 = (_e51 * b_18) + (_e53 - (q_6 * b_18));
                    c_4 = q_6;
                }
            }
            metal::uint4 _e60 = num_2;
            metal::uint4 _e61 = nyq_mul128_u32_(_e60, chunk);
            uint _e62 = rev_1;
            metal::uint4 _e67 = nyq_add128_(_e61, metal::uint4(_e62, 0u, 0u, 0u));
            num_2 = _e67;
            metal::uint4 _e68 = den_2;
            metal::uint4 _e69 = nyq_mul128_u32_(_e68, chunk);
            den_2 = _e69;
        }
    }
    metal::uint4 _e70 = num_2;
    metal::uint4 _e71 = den_2;
    return NyqFraction {_e70, _e71, 0u, 0u};
}

NyqFraction nyq_permuted_fraction(
    uint t_5,
    metal::uint2 a_16,
    metal::uint2 seed_21,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint2 x_24 = {};
    metal::uint4 num_3 = metal::uint4(0u);
    metal::uint4 den_3 = metal::uint4(1u, 0u, 0u, 0u);
    bool local_29 = {};
    bool local_30 = {};
    uint c_5 = {};
    uint part = {};
    uint scale = {};
    uint i_14 = {};
    bool local_31 = {};
    bool local_32 = {};
    bool local_33 = {};
    uint b_19 = nyq_halton_bases[t_5];
    uint chunk_1 = nyq_halton_bases[t_5 + 4u];
    uint run_1 = nyq_halton_bases[t_5 + 5u];
    metal::uint2 _e16 = nyq_u64_(b_19);
    metal::uint2 _e17 = nyq_hash2_(seed_21, _e16);
    NyqPermutation _e21 = nyq_permutation(b_19, _e17.x ^ _e17.y);
    x_24 = a_16;
    uint2 loop_bound_30 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_30 == uint2(0u))) { break; }
        loop_bound_30 -= uint2(loop_bound_30.y == 0u, 1u);
        uint _e33 = x_24.x;
        if (!((_e33 != 0u))) {
            uint _e40 = x_24.y;
            local_29 = _e40 != 0u;
        } else {
            local_29 = true;
        }
        bool _e44 = local_29;
        if (_e44) {
        } else {
            break;
        }
        {
            metal::uint2 _e45 = x_24;
            metal::uint3 _e46 = nyq_divmod64_small(_e45, chunk_1);
            x_24 = _e46.xy;
            uint _e49 = x_24.x;
            if (_e49 == 0u) {
                uint _e55 = x_24.y;
                local_30 = _e55 == 0u;
            } else {
                local_30 = false;
            }
            bool last = local_30;
            c_5 = _e46.z;
            part = 0u;
            scale = 1u;
            i_14 = 0u;
            uint2 loop_bound_31 = uint2(4294967295u);
            bool loop_init_22 = true;
            while(true) {
                if (metal::all(loop_bound_31 == uint2(0u))) { break; }
                loop_bound_31 -= uint2(loop_bound_31.y == 0u, 1u);
                if (!loop_init_22) {
                    uint _e89 = i_14;
                    i_14 = _e89 + 1u;
                }
                loop_init_22 = false;
                uint _e68 = i_14;
                if (_e68 < run_1) {
                } else {
                    break;
                }
                {
                    if (last) {
                        uint _e72 = c_5;
                        local_31 = _e72 == 0u;
                    } else {
                        local_31 = false;
                    }
                    bool _e76 = local_31;
                    if (_e76) {
                        break;
                    }
                    uint _e77 = c_5;
                    uint q_7 = naga_div(_e77, b_19);
                    uint _e79 = part;
                    uint _e81 = c_5;
                    uint _e84 = nyq_permutation_apply(_e21, _e81 - (q_7 * b_19));
                    part = (_e79 * b_19) + _e84;
                    uint _e86 = scale;
                    scale = _e86 * b_19;
                    c_5 = q_7;
                }
            }
            metal::uint4 _e91 = num_3;
            uint _e92 = scale;
            metal::uint4 _e93 = nyq_mul128_u32_(_e91, _e92);
            uint _e94 = part;
            metal::uint4 _e99 = nyq_add128_(_e93, metal::uint4(_e94, 0u, 0u, 0u));
            num_3 = _e99;
            metal::uint4 _e100 = den_3;
            uint _e101 = scale;
            metal::uint4 _e102 = nyq_mul128_u32_(_e100, _e101);
            den_3 = _e102;
        }
    }
    uint _e104 = nyq_permutation_apply(_e21, 0u);
    metal::uint4 _e105 = num_3;
    metal::uint4 _e108 = nyq_mul128_u32_(_e105, b_19 - 1u);
    metal::uint4 _e113 = nyq_add128_(_e108, metal::uint4(_e104, 0u, 0u, 0u));
    num_3 = _e113;
    metal::uint4 _e114 = den_3;
    metal::uint4 _e117 = nyq_mul128_u32_(_e114, b_19 - 1u);
    den_3 = _e117;
    uint _e119 = den_3.w;
    if (_e119 == 0u) {
        uint _e125 = den_3.z;
        local_32 = _e125 == 0u;
    } else {
        local_32 = false;
    }
    bool _e129 = local_32;
    if (_e129) {
        uint _e133 = den_3.y;
        local_33 = _e133 < 2097152u;
    } else {
        local_33 = false;
    }
    bool small = local_33;
    metal::uint4 _e138 = num_3;
    metal::uint4 _e139 = den_3;
    return NyqFraction {_e138, _e139, small ? 1u : 0u, (_e104 == (b_19 - 1u)) ? 1u : 0u};
}

NyqFraction nyq_nested_fraction(
    uint d_4,
    metal::uint2 a_17,
    metal::uint2 seed_22,
    bool affine,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint2 rest = {};
    metal::uint2 pow = metal::uint2(1u, 0u);
    uint level = 0u;
    metal::uint2 num_4 = metal::uint2(0u, 0u);
    metal::uint2 den_4 = metal::uint2(1u, 0u);
    metal::uint2 next = {};
    uint digit_1 = {};
    bool local_34 = {};
    uint out_2 = {};
    uint b_20 = nyq_halton_bases[NYQ_HALTON_WORDS * d_4];
    metal::uint2 _e9 = nyq_u64_(d_4);
    metal::uint2 _e13 = nyq_hash3_(seed_22, _e9, affine ? NYQ_OWEN_TAG_AFFINE : NYQ_OWEN_TAG_UNIFORM);
    rest = a_17;
    uint2 loop_bound_32 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_32 == uint2(0u))) { break; }
        loop_bound_32 -= uint2(loop_bound_32.y == 0u, 1u);
        uint _e30 = den_4.y;
        if (_e30 == 0u) {
        } else {
            break;
        }
        {
            next = metal::uint2(0u, 0u);
            digit_1 = 0u;
            uint _e40 = rest.x;
            if (!((_e40 != 0u))) {
                uint _e47 = rest.y;
                local_34 = _e47 != 0u;
            } else {
                local_34 = true;
            }
            bool _e51 = local_34;
            if (_e51) {
                metal::uint2 _e52 = rest;
                metal::uint3 _e53 = nyq_divmod64_small(_e52, b_20);
                next = _e53.xy;
                digit_1 = _e53.z;
            }
            metal::uint2 _e56 = rest;
            metal::uint2 _e57 = pow;
            metal::uint2 _e58 = nyq_mul64_(_e56, _e57);
            metal::uint2 _e59 = nyq_sub64_(a_17, _e58);
            metal::uint2 _e61 = nyq_mul64_(_e59, NYQ_OWEN_PREFIX_MUL);
            uint _e63 = level;
            metal::uint2 _e64 = nyq_u64_(_e63);
            metal::uint2 _e66 = nyq_mul64_(_e64, NYQ_OWEN_LEVEL_STEP);
            metal::uint2 _e67 = nyq_add64_(_e13 ^ _e61, _e66);
            metal::uint2 _e68 = nyq_mix64_(_e67);
            metal::uint2 _e69 = next;
            rest = _e69;
            metal::uint2 _e70 = pow;
            metal::uint2 _e71 = nyq_u64_(b_20);
            metal::uint2 _e72 = nyq_mul64_(_e70, _e71);
            pow = _e72;
            uint _e73 = level;
            level = _e73 + 1u;
            out_2 = uint {};
            if (affine) {
                metal::uint3 _e78 = nyq_mul64x32_(_e68, b_20);
                metal::uint3 _e83 = nyq_mul64x32_(_e78.xy, b_20 - 1u);
                uint m_8 = 1u + _e83.z;
                uint _e86 = digit_1;
                out_2 = naga_mod((m_8 * _e86) + _e78.z, b_20);
            } else {
                if (b_20 <= 16u) {
                    metal::uint2 _e93 = nyq_packed_table(b_20, _e68);
                    uint _e95 = digit_1;
                    uint _e97 = nyq_nibble(_e93, 4u * _e95);
                    out_2 = _e97;
                } else {
                    NyqPermutation _e101 = nyq_permutation(b_20, _e68.x ^ _e68.y);
                    uint _e102 = digit_1;
                    uint _e103 = nyq_permutation_apply(_e101, _e102);
                    out_2 = _e103;
                }
            }
            metal::uint2 _e104 = num_4;
            metal::uint3 _e105 = nyq_mul64x32_(_e104, b_20);
            uint _e107 = out_2;
            metal::uint2 _e110 = nyq_add64_(_e105.xy, metal::uint2(_e107, 0u));
            num_4 = _e110;
            metal::uint2 _e111 = den_4;
            metal::uint3 _e112 = nyq_mul64x32_(_e111, b_20);
            den_4 = _e112.xy;
        }
    }
    metal::uint2 _e114 = num_4;
    metal::uint2 _e118 = den_4;
    return NyqFraction {metal::uint4(_e114, 0u, 0u), metal::uint4(_e118, 0u, 0u), 1u, 0u};
}

float nyq_radical_inverse_scrambled(
    uint dim_32,
    metal::uint2 a_18,
    metal::uint2 seed_23,
    uint how_2,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    NyqRounding r_13 = {};
    bool local_35 = {};
    bool local_36 = {};
    bool local_37 = {};
    NyqFraction f = {};
    uint bits_2 = {};
    uint d_28 = naga_mod(dim_32, NYQ_PRIME_COUNT);
    uint t_7 = NYQ_HALTON_WORDS * d_28;
    if (how_2 == NYQ_SCRAMBLE_NONE) {
        local_35 = d_28 == 0u;
    } else {
        local_35 = false;
    }
    bool _e16 = local_35;
    if (_e16) {
        r_13 = NyqRounding {metal::uint4(metal::reverse_bits(a_18.y), metal::reverse_bits(a_18.x), 0u, 0u), -64, 0u, 0u, 0u};
    } else {
        if (how_2 == NYQ_SCRAMBLE_NONE) {
            local_36 = a_18.y == 0u;
        } else {
            local_36 = false;
        }
        bool _e37 = local_36;
        if (_e37) {
            uint _e45 = nyq_halton_bases[t_7 + 1u];
            local_37 = a_18.x < _e45;
        } else {
            local_37 = false;
        }
        bool _e48 = local_37;
        if (_e48) {
            if (a_18.x != 0u) {
                NyqRounding _e53 = nyq_phi_short(t_7, a_18.x, nyq_halton_bases, _buffer_sizes);
                r_13 = _e53;
            }
        } else {
            if (how_2 == NYQ_SCRAMBLE_NONE) {
                NyqFraction _e57 = nyq_phi_fraction(t_7, a_18, nyq_halton_bases, _buffer_sizes);
                f = _e57;
            } else {
                if (how_2 == NYQ_SCRAMBLE_PERMUTE_DIGITS) {
                    NyqFraction _e60 = nyq_permuted_fraction(t_7, a_18, seed_23, nyq_halton_bases, _buffer_sizes);
                    f = _e60;
                } else {
                    NyqFraction _e63 = nyq_nested_fraction(d_28, a_18, seed_23, how_2 == NYQ_SCRAMBLE_FAST_OWEN, nyq_halton_bases, _buffer_sizes);
                    f = _e63;
                }
            }
            metal::uint4 _e65 = f.num;
            metal::uint4 _e67 = f.den;
            uint _e69 = f.twice;
            NyqRounding _e72 = nyq_divide(_e65, _e67, _e69 != 0u);
            r_13 = _e72;
            uint _e75 = f.below;
            r_13.below = _e75;
        }
    }
    metal::uint4 _e77 = r_13.x;
    int _e79 = r_13.e;
    uint _e81 = r_13.sticky;
    uint _e85 = r_13.twice;
    uint _e88 = nyq_round_bits(_e77, _e79, _e81 != 0u, _e85 != 0u);
    bits_2 = _e88;
    uint _e91 = r_13.below;
    if (_e91 != 0u) {
        uint _e95 = r_13.twice;
        if (_e95 == 0u) {
            uint _e98 = bits_2;
            bits_2 = metal::min(_e98, NYQ_BELOW_ONE_BITS);
        }
        uint _e101 = bits_2;
        bits_2 = _e101 - 1u;
    }
    uint _e104 = bits_2;
    return as_type<float>(metal::min(_e104, NYQ_BELOW_ONE_BITS));
}

float nyq_radical_inverse(
    uint dim_33,
    metal::uint2 a_19,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e6 = nyq_radical_inverse_scrambled(dim_33, a_19, metal::uint2(0u, 0u), NYQ_SCRAMBLE_NONE, nyq_halton_bases, _buffer_sizes);
    return _e6;
}

float nyq_scrambled_radical_inverse(
    uint dim_34,
    metal::uint2 a_20,
    metal::uint2 seed_24,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e4 = nyq_radical_inverse_scrambled(dim_34, a_20, seed_24, NYQ_SCRAMBLE_PERMUTE_DIGITS, nyq_halton_bases, _buffer_sizes);
    return _e4;
}

float nyq_owen_scrambled_radical_inverse(
    uint dim_35,
    metal::uint2 a_21,
    metal::uint2 seed_25,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e4 = nyq_radical_inverse_scrambled(dim_35, a_21, seed_25, NYQ_SCRAMBLE_OWEN, nyq_halton_bases, _buffer_sizes);
    return _e4;
}

float nyq_fast_owen_scrambled_radical_inverse(
    uint dim_36,
    metal::uint2 a_22,
    metal::uint2 seed_26,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e4 = nyq_radical_inverse_scrambled(dim_36, a_22, seed_26, NYQ_SCRAMBLE_FAST_OWEN, nyq_halton_bases, _buffer_sizes);
    return _e4;
}

NyqHalton nyq_halton(
    uint dims_3,
    uint scramble_2,
    metal::uint2 seed_27
) {
    return NyqHalton {dims_3, scramble_2, seed_27};
}

float nyq_halton_sample(
    NyqHalton h_1,
    metal::uint2 index_15,
    uint dim_37,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    float _e7 = nyq_radical_inverse_scrambled(naga_mod(dim_37, h_1.dims), index_15, h_1.seed, h_1.scramble, nyq_halton_bases, _buffer_sizes);
    return _e7;
}

int naga_div(int lhs, int rhs) {
    return lhs / metal::select(rhs, 1, (lhs == (-2147483647 - 1) & rhs == -1) | (rhs == 0));
}

int naga_mod(int lhs, int rhs) {
    int divisor = metal::select(rhs, 1, (lhs == (-2147483647 - 1) & rhs == -1) | (rhs == 0));
    return lhs - (lhs / divisor) * divisor;
}

uint nyq_mod_inverse(
    uint a_23,
    uint n_6
) {
    int r0_ = {};
    int r1_ = {};
    int t0_ = 0;
    int t1_ = 1;
    int m_4 = {};
    r0_ = static_cast<int>(n_6);
    r1_ = static_cast<int>(naga_mod(a_23, n_6));
    uint2 loop_bound_33 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_33 == uint2(0u))) { break; }
        loop_bound_33 -= uint2(loop_bound_33.y == 0u, 1u);
        int _e11 = r1_;
        if (_e11 != 0) {
        } else {
            break;
        }
        {
            int _e14 = r0_;
            int _e15 = r1_;
            int q_8 = naga_div(_e14, _e15);
            int _e17 = r0_;
            int _e18 = r1_;
            int r2_1 = as_type<int>(as_type<uint>(_e17) - as_type<uint>(as_type<int>(as_type<uint>(q_8) * as_type<uint>(_e18))));
            int _e21 = t0_;
            int _e22 = t1_;
            int t2_3 = as_type<int>(as_type<uint>(_e21) - as_type<uint>(as_type<int>(as_type<uint>(q_8) * as_type<uint>(_e22))));
            int _e25 = r1_;
            r0_ = _e25;
            r1_ = r2_1;
            int _e26 = t1_;
            t0_ = _e26;
            t1_ = t2_3;
        }
    }
    int _e27 = t0_;
    m_4 = naga_mod(_e27, static_cast<int>(n_6));
    int _e31 = m_4;
    if (_e31 < 0) {
        int _e34 = m_4;
        m_4 = as_type<int>(as_type<uint>(_e34) + as_type<uint>(static_cast<int>(n_6)));
    }
    int _e37 = m_4;
    return static_cast<uint>(_e37);
}

metal::uint2 nyq_halton_scale(
    uint extent,
    uint b_12
) {
    uint scale_1 = 1u;
    uint e_1 = 0u;
    uint goal = metal::min(extent, 128u);
    uint2 loop_bound_34 = uint2(4294967295u);
    while(true) {
        if (metal::all(loop_bound_34 == uint2(0u))) { break; }
        loop_bound_34 -= uint2(loop_bound_34.y == 0u, 1u);
        uint _e8 = scale_1;
        if (_e8 < goal) {
        } else {
            break;
        }
        {
            uint _e10 = scale_1;
            scale_1 = _e10 * b_12;
            uint _e12 = e_1;
            e_1 = _e12 + 1u;
        }
    }
    uint _e15 = scale_1;
    uint _e16 = e_1;
    return metal::uint2(_e15, _e16);
}

NyqHaltonSampler nyq_halton_sampler(
    metal::uint2 resolution_2,
    uint spp,
    uint scramble_3,
    metal::uint2 seed_28
) {
    metal::uint2 _e6 = nyq_halton_scale(resolution_2.x, 2u);
    metal::uint2 _e9 = nyq_halton_scale(resolution_2.y, 3u);
    metal::uint2 scales = metal::uint2(_e6.x, _e9.x);
    uint _e16 = nyq_mod_inverse(_e9.x, _e6.x);
    uint _e21 = nyq_mod_inverse(_e6.x, _e9.x);
    metal::uint2 basis = metal::uint2(_e9.x * _e16, _e6.x * _e21);
    return NyqHaltonSampler {spp, scramble_3, seed_28, metal::uint2(_e6.y, _e9.y), scales, _e6.x * _e9.x, {}, basis, metal::uint2(0u, 0u), 0u};
}

uint nyq_inverse_radical_inverse(
    uint b_13,
    uint inverse_in,
    uint n_7
) {
    uint inverse_1 = {};
    uint index_16 = 0u;
    uint done = 0u;
    uint k_15 = {};
    inverse_1 = inverse_in;
    uint2 loop_bound_35 = uint2(4294967295u);
    bool loop_init_23 = true;
    while(true) {
        if (metal::all(loop_bound_35 == uint2(0u))) { break; }
        loop_bound_35 -= uint2(loop_bound_35.y == 0u, 1u);
        if (!loop_init_23) {
            uint _e32 = done;
            done = _e32 + 1u;
        }
        loop_init_23 = false;
        uint _e8 = done;
        if (_e8 < n_7) {
        } else {
            break;
        }
        {
            uint _e10 = inverse_1;
            if (_e10 == 0u) {
                uint _e13 = done;
                k_15 = _e13;
                uint2 loop_bound_36 = uint2(4294967295u);
                bool loop_init_24 = true;
                while(true) {
                    if (metal::all(loop_bound_36 == uint2(0u))) { break; }
                    loop_bound_36 -= uint2(loop_bound_36.y == 0u, 1u);
                    if (!loop_init_24) {
                        uint _e20 = k_15;
                        k_15 = _e20 + 1u;
                    }
                    loop_init_24 = false;
                    uint _e15 = k_15;
                    if (_e15 < n_7) {
                    } else {
                        break;
                    }
                    {
                        uint _e17 = index_16;
                        index_16 = _e17 * b_13;
                    }
                }
                uint _e22 = index_16;
                return _e22;
            }
            uint _e23 = inverse_1;
            uint q_9 = naga_div(_e23, b_13);
            uint _e25 = index_16;
            uint _e27 = inverse_1;
            index_16 = (_e25 * b_13) + (_e27 - (q_9 * b_13));
            inverse_1 = q_9;
        }
    }
    uint _e34 = index_16;
    return _e34;
}

metal::uint2 nyq_halton_sampler_index(
    thread NyqHaltonSampler& s_77,
    metal::uint2 pixel_18,
    uint sample_index_16
) {
    uint offset_1 = {};
    uint stride = s_77.stride;
    metal::uint2 scales_1 = s_77.scales;
    metal::uint2 exponents = s_77.exponents;
    metal::uint2 basis_1 = s_77.basis;
    uint _e16 = nyq_inverse_radical_inverse(2u, naga_mod(pixel_18.x, scales_1.x), exponents.x);
    offset_1 = naga_mod(_e16 * basis_1.x, stride);
    uint _e26 = nyq_inverse_radical_inverse(3u, naga_mod(pixel_18.y, scales_1.y), exponents.y);
    uint _e27 = offset_1;
    offset_1 = naga_mod(_e27 + (_e26 * basis_1.y), stride);
    metal::uint2 _e32 = nyq_mul_wide(sample_index_16, stride);
    uint _e33 = offset_1;
    metal::uint2 _e34 = nyq_u64_(_e33);
    metal::uint2 _e35 = nyq_add64_(_e32, _e34);
    return _e35;
}

float nyq_halton_sampler_value(
    thread NyqHaltonSampler& s_78,
    uint dim_38,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint2 a_24 = {};
    uint d_29 = naga_mod(dim_38, NYQ_PRIME_COUNT);
    metal::uint2 index_19 = s_78.index;
    a_24 = index_19;
    if (d_29 == 0u) {
        uint e_6 = s_78.exponents.x;
        if (e_6 != 0u) {
            metal::uint2 _e14 = nyq_shr64_(index_19, e_6);
            a_24 = _e14;
        }
    } else {
        if (d_29 == 1u) {
            uint _e19 = s_78.scales.y;
            metal::uint3 _e20 = nyq_divmod64_small(index_19, _e19);
            a_24 = _e20.xy;
        }
    }
    metal::uint2 _e22 = a_24;
    metal::uint2 _e24 = s_78.seed;
    uint _e26 = s_78.scramble;
    float _e27 = nyq_radical_inverse_scrambled(d_29, _e22, _e24, _e26, nyq_halton_bases, _buffer_sizes);
    return _e27;
}

void nyq_halton_sampler_start(
    thread NyqHaltonSampler& s_79,
    metal::uint2 pixel_19,
    uint sample_index_17,
    uint dim_39
) {
    metal::uint2 _e5 = nyq_halton_sampler_index(s_79, pixel_19, sample_index_17);
    s_79.index = _e5;
    s_79.dim = dim_39;
    return;
}

float nyq_halton_sampler_get_1d(
    thread NyqHaltonSampler& s_80,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_30 = s_80.dim;
    s_80.dim = d_30 + 1u;
    float _e6 = nyq_halton_sampler_value(s_80, d_30, nyq_halton_bases, _buffer_sizes);
    return _e6;
}

metal::float2 nyq_halton_sampler_pair(
    thread NyqHaltonSampler& s_81,
    uint dim_40,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float2 v_6 = metal::float2(0.0, 0.0);
    uint k_16 = 0u;
    uint2 loop_bound_37 = uint2(4294967295u);
    bool loop_init_25 = true;
    while(true) {
        if (metal::all(loop_bound_37 == uint2(0u))) { break; }
        loop_bound_37 -= uint2(loop_bound_37.y == 0u, 1u);
        if (!loop_init_25) {
            uint _e17 = k_16;
            k_16 = _e17 + 1u;
        }
        loop_init_25 = false;
        uint _e8 = k_16;
        if (_e8 < 2u) {
        } else {
            break;
        }
        {
            uint _e11 = k_16;
            uint _e13 = k_16;
            float _e15 = nyq_halton_sampler_value(s_81, dim_40 + _e13, nyq_halton_bases, _buffer_sizes);
            v_6[_e11] = _e15;
        }
    }
    metal::float2 _e19 = v_6;
    return _e19;
}

metal::float2 nyq_halton_sampler_get_2d(
    thread NyqHaltonSampler& s_82,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_31 = s_82.dim;
    s_82.dim = d_31 + 2u;
    metal::float2 _e6 = nyq_halton_sampler_pair(s_82, d_31, nyq_halton_bases, _buffer_sizes);
    return _e6;
}

metal::float2 nyq_halton_sampler_get_pixel_2d(
    thread NyqHaltonSampler& s_83,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = s_83.dim;
    s_83.dim = metal::max(_e3, 2u);
    metal::float2 _e7 = nyq_halton_sampler_pair(s_83, 0u, nyq_halton_bases, _buffer_sizes);
    return _e7;
}

NyqCameraSample nyq_halton_sampler_camera_sample(
    thread NyqHaltonSampler& s_84,
    metal::uint2 pixel_20,
    uint sample_index_18,
    device type_4 const& nyq_halton_bases,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::float4 v_7 = metal::float4(0.0, 0.0, 0.0, 0.0);
    float lens_y = 0.0;
    uint d_5 = 0u;
    nyq_halton_sampler_start(s_84, pixel_20, sample_index_18, 5u);
    uint2 loop_bound_38 = uint2(4294967295u);
    bool loop_init_26 = true;
    while(true) {
        if (metal::all(loop_bound_38 == uint2(0u))) { break; }
        loop_bound_38 -= uint2(loop_bound_38.y == 0u, 1u);
        if (!loop_init_26) {
            uint _e25 = d_5;
            d_5 = _e25 + 1u;
        }
        loop_init_26 = false;
        uint _e14 = d_5;
        if (_e14 < 5u) {
        } else {
            break;
        }
        {
            uint _e17 = d_5;
            float _e18 = nyq_halton_sampler_value(s_84, _e17, nyq_halton_bases, _buffer_sizes);
            uint _e19 = d_5;
            if (_e19 < 4u) {
                uint _e22 = d_5;
                v_7[_e22] = _e18;
            } else {
                lens_y = _e18;
            }
        }
    }
    float _e29 = v_7.x;
    float _e30 = nyq_film_coordinate(pixel_20.x, _e29);
    float _e33 = v_7.y;
    float _e34 = nyq_film_coordinate(pixel_20.y, _e33);
    metal::float2 film_6 = metal::float2(_e30, _e34);
    float _e37 = v_7.w;
    float _e38 = lens_y;
    float _e41 = v_7.z;
    return NyqCameraSample {film_6, metal::float2(_e37, _e38), _e41};
}

uint nyq_blue_entry(
    uint family,
    uint x_25,
    uint y_1,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e16 = nyq_blue_tiles[(((family * NYQ_BLUE_TILE_SIZE) * NYQ_BLUE_TILE_SIZE) + ((y_1 & 127u) * NYQ_BLUE_TILE_SIZE)) + (x_25 & 127u)];
    return _e16;
}

metal::uint2 nyq_blue_offset(
    metal::uint2 seed_29,
    uint frame_1,
    uint block
) {
    metal::uint2 _e5 = nyq_u64_(block ^ 1112298821u);
    metal::uint2 _e6 = nyq_hash2_(seed_29, _e5);
    metal::uint2 r_17 = metal::uint2((frame_1 * 3242174889u) >> 25u, (frame_1 * 2447445414u) >> 25u);
    return (_e6 + r_17) & metal::uint2(127u);
}

uint nyq_blue_block_entry(
    uint family_1,
    metal::uint2 seed_30,
    uint frame_2,
    metal::uint2 pixel_21,
    uint block_1,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    metal::uint2 _e5 = nyq_blue_offset(seed_30, frame_2, block_1);
    metal::uint2 p_4 = pixel_21 + _e5;
    uint _e9 = nyq_blue_entry(family_1, p_4.x, p_4.y, nyq_blue_tiles, _buffer_sizes);
    return _e9;
}

float nyq_blue_film_coordinate(
    uint pixel_22,
    float offset_2
) {
    float _e2 = nyq_u32_to_f32_(pixel_22);
    float x_29 = _e2 + offset_2;
    float edge_1 = _e2 + 1.0;
    if (x_29 < edge_1) {
        return x_29;
    }
    float below_1 = as_type<float>(as_type<uint>(edge_1) - 1u);
    return (below_1 >= _e2) ? below_1 : _e2;
}

NyqCameraSample nyq_blue_camera(
    metal::uint2 pixel_23,
    type_12 v_8
) {
    float _e4 = nyq_blue_film_coordinate(pixel_23.x, v_8.inner[0]);
    float _e7 = nyq_blue_film_coordinate(pixel_23.y, v_8.inner[1]);
    metal::float2 p_5 = metal::float2(_e4, _e7);
    return NyqCameraSample {p_5, metal::float2(v_8.inner[3], v_8.inner[4]), v_8.inner[2]};
}

uint nyq_blue_shift(
    uint key_4,
    uint c_6
) {
    uint _e7 = nyq_mix32_(key_4 ^ ((c_6 + 1u) * 2654435769u));
    return _e7;
}

NyqBlueSampler nyq_blue_sampler(
    metal::uint2 seed_31,
    uint frame_3
) {
    return NyqBlueSampler {seed_31, frame_3, {}, metal::uint2(0u), 0u, 0u, metal::uint2(0u), metal::uint2(0u)};
}

uint nyq_owen_sobol_bn_key(
    uint entry
) {
    uint _e5 = nyq_mix32_((entry >> 8u) ^ 1112296192u);
    return _e5;
}

uint nyq_owen_sobol_bn_rev(
    uint entry_1,
    uint key_5,
    uint index_17
) {
    uint _e8 = nyq_mix32_(key_5 ^ 1397249350u);
    uint _e9 = nyq_shuffle_rev(index_17 ^ (entry_1 & 255u), _e8);
    return _e9;
}

float nyq_owen_sobol_bn_value_at(
    uint key_6,
    uint rev_2,
    uint c_7,
    device type_4 const& nyq_sobol_matrices,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = nyq_dim_seed(key_6, c_7);
    uint _e4 = nyq_owen_sobol_rev(rev_2, c_7, _e3, nyq_sobol_matrices, _buffer_sizes);
    float _e5 = nyq_rev_to_f32_(_e4);
    return _e5;
}

NyqBlueSampler nyq_owen_sobol_bn_sampler(
    metal::uint2 seed_32,
    uint frame_4
) {
    NyqBlueSampler _e2 = nyq_blue_sampler(seed_32, frame_4);
    return _e2;
}

void nyq_owen_sobol_bn_start(
    thread NyqBlueSampler& s_85,
    metal::uint2 pixel_24,
    uint sample_index_19,
    uint dim_41,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint b_14 = 0u;
    s_85.pixel = pixel_24;
    s_85.index = sample_index_19;
    s_85.dim = dim_41;
    uint2 loop_bound_39 = uint2(4294967295u);
    bool loop_init_27 = true;
    while(true) {
        if (metal::all(loop_bound_39 == uint2(0u))) { break; }
        loop_bound_39 -= uint2(loop_bound_39.y == 0u, 1u);
        if (!loop_init_27) {
            uint _e28 = b_14;
            b_14 = _e28 + 1u;
        }
        loop_init_27 = false;
        uint _e9 = b_14;
        if (_e9 < 2u) {
        } else {
            break;
        }
        {
            metal::uint2 _e14 = s_85.seed;
            uint _e16 = s_85.frame;
            uint _e17 = b_14;
            uint _e18 = nyq_blue_block_entry(NYQ_BLUE_OWEN_SOBOL, _e14, _e16, pixel_24, _e17, nyq_blue_tiles, _buffer_sizes);
            uint _e19 = nyq_owen_sobol_bn_key(_e18);
            uint _e21 = b_14;
            s_85.key[_e21] = _e19;
            uint _e24 = b_14;
            uint _e26 = nyq_owen_sobol_bn_rev(_e18, _e19, sample_index_19);
            s_85.prepared[_e24] = _e26;
        }
    }
    return;
}

float nyq_owen_sobol_bn_value(
    thread NyqBlueSampler& s_86,
    uint dim_42,
    device type_4 const& nyq_sobol_matrices,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint b_21 = naga_div(dim_42, 4u);
    uint c_14 = naga_mod(dim_42, 4u);
    if (b_21 < 2u) {
        uint _e10 = s_86.key[b_21];
        uint _e13 = s_86.prepared[b_21];
        float _e14 = nyq_owen_sobol_bn_value_at(_e10, _e13, c_14, nyq_sobol_matrices, _buffer_sizes);
        return _e14;
    }
    metal::uint2 _e17 = s_86.seed;
    uint _e19 = s_86.frame;
    metal::uint2 _e21 = s_86.pixel;
    uint _e22 = nyq_blue_block_entry(NYQ_BLUE_OWEN_SOBOL, _e17, _e19, _e21, b_21, nyq_blue_tiles, _buffer_sizes);
    uint _e23 = nyq_owen_sobol_bn_key(_e22);
    uint _e25 = s_86.index;
    uint _e26 = nyq_owen_sobol_bn_rev(_e22, _e23, _e25);
    float _e27 = nyq_owen_sobol_bn_value_at(_e23, _e26, c_14, nyq_sobol_matrices, _buffer_sizes);
    return _e27;
}

float nyq_owen_sobol_bn_get_1d(
    thread NyqBlueSampler& s_87,
    device type_4 const& nyq_sobol_matrices,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_32 = s_87.dim;
    s_87.dim = d_32 + 1u;
    float _e6 = nyq_owen_sobol_bn_value(s_87, d_32, nyq_sobol_matrices, nyq_blue_tiles, _buffer_sizes);
    return _e6;
}

metal::float2 nyq_owen_sobol_bn_get_2d(
    thread NyqBlueSampler& s_88,
    device type_4 const& nyq_sobol_matrices,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_33 = s_88.dim;
    s_88.dim = d_33 + 2u;
    float _e6 = nyq_owen_sobol_bn_value(s_88, d_33, nyq_sobol_matrices, nyq_blue_tiles, _buffer_sizes);
    float _e9 = nyq_owen_sobol_bn_value(s_88, d_33 + 1u, nyq_sobol_matrices, nyq_blue_tiles, _buffer_sizes);
    return metal::float2(_e6, _e9);
}

metal::float2 nyq_owen_sobol_bn_get_pixel_2d(
    thread NyqBlueSampler& s_89,
    device type_4 const& nyq_sobol_matrices,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = s_89.dim;
    s_89.dim = metal::max(_e3, 2u);
    float _e7 = nyq_owen_sobol_bn_value(s_89, 0u, nyq_sobol_matrices, nyq_blue_tiles, _buffer_sizes);
    float _e9 = nyq_owen_sobol_bn_value(s_89, 1u, nyq_sobol_matrices, nyq_blue_tiles, _buffer_sizes);
    return metal::float2(_e7, _e9);
}

NyqCameraSample nyq_owen_sobol_bn_camera_sample(
    thread NyqBlueSampler& s_90,
    metal::uint2 pixel_25,
    uint sample_index_20,
    device type_4 const& nyq_sobol_matrices,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    type_12 v_9 = {};
    uint d_6 = 0u;
    nyq_owen_sobol_bn_start(s_90, pixel_25, sample_index_20, 0u, nyq_blue_tiles, _buffer_sizes);
    uint2 loop_bound_40 = uint2(4294967295u);
    bool loop_init_28 = true;
    while(true) {
        if (metal::all(loop_bound_40 == uint2(0u))) { break; }
        loop_bound_40 -= uint2(loop_bound_40.y == 0u, 1u);
        if (!loop_init_28) {
            uint _e15 = d_6;
            d_6 = _e15 + 1u;
        }
        loop_init_28 = false;
        uint _e7 = d_6;
        if (_e7 < 5u) {
        } else {
            break;
        }
        {
            uint _e10 = d_6;
            uint _e12 = d_6;
            float _e13 = nyq_owen_sobol_bn_value(s_90, _e12, nyq_sobol_matrices, nyq_blue_tiles, _buffer_sizes);
            v_9.inner[_e10] = _e13;
        }
    }
    s_90.dim = 5u;
    type_12 _e19 = v_9;
    NyqCameraSample _e20 = nyq_blue_camera(pixel_25, _e19);
    return _e20;
}

uint nyq_pmj02_bn_key(
    uint entry_2,
    uint i_15
) {
    uint _e6 = nyq_mix32_((entry_2 >> 8u) ^ 1347242496u);
    uint epoch = i_15 >> 16u;
    uint _e9 = nyq_mix32_(epoch);
    uint _e11 = nyq_mix32_(_e6 ^ _e9);
    return (epoch == 0u) ? _e6 : _e11;
}

uint nyq_pmj02_bn_points(
    uint k_17,
    uint i_16
) {
    uint _e6 = nyq_mix32_(k_17 ^ 1397249350u);
    uint _e7 = nyq_shuffle_rev(i_16 & 65535u, _e6);
    uint p0_ = metal::reverse_bits(_e7) & 65535u;
    uint _e15 = nyq_mix32_(k_17 ^ 1397249351u);
    uint _e16 = nyq_shuffle_rev(i_16 & 65535u, _e15);
    uint p1_ = metal::reverse_bits(_e16) & 65535u;
    return p0_ | (p1_ << 16u);
}

float nyq_pmj02_bn_value_at(
    uint k_18,
    uint points,
    uint c_8
) {
    uint point = (points >> (16u * naga_div(c_8, 2u))) & 65535u;
    uint _e13 = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, point, naga_mod(c_8, 2u));
    uint _e14 = nyq_blue_shift(k_18, c_8);
    float _e16 = nyq_fraction_to_f32_(_e13 ^ _e14);
    return _e16;
}

NyqBlueSampler nyq_pmj02_bn_sampler(
    metal::uint2 seed_33,
    uint frame_5
) {
    NyqBlueSampler _e2 = nyq_blue_sampler(seed_33, frame_5);
    return _e2;
}

void nyq_pmj02_bn_start(
    thread NyqBlueSampler& s_91,
    metal::uint2 pixel_26,
    uint sample_index_21,
    uint dim_43,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint b_15 = 0u;
    s_91.pixel = pixel_26;
    s_91.index = sample_index_21;
    s_91.dim = dim_43;
    uint2 loop_bound_41 = uint2(4294967295u);
    bool loop_init_29 = true;
    while(true) {
        if (metal::all(loop_bound_41 == uint2(0u))) { break; }
        loop_bound_41 -= uint2(loop_bound_41.y == 0u, 1u);
        if (!loop_init_29) {
            uint _e31 = b_15;
            b_15 = _e31 + 1u;
        }
        loop_init_29 = false;
        uint _e9 = b_15;
        if (_e9 < 2u) {
        } else {
            break;
        }
        {
            metal::uint2 _e14 = s_91.seed;
            uint _e16 = s_91.frame;
            uint _e17 = b_15;
            uint _e18 = nyq_blue_block_entry(NYQ_BLUE_PMJ02_, _e14, _e16, pixel_26, _e17, nyq_blue_tiles, _buffer_sizes);
            uint i_18 = sample_index_21 ^ (_e18 & 255u);
            uint _e22 = nyq_pmj02_bn_key(_e18, i_18);
            uint _e24 = b_15;
            s_91.key[_e24] = _e22;
            uint _e27 = b_15;
            uint _e29 = nyq_pmj02_bn_points(_e22, i_18);
            s_91.prepared[_e27] = _e29;
        }
    }
    return;
}

float nyq_pmj02_bn_value(
    thread NyqBlueSampler& s_92,
    uint dim_44,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint b_22 = naga_div(dim_44, 4u);
    uint c_15 = naga_mod(dim_44, 4u);
    if (b_22 < 2u) {
        uint _e10 = s_92.key[b_22];
        uint _e13 = s_92.prepared[b_22];
        float _e14 = nyq_pmj02_bn_value_at(_e10, _e13, c_15);
        return _e14;
    }
    metal::uint2 _e17 = s_92.seed;
    uint _e19 = s_92.frame;
    metal::uint2 _e21 = s_92.pixel;
    uint _e22 = nyq_blue_block_entry(NYQ_BLUE_PMJ02_, _e17, _e19, _e21, b_22, nyq_blue_tiles, _buffer_sizes);
    uint _e24 = s_92.index;
    uint i_19 = _e24 ^ (_e22 & 255u);
    uint _e28 = nyq_pmj02_bn_key(_e22, i_19);
    uint _e29 = nyq_pmj02_bn_points(_e28, i_19);
    float _e30 = nyq_pmj02_bn_value_at(_e28, _e29, c_15);
    return _e30;
}

float nyq_pmj02_bn_get_1d(
    thread NyqBlueSampler& s_93,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_34 = s_93.dim;
    s_93.dim = d_34 + 1u;
    float _e6 = nyq_pmj02_bn_value(s_93, d_34, nyq_blue_tiles, _buffer_sizes);
    return _e6;
}

metal::float2 nyq_pmj02_bn_get_2d(
    thread NyqBlueSampler& s_94,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_35 = s_94.dim;
    s_94.dim = d_35 + 2u;
    float _e6 = nyq_pmj02_bn_value(s_94, d_35, nyq_blue_tiles, _buffer_sizes);
    float _e9 = nyq_pmj02_bn_value(s_94, d_35 + 1u, nyq_blue_tiles, _buffer_sizes);
    return metal::float2(_e6, _e9);
}

metal::float2 nyq_pmj02_bn_get_pixel_2d(
    thread NyqBlueSampler& s_95,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = s_95.dim;
    s_95.dim = metal::max(_e3, 2u);
    float _e7 = nyq_pmj02_bn_value(s_95, 0u, nyq_blue_tiles, _buffer_sizes);
    float _e9 = nyq_pmj02_bn_value(s_95, 1u, nyq_blue_tiles, _buffer_sizes);
    return metal::float2(_e7, _e9);
}

NyqCameraSample nyq_pmj02_bn_camera_sample(
    thread NyqBlueSampler& s_96,
    metal::uint2 pixel_27,
    uint sample_index_22,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    type_12 v_10 = {};
    uint d_7 = 0u;
    nyq_pmj02_bn_start(s_96, pixel_27, sample_index_22, 0u, nyq_blue_tiles, _buffer_sizes);
    uint2 loop_bound_42 = uint2(4294967295u);
    bool loop_init_30 = true;
    while(true) {
        if (metal::all(loop_bound_42 == uint2(0u))) { break; }
        loop_bound_42 -= uint2(loop_bound_42.y == 0u, 1u);
        if (!loop_init_30) {
            uint _e15 = d_7;
            d_7 = _e15 + 1u;
        }
        loop_init_30 = false;
        uint _e7 = d_7;
        if (_e7 < 5u) {
        } else {
            break;
        }
        {
            uint _e10 = d_7;
            uint _e12 = d_7;
            float _e13 = nyq_pmj02_bn_value(s_96, _e12, nyq_blue_tiles, _buffer_sizes);
            v_10.inner[_e10] = _e13;
        }
    }
    s_96.dim = 5u;
    type_12 _e19 = v_10;
    NyqCameraSample _e20 = nyq_blue_camera(pixel_27, _e19);
    return _e20;
}

uint nyq_lattice_bn_key(
    uint entry_3
) {
    uint _e5 = nyq_mix32_((entry_3 >> 8u) ^ 1279349760u);
    return _e5;
}

uint nyq_lattice_bn_rev(
    uint entry_4,
    uint key_7,
    uint index_18
) {
    uint _e8 = nyq_mix32_(key_7 ^ 1397249350u);
    uint _e9 = nyq_shuffle_rev(index_18 ^ (entry_4 & 255u), _e8);
    return _e9;
}

float nyq_lattice_bn_value_at(
    uint key_8,
    uint rev_3,
    uint c_9
) {
    uint _e6 = nyq_blue_shift(key_8, c_9);
    float _e8 = nyq_fraction_to_f32_((rev_3 * NYQ_LATTICE_BN_GENERATOR[c_9]) + _e6);
    return _e8;
}

NyqBlueSampler nyq_lattice_bn_sampler(
    metal::uint2 seed_34,
    uint frame_6
) {
    NyqBlueSampler _e2 = nyq_blue_sampler(seed_34, frame_6);
    return _e2;
}

void nyq_lattice_bn_start(
    thread NyqBlueSampler& s_97,
    metal::uint2 pixel_28,
    uint sample_index_23,
    uint dim_45,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint b_16 = 0u;
    s_97.pixel = pixel_28;
    s_97.index = sample_index_23;
    s_97.dim = dim_45;
    uint2 loop_bound_43 = uint2(4294967295u);
    bool loop_init_31 = true;
    while(true) {
        if (metal::all(loop_bound_43 == uint2(0u))) { break; }
        loop_bound_43 -= uint2(loop_bound_43.y == 0u, 1u);
        if (!loop_init_31) {
            uint _e28 = b_16;
            b_16 = _e28 + 1u;
        }
        loop_init_31 = false;
        uint _e9 = b_16;
        if (_e9 < 2u) {
        } else {
            break;
        }
        {
            metal::uint2 _e14 = s_97.seed;
            uint _e16 = s_97.frame;
            uint _e17 = b_16;
            uint _e18 = nyq_blue_block_entry(NYQ_BLUE_LATTICE, _e14, _e16, pixel_28, _e17, nyq_blue_tiles, _buffer_sizes);
            uint _e19 = nyq_lattice_bn_key(_e18);
            uint _e21 = b_16;
            s_97.key[_e21] = _e19;
            uint _e24 = b_16;
            uint _e26 = nyq_lattice_bn_rev(_e18, _e19, sample_index_23);
            s_97.prepared[_e24] = _e26;
        }
    }
    return;
}

float nyq_lattice_bn_value(
    thread NyqBlueSampler& s_98,
    uint dim_46,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint b_23 = naga_div(dim_46, 4u);
    uint c_16 = naga_mod(dim_46, 4u);
    if (b_23 < 2u) {
        uint _e10 = s_98.key[b_23];
        uint _e13 = s_98.prepared[b_23];
        float _e14 = nyq_lattice_bn_value_at(_e10, _e13, c_16);
        return _e14;
    }
    metal::uint2 _e17 = s_98.seed;
    uint _e19 = s_98.frame;
    metal::uint2 _e21 = s_98.pixel;
    uint _e22 = nyq_blue_block_entry(NYQ_BLUE_LATTICE, _e17, _e19, _e21, b_23, nyq_blue_tiles, _buffer_sizes);
    uint _e23 = nyq_lattice_bn_key(_e22);
    uint _e25 = s_98.index;
    uint _e26 = nyq_lattice_bn_rev(_e22, _e23, _e25);
    float _e27 = nyq_lattice_bn_value_at(_e23, _e26, c_16);
    return _e27;
}

float nyq_lattice_bn_get_1d(
    thread NyqBlueSampler& s_99,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_36 = s_99.dim;
    s_99.dim = d_36 + 1u;
    float _e6 = nyq_lattice_bn_value(s_99, d_36, nyq_blue_tiles, _buffer_sizes);
    return _e6;
}

metal::float2 nyq_lattice_bn_get_2d(
    thread NyqBlueSampler& s_100,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint d_37 = s_100.dim;
    s_100.dim = d_37 + 2u;
    float _e6 = nyq_lattice_bn_value(s_100, d_37, nyq_blue_tiles, _buffer_sizes);
    float _e9 = nyq_lattice_bn_value(s_100, d_37 + 1u, nyq_blue_tiles, _buffer_sizes);
    return metal::float2(_e6, _e9);
}

metal::float2 nyq_lattice_bn_get_pixel_2d(
    thread NyqBlueSampler& s_101,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = s_101.dim;
    s_101.dim = metal::max(_e3, 2u);
    float _e7 = nyq_lattice_bn_value(s_101, 0u, nyq_blue_tiles, _buffer_sizes);
    float _e9 = nyq_lattice_bn_value(s_101, 1u, nyq_blue_tiles, _buffer_sizes);
    return metal::float2(_e7, _e9);
}

NyqCameraSample nyq_lattice_bn_camera_sample(
    thread NyqBlueSampler& s_102,
    metal::uint2 pixel_29,
    uint sample_index_24,
    device type_4 const& nyq_blue_tiles,
    constant _mslBufferSizes& _buffer_sizes
) {
    type_12 v_11 = {};
    uint d_8 = 0u;
    nyq_lattice_bn_start(s_102, pixel_29, sample_index_24, 0u, nyq_blue_tiles, _buffer_sizes);
    uint2 loop_bound_44 = uint2(4294967295u);
    bool loop_init_32 = true;
    while(true) {
        if (metal::all(loop_bound_44 == uint2(0u))) { break; }
        loop_bound_44 -= uint2(loop_bound_44.y == 0u, 1u);
        if (!loop_init_32) {
            uint _e15 = d_8;
            d_8 = _e15 + 1u;
        }
        loop_init_32 = false;
        uint _e7 = d_8;
        if (_e7 < 5u) {
        } else {
            break;
        }
        {
            uint _e10 = d_8;
            uint _e12 = d_8;
            float _e13 = nyq_lattice_bn_value(s_102, _e12, nyq_blue_tiles, _buffer_sizes);
            v_11.inner[_e10] = _e13;
        }
    }
    s_102.dim = 5u;
    type_12 _e19 = v_11;
    NyqCameraSample _e20 = nyq_blue_camera(pixel_29, _e19);
    return _e20;
}

metal::uint4 nyq_fill_request(
    uint i_17,
    constant NyqFillJob& nyq_job,
    device type_28 const& nyq_requests,
    constant _mslBufferSizes& _buffer_sizes
) {
    uint _e3 = nyq_job.implicit;
    if (_e3 == 0u) {
        metal::uint4 _e8 = nyq_requests[i_17];
        return _e8;
    }
    uint _e11 = nyq_job.first;
    uint n_13 = _e11 + i_17;
    uint _e15 = nyq_job.spp;
    uint pixel_30 = naga_div(n_13, _e15);
    uint _e20 = nyq_job.resolution.x;
    uint _e25 = nyq_job.resolution.x;
    uint _e29 = nyq_job.spp;
    return metal::uint4(naga_mod(pixel_30, _e20), naga_div(pixel_30, _e25), naga_mod(n_13, _e29), 5u);
}

void nyq_fill_camera(
    uint out_3,
    NyqCameraSample c_10,
    device type_4& nyq_values,
    constant _mslBufferSizes& _buffer_sizes
) {
    nyq_values[out_3] = as_type<uint>(c_10.p_film.x);
    nyq_values[out_3 + 1u] = as_type<uint>(c_10.p_film.y);
    nyq_values[out_3 + 2u] = as_type<uint>(c_10.time);
    nyq_values[out_3 + 3u] = as_type<uint>(c_10.lens.x);
    nyq_values[out_3 + 4u] = as_type<uint>(c_10.lens.y);
    return;
}

void nyq_fill_values(
    uint out_4,
    float one,
    metal::float2 two,
    device type_4& nyq_values,
    constant _mslBufferSizes& _buffer_sizes
) {
    nyq_values[out_4 + 5u] = as_type<uint>(one);
    nyq_values[out_4 + 6u] = as_type<uint>(two.x);
    nyq_values[out_4 + 7u] = as_type<uint>(two.y);
    return;
}

struct nyq_fillInput {
};
kernel void nyq_fill(
  metal::uint3 id [[thread_position_in_grid]]
, device type_4 const& nyq_sobol_matrices [[buffer(0)]]
, device type_4 const& nyq_halton_bases [[buffer(4)]]
, device type_4 const& nyq_blue_tiles [[buffer(5)]]
, constant NyqFillJob& nyq_job [[buffer(1)]]
, device type_28 const& nyq_requests [[buffer(2)]]
, device type_4& nyq_values [[buffer(3)]]
, constant _mslBufferSizes& _buffer_sizes [[buffer(6)]]
) {
    NyqOwenSobolSampler s = {};
    NyqZSobolSampler s_1 = {};
    NyqRandomSampler s_2 = {};
    NyqLatticeSampler s_3 = {};
    NyqStratifiedSampler s_4 = {};
    NyqPmj02Sampler s_5 = {};
    NyqSobolSampler s_6 = {};
    NyqHaltonSampler s_7 = {};
    NyqBlueSampler s_8 = {};
    NyqBlueSampler s_9 = {};
    NyqBlueSampler s_10 = {};
    uint k = 0u;
    uint k_1 = 0u;
    uint k_2 = 0u;
    uint k_3 = 0u;
    uint k_4 = 0u;
    uint k_5 = 0u;
    uint i_20 = id.x;
    uint _e4 = nyq_job.count;
    if (i_20 >= _e4) {
        return;
    }
    metal::uint4 _e6 = nyq_fill_request(i_20, nyq_job, nyq_requests, _buffer_sizes);
    metal::uint2 pixel_31 = _e6.xy;
    uint out_5 = 8u * i_20;
    uint _e12 = nyq_job.kind;
    switch(_e12) {
        case 0u: {
            metal::uint2 _e15 = nyq_job.seed;
            uint _e18 = nyq_job.frame;
            NyqOwenSobolSampler _e19 = nyq_owen_sobol_sampler(_e15, _e18);
            s = _e19;
            NyqCameraSample _e22 = nyq_owen_sobol_camera_sample(s, pixel_31, _e6.z, nyq_sobol_matrices, _buffer_sizes);
            nyq_fill_camera(out_5, _e22, nyq_values, _buffer_sizes);
            nyq_owen_sobol_start(s, pixel_31, _e6.z, _e6.w);
            float _e25 = nyq_owen_sobol_get_1d(s, nyq_sobol_matrices, _buffer_sizes);
            metal::float2 _e26 = nyq_owen_sobol_get_2d(s, nyq_sobol_matrices, _buffer_sizes);
            nyq_fill_values(out_5, _e25, _e26, nyq_values, _buffer_sizes);
            return;
        }
        case 1u: {
            metal::uint2 _e29 = nyq_job.resolution;
            uint _e32 = nyq_job.spp;
            uint _e35 = nyq_job.scramble;
            metal::uint2 _e38 = nyq_job.seed;
            NyqZSobolSampler _e39 = nyq_zsobol_sampler(_e29, _e32, _e35, _e38);
            s_1 = _e39;
            NyqCameraSample _e42 = nyq_zsobol_camera_sample(s_1, pixel_31, _e6.z, nyq_sobol_matrices, _buffer_sizes);
            nyq_fill_camera(out_5, _e42, nyq_values, _buffer_sizes);
            nyq_zsobol_start(s_1, pixel_31, _e6.z, _e6.w);
            float _e45 = nyq_zsobol_get_1d(s_1);
            metal::float2 _e46 = nyq_zsobol_get_2d(s_1, nyq_sobol_matrices, _buffer_sizes);
            nyq_fill_values(out_5, _e45, _e46, nyq_values, _buffer_sizes);
            return;
        }
        case 2u: {
            metal::uint2 _e49 = nyq_job.seed;
            NyqRandomSampler _e50 = nyq_random_sampler(_e49);
            s_2 = _e50;
            NyqCameraSample _e53 = nyq_random_camera_sample(s_2, pixel_31, _e6.z);
            nyq_fill_camera(out_5, _e53, nyq_values, _buffer_sizes);
            nyq_random_start(s_2, pixel_31, _e6.z, _e6.w);
            float _e56 = nyq_random_get_1d(s_2);
            metal::float2 _e57 = nyq_random_get_2d(s_2);
            nyq_fill_values(out_5, _e56, _e57, nyq_values, _buffer_sizes);
            return;
        }
        case 3u: {
            uint _e60 = nyq_job.lattice;
            uint _e63 = nyq_job.spp;
            uint _e66 = nyq_job.generator;
            metal::uint2 _e69 = nyq_job.seed;
            NyqLatticeSampler _e70 = nyq_lattice_sampler(_e60, _e63, _e66, _e69);
            s_3 = _e70;
            NyqCameraSample _e73 = nyq_lattice_camera_sample(s_3, pixel_31, _e6.z);
            nyq_fill_camera(out_5, _e73, nyq_values, _buffer_sizes);
            nyq_lattice_start(s_3, pixel_31, _e6.z, _e6.w);
            float _e76 = nyq_lattice_get_1d(s_3);
            metal::float2 _e77 = nyq_lattice_get_2d(s_3);
            nyq_fill_values(out_5, _e76, _e77, nyq_values, _buffer_sizes);
            return;
        }
        case 4u: {
            uint _e81 = nyq_job.resolution.x;
            uint _e85 = nyq_job.resolution.y;
            uint _e88 = nyq_job.scramble;
            metal::uint2 _e91 = nyq_job.seed;
            NyqStratifiedSampler _e92 = nyq_stratified_sampler(_e81, _e85, _e88, _e91);
            s_4 = _e92;
            NyqCameraSample _e95 = nyq_stratified_camera_sample(s_4, pixel_31, _e6.z);
            nyq_fill_camera(out_5, _e95, nyq_values, _buffer_sizes);
            nyq_stratified_start(s_4, pixel_31, _e6.z, _e6.w);
            float _e98 = nyq_stratified_get_1d(s_4);
            metal::float2 _e99 = nyq_stratified_get_2d(s_4);
            nyq_fill_values(out_5, _e98, _e99, nyq_values, _buffer_sizes);
            return;
        }
        case 5u: {
            metal::uint2 _e102 = nyq_job.seed;
            NyqPmj02Sampler _e103 = nyq_pmj02_sampler(_e102);
            s_5 = _e103;
            NyqCameraSample _e106 = nyq_pmj02_camera_sample(s_5, pixel_31, _e6.z);
            nyq_fill_camera(out_5, _e106, nyq_values, _buffer_sizes);
            nyq_pmj02_start(s_5, pixel_31, _e6.z, _e6.w);
            float _e109 = nyq_pmj02_get_1d(s_5);
            metal::float2 _e110 = nyq_pmj02_get_2d(s_5);
            nyq_fill_values(out_5, _e109, _e110, nyq_values, _buffer_sizes);
            return;
        }
        case 6u: {
            metal::uint2 _e113 = nyq_job.resolution;
            uint _e116 = nyq_job.spp;
            uint _e119 = nyq_job.scramble;
            metal::uint2 _e122 = nyq_job.seed;
            NyqSobolSampler _e123 = nyq_sobol_sampler(_e113, _e116, _e119, _e122, nyq_sobol_matrices, _buffer_sizes);
            s_6 = _e123;
            NyqCameraSample _e126 = nyq_sobol_sampler_camera_sample(s_6, pixel_31, _e6.z, nyq_sobol_matrices, _buffer_sizes);
            nyq_fill_camera(out_5, _e126, nyq_values, _buffer_sizes);
            nyq_sobol_sampler_start(s_6, pixel_31, _e6.z, _e6.w, nyq_sobol_matrices, _buffer_sizes);
            float _e129 = nyq_sobol_sampler_get_1d(s_6, nyq_sobol_matrices, _buffer_sizes);
            metal::float2 _e130 = nyq_sobol_sampler_get_2d(s_6, nyq_sobol_matrices, _buffer_sizes);
            nyq_fill_values(out_5, _e129, _e130, nyq_values, _buffer_sizes);
            return;
        }
        case 7u: {
            metal::uint2 _e133 = nyq_job.resolution;
            uint _e136 = nyq_job.spp;
            uint _e139 = nyq_job.scramble;
            metal::uint2 _e142 = nyq_job.seed;
            NyqHaltonSampler _e143 = nyq_halton_sampler(_e133, _e136, _e139, _e142);
            s_7 = _e143;
            NyqCameraSample _e146 = nyq_halton_sampler_camera_sample(s_7, pixel_31, _e6.z, nyq_halton_bases, _buffer_sizes);
            nyq_fill_camera(out_5, _e146, nyq_values, _buffer_sizes);
            nyq_halton_sampler_start(s_7, pixel_31, _e6.z, _e6.w);
            float _e149 = nyq_halton_sampler_get_1d(s_7, nyq_halton_bases, _buffer_sizes);
            metal::float2 _e150 = nyq_halton_sampler_get_2d(s_7, nyq_halton_bases, _buffer_sizes);
            nyq_fill_values(out_5, _e149, _e150, nyq_values, _buffer_sizes);
            return;
        }
        case 8u: {
            metal::uint2 _e153 = nyq_job.seed;
            uint _e156 = nyq_job.frame;
            NyqBlueSampler _e157 = nyq_owen_sobol_bn_sampler(_e153, _e156);
            s_8 = _e157;
            NyqCameraSample _e160 = nyq_owen_sobol_bn_camera_sample(s_8, pixel_31, _e6.z, nyq_sobol_matrices, nyq_blue_tiles, _buffer_sizes);
            nyq_fill_camera(out_5, _e160, nyq_values, _buffer_sizes);
            nyq_owen_sobol_bn_start(s_8, pixel_31, _e6.z, _e6.w, nyq_blue_tiles, _buffer_sizes);
            float _e163 = nyq_owen_sobol_bn_get_1d(s_8, nyq_sobol_matrices, nyq_blue_tiles, _buffer_sizes);
            metal::float2 _e164 = nyq_owen_sobol_bn_get_2d(s_8, nyq_sobol_matrices, nyq_blue_tiles, _buffer_sizes);
            nyq_fill_values(out_5, _e163, _e164, nyq_values, _buffer_sizes);
            return;
        }
        case 9u: {
            metal::uint2 _e167 = nyq_job.seed;
            uint _e170 = nyq_job.frame;
            NyqBlueSampler _e171 = nyq_pmj02_bn_sampler(_e167, _e170);
            s_9 = _e171;
            NyqCameraSample _e174 = nyq_pmj02_bn_camera_sample(s_9, pixel_31, _e6.z, nyq_blue_tiles, _buffer_sizes);
            nyq_fill_camera(out_5, _e174, nyq_values, _buffer_sizes);
            nyq_pmj02_bn_start(s_9, pixel_31, _e6.z, _e6.w, nyq_blue_tiles, _buffer_sizes);
            float _e177 = nyq_pmj02_bn_get_1d(s_9, nyq_blue_tiles, _buffer_sizes);
            metal::float2 _e178 = nyq_pmj02_bn_get_2d(s_9, nyq_blue_tiles, _buffer_sizes);
            nyq_fill_values(out_5, _e177, _e178, nyq_values, _buffer_sizes);
            return;
        }
        case 10u: {
            metal::uint2 _e181 = nyq_job.seed;
            uint _e184 = nyq_job.frame;
            NyqBlueSampler _e185 = nyq_lattice_bn_sampler(_e181, _e184);
            s_10 = _e185;
            NyqCameraSample _e188 = nyq_lattice_bn_camera_sample(s_10, pixel_31, _e6.z, nyq_blue_tiles, _buffer_sizes);
            nyq_fill_camera(out_5, _e188, nyq_values, _buffer_sizes);
            nyq_lattice_bn_start(s_10, pixel_31, _e6.z, _e6.w, nyq_blue_tiles, _buffer_sizes);
            float _e191 = nyq_lattice_bn_get_1d(s_10, nyq_blue_tiles, _buffer_sizes);
            metal::float2 _e192 = nyq_lattice_bn_get_2d(s_10, nyq_blue_tiles, _buffer_sizes);
            nyq_fill_values(out_5, _e191, _e192, nyq_values, _buffer_sizes);
            return;
        }
        case 16u: {
            uint _e195 = nyq_job.dims;
            uint _e198 = nyq_job.scramble;
            metal::uint2 _e203 = nyq_job.seed;
            NyqSobol _e204 = nyq_sobol(_e195, _e198 != 0u, _e203);
            uint2 loop_bound_45 = uint2(4294967295u);
            bool loop_init_33 = true;
            while(true) {
                if (metal::all(loop_bound_45 == uint2(0u))) { break; }
                loop_bound_45 -= uint2(loop_bound_45.y == 0u, 1u);
                if (!loop_init_33) {
                    uint _e232 = k;
                    k = _e232 + 1u;
                }
                loop_init_33 = false;
                uint _e207 = k;
                if (_e207 < 4u) {
                } else {
                    break;
                }
                {
                    uint _e211 = k;
                    uint _e216 = k;
                    uint _e218 = nyq_sobol_sample_u32_(_e204, _e6.z, _e6.w + _e216, nyq_sobol_matrices, _buffer_sizes);
                    nyq_values[out_5 + _e211] = _e218;
                    uint _e222 = k;
                    uint _e227 = k;
                    float _e229 = nyq_sobol_sample(_e204, _e6.z, _e6.w + _e227, nyq_sobol_matrices, _buffer_sizes);
                    nyq_values[(out_5 + 4u) + _e222] = as_type<uint>(_e229);
                }
            }
            return;
        }
        case 17u: {
            uint _e236 = nyq_job.dims;
            metal::uint2 _e239 = nyq_job.seed;
            NyqOwenSobol _e240 = nyq_owen_sobol(_e236, _e239);
            metal::float4 _e243 = nyq_owen_sobol_sample_4d(_e240, _e6.z, _e6.w, nyq_sobol_matrices, _buffer_sizes);
            uint2 loop_bound_46 = uint2(4294967295u);
            bool loop_init_34 = true;
            while(true) {
                if (metal::all(loop_bound_46 == uint2(0u))) { break; }
                loop_bound_46 -= uint2(loop_bound_46.y == 0u, 1u);
                if (!loop_init_34) {
                    uint _e268 = k_1;
                    k_1 = _e268 + 1u;
                }
                loop_init_34 = false;
                uint _e246 = k_1;
                if (_e246 < 4u) {
                } else {
                    break;
                }
                {
                    uint _e250 = k_1;
                    uint _e255 = k_1;
                    uint _e257 = nyq_owen_sobol_sample_u32_(_e240, _e6.z, _e6.w + _e255, nyq_sobol_matrices, _buffer_sizes);
                    nyq_values[out_5 + _e250] = _e257;
                    uint _e261 = k_1;
                    uint _e264 = k_1;
                    nyq_values[(out_5 + 4u) + _e261] = as_type<uint>(_e243[_e264]);
                }
            }
            return;
        }
        case 18u: {
            uint _e272 = nyq_job.scramble;
            metal::uint2 _e277 = nyq_job.seed;
            NyqPmj02_ _e278 = nyq_pmj02_(_e272 != 0u, _e277);
            uint2 loop_bound_47 = uint2(4294967295u);
            bool loop_init_35 = true;
            while(true) {
                if (metal::all(loop_bound_47 == uint2(0u))) { break; }
                loop_bound_47 -= uint2(loop_bound_47.y == 0u, 1u);
                if (!loop_init_35) {
                    uint _e306 = k_2;
                    k_2 = _e306 + 1u;
                }
                loop_init_35 = false;
                uint _e281 = k_2;
                if (_e281 < 4u) {
                } else {
                    break;
                }
                {
                    uint _e285 = k_2;
                    uint _e290 = k_2;
                    uint _e292 = nyq_pmj02_sample_u32_(_e278, _e6.z, _e6.w + _e290);
                    nyq_values[out_5 + _e285] = _e292;
                    uint _e296 = k_2;
                    uint _e301 = k_2;
                    float _e303 = nyq_pmj02_sample(_e278, _e6.z, _e6.w + _e301);
                    nyq_values[(out_5 + 4u) + _e296] = as_type<uint>(_e303);
                }
            }
            return;
        }
        case 19u: {
            uint _e310 = nyq_job.dims;
            uint _e313 = nyq_job.scramble;
            metal::uint2 _e316 = nyq_job.seed;
            NyqHalton _e317 = nyq_halton(_e310, _e313, _e316);
            uint high_2 = ((_e6.x * 2654435769u) + _e6.y) >> (_e6.y & 31u);
            uint2 loop_bound_48 = uint2(4294967295u);
            bool loop_init_36 = true;
            while(true) {
                if (metal::all(loop_bound_48 == uint2(0u))) { break; }
                loop_bound_48 -= uint2(loop_bound_48.y == 0u, 1u);
                if (!loop_init_36) {
                    uint _e351 = k_3;
                    k_3 = _e351 + 1u;
                }
                loop_init_36 = false;
                uint _e329 = k_3;
                if (_e329 < 8u) {
                } else {
                    break;
                }
                {
                    uint _e334 = k_3;
                    metal::uint2 index_20 = metal::uint2(_e6.z, (_e334 >= 4u) ? high_2 : 0u);
                    uint _e340 = k_3;
                    uint _e344 = k_3;
                    float _e348 = nyq_halton_sample(_e317, index_20, _e6.w + (_e344 & 3u), nyq_halton_bases, _buffer_sizes);
                    nyq_values[out_5 + _e340] = as_type<uint>(_e348);
                }
            }
            return;
        }
        case 20u: {
            uint _e355 = nyq_job.lattice;
            uint _e358 = nyq_job.spp;
            uint _e361 = nyq_job.generator;
            uint _e364 = nyq_job.dims;
            uint _e367 = nyq_job.scramble;
            metal::uint2 _e372 = nyq_job.seed;
            NyqLattice _e373 = nyq_lattice(_e355, _e358, _e361, _e364, _e367 != 0u, _e372);
            uint2 loop_bound_49 = uint2(4294967295u);
            bool loop_init_37 = true;
            while(true) {
                if (metal::all(loop_bound_49 == uint2(0u))) { break; }
                loop_bound_49 -= uint2(loop_bound_49.y == 0u, 1u);
                if (!loop_init_37) {
                    uint _e390 = k_4;
                    k_4 = _e390 + 1u;
                }
                loop_init_37 = false;
                uint _e376 = k_4;
                if (_e376 < 4u) {
                } else {
                    break;
                }
                {
                    uint _e380 = k_4;
                    uint _e385 = k_4;
                    float _e387 = nyq_lattice_sample(_e373, _e6.z, _e6.w + _e385);
                    nyq_values[out_5 + _e380] = as_type<uint>(_e387);
                }
            }
            metal::uint2 _e394 = nyq_lattice_fixed(_e373, _e6.z, _e6.w);
            metal::uint2 _e395 = nyq_fixed_to_f64_bits(_e394);
            metal::uint2 _e400 = nyq_lattice_fixed(_e373, _e6.z, _e6.w + 1u);
            metal::uint2 _e401 = nyq_fixed_to_f64_bits(_e400);
            nyq_values[out_5 + 4u] = _e395.x;
            nyq_values[out_5 + 5u] = _e395.y;
            nyq_values[out_5 + 6u] = _e401.x;
            nyq_values[out_5 + 7u] = _e401.y;
            return;
        }
        default: {
            uint2 loop_bound_50 = uint2(4294967295u);
            bool loop_init_38 = true;
            while(true) {
                if (metal::all(loop_bound_50 == uint2(0u))) { break; }
                loop_bound_50 -= uint2(loop_bound_50.y == 0u, 1u);
                if (!loop_init_38) {
                    uint _e433 = k_5;
                    k_5 = _e433 + 1u;
                }
                loop_init_38 = false;
                uint _e424 = k_5;
                if (_e424 < 8u) {
                } else {
                    break;
                }
                {
                    uint _e428 = k_5;
                    nyq_values[out_5 + _e428] = 4294967295u;
                }
            }
            return;
        }
    }
}

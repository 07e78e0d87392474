struct NyqCameraSample {
    float2 p_film;
    float2 lens;
    float time;
    int _end_pad_0;
};

struct NyqSobol {
    uint dims;
    uint scrambled;
    uint2 seed;
};

struct NyqSobolSampler {
    uint spp;
    uint m;
    uint scramble;
    int _pad3_0;
    uint2 seed;
    int _pad4_0;
    int _pad4_1;
    uint4 inverse0_;
    uint4 inverse1_;
    uint4 inverse2_;
    uint4 inverse3_;
    uint4 inverse4_;
    uint4 inverse5_;
    uint4 inverse6_;
    uint4 inverse7_;
    uint2 shift;
    uint index;
    uint dim;
};

struct NyqOwenSobol {
    uint dims;
    uint shuffle_seed;
    uint key;
};

struct NyqOwenSobolSampler {
    uint2 seed;
    uint frame;
    uint key;
    uint r;
    uint dim;
};

struct NyqZSobolSampler {
    uint spp;
    uint log2_spp;
    uint log2_res;
    uint scramble;
    uint2 seed;
    uint digits;
    uint sample_digits;
    uint odd;
    uint morton;
    uint dim;
    int _end_pad_0;
};

struct NyqPcg32_ {
    uint2 state;
};

struct NyqRandomSampler {
    uint2 seed;
    uint2 base;
    NyqPcg32_ rng;
    uint dim;
    int _end_pad_0;
};

struct NyqLatticeSampler {
    uint lattice;
    uint n;
    uint g;
    int _pad3_0;
    uint2 seed;
    uint2 pixel;
    uint index;
    uint dim;
};

struct NyqPermutation {
    uint n;
    uint mask;
    uint half_;
    uint third;
    uint key;
    uint key2_;
    uint offset;
    int _pad7_0;
    uint2 table;
};

struct NyqStratifiedSampler {
    uint xs;
    uint ys;
    uint spp;
    int _pad3_0;
    float3 inv;
    uint jitter;
    uint2 seed;
    uint2 pixel_key;
    uint2 sample_key;
    uint index;
    uint dim;
};

struct NyqPmj02_ {
    uint scrambled;
    int _pad1_0;
    uint2 keys;
};

struct NyqPmj02Sampler {
    uint2 seed;
    uint2 pixel_key;
    uint index_rev;
    uint dim;
};

struct NyqFillJob {
    uint kind;
    uint scramble;
    uint spp;
    uint frame;
    uint2 seed;
    uint2 resolution;
    uint dims;
    uint implicit;
    uint first;
    uint count;
    uint lattice;
    uint generator;
    uint pad0_;
    uint pad1_;
};

typedef uint ret_Constructarray24_uint_[24];
ret_Constructarray24_uint_ Constructarray24_uint_(uint arg0, uint arg1, uint arg2, uint arg3, uint arg4, uint arg5, uint arg6, uint arg7, uint arg8, uint arg9, uint arg10, uint arg11, uint arg12, uint arg13, uint arg14, uint arg15, uint arg16, uint arg17, uint arg18, uint arg19, uint arg20, uint arg21, uint arg22, uint arg23) {
    uint ret[24] = { arg0, arg1, arg2, arg3, arg4, arg5, arg6, arg7, arg8, arg9, arg10, arg11, arg12, arg13, arg14, arg15, arg16, arg17, arg18, arg19, arg20, arg21, arg22, arg23 };
    return ret;
}

typedef uint2 ret_Constructarray2_uint2_[2];
ret_Constructarray2_uint2_ Constructarray2_uint2_(uint2 arg0, uint2 arg1) {
    uint2 ret[2] = { arg0, arg1 };
    return ret;
}

typedef uint ret_Constructarray32_uint_[32];
ret_Constructarray32_uint_ Constructarray32_uint_(uint arg0, uint arg1, uint arg2, uint arg3, uint arg4, uint arg5, uint arg6, uint arg7, uint arg8, uint arg9, uint arg10, uint arg11, uint arg12, uint arg13, uint arg14, uint arg15, uint arg16, uint arg17, uint arg18, uint arg19, uint arg20, uint arg21, uint arg22, uint arg23, uint arg24, uint arg25, uint arg26, uint arg27, uint arg28, uint arg29, uint arg30, uint arg31) {
    uint ret[32] = { arg0, arg1, arg2, arg3, arg4, arg5, arg6, arg7, arg8, arg9, arg10, arg11, arg12, arg13, arg14, arg15, arg16, arg17, arg18, arg19, arg20, arg21, arg22, arg23, arg24, arg25, arg26, arg27, arg28, arg29, arg30, arg31 };
    return ret;
}

typedef uint ret_Constructarray16_uint_[16];
ret_Constructarray16_uint_ Constructarray16_uint_(uint arg0, uint arg1, uint arg2, uint arg3, uint arg4, uint arg5, uint arg6, uint arg7, uint arg8, uint arg9, uint arg10, uint arg11, uint arg12, uint arg13, uint arg14, uint arg15) {
    uint ret[16] = { arg0, arg1, arg2, arg3, arg4, arg5, arg6, arg7, arg8, arg9, arg10, arg11, arg12, arg13, arg14, arg15 };
    return ret;
}

static const uint NYQ_SCRAMBLE_NONE = 0u;
static const uint NYQ_SCRAMBLE_PERMUTE_DIGITS = 1u;
static const uint NYQ_SCRAMBLE_FAST_OWEN = 2u;
static const uint NYQ_SCRAMBLE_OWEN = 3u;
static const uint NYQ_SOBOL_DIMS = 1024u;
static const uint NYQ_PERMUTATIONS_4_[24] = Constructarray24_uint_(228u, 180u, 216u, 120u, 156u, 108u, 225u, 177u, 201u, 57u, 141u, 45u, 210u, 114u, 198u, 54u, 78u, 30u, 147u, 99u, 135u, 39u, 75u, 27u);
static const uint2 NYQ_PCG_MULTIPLIER = uint2(1284865837u, 1481765933u);
static const uint2 NYQ_RANDOM_INCREMENT = uint2(2665069115u, 1250683170u);
static const uint NYQ_LATTICE_FIBONACCI = 0u;
static const uint NYQ_LATTICE_KOROBOV = 1u;
static const uint NYQ_LATTICE_R2_ = 2u;
static const uint2 NYQ_R2_ALPHA[2] = Constructarray2_uint2_(uint2(44445696u, 3242174889u), uint2(3349051392u, 2447445413u));
static const uint NYQ_SMALL_PERMUTATIONS[32] = Constructarray32_uint_(16u, 1u, 528u, 288u, 513u, 33u, 258u, 18u, 12816u, 8976u, 12576u, 4896u, 8496u, 4656u, 12801u, 8961u, 12321u, 801u, 8241u, 561u, 12546u, 4866u, 12306u, 786u, 4146u, 306u, 8451u, 4611u, 8211u, 531u, 4131u, 291u);
static const uint NYQ_JITTERED = 0u;
static const uint NYQ_CENTERED = 1u;
static const uint2 NYQ_DIM_STEP = uint2(2135587861u, 2654435769u);
static const uint2 NYQ_JITTER_STEP = uint2(668265295u, 3266489917u);
static const uint2 NYQ_PMJ02_TABLE_SEED = uint2(845116513u, 1886218800u);
static const uint2 NYQ_WYRAND_INC = uint2(2025677871u, 2692095332u);
static const uint2 NYQ_WYRAND_FOLD = uint2(2696161499u, 3875765969u);
static const uint NYQ_PMJ02_XOR_X[16] = Constructarray16_uint_(0u, 0u, 2u, 6u, 6u, 14u, 54u, 78u, 22u, 46u, 630u, 1742u, 1814u, 3118u, 12406u, 16590u);
static const uint NYQ_PMJ02_XOR_Y[16] = Constructarray16_uint_(0u, 1u, 3u, 3u, 7u, 27u, 39u, 11u, 23u, 315u, 871u, 907u, 1559u, 6203u, 8295u, 139u);
static const uint NYQ_FILL_OWEN_SOBOL_SAMPLER = 0u;
static const uint NYQ_FILL_ZSOBOL_SAMPLER = 1u;
static const uint NYQ_FILL_RANDOM_SAMPLER = 2u;
static const uint NYQ_FILL_LATTICE_SAMPLER = 3u;
static const uint NYQ_FILL_STRATIFIED_SAMPLER = 4u;
static const uint NYQ_FILL_PMJ02_SAMPLER = 5u;
static const uint NYQ_FILL_SOBOL_SAMPLER = 6u;
static const uint NYQ_FILL_SOBOL = 16u;
static const uint NYQ_FILL_OWEN_SOBOL = 17u;
static const uint NYQ_FILL_PMJ02_ = 18u;

ByteAddressBuffer nyq_sobol_matrices : register(t0);
cbuffer nyq_job : register(b1) { NyqFillJob nyq_job; }
ByteAddressBuffer nyq_requests : register(t2);
RWByteAddressBuffer nyq_values : register(u3);

uint2 nyq_mul_wide(uint a, uint b)
{
    uint a0_ = (a & 65535u);
    uint a1_ = (a >> 16u);
    uint b0_ = (b & 65535u);
    uint b1_ = (b >> 16u);
    uint p00_ = (a0_ * b0_);
    uint p01_ = (a0_ * b1_);
    uint p10_ = (a1_ * b0_);
    uint p11_ = (a1_ * b1_);
    uint mid = (((p00_ >> 16u) + (p01_ & 65535u)) + (p10_ & 65535u));
    return uint2(((p00_ & 65535u) | (mid << 16u)), (((p11_ + (p01_ >> 16u)) + (p10_ >> 16u)) + (mid >> 16u)));
}

uint2 nyq_mul64_(uint2 a_1, uint2 b_1)
{
    const uint2 _e4 = nyq_mul_wide(a_1.x, b_1.x);
    return uint2(_e4.x, ((_e4.y + (a_1.x * b_1.y)) + (a_1.y * b_1.x)));
}

uint2 nyq_add64_(uint2 a_2, uint2 b_2)
{
    uint low_1 = (a_2.x + b_2.x);
    return uint2(low_1, ((a_2.y + b_2.y) + ((low_1 < a_2.x) ? 1u : 0u)));
}

uint2 nyq_shr64_(uint2 a_3, uint s_7)
{
    return uint2(((a_3.x >> s_7) | (a_3.y << (32u - s_7))), (a_3.y >> s_7));
}

uint2 nyq_shl64_(uint2 a_4, uint s_8)
{
    return uint2((a_4.x << s_8), ((a_4.y << s_8) | (a_4.x >> (32u - s_8))));
}

uint2 nyq_u64_(uint x)
{
    return uint2(x, 0u);
}

uint nyq_mix32_(uint x_in)
{
    uint x_1 = (uint)0;

    x_1 = x_in;
    uint _e2 = x_1;
    uint _e3 = x_1;
    x_1 = (_e2 ^ (_e3 >> 16u));
    uint _e7 = x_1;
    x_1 = (_e7 * 2146121005u);
    uint _e10 = x_1;
    uint _e11 = x_1;
    x_1 = (_e10 ^ (_e11 >> 15u));
    uint _e15 = x_1;
    x_1 = (_e15 * 2221713035u);
    uint _e18 = x_1;
    uint _e19 = x_1;
    return (_e18 ^ (_e19 >> 16u));
}

uint2 nyq_mix64_(uint2 x_in_1)
{
    uint2 x_2 = (uint2)0;

    x_2 = x_in_1;
    uint2 _e2 = x_2;
    uint2 _e3 = x_2;
    const uint2 _e5 = nyq_shr64_(_e3, 30u);
    x_2 = (_e2 ^ _e5);
    uint2 _e7 = x_2;
    const uint2 _e11 = nyq_mul64_(_e7, uint2(484763065u, 3210233709u));
    x_2 = _e11;
    uint2 _e12 = x_2;
    uint2 _e13 = x_2;
    const uint2 _e15 = nyq_shr64_(_e13, 27u);
    x_2 = (_e12 ^ _e15);
    uint2 _e17 = x_2;
    const uint2 _e21 = nyq_mul64_(_e17, uint2(321982955u, 2496678331u));
    x_2 = _e21;
    uint2 _e22 = x_2;
    uint2 _e23 = x_2;
    const uint2 _e25 = nyq_shr64_(_e23, 31u);
    return (_e22 ^ _e25);
}

uint2 nyq_hash2_(uint2 a_5, uint2 b_3)
{
    uint2 golden = uint2(2135587861u, 2654435769u);
    uint2 golden2_ = uint2(4271175722u, 1013904242u);
    const uint2 _e8 = nyq_add64_(a_5, golden);
    const uint2 _e9 = nyq_mix64_(_e8);
    const uint2 _e10 = nyq_add64_(b_3, golden2_);
    const uint2 _e12 = nyq_mix64_((_e9 ^ _e10));
    return _e12;
}

uint2 nyq_hash4_(uint2 a_6, uint2 b_4, uint2 c, uint2 d)
{
    uint2 golden_1 = uint2(2135587861u, 2654435769u);
    const uint2 _e7 = nyq_hash2_(golden_1, a_6);
    const uint2 _e8 = nyq_hash2_(_e7, b_4);
    const uint2 _e9 = nyq_hash2_(_e8, c);
    const uint2 _e10 = nyq_hash2_(_e9, d);
    return _e10;
}

float nyq_fraction_to_f32_(uint v)
{
    return (float((v >> 8u)) * 5.9604645e-8);
}

float nyq_rev_to_f32_(uint w_rev)
{
    const float _e2 = nyq_fraction_to_f32_(reversebits(w_rev));
    return _e2;
}

uint nyq_shr(uint x_3, uint s_9)
{
    return ((s_9 >= 32u) ? 0u : (x_3 >> (s_9 & 31u)));
}

float nyq_film_coordinate(uint pixel, float offset)
{
    float base_1 = float(pixel);
    float x_17 = (base_1 + offset);
    float edge = (base_1 + 1.0);
    if ((x_17 < edge)) {
        return x_17;
    }
    float below = asfloat((asuint(edge) - 1u));
    return ((below >= base_1) ? below : base_1);
}

uint nyq_lk_hash(uint x_rev, uint seed)
{
    uint x_4 = (uint)0;

    x_4 = (x_rev ^ (x_rev * 1025551850u));
    uint _e6 = x_4;
    x_4 = ((_e6 + seed) * ((seed >> 16u) | 1u));
    uint _e13 = x_4;
    uint _e14 = x_4;
    x_4 = (_e13 ^ (_e14 * 89287766u));
    uint _e18 = x_4;
    uint _e19 = x_4;
    x_4 = (_e18 ^ (_e19 * 1403136100u));
    uint _e23 = x_4;
    return _e23;
}

uint nyq_fast_owen_scramble(uint x_5, uint seed_1)
{
    const uint _e5 = nyq_mix32_((seed_1 ^ 1779033703u));
    const uint _e6 = nyq_lk_hash(reversebits(x_5), _e5);
    return reversebits(_e6);
}

uint nyq_nested_uniform_shuffle(uint index, uint seed_2)
{
    const uint _e2 = nyq_fast_owen_scramble(index, seed_2);
    return _e2;
}

uint nyq_owen_scramble(uint x_6, uint seed_3)
{
    uint out_ = (uint)0;
    uint k_4 = 0u;

    const uint _e4 = nyq_mix32_((seed_3 ^ 3144134277u));
    out_ = x_6;
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e41 = k_4;
            k_4 = (_e41 + 1u);
        }
        loop_init = false;
        uint _e8 = k_4;
        if ((_e8 < 32u)) {
        } else {
            break;
        }
        {
            uint _e12 = k_4;
            uint _e18 = k_4;
            uint prefix = ((_e18 == 0u) ? 0u : (x_6 >> ((32u - _e12) & 31u)));
            uint _e23 = k_4;
            uint2 word = uint2(((1u << _e23) | prefix), _e4);
            const uint2 _e27 = nyq_mix64_(word);
            if (((_e27.y >> 31u) == 1u)) {
                uint _e33 = out_;
                uint _e36 = k_4;
                out_ = (_e33 ^ (1u << (31u - _e36)));
            }
        }
    }
    uint _e43 = out_;
    return _e43;
}

uint nyq_scramble_u32_(uint x_7, uint seed_4, uint how)
{
    switch(how) {
        case 1u: {
            const uint _e5 = nyq_mix32_((seed_4 ^ 1013904242u));
            return (x_7 ^ _e5);
        }
        case 2u: {
            const uint _e7 = nyq_fast_owen_scramble(x_7, seed_4);
            return _e7;
        }
        case 3u: {
            const uint _e8 = nyq_owen_scramble(x_7, seed_4);
            return _e8;
        }
        default: {
            return x_7;
        }
    }
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

uint nyq_sobol_u32_(uint index_1, uint dim)
{
    uint v_1 = 0u;
    uint bits = (uint)0;

    uint base_2 = (naga_mod(dim, NYQ_SOBOL_DIMS) * 32u);
    bits = index_1;
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        uint _e9 = bits;
        if ((_e9 != 0u)) {
        } else {
            break;
        }
        {
            uint _e12 = v_1;
            uint _e14 = bits;
            uint _e18 = asuint(nyq_sobol_matrices.Load((base_2 + min(32u, firstbitlow(_e14)))*4));
            v_1 = (_e12 ^ _e18);
            uint _e20 = bits;
            uint _e21 = bits;
            bits = (_e20 & (_e21 - 1u));
        }
    }
    uint _e25 = v_1;
    return _e25;
}

uint nyq_sobol_rev(uint r, uint dim_1)
{
    const uint _e3 = nyq_sobol_u32_(reversebits(r), dim_1);
    return reversebits(_e3);
}

NyqSobol ConstructNyqSobol(uint arg0, uint arg1, uint2 arg2) {
    NyqSobol ret = (NyqSobol)0;
    ret.dims = arg0;
    ret.scrambled = arg1;
    ret.seed = arg2;
    return ret;
}

NyqSobol nyq_sobol(uint dims, bool scrambled, uint2 seed_5)
{
    const NyqSobol nyqsobol = ConstructNyqSobol(dims, (scrambled ? 1u : 0u), seed_5);
    return nyqsobol;
}

uint nyq_sobol_sample_u32_(NyqSobol s_10, uint index_2, uint dim_2)
{
    uint shift = 0u;

    uint d_3 = naga_mod(dim_2, s_10.dims);
    if ((s_10.scrambled != 0u)) {
        const uint2 _e11 = nyq_u64_(d_3);
        const uint2 _e12 = nyq_hash2_(s_10.seed, _e11);
        shift = _e12.y;
    }
    const uint _e14 = nyq_sobol_u32_(index_2, d_3);
    uint _e15 = shift;
    return (_e14 ^ _e15);
}

float nyq_sobol_sample(NyqSobol s_11, uint index_3, uint dim_3)
{
    const uint _e3 = nyq_sobol_sample_u32_(s_11, index_3, dim_3);
    const float _e4 = nyq_fraction_to_f32_(_e3);
    return _e4;
}

uint nyq_top(uint v_2, uint bits_1)
{
    return ((bits_1 == 0u) ? 0u : (v_2 >> ((32u - bits_1) & 31u)));
}

NyqSobolSampler ConstructNyqSobolSampler(uint arg0, uint arg1, uint arg2, uint2 arg3, uint4 arg4, uint4 arg5, uint4 arg6, uint4 arg7, uint4 arg8, uint4 arg9, uint4 arg10, uint4 arg11, uint2 arg12, uint arg13, uint arg14) {
    NyqSobolSampler ret = (NyqSobolSampler)0;
    ret.spp = arg0;
    ret.m = arg1;
    ret.scramble = arg2;
    ret.seed = arg3;
    ret.inverse0_ = arg4;
    ret.inverse1_ = arg5;
    ret.inverse2_ = arg6;
    ret.inverse3_ = arg7;
    ret.inverse4_ = arg8;
    ret.inverse5_ = arg9;
    ret.inverse6_ = arg10;
    ret.inverse7_ = arg11;
    ret.shift = arg12;
    ret.index = arg13;
    ret.dim = arg14;
    return ret;
}

NyqSobolSampler nyq_sobol_sampler(uint2 resolution, uint spp_requested, uint scramble, uint2 seed_in)
{
    uint2 seed_6 = (uint2)0;
    uint2 shift_1 = uint2(0u, 0u);
    uint2 rows[32] = (uint2[32])0;
    uint c_1 = 0u;
    uint i = (uint)0;
    uint i_1 = 0u;
    uint col = 0u;
    uint pivot = (uint)0;
    uint r_1 = (uint)0;
    uint r_2 = (uint)0;
    bool local = (bool)0;
    uint inverse[32] = (uint[32])0;
    uint i_2 = 0u;
    uint r_3 = (uint)0;

    uint spp = ((spp_requested <= 1u) ? 1u : (1u << (32u - (31u - firstbithigh((spp_requested - 1u))))));
    uint side = max(resolution.x, resolution.y);
    uint m_2 = (32u - (31u - firstbithigh((side - 1u))));
    seed_6 = seed_in;
    if ((scramble == NYQ_SCRAMBLE_NONE)) {
        seed_6 = uint2(0u, 0u);
    }
    if ((scramble == NYQ_SCRAMBLE_PERMUTE_DIGITS)) {
        uint mask = ((m_2 == 0u) ? 4294967295u : (4294967295u >> (m_2 & 31u)));
        uint2 _e43 = seed_6;
        const uint2 _e45 = nyq_u64_(0u);
        const uint2 _e46 = nyq_hash2_(_e43, _e45);
        uint2 _e49 = seed_6;
        const uint2 _e51 = nyq_u64_(1u);
        const uint2 _e52 = nyq_hash2_(_e49, _e51);
        shift_1 = uint2((_e46.x & mask), (_e52.x & mask));
    }
    uint n_3 = (2u * m_2);
    uint2 loop_bound_2 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_2 == uint2(0u, 0u))) { break; }
        loop_bound_2 -= uint2(loop_bound_2.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e121 = c_1;
            c_1 = (_e121 + 1u);
        }
        loop_init_1 = false;
        uint _e61 = c_1;
        if ((_e61 < n_3)) {
        } else {
            break;
        }
        {
            uint _e64 = c_1;
            const uint _e67 = nyq_sobol_u32_((1u << _e64), 0u);
            const uint _e68 = nyq_top(_e67, m_2);
            uint _e70 = c_1;
            const uint _e73 = nyq_sobol_u32_((1u << _e70), 1u);
            const uint _e74 = nyq_top(_e73, m_2);
            uint2 image_bits = uint2((_e68 | (_e74 << (m_2 & 31u))), ((m_2 == 0u) ? 0u : (_e74 >> ((32u - m_2) & 31u))));
            i = 0u;
            uint2 loop_bound_3 = uint2(4294967295u, 4294967295u);
            bool loop_init_2 = true;
            while(true) {
                if (all(loop_bound_3 == uint2(0u, 0u))) { break; }
                loop_bound_3 -= uint2(loop_bound_3.y == 0u, 1u);
                if (!loop_init_2) {
                    uint _e118 = i;
                    i = (_e118 + 1u);
                }
                loop_init_2 = false;
                uint _e91 = i;
                if ((_e91 < n_3)) {
                } else {
                    break;
                }
                {
                    uint _e94 = i;
                    uint _e97 = i;
                    uint _e101 = i;
                    uint bit = (((_e101 >= 32u) ? (image_bits.y >> (_e97 - 32u)) : (image_bits.x >> _e94)) & 1u);
                    if ((bit == 1u)) {
                        uint _e109 = i;
                        uint _e112 = rows[min(uint(_e109), 31u)].x;
                        uint _e114 = c_1;
                        rows[min(uint(_e109), 31u)].x = (_e112 | (1u << _e114));
                    }
                }
            }
        }
    }
    uint2 loop_bound_4 = uint2(4294967295u, 4294967295u);
    bool loop_init_3 = true;
    while(true) {
        if (all(loop_bound_4 == uint2(0u, 0u))) { break; }
        loop_bound_4 -= uint2(loop_bound_4.y == 0u, 1u);
        if (!loop_init_3) {
            uint _e136 = i_1;
            i_1 = (_e136 + 1u);
        }
        loop_init_3 = false;
        uint _e125 = i_1;
        if ((_e125 < n_3)) {
        } else {
            break;
        }
        {
            uint _e127 = i_1;
            uint _e130 = rows[min(uint(_e127), 31u)].y;
            uint _e132 = i_1;
            rows[min(uint(_e127), 31u)].y = (_e130 | (1u << _e132));
        }
    }
    uint2 loop_bound_5 = uint2(4294967295u, 4294967295u);
    bool loop_init_4 = true;
    while(true) {
        if (all(loop_bound_5 == uint2(0u, 0u))) { break; }
        loop_bound_5 -= uint2(loop_bound_5.y == 0u, 1u);
        if (!loop_init_4) {
            uint _e204 = col;
            col = (_e204 + 1u);
        }
        loop_init_4 = false;
        uint _e140 = col;
        if ((_e140 < n_3)) {
        } else {
            break;
        }
        {
            uint _e142 = col;
            pivot = _e142;
            uint _e144 = col;
            r_1 = _e144;
            uint2 loop_bound_6 = uint2(4294967295u, 4294967295u);
            bool loop_init_5 = true;
            while(true) {
                if (all(loop_bound_6 == uint2(0u, 0u))) { break; }
                loop_bound_6 -= uint2(loop_bound_6.y == 0u, 1u);
                if (!loop_init_5) {
                    uint _e160 = r_1;
                    r_1 = (_e160 + 1u);
                }
                loop_init_5 = false;
                uint _e146 = r_1;
                if ((_e146 < n_3)) {
                } else {
                    break;
                }
                {
                    uint _e148 = r_1;
                    uint _e151 = rows[min(uint(_e148), 31u)].x;
                    uint _e152 = col;
                    if ((((_e151 >> _e152) & 1u) == 1u)) {
                        uint _e158 = r_1;
                        pivot = _e158;
                        break;
                    }
                }
            }
            uint _e162 = col;
            uint2 t_3 = rows[min(uint(_e162), 31u)];
            uint _e165 = col;
            uint _e167 = pivot;
            uint2 _e169 = rows[min(uint(_e167), 31u)];
            rows[min(uint(_e165), 31u)] = _e169;
            uint _e170 = pivot;
            rows[min(uint(_e170), 31u)] = t_3;
            r_2 = 0u;
            uint2 loop_bound_7 = uint2(4294967295u, 4294967295u);
            bool loop_init_6 = true;
            while(true) {
                if (all(loop_bound_7 == uint2(0u, 0u))) { break; }
                loop_bound_7 -= uint2(loop_bound_7.y == 0u, 1u);
                if (!loop_init_6) {
                    uint _e201 = r_2;
                    r_2 = (_e201 + 1u);
                }
                loop_init_6 = false;
                uint _e174 = r_2;
                if ((_e174 < n_3)) {
                } else {
                    break;
                }
                {
                    uint _e176 = r_2;
                    uint _e177 = col;
                    if ((_e176 != _e177)) {
                        uint _e181 = r_2;
                        uint _e184 = rows[min(uint(_e181), 31u)].x;
                        uint _e185 = col;
                        local = (((_e184 >> _e185) & 1u) == 1u);
                    } else {
                        local = false;
                    }
                    bool _e192 = local;
                    if (_e192) {
                        uint _e193 = r_2;
                        uint2 _e195 = rows[min(uint(_e193), 31u)];
                        uint _e196 = col;
                        uint2 _e198 = rows[min(uint(_e196), 31u)];
                        rows[min(uint(_e193), 31u)] = (_e195 ^ _e198);
                    }
                }
            }
        }
    }
    uint2 loop_bound_8 = uint2(4294967295u, 4294967295u);
    bool loop_init_7 = true;
    while(true) {
        if (all(loop_bound_8 == uint2(0u, 0u))) { break; }
        loop_bound_8 -= uint2(loop_bound_8.y == 0u, 1u);
        if (!loop_init_7) {
            uint _e236 = i_2;
            i_2 = (_e236 + 1u);
        }
        loop_init_7 = false;
        uint _e209 = i_2;
        if ((_e209 < n_3)) {
        } else {
            break;
        }
        {
            r_3 = 0u;
            uint2 loop_bound_9 = uint2(4294967295u, 4294967295u);
            bool loop_init_8 = true;
            while(true) {
                if (all(loop_bound_9 == uint2(0u, 0u))) { break; }
                loop_bound_9 -= uint2(loop_bound_9.y == 0u, 1u);
                if (!loop_init_8) {
                    uint _e233 = r_3;
                    r_3 = (_e233 + 1u);
                }
                loop_init_8 = false;
                uint _e213 = r_3;
                if ((_e213 < n_3)) {
                } else {
                    break;
                }
                {
                    uint _e215 = i_2;
                    uint _e218 = rows[min(uint(_e215), 31u)].y;
                    uint _e219 = r_3;
                    if ((((_e218 >> _e219) & 1u) == 1u)) {
                        uint _e225 = r_3;
                        uint _e227 = inverse[min(uint(_e225), 31u)];
                        uint _e229 = i_2;
                        inverse[min(uint(_e225), 31u)] = (_e227 | (1u << _e229));
                    }
                }
            }
        }
    }
    uint _e239 = inverse[0];
    uint _e241 = inverse[1];
    uint _e243 = inverse[2];
    uint _e245 = inverse[3];
    uint4 v0_ = uint4(_e239, _e241, _e243, _e245);
    uint _e248 = inverse[4];
    uint _e250 = inverse[5];
    uint _e252 = inverse[6];
    uint _e254 = inverse[7];
    uint4 v1_ = uint4(_e248, _e250, _e252, _e254);
    uint _e257 = inverse[8];
    uint _e259 = inverse[9];
    uint _e261 = inverse[10];
    uint _e263 = inverse[11];
    uint4 v2_ = uint4(_e257, _e259, _e261, _e263);
    uint _e266 = inverse[12];
    uint _e268 = inverse[13];
    uint _e270 = inverse[14];
    uint _e272 = inverse[15];
    uint4 v3_ = uint4(_e266, _e268, _e270, _e272);
    uint _e275 = inverse[16];
    uint _e277 = inverse[17];
    uint _e279 = inverse[18];
    uint _e281 = inverse[19];
    uint4 v4_ = uint4(_e275, _e277, _e279, _e281);
    uint _e284 = inverse[20];
    uint _e286 = inverse[21];
    uint _e288 = inverse[22];
    uint _e290 = inverse[23];
    uint4 v5_ = uint4(_e284, _e286, _e288, _e290);
    uint _e293 = inverse[24];
    uint _e295 = inverse[25];
    uint _e297 = inverse[26];
    uint _e299 = inverse[27];
    uint4 v6_ = uint4(_e293, _e295, _e297, _e299);
    uint _e302 = inverse[28];
    uint _e304 = inverse[29];
    uint _e306 = inverse[30];
    uint _e308 = inverse[31];
    uint4 v7_ = uint4(_e302, _e304, _e306, _e308);
    uint2 _e310 = seed_6;
    uint2 _e311 = shift_1;
    const NyqSobolSampler nyqsobolsampler = ConstructNyqSobolSampler(spp, m_2, scramble, _e310, v0_, v1_, v2_, v3_, v4_, v5_, v6_, v7_, _e311, 0u, 0u);
    return nyqsobolsampler;
}

uint4 ZeroValueuint4() {
    return (uint4)0;
}

uint nyq_sobol_sampler_invert(inout NyqSobolSampler s_12, uint t_in)
{
    uint low = 0u;
    uint t = (uint)0;
    uint4 four = (uint4)0;

    t = t_in;
    uint2 loop_bound_10 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_10 == uint2(0u, 0u))) { break; }
        loop_bound_10 -= uint2(loop_bound_10.y == 0u, 1u);
        uint _e5 = t;
        if ((_e5 != 0u)) {
        } else {
            break;
        }
        {
            uint _e8 = t;
            uint k_10 = min(32u, firstbitlow(_e8));
            four = ZeroValueuint4();
            bool should_continue = false;
            switch((k_10 >> 2u)) {
                case 0u: {
                    uint4 _e15 = s_12.inverse0_;
                    four = _e15;
                    break;
                }
                case 1u: {
                    uint4 _e17 = s_12.inverse1_;
                    four = _e17;
                    break;
                }
                case 2u: {
                    uint4 _e19 = s_12.inverse2_;
                    four = _e19;
                    break;
                }
                case 3u: {
                    uint4 _e21 = s_12.inverse3_;
                    four = _e21;
                    break;
                }
                case 4u: {
                    uint4 _e23 = s_12.inverse4_;
                    four = _e23;
                    break;
                }
                case 5u: {
                    uint4 _e25 = s_12.inverse5_;
                    four = _e25;
                    break;
                }
                case 6u: {
                    uint4 _e27 = s_12.inverse6_;
                    four = _e27;
                    break;
                }
                default: {
                    uint4 _e29 = s_12.inverse7_;
                    four = _e29;
                    break;
                }
            }
            uint _e30 = low;
            uint _e34 = four[min(uint((k_10 & 3u)), 3u)];
            low = (_e30 ^ _e34);
            uint _e36 = t;
            uint _e37 = t;
            t = (_e36 & (_e37 - 1u));
        }
    }
    uint _e41 = low;
    return _e41;
}

uint nyq_sobol_sampler_index(inout NyqSobolSampler s_13, uint2 pixel_1, uint sample_index)
{
    uint m_3 = s_13.m;
    uint _e6 = s_13.spp;
    uint si = naga_mod(sample_index, _e6);
    uint high = (((2u * m_3) >= 32u) ? 0u : (si << ((2u * m_3) & 31u)));
    uint mask_1 = ((m_3 == 0u) ? 0u : (4294967295u >> ((32u - m_3) & 31u)));
    uint want = ((pixel_1.x & mask_1) | ((pixel_1.y & mask_1) << (m_3 & 31u)));
    const uint _e38 = nyq_sobol_u32_(high, 0u);
    const uint _e39 = nyq_top(_e38, m_3);
    const uint _e41 = nyq_sobol_u32_(high, 1u);
    const uint _e42 = nyq_top(_e41, m_3);
    uint have = (_e39 | (_e42 << (m_3 & 31u)));
    const uint _e48 = nyq_sobol_sampler_invert(s_13, (want ^ have));
    return (high | _e48);
}

float nyq_sobol_sampler_value(inout NyqSobolSampler s_14, uint dim_4)
{
    uint v_3 = (uint)0;
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;

    uint d_4 = naga_mod(dim_4, NYQ_SOBOL_DIMS);
    uint2 seed_20 = s_14.seed;
    uint _e7 = s_14.index;
    const uint _e8 = nyq_sobol_u32_(_e7, d_4);
    v_3 = _e8;
    uint how_2 = s_14.scramble;
    if (!((how_2 == NYQ_SCRAMBLE_FAST_OWEN))) {
        local_1 = (how_2 == NYQ_SCRAMBLE_OWEN);
    } else {
        local_1 = true;
    }
    bool _e20 = local_1;
    if (_e20) {
        uint _e21 = v_3;
        uint _e22 = v_3;
        uint _e24 = s_14.m;
        if ((d_4 < 2u)) {
            uint _e33 = s_14.m;
            local_2 = (_e33 < 32u);
        } else {
            local_2 = false;
        }
        bool _e37 = local_2;
        uint w_1 = (_e37 ? (_e22 << (_e24 & 31u)) : _e21);
        const uint2 _e39 = nyq_u64_(d_4);
        const uint2 _e40 = nyq_hash2_(seed_20, _e39);
        const uint _e42 = nyq_scramble_u32_(w_1, _e40.y, how_2);
        const float _e43 = nyq_fraction_to_f32_(_e42);
        return _e43;
    }
    if ((d_4 < 2u)) {
        uint _e46 = v_3;
        uint _e49 = s_14.shift[min(uint(d_4), 1u)];
        uint _e52 = s_14.m;
        v_3 = ((_e46 ^ _e49) << _e52);
    } else {
        if ((d_4 < 32u)) {
            if ((how_2 == NYQ_SCRAMBLE_PERMUTE_DIGITS)) {
                uint _e58 = v_3;
                const uint2 _e59 = nyq_u64_(d_4);
                const uint2 _e60 = nyq_hash2_(seed_20, _e59);
                v_3 = (_e58 ^ (all((seed_20 == uint2(0u, 0u))) ? 0u : _e60.x));
            } else {
                uint _e70 = v_3;
                const uint2 _e71 = nyq_u64_(d_4);
                const uint2 _e72 = nyq_hash2_(seed_20, _e71);
                v_3 = (_e70 ^ _e72.y);
            }
        } else {
            uint _e75 = v_3;
            const uint2 _e76 = nyq_u64_(d_4);
            const uint2 _e77 = nyq_hash2_(seed_20, _e76);
            v_3 = (_e75 ^ (all((seed_20 == uint2(0u, 0u))) ? 0u : _e77.x));
        }
    }
    uint _e87 = v_3;
    const float _e88 = nyq_fraction_to_f32_(_e87);
    return _e88;
}

void nyq_sobol_sampler_start(inout NyqSobolSampler s_15, uint2 pixel_2, uint sample_index_1, uint dim_5)
{
    const uint _e5 = nyq_sobol_sampler_index(s_15, pixel_2, sample_index_1);
    s_15.index = _e5;
    s_15.dim = dim_5;
    return;
}

float nyq_sobol_sampler_get_1d(inout NyqSobolSampler s_16)
{
    uint d_5 = s_16.dim;
    s_16.dim = (d_5 + 1u);
    const float _e6 = nyq_sobol_sampler_value(s_16, d_5);
    return _e6;
}

float2 nyq_sobol_sampler_get_2d(inout NyqSobolSampler s_17)
{
    uint d_6 = s_17.dim;
    s_17.dim = (d_6 + 2u);
    const float _e6 = nyq_sobol_sampler_value(s_17, d_6);
    const float _e9 = nyq_sobol_sampler_value(s_17, (d_6 + 1u));
    return float2(_e6, _e9);
}

float2 nyq_sobol_sampler_get_pixel_2d(inout NyqSobolSampler s_18)
{
    uint _e3 = s_18.dim;
    s_18.dim = max(_e3, 2u);
    const float _e7 = nyq_sobol_sampler_value(s_18, 0u);
    const float _e9 = nyq_sobol_sampler_value(s_18, 1u);
    return float2(_e7, _e9);
}

NyqCameraSample ConstructNyqCameraSample(float2 arg0, float2 arg1, float arg2) {
    NyqCameraSample ret = (NyqCameraSample)0;
    ret.p_film = arg0;
    ret.lens = arg1;
    ret.time = arg2;
    return ret;
}

NyqCameraSample nyq_sobol_sampler_camera_sample(inout NyqSobolSampler s_19, uint2 pixel_3, uint sample_index_2)
{
    nyq_sobol_sampler_start(s_19, pixel_3, sample_index_2, 0u);
    const float2 _e4 = nyq_sobol_sampler_get_pixel_2d(s_19);
    const float _e5 = nyq_sobol_sampler_get_1d(s_19);
    const float2 _e6 = nyq_sobol_sampler_get_2d(s_19);
    const float _e9 = nyq_film_coordinate(pixel_3.x, _e4.x);
    const float _e12 = nyq_film_coordinate(pixel_3.y, _e4.y);
    float2 film = float2(_e9, _e12);
    const NyqCameraSample nyqcamerasample = ConstructNyqCameraSample(film, _e6, _e5);
    return nyqcamerasample;
}

uint nyq_dim_seed(uint key, uint dim_6)
{
    const uint _e5 = nyq_mix32_((key ^ (dim_6 * 2654435769u)));
    return _e5;
}

uint nyq_shuffle_rev(uint index_4, uint shuffle_seed)
{
    const uint _e3 = nyq_lk_hash(0u, shuffle_seed);
    uint fix = (_e3 & 65535u);
    const uint _e7 = nyq_lk_hash(reversebits(index_4), shuffle_seed);
    return (_e7 ^ fix);
}

uint nyq_owen_sobol_rev(uint r_4, uint dim_7, uint dim_seed)
{
    const uint _e5 = nyq_sobol_rev(r_4, naga_mod(dim_7, NYQ_SOBOL_DIMS));
    const uint _e6 = nyq_lk_hash(_e5, dim_seed);
    return _e6;
}

NyqOwenSobol ConstructNyqOwenSobol(uint arg0, uint arg1, uint arg2) {
    NyqOwenSobol ret = (NyqOwenSobol)0;
    ret.dims = arg0;
    ret.shuffle_seed = arg1;
    ret.key = arg2;
    return ret;
}

NyqOwenSobol nyq_owen_sobol(uint dims_1, uint2 seed_7)
{
    const uint2 _e3 = nyq_u64_(1331119438u);
    const uint2 _e4 = nyq_hash2_(seed_7, _e3);
    const uint _e6 = nyq_mix32_(_e4.y);
    const NyqOwenSobol nyqowensobol = ConstructNyqOwenSobol(dims_1, _e6, _e4.x);
    return nyqowensobol;
}

uint nyq_owen_sobol_sample_u32_(NyqOwenSobol s_20, uint index_5, uint dim_8)
{
    uint d_7 = naga_mod(dim_8, s_20.dims);
    const uint _e6 = nyq_shuffle_rev(index_5, s_20.shuffle_seed);
    const uint _e8 = nyq_dim_seed(s_20.key, d_7);
    const uint _e9 = nyq_owen_sobol_rev(_e6, d_7, _e8);
    return reversebits(_e9);
}

float nyq_owen_sobol_sample(NyqOwenSobol s_21, uint index_6, uint dim_9)
{
    const uint _e3 = nyq_owen_sobol_sample_u32_(s_21, index_6, dim_9);
    const float _e4 = nyq_fraction_to_f32_(_e3);
    return _e4;
}

float4 nyq_owen_sobol_sample_4d(NyqOwenSobol s_22, uint index_7, uint first_dim)
{
    float4 out_1 = (float4)0;
    uint k_5 = 0u;

    const uint _e4 = nyq_shuffle_rev(index_7, s_22.shuffle_seed);
    uint2 loop_bound_11 = uint2(4294967295u, 4294967295u);
    bool loop_init_9 = true;
    while(true) {
        if (all(loop_bound_11 == uint2(0u, 0u))) { break; }
        loop_bound_11 -= uint2(loop_bound_11.y == 0u, 1u);
        if (!loop_init_9) {
            uint _e22 = k_5;
            k_5 = (_e22 + 1u);
        }
        loop_init_9 = false;
        uint _e8 = k_5;
        if ((_e8 < 4u)) {
        } else {
            break;
        }
        {
            uint _e11 = k_5;
            uint d_8 = naga_mod((first_dim + _e11), s_22.dims);
            uint _e15 = k_5;
            const uint _e18 = nyq_dim_seed(s_22.key, d_8);
            const uint _e19 = nyq_owen_sobol_rev(_e4, d_8, _e18);
            const float _e20 = nyq_rev_to_f32_(_e19);
            out_1[min(uint(_e15), 3u)] = _e20;
        }
    }
    float4 _e24 = out_1;
    return _e24;
}

NyqOwenSobolSampler ConstructNyqOwenSobolSampler(uint2 arg0, uint arg1, uint arg2, uint arg3, uint arg4) {
    NyqOwenSobolSampler ret = (NyqOwenSobolSampler)0;
    ret.seed = arg0;
    ret.frame = arg1;
    ret.key = arg2;
    ret.r = arg3;
    ret.dim = arg4;
    return ret;
}

NyqOwenSobolSampler nyq_owen_sobol_sampler(uint2 seed_8, uint frame)
{
    const NyqOwenSobolSampler nyqowensobolsampler = ConstructNyqOwenSobolSampler(seed_8, frame, 0u, 0u, 0u);
    return nyqowensobolsampler;
}

void nyq_owen_sobol_start(inout NyqOwenSobolSampler s_23, uint2 pixel_4, uint sample_index_3, uint dim_10)
{
    const uint2 _e5 = nyq_u64_(pixel_4.x);
    const uint2 _e7 = nyq_u64_(pixel_4.y);
    uint _e9 = s_23.frame;
    const uint2 _e10 = nyq_u64_(_e9);
    uint2 _e12 = s_23.seed;
    const uint2 _e13 = nyq_hash4_(_e5, _e7, _e10, _e12);
    s_23.key = _e13.x;
    const uint _e18 = nyq_mix32_(_e13.y);
    const uint _e19 = nyq_shuffle_rev(sample_index_3, _e18);
    s_23.r = _e19;
    s_23.dim = dim_10;
    return;
}

float nyq_owen_sobol_value(inout NyqOwenSobolSampler s_24, uint dim_11)
{
    uint _e3 = s_24.r;
    uint _e5 = s_24.key;
    const uint _e6 = nyq_dim_seed(_e5, dim_11);
    const uint _e7 = nyq_owen_sobol_rev(_e3, dim_11, _e6);
    const float _e8 = nyq_rev_to_f32_(_e7);
    return _e8;
}

float nyq_owen_sobol_get_1d(inout NyqOwenSobolSampler s_25)
{
    uint d_9 = s_25.dim;
    s_25.dim = (d_9 + 1u);
    const float _e6 = nyq_owen_sobol_value(s_25, d_9);
    return _e6;
}

float2 nyq_owen_sobol_get_2d(inout NyqOwenSobolSampler s_26)
{
    uint d_10 = s_26.dim;
    s_26.dim = (d_10 + 2u);
    const float _e6 = nyq_owen_sobol_value(s_26, d_10);
    const float _e9 = nyq_owen_sobol_value(s_26, (d_10 + 1u));
    return float2(_e6, _e9);
}

float2 nyq_owen_sobol_get_pixel_2d(inout NyqOwenSobolSampler s_27)
{
    uint _e3 = s_27.dim;
    s_27.dim = max(_e3, 2u);
    const float _e7 = nyq_owen_sobol_value(s_27, 0u);
    const float _e9 = nyq_owen_sobol_value(s_27, 1u);
    return float2(_e7, _e9);
}

NyqCameraSample nyq_owen_sobol_camera_sample(inout NyqOwenSobolSampler s_28, uint2 pixel_5, uint sample_index_4)
{
    float v_4[5] = (float[5])0;
    uint d_1 = 0u;

    nyq_owen_sobol_start(s_28, pixel_5, sample_index_4, 0u);
    uint2 loop_bound_12 = uint2(4294967295u, 4294967295u);
    bool loop_init_10 = true;
    while(true) {
        if (all(loop_bound_12 == uint2(0u, 0u))) { break; }
        loop_bound_12 -= uint2(loop_bound_12.y == 0u, 1u);
        if (!loop_init_10) {
            uint _e15 = d_1;
            d_1 = (_e15 + 1u);
        }
        loop_init_10 = false;
        uint _e7 = d_1;
        if ((_e7 < 5u)) {
        } else {
            break;
        }
        {
            uint _e10 = d_1;
            uint _e12 = d_1;
            const float _e13 = nyq_owen_sobol_value(s_28, _e12);
            v_4[min(uint(_e10), 4u)] = _e13;
        }
    }
    s_28.dim = 5u;
    float _e21 = v_4[0];
    const float _e22 = nyq_film_coordinate(pixel_5.x, _e21);
    float _e25 = v_4[1];
    const float _e26 = nyq_film_coordinate(pixel_5.y, _e25);
    float2 p_2 = float2(_e22, _e26);
    float _e29 = v_4[3];
    float _e31 = v_4[4];
    float _e34 = v_4[2];
    const NyqCameraSample nyqcamerasample_1 = ConstructNyqCameraSample(p_2, float2(_e29, _e31), _e34);
    return nyqcamerasample_1;
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

NyqZSobolSampler ConstructNyqZSobolSampler(uint arg0, uint arg1, uint arg2, uint arg3, uint2 arg4, uint arg5, uint arg6, uint arg7, uint arg8, uint arg9) {
    NyqZSobolSampler ret = (NyqZSobolSampler)0;
    ret.spp = arg0;
    ret.log2_spp = arg1;
    ret.log2_res = arg2;
    ret.scramble = arg3;
    ret.seed = arg4;
    ret.digits = arg5;
    ret.sample_digits = arg6;
    ret.odd = arg7;
    ret.morton = arg8;
    ret.dim = arg9;
    return ret;
}

NyqZSobolSampler nyq_zsobol_sampler(uint2 resolution_1, uint spp_requested_1, uint scramble_1, uint2 seed_9)
{
    uint spp_1 = ((spp_requested_1 <= 1u) ? 1u : (1u << (32u - (31u - firstbithigh((spp_requested_1 - 1u))))));
    uint side_1 = max(resolution_1.x, resolution_1.y);
    uint log2_res = (32u - (31u - firstbithigh((side_1 - 1u))));
    uint log2_spp = min(32u, firstbitlow(spp_1));
    uint bits_2 = ((2u * log2_res) + log2_spp);
    const NyqZSobolSampler nyqzsobolsampler = ConstructNyqZSobolSampler(spp_1, log2_spp, log2_res, scramble_1, seed_9, naga_div(bits_2, 2u), naga_div(log2_spp, 2u), (log2_spp & 1u), 0u, 0u);
    return nyqzsobolsampler;
}

uint nyq_spread(uint x_in_2)
{
    uint x_8 = (uint)0;

    x_8 = (x_in_2 & 65535u);
    uint _e4 = x_8;
    uint _e5 = x_8;
    x_8 = ((_e4 | (_e5 << 8u)) & 16711935u);
    uint _e11 = x_8;
    uint _e12 = x_8;
    x_8 = ((_e11 | (_e12 << 4u)) & 252645135u);
    uint _e18 = x_8;
    uint _e19 = x_8;
    x_8 = ((_e18 | (_e19 << 2u)) & 858993459u);
    uint _e25 = x_8;
    uint _e26 = x_8;
    return ((_e25 | (_e26 << 1u)) & 1431655765u);
}

uint nyq_zsobol_morton(NyqZSobolSampler s_29, uint2 pixel_6)
{
    uint mask_2 = ((s_29.log2_res == 0u) ? 0u : (4294967295u >> ((32u - s_29.log2_res) & 31u)));
    const uint _e16 = nyq_spread((pixel_6.x & mask_2));
    const uint _e19 = nyq_spread((pixel_6.y & mask_2));
    return (_e16 | (_e19 << 1u));
}

uint nyq_one_of_24_(uint h)
{
    const uint2 _e2 = nyq_mul_wide(h, 24u);
    return _e2.y;
}

uint2 nyq_zsobol_dim_key(uint2 seed_10, uint dim_12)
{
    const uint2 _e6 = nyq_hash2_(seed_10, uint2((dim_12 ^ 1329745740u), 23123u));
    return _e6;
}

uint nyq_zsobol_pixel_node(uint higher, uint2 key_1)
{
    const uint2 _e4 = nyq_shr64_(key_1, 16u);
    const uint _e7 = nyq_mix32_((higher ^ _e4.x));
    const uint _e8 = nyq_one_of_24_(_e7);
    return NYQ_PERMUTATIONS_4_[min(uint(_e8), 23u)];
}

uint nyq_permuted_digit(uint perm, uint digit, uint shift_2)
{
    return (((perm >> (2u * digit)) & 3u) << shift_2);
}

uint2 nyq_zsobol_pixel_word(uint pixel_morton, uint2 key_2)
{
    const uint2 _e3 = nyq_shl64_(key_2, 17u);
    uint2 rotated = (_e3 | uint2((key_2.y >> 15u), 0u));
    const uint2 _e10 = nyq_u64_(pixel_morton);
    const uint2 _e12 = nyq_mix64_((_e10 ^ rotated));
    return _e12;
}

uint2 nyq_zsobol_nested_word(uint2 w, uint higher_1, uint shift_3)
{
    uint2 tag = uint2(((higher_1 << 6u) | shift_3), (higher_1 >> 26u));
    const uint2 _e12 = nyq_mul64_(tag, uint2(2135587861u, 2654435769u));
    const uint2 _e17 = nyq_mul64_((w ^ _e12), uint2(3516067075u, 3518319154u));
    return _e17;
}

uint nyq_zsobol_index(NyqZSobolSampler s_30, uint morton, uint2 key_3)
{
    uint index_8 = 0u;
    uint i_3 = (uint)0;
    uint i_4 = (uint)0;

    i_3 = s_30.digits;
    uint2 loop_bound_13 = uint2(4294967295u, 4294967295u);
    bool loop_init_11 = true;
    while(true) {
        if (all(loop_bound_13 == uint2(0u, 0u))) { break; }
        loop_bound_13 -= uint2(loop_bound_13.y == 0u, 1u);
        if (!loop_init_11) {
            uint _e28 = i_3;
            i_3 = (_e28 - 1u);
        }
        loop_init_11 = false;
        uint _e7 = i_3;
        if ((_e7 > s_30.sample_digits)) {
        } else {
            break;
        }
        {
            uint _e11 = i_3;
            uint shift_4 = ((2u * (_e11 - 1u)) + s_30.odd);
            uint digit_1 = ((morton >> shift_4) & 3u);
            uint _e20 = index_8;
            const uint _e23 = nyq_shr(morton, (shift_4 + 2u));
            const uint _e24 = nyq_zsobol_pixel_node(_e23, key_3);
            const uint _e25 = nyq_permuted_digit(_e24, digit_1, shift_4);
            index_8 = (_e20 | _e25);
        }
    }
    const uint _e31 = nyq_shr(morton, s_30.log2_spp);
    const uint2 _e32 = nyq_zsobol_pixel_word(_e31, key_3);
    uint sample_ = (morton & (s_30.spp - 1u));
    i_4 = s_30.sample_digits;
    uint2 loop_bound_14 = uint2(4294967295u, 4294967295u);
    bool loop_init_12 = true;
    while(true) {
        if (all(loop_bound_14 == uint2(0u, 0u))) { break; }
        loop_bound_14 -= uint2(loop_bound_14.y == 0u, 1u);
        if (!loop_init_12) {
            uint _e64 = i_4;
            i_4 = (_e64 - 1u);
        }
        loop_init_12 = false;
        uint _e39 = i_4;
        if ((_e39 > 0u)) {
        } else {
            break;
        }
        {
            uint _e43 = i_4;
            uint shift_5 = ((2u * (_e43 - 1u)) + s_30.odd);
            uint digit_2 = ((sample_ >> shift_5) & 3u);
            const uint _e54 = nyq_shr(sample_, (shift_5 + 2u));
            const uint2 _e55 = nyq_zsobol_nested_word(_e32, _e54, shift_5);
            const uint _e57 = nyq_one_of_24_(_e55.y);
            uint _e58 = index_8;
            const uint _e61 = nyq_permuted_digit(NYQ_PERMUTATIONS_4_[min(uint(_e57), 23u)], digit_2, shift_5);
            index_8 = (_e58 | _e61);
        }
    }
    if ((s_30.odd == 1u)) {
        uint _e69 = index_8;
        const uint2 _e75 = nyq_zsobol_nested_word(_e32, (sample_ >> 1u), 0u);
        index_8 = (_e69 | ((sample_ & 1u) ^ (_e75.y >> 31u)));
    }
    uint _e81 = index_8;
    return _e81;
}

uint nyq_zsobol_sequence_index(NyqZSobolSampler s_31, uint2 pixel_7, uint sample_index_5, uint dim_13)
{
    const uint _e4 = nyq_zsobol_morton(s_31, pixel_7);
    uint morton_1 = ((_e4 << s_31.log2_spp) | (sample_index_5 & (s_31.spp - 1u)));
    const uint2 _e13 = nyq_zsobol_dim_key(s_31.seed, dim_13);
    const uint _e14 = nyq_zsobol_index(s_31, morton_1, _e13);
    return _e14;
}

uint nyq_zsobol_dim0_(uint index_9, uint seed_11, uint how_1)
{
    if ((how_1 == NYQ_SCRAMBLE_FAST_OWEN)) {
        const uint _e5 = nyq_lk_hash(index_9, seed_11);
        return reversebits(_e5);
    }
    const uint _e8 = nyq_scramble_u32_(reversebits(index_9), seed_11, how_1);
    return _e8;
}

float nyq_zsobol_value_1d(inout NyqZSobolSampler s_32, uint dim_14)
{
    uint2 _e3 = s_32.seed;
    const uint2 _e4 = nyq_zsobol_dim_key(_e3, dim_14);
    NyqZSobolSampler _e5 = s_32;
    uint _e7 = s_32.morton;
    const uint _e8 = nyq_zsobol_index(_e5, _e7, _e4);
    uint _e11 = s_32.scramble;
    const uint _e12 = nyq_zsobol_dim0_(_e8, _e4.x, _e11);
    const float _e13 = nyq_fraction_to_f32_(_e12);
    return _e13;
}

float2 nyq_zsobol_value_2d(inout NyqZSobolSampler s_33, uint dim_15)
{
    uint y = (uint)0;

    uint2 _e3 = s_33.seed;
    const uint2 _e4 = nyq_zsobol_dim_key(_e3, dim_15);
    NyqZSobolSampler _e5 = s_33;
    uint _e7 = s_33.morton;
    const uint _e8 = nyq_zsobol_index(_e5, _e7, _e4);
    uint _e11 = s_33.scramble;
    const uint _e12 = nyq_zsobol_dim0_(_e8, _e4.x, _e11);
    uint _e15 = s_33.scramble;
    if ((_e15 == NYQ_SCRAMBLE_FAST_OWEN)) {
        const uint _e19 = nyq_sobol_u32_(_e8, 1u);
        const uint _e22 = nyq_lk_hash(reversebits(_e19), _e4.y);
        y = reversebits(_e22);
    } else {
        const uint _e25 = nyq_sobol_u32_(_e8, 1u);
        uint _e28 = s_33.scramble;
        const uint _e29 = nyq_scramble_u32_(_e25, _e4.y, _e28);
        y = _e29;
    }
    const float _e30 = nyq_fraction_to_f32_(_e12);
    uint _e31 = y;
    const float _e32 = nyq_fraction_to_f32_(_e31);
    return float2(_e30, _e32);
}

void nyq_zsobol_start(inout NyqZSobolSampler s_34, uint2 pixel_8, uint sample_index_6, uint dim_16)
{
    NyqZSobolSampler _e5 = s_34;
    const uint _e6 = nyq_zsobol_morton(_e5, pixel_8);
    uint _e8 = s_34.log2_spp;
    uint _e11 = s_34.spp;
    s_34.morton = ((_e6 << _e8) | (sample_index_6 & (_e11 - 1u)));
    s_34.dim = dim_16;
    return;
}

float nyq_zsobol_get_1d(inout NyqZSobolSampler s_35)
{
    uint d_11 = s_35.dim;
    s_35.dim = (d_11 + 1u);
    const float _e6 = nyq_zsobol_value_1d(s_35, d_11);
    return _e6;
}

float2 nyq_zsobol_get_2d(inout NyqZSobolSampler s_36)
{
    uint d_12 = s_36.dim;
    s_36.dim = (d_12 + 2u);
    const float2 _e6 = nyq_zsobol_value_2d(s_36, d_12);
    return _e6;
}

float2 nyq_zsobol_get_pixel_2d(inout NyqZSobolSampler s_37)
{
    uint _e3 = s_37.dim;
    s_37.dim = max(_e3, 2u);
    const float2 _e7 = nyq_zsobol_value_2d(s_37, 0u);
    return _e7;
}

NyqCameraSample nyq_zsobol_camera_sample(inout NyqZSobolSampler s_38, uint2 pixel_9, uint sample_index_7)
{
    nyq_zsobol_start(s_38, pixel_9, sample_index_7, 0u);
    const float2 _e5 = nyq_zsobol_value_2d(s_38, 0u);
    const float _e7 = nyq_zsobol_value_1d(s_38, 2u);
    const float2 _e9 = nyq_zsobol_value_2d(s_38, 3u);
    s_38.dim = 5u;
    const float _e14 = nyq_film_coordinate(pixel_9.x, _e5.x);
    const float _e17 = nyq_film_coordinate(pixel_9.y, _e5.y);
    float2 film_1 = float2(_e14, _e17);
    const NyqCameraSample nyqcamerasample_2 = ConstructNyqCameraSample(film_1, _e9, _e7);
    return nyqcamerasample_2;
}

NyqPcg32_ ConstructNyqPcg32_(uint2 arg0) {
    NyqPcg32_ ret = (NyqPcg32_)0;
    ret.state = arg0;
    return ret;
}

NyqPcg32_ nyq_pcg32_(uint2 state)
{
    const uint2 _e2 = nyq_add64_(state, NYQ_RANDOM_INCREMENT);
    const uint2 _e4 = nyq_mul64_(_e2, NYQ_PCG_MULTIPLIER);
    const uint2 _e6 = nyq_add64_(_e4, NYQ_RANDOM_INCREMENT);
    const NyqPcg32_ nyqpcg32_ = ConstructNyqPcg32_(_e6);
    return nyqpcg32_;
}

uint nyq_pcg32_next(inout NyqPcg32_ g)
{
    uint2 old = g.state;
    const uint2 _e5 = nyq_mul64_(old, NYQ_PCG_MULTIPLIER);
    const uint2 _e7 = nyq_add64_(_e5, NYQ_RANDOM_INCREMENT);
    g.state = _e7;
    const uint2 _e9 = nyq_shr64_(old, 18u);
    const uint2 _e12 = nyq_shr64_((_e9 ^ old), 27u);
    uint x_18 = _e12.x;
    uint rot = (old.y >> 27u);
    return ((x_18 >> rot) | (x_18 << ((32u - rot) & 31u)));
}

void nyq_pcg32_advance(inout NyqPcg32_ g_1, uint delta)
{
    uint2 acc_mult = uint2(1u, 0u);
    uint2 acc_plus = uint2(0u, 0u);
    uint2 cur_mult = NYQ_PCG_MULTIPLIER;
    uint2 cur_plus = NYQ_RANDOM_INCREMENT;
    uint d_2 = (uint)0;

    d_2 = delta;
    uint2 loop_bound_15 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_15 == uint2(0u, 0u))) { break; }
        loop_bound_15 -= uint2(loop_bound_15.y == 0u, 1u);
        uint _e15 = d_2;
        if ((_e15 > 0u)) {
        } else {
            break;
        }
        {
            uint _e18 = d_2;
            if (((_e18 & 1u) != 0u)) {
                uint2 _e23 = acc_mult;
                uint2 _e24 = cur_mult;
                const uint2 _e25 = nyq_mul64_(_e23, _e24);
                acc_mult = _e25;
                uint2 _e26 = acc_plus;
                uint2 _e27 = cur_mult;
                const uint2 _e28 = nyq_mul64_(_e26, _e27);
                uint2 _e29 = cur_plus;
                const uint2 _e30 = nyq_add64_(_e28, _e29);
                acc_plus = _e30;
            }
            uint2 _e31 = cur_mult;
            const uint2 _e35 = nyq_add64_(_e31, uint2(1u, 0u));
            uint2 _e36 = cur_plus;
            const uint2 _e37 = nyq_mul64_(_e35, _e36);
            cur_plus = _e37;
            uint2 _e38 = cur_mult;
            uint2 _e39 = cur_mult;
            const uint2 _e40 = nyq_mul64_(_e38, _e39);
            cur_mult = _e40;
            uint _e41 = d_2;
            d_2 = (_e41 >> 1u);
        }
    }
    uint2 _e45 = acc_mult;
    uint2 _e47 = g_1.state;
    const uint2 _e48 = nyq_mul64_(_e45, _e47);
    uint2 _e49 = acc_plus;
    const uint2 _e50 = nyq_add64_(_e48, _e49);
    g_1.state = _e50;
    return;
}

float nyq_unit_f32_(uint h_1)
{
    return (float((h_1 >> 8u)) * 5.9604645e-8);
}

uint2 nyq_hash3_(uint2 a_7, uint2 b_5, uint2 c_2)
{
    const uint2 _e3 = nyq_hash2_(a_7, b_5);
    const uint2 _e7 = nyq_add64_(c_2, uint2(2111796287u, 3668340012u));
    const uint2 _e9 = nyq_mix64_((_e3 ^ _e7));
    return _e9;
}

NyqRandomSampler ConstructNyqRandomSampler(uint2 arg0, uint2 arg1, NyqPcg32_ arg2, uint arg3) {
    NyqRandomSampler ret = (NyqRandomSampler)0;
    ret.seed = arg0;
    ret.base = arg1;
    ret.rng = arg2;
    ret.dim = arg3;
    return ret;
}

NyqRandomSampler nyq_random_sampler(uint2 seed_12)
{
    const NyqRandomSampler nyqrandomsampler = ConstructNyqRandomSampler(seed_12, uint2(0u, 0u), ConstructNyqPcg32_(uint2(0u, 0u)), 0u);
    return nyqrandomsampler;
}

NyqPcg32_ nyq_random_at(inout NyqRandomSampler s_39, uint dim_17)
{
    NyqPcg32_ g_2 = (NyqPcg32_)0;

    uint2 _e3 = s_39.base;
    const NyqPcg32_ _e4 = nyq_pcg32_(_e3);
    g_2 = _e4;
    uint d_13 = (dim_17 & 65535u);
    if ((d_13 != 0u)) {
        nyq_pcg32_advance(g_2, d_13);
    }
    NyqPcg32_ _e10 = g_2;
    const NyqPcg32_ nyqpcg32_1 = _e10;
    return nyqpcg32_1;
}

void nyq_random_start(inout NyqRandomSampler s_40, uint2 pixel_10, uint sample_index_8, uint dim_18)
{
    uint2 _e5 = s_40.seed;
    const uint2 _e7 = nyq_u64_(1918987876u);
    const uint2 _e8 = nyq_hash3_(pixel_10, _e5, _e7);
    uint2 golden_2 = uint2(2135587861u, 2654435769u);
    const uint2 _e13 = nyq_u64_(sample_index_8);
    const uint2 _e14 = nyq_mul64_(_e13, golden_2);
    const uint2 _e16 = nyq_mix64_((_e8 ^ _e14));
    s_40.base = _e16;
    s_40.dim = dim_18;
    const NyqPcg32_ _e19 = nyq_random_at(s_40, dim_18);
    s_40.rng = _e19;
    return;
}

float nyq_random_get_1d(inout NyqRandomSampler s_41)
{
    NyqPcg32_ g_3 = (NyqPcg32_)0;

    NyqPcg32_ _e2 = s_41.rng;
    g_3 = _e2;
    const uint _e4 = nyq_pcg32_next(g_3);
    const float _e5 = nyq_unit_f32_(_e4);
    NyqPcg32_ _e7 = g_3;
    s_41.rng = _e7;
    uint _e9 = s_41.dim;
    s_41.dim = (_e9 + 1u);
    uint _e13 = s_41.dim;
    if (((_e13 & 65535u) == 0u)) {
        const NyqPcg32_ _e20 = nyq_random_at(s_41, 0u);
        s_41.rng = _e20;
    }
    return _e5;
}

float2 nyq_random_get_2d(inout NyqRandomSampler s_42)
{
    const float _e1 = nyq_random_get_1d(s_42);
    const float _e2 = nyq_random_get_1d(s_42);
    return float2(_e1, _e2);
}

float2 nyq_random_get_pixel_2d(inout NyqRandomSampler s_43)
{
    NyqPcg32_ g_4 = (NyqPcg32_)0;

    uint _e2 = s_43.dim;
    if ((_e2 == 0u)) {
        const float2 _e5 = nyq_random_get_2d(s_43);
        return _e5;
    }
    const NyqPcg32_ _e7 = nyq_random_at(s_43, 0u);
    g_4 = _e7;
    const uint _e9 = nyq_pcg32_next(g_4);
    const float _e10 = nyq_unit_f32_(_e9);
    const uint _e11 = nyq_pcg32_next(g_4);
    const float _e12 = nyq_unit_f32_(_e11);
    float2 p_3 = float2(_e10, _e12);
    uint _e15 = s_43.dim;
    if ((_e15 < 2u)) {
        s_43.dim = 2u;
        NyqPcg32_ _e21 = g_4;
        s_43.rng = _e21;
    }
    return p_3;
}

NyqCameraSample nyq_random_camera_sample(inout NyqRandomSampler s_44, uint2 pixel_11, uint sample_index_9)
{
    nyq_random_start(s_44, pixel_11, sample_index_9, 0u);
    const float2 _e4 = nyq_random_get_pixel_2d(s_44);
    const float _e5 = nyq_random_get_1d(s_44);
    const float2 _e6 = nyq_random_get_2d(s_44);
    const float _e9 = nyq_film_coordinate(pixel_11.x, _e4.x);
    const float _e12 = nyq_film_coordinate(pixel_11.y, _e4.y);
    float2 film_2 = float2(_e9, _e12);
    const NyqCameraSample nyqcamerasample_3 = ConstructNyqCameraSample(film_2, _e6, _e5);
    return nyqcamerasample_3;
}

uint nyq_mod64_(uint2 x_9, uint n)
{
    uint r_5 = 0u;
    uint i_5 = 0u;
    bool local_3 = (bool)0;

    uint2 loop_bound_16 = uint2(4294967295u, 4294967295u);
    bool loop_init_13 = true;
    while(true) {
        if (all(loop_bound_16 == uint2(0u, 0u))) { break; }
        loop_bound_16 -= uint2(loop_bound_16.y == 0u, 1u);
        if (!loop_init_13) {
            uint _e42 = i_5;
            i_5 = (_e42 + 1u);
        }
        loop_init_13 = false;
        uint _e6 = i_5;
        if ((_e6 < 64u)) {
        } else {
            break;
        }
        {
            uint _e11 = i_5;
            uint word_1 = ((_e11 < 32u) ? x_9.y : x_9.x);
            uint _e16 = i_5;
            uint bit_1 = ((word_1 >> (31u - (_e16 & 31u))) & 1u);
            uint _e23 = r_5;
            uint carry = (_e23 >> 31u);
            uint _e26 = r_5;
            r_5 = ((_e26 << 1u) | bit_1);
            if (!((carry == 1u))) {
                uint _e35 = r_5;
                local_3 = (_e35 >= n);
            } else {
                local_3 = true;
            }
            bool _e38 = local_3;
            if (_e38) {
                uint _e39 = r_5;
                r_5 = (_e39 - n);
            }
        }
    }
    uint _e44 = r_5;
    return _e44;
}

uint2 nyq_fixed_ratio(uint num, uint den)
{
    uint r_6 = (uint)0;
    uint2 q = uint2(0u, 0u);
    uint i_6 = 0u;
    bool local_4 = (bool)0;

    r_6 = num;
    uint2 loop_bound_17 = uint2(4294967295u, 4294967295u);
    bool loop_init_14 = true;
    while(true) {
        if (all(loop_bound_17 == uint2(0u, 0u))) { break; }
        loop_bound_17 -= uint2(loop_bound_17.y == 0u, 1u);
        if (!loop_init_14) {
            uint _e37 = i_6;
            i_6 = (_e37 + 1u);
        }
        loop_init_14 = false;
        uint _e9 = i_6;
        if ((_e9 < 64u)) {
        } else {
            break;
        }
        {
            uint _e12 = r_6;
            uint carry_1 = (_e12 >> 31u);
            uint _e15 = r_6;
            r_6 = (_e15 << 1u);
            uint2 _e18 = q;
            const uint2 _e20 = nyq_shl64_(_e18, 1u);
            q = _e20;
            if (!((carry_1 == 1u))) {
                uint _e26 = r_6;
                local_4 = (_e26 >= den);
            } else {
                local_4 = true;
            }
            bool _e29 = local_4;
            if (_e29) {
                uint _e30 = r_6;
                r_6 = (_e30 - den);
                uint _e33 = q.x;
                q.x = (_e33 | 1u);
            }
        }
    }
    uint2 _e39 = q;
    return _e39;
}

float nyq_fixed_to_f32_(uint2 x_10)
{
    return (float((x_10.y >> 8u)) * 5.9604645e-8);
}

NyqLatticeSampler ConstructNyqLatticeSampler(uint arg0, uint arg1, uint arg2, uint2 arg3, uint2 arg4, uint arg5, uint arg6) {
    NyqLatticeSampler ret = (NyqLatticeSampler)0;
    ret.lattice = arg0;
    ret.n = arg1;
    ret.g = arg2;
    ret.seed = arg3;
    ret.pixel = arg4;
    ret.index = arg5;
    ret.dim = arg6;
    return ret;
}

NyqLatticeSampler nyq_lattice_sampler(uint lattice, uint n_1, uint g_5, uint2 seed_13)
{
    const NyqLatticeSampler nyqlatticesampler = ConstructNyqLatticeSampler(lattice, n_1, g_5, seed_13, uint2(0u, 0u), 0u, 0u);
    return nyqlatticesampler;
}

float nyq_lattice_value(inout NyqLatticeSampler s_45, uint dim_19)
{
    uint2 base = (uint2)0;
    uint g_6 = (uint)0;

    uint n_4 = s_45.n;
    uint _e5 = s_45.index;
    uint k_11 = naga_mod(_e5, n_4);
    uint component = naga_mod(dim_19, 2u);
    uint _e11 = s_45.lattice;
    switch(_e11) {
        case 2u: {
            const uint2 _e15 = nyq_u64_(k_11);
            const uint2 _e18 = nyq_mul64_(_e15, NYQ_R2_ALPHA[min(uint(component), 1u)]);
            const uint2 _e19 = nyq_add64_(uint2(0u, 2147483648u), _e18);
            base = _e19;
            break;
        }
        default: {
            uint _e21 = s_45.g;
            g_6 = _e21;
            if ((component == 0u)) {
                g_6 = naga_mod(1u, n_4);
            }
            uint _e27 = g_6;
            const uint2 _e28 = nyq_mul_wide(k_11, _e27);
            const uint _e29 = nyq_mod64_(_e28, n_4);
            const uint2 _e30 = nyq_fixed_ratio(_e29, n_4);
            base = _e30;
            break;
        }
    }
    uint2 _e32 = s_45.pixel;
    const uint2 _e35 = nyq_u64_(naga_div(dim_19, 2u));
    uint2 _e37 = s_45.seed;
    const uint2 _e38 = nyq_hash3_(_e32, _e35, _e37);
    uint2 _e39 = base;
    const uint2 _e40 = nyq_u64_(component);
    const uint2 _e41 = nyq_hash2_(_e38, _e40);
    const uint2 _e42 = nyq_add64_(_e39, _e41);
    const float _e43 = nyq_fixed_to_f32_(_e42);
    return _e43;
}

void nyq_lattice_start(inout NyqLatticeSampler s_46, uint2 pixel_12, uint sample_index_10, uint dim_20)
{
    s_46.pixel = pixel_12;
    s_46.index = sample_index_10;
    s_46.dim = dim_20;
    return;
}

float nyq_lattice_get_1d(inout NyqLatticeSampler s_47)
{
    uint d_14 = s_47.dim;
    s_47.dim = (d_14 + 1u);
    const float _e6 = nyq_lattice_value(s_47, d_14);
    return _e6;
}

float2 nyq_lattice_get_2d(inout NyqLatticeSampler s_48)
{
    uint d_15 = s_48.dim;
    s_48.dim = (d_15 + 2u);
    const float _e6 = nyq_lattice_value(s_48, d_15);
    const float _e9 = nyq_lattice_value(s_48, (d_15 + 1u));
    return float2(_e6, _e9);
}

float2 nyq_lattice_get_pixel_2d(inout NyqLatticeSampler s_49)
{
    uint _e3 = s_49.dim;
    s_49.dim = max(_e3, 2u);
    const float _e7 = nyq_lattice_value(s_49, 0u);
    const float _e9 = nyq_lattice_value(s_49, 1u);
    return float2(_e7, _e9);
}

NyqCameraSample nyq_lattice_camera_sample(inout NyqLatticeSampler s_50, uint2 pixel_13, uint sample_index_11)
{
    nyq_lattice_start(s_50, pixel_13, sample_index_11, 0u);
    const float2 _e4 = nyq_lattice_get_pixel_2d(s_50);
    const float _e5 = nyq_lattice_get_1d(s_50);
    const float2 _e6 = nyq_lattice_get_2d(s_50);
    const float _e9 = nyq_film_coordinate(pixel_13.x, _e4.x);
    const float _e12 = nyq_film_coordinate(pixel_13.y, _e4.y);
    float2 film_3 = float2(_e9, _e12);
    const NyqCameraSample nyqcamerasample_4 = ConstructNyqCameraSample(film_3, _e6, _e5);
    return nyqcamerasample_4;
}

float nyq_u32_to_f32_(uint x_11)
{
    uint m = (uint)0;
    bool local_5 = (bool)0;
    bool local_6 = (bool)0;

    if ((x_11 < 16777216u)) {
        return float(x_11);
    }
    uint top = (31u - (31u - firstbithigh(x_11)));
    uint drop = (top - 23u);
    m = (x_11 >> drop);
    uint rest = (x_11 & ((1u << drop) - 1u));
    uint half_ = (1u << (drop - 1u));
    if (!((rest > half_))) {
        if ((rest == half_)) {
            uint _e27 = m;
            local_6 = ((_e27 & 1u) == 1u);
        } else {
            local_6 = false;
        }
        bool _e33 = local_6;
        local_5 = _e33;
    } else {
        local_5 = true;
    }
    bool _e35 = local_5;
    if (_e35) {
        uint _e36 = m;
        m = (_e36 + 1u);
    }
    uint _e43 = m;
    return asfloat(((((top + 127u) << 23u) + _e43) - 8388608u));
}

float nyq_recip_f32_(float x_12)
{
    uint r_7 = 16777216u;
    uint q_1 = 0u;
    uint i_7 = 0u;
    bool local_7 = (bool)0;
    bool local_8 = (bool)0;

    uint bits_3 = asuint(x_12);
    uint m_4 = ((bits_3 & 8388607u) | 8388608u);
    int e = asint(asuint(int((bits_3 >> 23u))) - asuint(int(127)));
    if ((m_4 == 8388608u)) {
        return asfloat((uint(asint(asuint(int(127)) - asuint(e))) << 23u));
    }
    uint2 loop_bound_18 = uint2(4294967295u, 4294967295u);
    bool loop_init_15 = true;
    while(true) {
        if (all(loop_bound_18 == uint2(0u, 0u))) { break; }
        loop_bound_18 -= uint2(loop_bound_18.y == 0u, 1u);
        if (!loop_init_15) {
            uint _e42 = i_7;
            i_7 = (_e42 + 1u);
        }
        loop_init_15 = false;
        uint _e25 = i_7;
        if ((_e25 < 25u)) {
        } else {
            break;
        }
        {
            uint _e28 = q_1;
            q_1 = (_e28 << 1u);
            uint _e31 = r_7;
            if ((_e31 >= m_4)) {
                uint _e33 = r_7;
                r_7 = (_e33 - m_4);
                uint _e35 = q_1;
                q_1 = (_e35 | 1u);
            }
            uint _e38 = r_7;
            r_7 = (_e38 << 1u);
        }
    }
    uint _e44 = q_1;
    uint round_ = (_e44 & 1u);
    uint _e47 = q_1;
    q_1 = (_e47 >> 1u);
    if ((round_ == 1u)) {
        uint _e54 = r_7;
        if (!((_e54 != 0u))) {
            uint _e60 = q_1;
            local_8 = ((_e60 & 1u) == 1u);
        } else {
            local_8 = true;
        }
        bool _e66 = local_8;
        local_7 = _e66;
    } else {
        local_7 = false;
    }
    bool _e68 = local_7;
    if (_e68) {
        uint _e69 = q_1;
        q_1 = (_e69 + 1u);
    }
    uint _e79 = q_1;
    return asfloat((((uint(asint(asuint(asint(asuint(int(127)) - asuint(e))) - asuint(int(1)))) << 23u) + _e79) - 8388608u));
}

uint3 nyq_mul64x32_(uint2 r_8, uint k_6)
{
    const uint2 _e3 = nyq_mul_wide(r_8.x, k_6);
    const uint2 _e5 = nyq_mul_wide(r_8.y, k_6);
    const uint2 _e9 = nyq_add64_(_e5, uint2(_e3.y, 0u));
    return uint3(_e3.x, _e9.x, _e9.y);
}

uint nyq_nibble(uint2 t_1, uint s_51)
{
    return ((((s_51 >= 32u) ? t_1.y : t_1.x) >> (s_51 & 31u)) & 15u);
}

uint2 nyq_shl64_any(uint2 x_13, uint s_52)
{
    if ((s_52 == 0u)) {
        return x_13;
    }
    if ((s_52 >= 32u)) {
        return uint2(0u, (x_13.x << (s_52 - 32u)));
    }
    const uint2 _e12 = nyq_shl64_(x_13, s_52);
    return _e12;
}

typedef uint ret_Constructarray5_uint_[5];
ret_Constructarray5_uint_ Constructarray5_uint_(uint arg0, uint arg1, uint arg2, uint arg3, uint arg4) {
    uint ret[5] = { arg0, arg1, arg2, arg3, arg4 };
    return ret;
}

uint2 nyq_packed_table(uint n_2, uint2 r_in)
{
    uint2 t_2 = uint2(1985229328u, 4275878552u);
    uint2 r_9 = (uint2)0;
    uint k_7 = (uint)0;

    if ((n_2 <= 4u)) {
        if ((n_2 < 2u)) {
            return uint2(0u, 0u);
        }
        uint factorial[5] = Constructarray5_uint_(1u, 1u, 2u, 6u, 24u);
        uint start[5] = Constructarray5_uint_(0u, 0u, 0u, 2u, 8u);
        const uint3 _e22 = nyq_mul64x32_(r_in, factorial[min(uint(n_2), 4u)]);
        uint rank = _e22.z;
        return uint2(NYQ_SMALL_PERMUTATIONS[min(uint(((start[min(uint(n_2), 4u)] + rank) & 31u)), 31u)], 0u);
    }
    if ((n_2 < 16u)) {
        uint keep = (4u * n_2);
        if ((keep < 32u)) {
            uint _e43 = t_2.x;
            t_2 = uint2((_e43 & ((1u << keep) - 1u)), 0u);
        } else {
            uint _e52 = t_2.y;
            t_2.y = (_e52 & ((1u << (keep - 32u)) - 1u));
        }
    }
    r_9 = r_in;
    k_7 = n_2;
    uint2 loop_bound_19 = uint2(4294967295u, 4294967295u);
    bool loop_init_16 = true;
    while(true) {
        if (all(loop_bound_19 == uint2(0u, 0u))) { break; }
        loop_bound_19 -= uint2(loop_bound_19.y == 0u, 1u);
        if (!loop_init_16) {
            uint _e94 = k_7;
            k_7 = (_e94 - 1u);
        }
        loop_init_16 = false;
        uint _e62 = k_7;
        if ((_e62 > 1u)) {
        } else {
            break;
        }
        {
            uint2 _e65 = r_9;
            uint _e66 = k_7;
            const uint3 _e67 = nyq_mul64x32_(_e65, _e66);
            uint j_1 = _e67.z;
            r_9 = _e67.xy;
            uint _e71 = k_7;
            uint hi = (4u * (_e71 - 1u));
            uint lo = (4u * j_1);
            uint2 _e77 = t_2;
            const uint _e78 = nyq_nibble(_e77, hi);
            uint2 _e79 = t_2;
            const uint _e80 = nyq_nibble(_e79, lo);
            uint x_19 = ((_e78 ^ _e80) & 15u);
            uint2 _e84 = t_2;
            const uint2 _e87 = nyq_shl64_any(uint2(x_19, 0u), hi);
            const uint2 _e90 = nyq_shl64_any(uint2(x_19, 0u), lo);
            t_2 = (_e84 ^ (_e87 | _e90));
        }
    }
    uint2 _e96 = t_2;
    return _e96;
}

NyqPermutation ConstructNyqPermutation(uint arg0, uint arg1, uint arg2, uint arg3, uint arg4, uint arg5, uint arg6, uint2 arg7) {
    NyqPermutation ret = (NyqPermutation)0;
    ret.n = arg0;
    ret.mask = arg1;
    ret.half_ = arg2;
    ret.third = arg3;
    ret.key = arg4;
    ret.key2_ = arg5;
    ret.offset = arg6;
    ret.table = arg7;
    return ret;
}

NyqPermutation nyq_permutation(uint n_in, uint seed_14)
{
    uint n_5 = max(n_in, 1u);
    if ((n_5 <= 16u)) {
        const uint2 _e10 = nyq_mix64_(uint2((seed_14 ^ 2242054355u), 608135816u));
        const uint2 _e11 = nyq_packed_table(n_5, _e10);
        const NyqPermutation nyqpermutation = ConstructNyqPermutation(n_5, 0u, 0u, 0u, 0u, 0u, 0u, _e11);
        return nyqpermutation;
    }
    uint mask_3 = (4294967295u >> (31u - firstbithigh((n_5 - 1u))));
    uint bits_4 = (32u - (31u - firstbithigh(mask_3)));
    const uint _e29 = nyq_mix32_((seed_14 ^ 1540483477u));
    const uint _e32 = nyq_mix32_((_e29 + 1759714724u));
    const uint _e35 = nyq_mix32_((_e32 ^ 625341585u));
    const uint2 _e36 = nyq_mul_wide(_e35, n_5);
    uint offset_1 = _e36.y;
    const NyqPermutation nyqpermutation_1 = ConstructNyqPermutation(n_5, mask_3, max(naga_div((bits_4 + 1u), 2u), 1u), max(naga_div(bits_4, 3u), 1u), _e29, _e32, offset_1, uint2(0u, 0u));
    return nyqpermutation_1;
}

uint nyq_permutation_apply(NyqPermutation p, uint i_8)
{
    uint x_14 = (uint)0;
    bool local_9 = (bool)0;

    uint n_6 = p.n;
    if ((n_6 <= 16u)) {
        const uint _e11 = nyq_nibble(p.table, (4u * (naga_mod(i_8, n_6) & 15u)));
        return _e11;
    }
    x_14 = naga_mod(i_8, n_6);
    uint2 loop_bound_20 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_20 == uint2(0u, 0u))) { break; }
        loop_bound_20 -= uint2(loop_bound_20.y == 0u, 1u);
        uint _e14 = x_14;
        x_14 = (_e14 ^ (p.key & p.mask));
        uint _e19 = x_14;
        x_14 = ((_e19 * 3782248765u) & p.mask);
        uint _e24 = x_14;
        uint _e25 = x_14;
        x_14 = (_e24 ^ (_e25 >> p.half_));
        uint _e29 = x_14;
        x_14 = ((_e29 + p.key2_) & p.mask);
        uint _e34 = x_14;
        x_14 = ((_e34 * (p.key | 1u)) & p.mask);
        uint _e41 = x_14;
        uint _e42 = x_14;
        x_14 = (_e41 ^ (_e42 >> p.half_));
        uint _e46 = x_14;
        x_14 = (_e46 ^ ((p.key2_ >> 7u) & p.mask));
        uint _e53 = x_14;
        x_14 = ((_e53 * 153742143u) & p.mask);
        uint _e58 = x_14;
        uint _e59 = x_14;
        x_14 = (_e58 ^ (_e59 >> p.half_));
        uint _e63 = x_14;
        x_14 = ((_e63 * (1765145193u ^ (p.key2_ & 4294967294u))) & p.mask);
        uint _e72 = x_14;
        uint _e73 = x_14;
        x_14 = (_e72 ^ (_e73 >> p.third));
        uint _e77 = x_14;
        if ((_e77 < n_6)) {
            break;
        }
    }
    uint _e79 = x_14;
    uint q_2 = (_e79 + p.offset);
    uint _e83 = x_14;
    if (!((q_2 < _e83))) {
        local_9 = (q_2 >= n_6);
    } else {
        local_9 = true;
    }
    bool _e90 = local_9;
    return (_e90 ? (q_2 - n_6) : q_2);
}

NyqStratifiedSampler ConstructNyqStratifiedSampler(uint arg0, uint arg1, uint arg2, float3 arg3, uint arg4, uint2 arg5, uint2 arg6, uint2 arg7, uint arg8, uint arg9) {
    NyqStratifiedSampler ret = (NyqStratifiedSampler)0;
    ret.xs = arg0;
    ret.ys = arg1;
    ret.spp = arg2;
    ret.inv = arg3;
    ret.jitter = arg4;
    ret.seed = arg5;
    ret.pixel_key = arg6;
    ret.sample_key = arg7;
    ret.index = arg8;
    ret.dim = arg9;
    return ret;
}

NyqStratifiedSampler nyq_stratified_sampler(uint xs, uint ys, uint jitter, uint2 seed_15)
{
    uint spp_2 = (xs * ys);
    const float _e5 = nyq_u32_to_f32_(xs);
    const float _e6 = nyq_recip_f32_(_e5);
    const float _e7 = nyq_u32_to_f32_(ys);
    const float _e8 = nyq_recip_f32_(_e7);
    const float _e9 = nyq_u32_to_f32_(spp_2);
    const float _e10 = nyq_recip_f32_(_e9);
    float3 inv = float3(_e6, _e8, _e10);
    uint2 zero = uint2(0u, 0u);
    const NyqStratifiedSampler nyqstratifiedsampler = ConstructNyqStratifiedSampler(xs, ys, spp_2, inv, jitter, seed_15, zero, zero, 0u, 0u);
    return nyqstratifiedsampler;
}

uint nyq_stratified_dim_key(uint2 pixel_key, uint dim_21)
{
    const uint2 _e2 = nyq_u64_(dim_21);
    const uint2 _e4 = nyq_mul64_(_e2, NYQ_DIM_STEP);
    const uint2 _e6 = nyq_mix64_((pixel_key ^ _e4));
    return (_e6.x ^ _e6.y);
}

uint nyq_stratified_stratum(inout NyqStratifiedSampler s_53, uint dim_22)
{
    if ((dim_22 == 0u)) {
        uint _e5 = s_53.index;
        uint _e7 = s_53.spp;
        return naga_mod(_e5, _e7);
    }
    uint _e10 = s_53.spp;
    uint2 _e12 = s_53.pixel_key;
    const uint _e13 = nyq_stratified_dim_key(_e12, dim_22);
    const NyqPermutation _e14 = nyq_permutation(_e10, _e13);
    uint _e16 = s_53.index;
    const uint _e17 = nyq_permutation_apply(_e14, _e16);
    return _e17;
}

float2 nyq_stratified_jitters(inout NyqStratifiedSampler s_54, uint dim_23)
{
    bool local_10 = (bool)0;

    uint _e3 = s_54.jitter;
    if ((_e3 != NYQ_JITTERED)) {
        return float2(0.5, 0.5);
    }
    if (!((dim_23 == 2u))) {
        local_10 = (dim_23 == 3u);
    } else {
        local_10 = true;
    }
    bool _e17 = local_10;
    if (_e17) {
        uint2 _e19 = s_54.sample_key;
        const uint2 _e24 = nyq_mul64_(uint2(2u, 0u), NYQ_JITTER_STEP);
        const uint2 _e26 = nyq_mix64_((_e19 ^ _e24));
        if ((dim_23 == 2u)) {
            return float2((float(((_e26.y >> 11u) & 2097151u)) * 4.7683716e-7), 0.5);
        }
        const uint2 _e40 = nyq_shr64_(_e26, 22u);
        return float2((float((_e40.x & 2097151u)) * 4.7683716e-7), (float(((_e26.x >> 1u) & 2097151u)) * 4.7683716e-7));
    }
    uint2 _e55 = s_54.sample_key;
    const uint2 _e56 = nyq_u64_(dim_23);
    const uint2 _e58 = nyq_mul64_(_e56, NYQ_JITTER_STEP);
    const uint2 _e60 = nyq_mix64_((_e55 ^ _e58));
    const float _e62 = nyq_unit_f32_(_e60.y);
    const float _e64 = nyq_unit_f32_(_e60.x);
    return float2(_e62, _e64);
}

float nyq_below_one(float x_15)
{
    return min(x_15, asfloat(1065353215u));
}

float2 nyq_stratified_cell(inout NyqStratifiedSampler s_55, uint st, float2 j)
{
    uint _e4 = s_55.xs;
    uint cx = naga_mod(st, _e4);
    uint _e7 = s_55.xs;
    uint cy = naga_div(st, _e7);
    const float _e9 = nyq_u32_to_f32_(cx);
    float _e14 = s_55.inv.x;
    const float _e16 = nyq_below_one(((_e9 + j.x) * _e14));
    const float _e17 = nyq_u32_to_f32_(cy);
    float _e22 = s_55.inv.y;
    const float _e24 = nyq_below_one(((_e17 + j.y) * _e22));
    return float2(_e16, _e24);
}

void nyq_stratified_start(inout NyqStratifiedSampler s_56, uint2 pixel_14, uint sample_index_12, uint dim_24)
{
    uint2 _e6 = s_56.seed;
    const uint2 _e8 = nyq_u64_(1937011297u);
    const uint2 _e9 = nyq_hash3_(pixel_14, _e6, _e8);
    s_56.pixel_key = _e9;
    s_56.index = sample_index_12;
    uint2 _e13 = s_56.pixel_key;
    const uint2 _e14 = nyq_u64_(sample_index_12);
    const uint2 _e16 = nyq_mul64_(_e14, NYQ_DIM_STEP);
    s_56.sample_key = (_e13 ^ _e16);
    s_56.dim = dim_24;
    return;
}

float nyq_stratified_get_1d(inout NyqStratifiedSampler s_57)
{
    uint d_16 = s_57.dim;
    s_57.dim = (d_16 + 1u);
    const uint _e6 = nyq_stratified_stratum(s_57, d_16);
    const float _e7 = nyq_u32_to_f32_(_e6);
    const float2 _e8 = nyq_stratified_jitters(s_57, d_16);
    float _e13 = s_57.inv.z;
    const float _e15 = nyq_below_one(((_e7 + _e8.x) * _e13));
    return _e15;
}

float2 nyq_stratified_get_2d(inout NyqStratifiedSampler s_58)
{
    uint d_17 = s_58.dim;
    s_58.dim = (d_17 + 2u);
    const uint _e6 = nyq_stratified_stratum(s_58, d_17);
    const float2 _e7 = nyq_stratified_jitters(s_58, d_17);
    const float2 _e8 = nyq_stratified_cell(s_58, _e6, _e7);
    return _e8;
}

float2 nyq_stratified_get_pixel_2d(inout NyqStratifiedSampler s_59)
{
    uint _e3 = s_59.dim;
    s_59.dim = max(_e3, 2u);
    const uint _e7 = nyq_stratified_stratum(s_59, 0u);
    const float2 _e9 = nyq_stratified_jitters(s_59, 0u);
    const float2 _e10 = nyq_stratified_cell(s_59, _e7, _e9);
    return _e10;
}

NyqCameraSample nyq_stratified_camera_sample(inout NyqStratifiedSampler s_60, uint2 pixel_15, uint sample_index_13)
{
    nyq_stratified_start(s_60, pixel_15, sample_index_13, 0u);
    const float2 _e4 = nyq_stratified_get_pixel_2d(s_60);
    const float _e5 = nyq_stratified_get_1d(s_60);
    const float2 _e6 = nyq_stratified_get_2d(s_60);
    const float _e9 = nyq_film_coordinate(pixel_15.x, _e4.x);
    const float _e12 = nyq_film_coordinate(pixel_15.y, _e4.y);
    float2 film_4 = float2(_e9, _e12);
    const NyqCameraSample nyqcamerasample_5 = ConstructNyqCameraSample(film_4, _e6, _e5);
    return nyqcamerasample_5;
}

uint2 nyq_mul64_high(uint2 a_8, uint2 b_6)
{
    const uint2 _e4 = nyq_mul_wide(a_8.x, b_6.x);
    const uint2 _e7 = nyq_mul_wide(a_8.x, b_6.y);
    const uint2 _e10 = nyq_mul_wide(a_8.y, b_6.x);
    const uint2 _e13 = nyq_mul_wide(a_8.y, b_6.y);
    const uint2 _e20 = nyq_add64_(uint2(_e4.y, 0u), uint2(_e7.x, 0u));
    const uint2 _e24 = nyq_add64_(_e20, uint2(_e10.x, 0u));
    const uint2 _e28 = nyq_add64_(_e13, uint2(_e7.y, 0u));
    const uint2 _e35 = nyq_add64_(uint2(_e10.y, 0u), uint2(_e24.y, 0u));
    const uint2 _e36 = nyq_add64_(_e28, _e35);
    return _e36;
}

uint2 nyq_wyrand(uint2 seed_16, uint i_9)
{
    const uint2 _e5 = nyq_u64_((i_9 + 1u));
    const uint2 _e6 = nyq_mul64_(NYQ_WYRAND_INC, _e5);
    const uint2 _e7 = nyq_add64_(seed_16, _e6);
    uint2 t_4 = (_e7 ^ NYQ_WYRAND_FOLD);
    const uint2 _e10 = nyq_mul64_high(_e7, t_4);
    const uint2 _e11 = nyq_mul64_(_e7, t_4);
    return (_e10 ^ _e11);
}

uint nyq_pmj02_point(uint2 seed_17, uint index_10, uint dim_25)
{
    uint x_16 = 0u;
    uint known = 0u;
    uint flips = 0u;
    uint p_1 = (uint)0;

    p_1 = (index_10 & 65535u);
    uint2 loop_bound_21 = uint2(4294967295u, 4294967295u);
    while(true) {
        if (all(loop_bound_21 == uint2(0u, 0u))) { break; }
        loop_bound_21 -= uint2(loop_bound_21.y == 0u, 1u);
        uint _e12 = p_1;
        if ((_e12 != 0u)) {
        } else {
            break;
        }
        {
            uint _e16 = p_1;
            uint level = (31u - (31u - firstbithigh(_e16)));
            uint swap = (2147483648u >> level);
            uint low_2 = (swap - 1u);
            uint _e23 = p_1;
            const uint2 _e24 = nyq_wyrand(seed_17, _e23);
            uint bits_5 = ((dim_25 == 0u) ? _e24.x : _e24.y);
            uint _e30 = x_16;
            uint _e32 = known;
            x_16 = (_e30 | ((bits_5 & low_2) & ~(_e32)));
            uint _e36 = known;
            known = (_e36 | low_2);
            uint _e38 = flips;
            flips = (_e38 ^ swap);
            uint c_4 = ((dim_25 == 0u) ? NYQ_PMJ02_XOR_X[min(uint((level & 15u)), 15u)] : NYQ_PMJ02_XOR_Y[min(uint((level & 15u)), 15u)]);
            uint _e51 = p_1;
            p_1 = ((_e51 - (1u << level)) ^ c_4);
        }
    }
    const uint2 _e57 = nyq_wyrand(seed_17, 0u);
    uint _e58 = x_16;
    uint _e64 = known;
    x_16 = (_e58 | (((dim_25 == 0u) ? _e57.x : _e57.y) & ~(_e64)));
    uint _e68 = x_16;
    uint _e69 = flips;
    return (_e68 ^ _e69);
}

NyqPmj02_ ConstructNyqPmj02_(uint arg0, uint2 arg1) {
    NyqPmj02_ ret = (NyqPmj02_)0;
    ret.scrambled = arg0;
    ret.keys = arg1;
    return ret;
}

NyqPmj02_ nyq_pmj02_(bool scrambled_1, uint2 seed_18)
{
    const uint2 _e5 = nyq_hash2_(seed_18, uint2(845115255u, 1886218800u));
    const NyqPmj02_ nyqpmj02_ = ConstructNyqPmj02_((scrambled_1 ? 1u : 0u), _e5);
    return nyqpmj02_;
}

uint nyq_pmj02_sample_u32_(NyqPmj02_ s_61, uint index_11, uint dim_26)
{
    uint d_18 = (dim_26 & 1u);
    const uint _e6 = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, index_11, d_18);
    if ((s_61.scrambled == 0u)) {
        return _e6;
    }
    const uint _e13 = nyq_lk_hash(reversebits(_e6), s_61.keys[min(uint(d_18), 1u)]);
    return reversebits(_e13);
}

float nyq_pmj02_sample(NyqPmj02_ s_62, uint index_12, uint dim_27)
{
    const uint _e3 = nyq_pmj02_sample_u32_(s_62, index_12, dim_27);
    const float _e4 = nyq_fraction_to_f32_(_e3);
    return _e4;
}

NyqPmj02Sampler ConstructNyqPmj02Sampler(uint2 arg0, uint2 arg1, uint arg2, uint arg3) {
    NyqPmj02Sampler ret = (NyqPmj02Sampler)0;
    ret.seed = arg0;
    ret.pixel_key = arg1;
    ret.index_rev = arg2;
    ret.dim = arg3;
    return ret;
}

NyqPmj02Sampler nyq_pmj02_sampler(uint2 seed_19)
{
    const NyqPmj02Sampler nyqpmj02sampler = ConstructNyqPmj02Sampler(seed_19, uint2(0u, 0u), 0u, 0u);
    return nyqpmj02sampler;
}

uint nyq_reverse16_(uint m_1)
{
    return (reversebits((m_1 & 65535u)) >> 16u);
}

uint3 nyq_pmj02_keys(inout NyqPmj02Sampler s_63, uint2 request)
{
    uint2 _e3 = s_63.pixel_key;
    const uint2 _e7 = nyq_mul64_(request, uint2(2135587861u, 2654435769u));
    const uint2 _e9 = nyq_mix64_((_e3 ^ _e7));
    const uint2 _e14 = nyq_mix64_((_e9 ^ uint2(1781543545u, 28781u)));
    return uint3(_e9.x, _e9.y, _e14.x);
}

float2 nyq_pmj02_keyed_point(uint3 k_8, uint i_10)
{
    const uint _e4 = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, i_10, 0u);
    const uint _e7 = nyq_pmj02_point(NYQ_PMJ02_TABLE_SEED, i_10, 1u);
    const uint _e10 = nyq_lk_hash(reversebits(_e4), k_8.y);
    const float _e11 = nyq_rev_to_f32_(_e10);
    const uint _e14 = nyq_lk_hash(reversebits(_e7), k_8.z);
    const float _e15 = nyq_rev_to_f32_(_e14);
    return float2(_e11, _e15);
}

uint nyq_pmj02_row(inout NyqPmj02Sampler s_64, uint3 k_9)
{
    uint _e3 = s_64.index_rev;
    const uint _e5 = nyq_lk_hash(_e3, k_9.x);
    return (_e5 >> 16u);
}

void nyq_pmj02_start(inout NyqPmj02Sampler s_65, uint2 pixel_16, uint sample_index_14, uint dim_28)
{
    uint2 _e6 = s_65.seed;
    const uint2 _e10 = nyq_hash3_(pixel_16, _e6, uint2(1835675698u, 112u));
    s_65.pixel_key = _e10;
    const uint _e12 = nyq_reverse16_(sample_index_14);
    s_65.index_rev = (_e12 << 16u);
    s_65.dim = dim_28;
    return;
}

float nyq_pmj02_get_1d(inout NyqPmj02Sampler s_66)
{
    uint d_19 = s_66.dim;
    s_66.dim = (d_19 + 1u);
    const uint2 _e6 = nyq_u64_(d_19);
    const uint2 _e8 = nyq_shl64_(_e6, 1u);
    const uint2 _e12 = nyq_add64_(_e8, uint2(1u, 0u));
    const uint3 _e13 = nyq_pmj02_keys(s_66, _e12);
    const uint _e14 = nyq_pmj02_row(s_66, _e13);
    const uint _e15 = nyq_reverse16_(_e14);
    const uint _e17 = nyq_lk_hash(_e15, _e13.y);
    const float _e18 = nyq_rev_to_f32_(_e17);
    return _e18;
}

float2 nyq_pmj02_get_2d(inout NyqPmj02Sampler s_67)
{
    uint d_20 = s_67.dim;
    s_67.dim = (d_20 + 2u);
    const uint2 _e6 = nyq_u64_(d_20);
    const uint2 _e8 = nyq_shl64_(_e6, 1u);
    const uint3 _e9 = nyq_pmj02_keys(s_67, _e8);
    if ((d_20 == 0u)) {
        uint _e13 = s_67.index_rev;
        const uint _e16 = nyq_reverse16_((_e13 >> 16u));
        const float2 _e17 = nyq_pmj02_keyed_point(_e9, _e16);
        return _e17;
    }
    const uint _e18 = nyq_pmj02_row(s_67, _e9);
    const uint _e19 = nyq_reverse16_(_e18);
    const float2 _e20 = nyq_pmj02_keyed_point(_e9, _e19);
    return _e20;
}

float2 nyq_pmj02_get_pixel_2d(inout NyqPmj02Sampler s_68)
{
    uint _e3 = s_68.dim;
    s_68.dim = max(_e3, 2u);
    const uint3 _e9 = nyq_pmj02_keys(s_68, uint2(0u, 0u));
    uint _e11 = s_68.index_rev;
    const uint _e14 = nyq_reverse16_((_e11 >> 16u));
    const float2 _e15 = nyq_pmj02_keyed_point(_e9, _e14);
    return _e15;
}

NyqCameraSample nyq_pmj02_camera_sample(inout NyqPmj02Sampler s_69, uint2 pixel_17, uint sample_index_15)
{
    nyq_pmj02_start(s_69, pixel_17, sample_index_15, 0u);
    const float2 _e4 = nyq_pmj02_get_pixel_2d(s_69);
    const float _e5 = nyq_pmj02_get_1d(s_69);
    const float2 _e6 = nyq_pmj02_get_2d(s_69);
    const float _e9 = nyq_film_coordinate(pixel_17.x, _e4.x);
    const float _e12 = nyq_film_coordinate(pixel_17.y, _e4.y);
    float2 film_5 = float2(_e9, _e12);
    const NyqCameraSample nyqcamerasample_6 = ConstructNyqCameraSample(film_5, _e6, _e5);
    return nyqcamerasample_6;
}

uint4 nyq_fill_request(uint i_11)
{
    uint _e3 = nyq_job.implicit;
    if ((_e3 == 0u)) {
        uint4 _e8 = asuint(nyq_requests.Load4(i_11*16));
        return _e8;
    }
    uint _e11 = nyq_job.first;
    uint n_7 = (_e11 + i_11);
    uint _e15 = nyq_job.spp;
    uint pixel_18 = naga_div(n_7, _e15);
    uint _e20 = nyq_job.resolution.x;
    uint _e25 = nyq_job.resolution.x;
    uint _e29 = nyq_job.spp;
    return uint4(naga_mod(pixel_18, _e20), naga_div(pixel_18, _e25), naga_mod(n_7, _e29), 5u);
}

void nyq_fill_camera(uint out_2, NyqCameraSample c_3)
{
    nyq_values.Store(out_2*4, asuint(asuint(c_3.p_film.x)));
    nyq_values.Store((out_2 + 1u)*4, asuint(asuint(c_3.p_film.y)));
    nyq_values.Store((out_2 + 2u)*4, asuint(asuint(c_3.time)));
    nyq_values.Store((out_2 + 3u)*4, asuint(asuint(c_3.lens.x)));
    nyq_values.Store((out_2 + 4u)*4, asuint(asuint(c_3.lens.y)));
    return;
}

void nyq_fill_values(uint out_3, float one, float2 two)
{
    nyq_values.Store((out_3 + 5u)*4, asuint(asuint(one)));
    nyq_values.Store((out_3 + 6u)*4, asuint(asuint(two.x)));
    nyq_values.Store((out_3 + 7u)*4, asuint(asuint(two.y)));
    return;
}

[numthreads(64, 1, 1)]
void nyq_fill(uint3 id : SV_DispatchThreadID)
{
    NyqOwenSobolSampler s = (NyqOwenSobolSampler)0;
    NyqZSobolSampler s_1 = (NyqZSobolSampler)0;
    NyqRandomSampler s_2 = (NyqRandomSampler)0;
    NyqLatticeSampler s_3 = (NyqLatticeSampler)0;
    NyqStratifiedSampler s_4 = (NyqStratifiedSampler)0;
    NyqPmj02Sampler s_5 = (NyqPmj02Sampler)0;
    NyqSobolSampler s_6 = (NyqSobolSampler)0;
    uint k = 0u;
    uint k_1 = 0u;
    uint k_2 = 0u;
    uint k_3 = 0u;

    uint i_12 = id.x;
    uint _e4 = nyq_job.count;
    if ((i_12 >= _e4)) {
        return;
    }
    const uint4 _e6 = nyq_fill_request(i_12);
    uint2 pixel_19 = _e6.xy;
    uint out_4 = (8u * i_12);
    uint _e12 = nyq_job.kind;
    switch(_e12) {
        case 0u: {
            uint2 _e15 = nyq_job.seed;
            uint _e18 = nyq_job.frame;
            const NyqOwenSobolSampler _e19 = nyq_owen_sobol_sampler(_e15, _e18);
            s = _e19;
            const NyqCameraSample _e22 = nyq_owen_sobol_camera_sample(s, pixel_19, _e6.z);
            nyq_fill_camera(out_4, _e22);
            nyq_owen_sobol_start(s, pixel_19, _e6.z, _e6.w);
            const float _e25 = nyq_owen_sobol_get_1d(s);
            const float2 _e26 = nyq_owen_sobol_get_2d(s);
            nyq_fill_values(out_4, _e25, _e26);
            return;
        }
        case 1u: {
            uint2 _e29 = nyq_job.resolution;
            uint _e32 = nyq_job.spp;
            uint _e35 = nyq_job.scramble;
            uint2 _e38 = nyq_job.seed;
            const NyqZSobolSampler _e39 = nyq_zsobol_sampler(_e29, _e32, _e35, _e38);
            s_1 = _e39;
            const NyqCameraSample _e42 = nyq_zsobol_camera_sample(s_1, pixel_19, _e6.z);
            nyq_fill_camera(out_4, _e42);
            nyq_zsobol_start(s_1, pixel_19, _e6.z, _e6.w);
            const float _e45 = nyq_zsobol_get_1d(s_1);
            const float2 _e46 = nyq_zsobol_get_2d(s_1);
            nyq_fill_values(out_4, _e45, _e46);
            return;
        }
        case 2u: {
            uint2 _e49 = nyq_job.seed;
            const NyqRandomSampler _e50 = nyq_random_sampler(_e49);
            s_2 = _e50;
            const NyqCameraSample _e53 = nyq_random_camera_sample(s_2, pixel_19, _e6.z);
            nyq_fill_camera(out_4, _e53);
            nyq_random_start(s_2, pixel_19, _e6.z, _e6.w);
            const float _e56 = nyq_random_get_1d(s_2);
            const float2 _e57 = nyq_random_get_2d(s_2);
            nyq_fill_values(out_4, _e56, _e57);
            return;
        }
        case 3u: {
            uint _e60 = nyq_job.lattice;
            uint _e63 = nyq_job.spp;
            uint _e66 = nyq_job.generator;
            uint2 _e69 = nyq_job.seed;
            const NyqLatticeSampler _e70 = nyq_lattice_sampler(_e60, _e63, _e66, _e69);
            s_3 = _e70;
            const NyqCameraSample _e73 = nyq_lattice_camera_sample(s_3, pixel_19, _e6.z);
            nyq_fill_camera(out_4, _e73);
            nyq_lattice_start(s_3, pixel_19, _e6.z, _e6.w);
            const float _e76 = nyq_lattice_get_1d(s_3);
            const float2 _e77 = nyq_lattice_get_2d(s_3);
            nyq_fill_values(out_4, _e76, _e77);
            return;
        }
        case 4u: {
            uint _e81 = nyq_job.resolution.x;
            uint _e85 = nyq_job.resolution.y;
            uint _e88 = nyq_job.scramble;
            uint2 _e91 = nyq_job.seed;
            const NyqStratifiedSampler _e92 = nyq_stratified_sampler(_e81, _e85, _e88, _e91);
            s_4 = _e92;
            const NyqCameraSample _e95 = nyq_stratified_camera_sample(s_4, pixel_19, _e6.z);
            nyq_fill_camera(out_4, _e95);
            nyq_stratified_start(s_4, pixel_19, _e6.z, _e6.w);
            const float _e98 = nyq_stratified_get_1d(s_4);
            const float2 _e99 = nyq_stratified_get_2d(s_4);
            nyq_fill_values(out_4, _e98, _e99);
            return;
        }
        case 5u: {
            uint2 _e102 = nyq_job.seed;
            const NyqPmj02Sampler _e103 = nyq_pmj02_sampler(_e102);
            s_5 = _e103;
            const NyqCameraSample _e106 = nyq_pmj02_camera_sample(s_5, pixel_19, _e6.z);
            nyq_fill_camera(out_4, _e106);
            nyq_pmj02_start(s_5, pixel_19, _e6.z, _e6.w);
            const float _e109 = nyq_pmj02_get_1d(s_5);
            const float2 _e110 = nyq_pmj02_get_2d(s_5);
            nyq_fill_values(out_4, _e109, _e110);
            return;
        }
        case 6u: {
            uint2 _e113 = nyq_job.resolution;
            uint _e116 = nyq_job.spp;
            uint _e119 = nyq_job.scramble;
            uint2 _e122 = nyq_job.seed;
            const NyqSobolSampler _e123 = nyq_sobol_sampler(_e113, _e116, _e119, _e122);
            s_6 = _e123;
            const NyqCameraSample _e126 = nyq_sobol_sampler_camera_sample(s_6, pixel_19, _e6.z);
            nyq_fill_camera(out_4, _e126);
            nyq_sobol_sampler_start(s_6, pixel_19, _e6.z, _e6.w);
            const float _e129 = nyq_sobol_sampler_get_1d(s_6);
            const float2 _e130 = nyq_sobol_sampler_get_2d(s_6);
            nyq_fill_values(out_4, _e129, _e130);
            return;
        }
        case 16u: {
            uint _e133 = nyq_job.dims;
            uint _e136 = nyq_job.scramble;
            uint2 _e141 = nyq_job.seed;
            const NyqSobol _e142 = nyq_sobol(_e133, (_e136 != 0u), _e141);
            uint2 loop_bound_22 = uint2(4294967295u, 4294967295u);
            bool loop_init_17 = true;
            while(true) {
                if (all(loop_bound_22 == uint2(0u, 0u))) { break; }
                loop_bound_22 -= uint2(loop_bound_22.y == 0u, 1u);
                if (!loop_init_17) {
                    uint _e170 = k;
                    k = (_e170 + 1u);
                }
                loop_init_17 = false;
                uint _e145 = k;
                if ((_e145 < 4u)) {
                } else {
                    break;
                }
                {
                    uint _e149 = k;
                    uint _e154 = k;
                    const uint _e156 = nyq_sobol_sample_u32_(_e142, _e6.z, (_e6.w + _e154));
                    nyq_values.Store((out_4 + _e149)*4, asuint(_e156));
                    uint _e160 = k;
                    uint _e165 = k;
                    const float _e167 = nyq_sobol_sample(_e142, _e6.z, (_e6.w + _e165));
                    nyq_values.Store(((out_4 + 4u) + _e160)*4, asuint(asuint(_e167)));
                }
            }
            return;
        }
        case 17u: {
            uint _e174 = nyq_job.dims;
            uint2 _e177 = nyq_job.seed;
            const NyqOwenSobol _e178 = nyq_owen_sobol(_e174, _e177);
            const float4 _e181 = nyq_owen_sobol_sample_4d(_e178, _e6.z, _e6.w);
            uint2 loop_bound_23 = uint2(4294967295u, 4294967295u);
            bool loop_init_18 = true;
            while(true) {
                if (all(loop_bound_23 == uint2(0u, 0u))) { break; }
                loop_bound_23 -= uint2(loop_bound_23.y == 0u, 1u);
                if (!loop_init_18) {
                    uint _e206 = k_1;
                    k_1 = (_e206 + 1u);
                }
                loop_init_18 = false;
                uint _e184 = k_1;
                if ((_e184 < 4u)) {
                } else {
                    break;
                }
                {
                    uint _e188 = k_1;
                    uint _e193 = k_1;
                    const uint _e195 = nyq_owen_sobol_sample_u32_(_e178, _e6.z, (_e6.w + _e193));
                    nyq_values.Store((out_4 + _e188)*4, asuint(_e195));
                    uint _e199 = k_1;
                    uint _e202 = k_1;
                    nyq_values.Store(((out_4 + 4u) + _e199)*4, asuint(asuint(_e181[min(uint(_e202), 3u)])));
                }
            }
            return;
        }
        case 18u: {
            uint _e210 = nyq_job.scramble;
            uint2 _e215 = nyq_job.seed;
            const NyqPmj02_ _e216 = nyq_pmj02_((_e210 != 0u), _e215);
            uint2 loop_bound_24 = uint2(4294967295u, 4294967295u);
            bool loop_init_19 = true;
            while(true) {
                if (all(loop_bound_24 == uint2(0u, 0u))) { break; }
                loop_bound_24 -= uint2(loop_bound_24.y == 0u, 1u);
                if (!loop_init_19) {
                    uint _e244 = k_2;
                    k_2 = (_e244 + 1u);
                }
                loop_init_19 = false;
                uint _e219 = k_2;
                if ((_e219 < 4u)) {
                } else {
                    break;
                }
                {
                    uint _e223 = k_2;
                    uint _e228 = k_2;
                    const uint _e230 = nyq_pmj02_sample_u32_(_e216, _e6.z, (_e6.w + _e228));
                    nyq_values.Store((out_4 + _e223)*4, asuint(_e230));
                    uint _e234 = k_2;
                    uint _e239 = k_2;
                    const float _e241 = nyq_pmj02_sample(_e216, _e6.z, (_e6.w + _e239));
                    nyq_values.Store(((out_4 + 4u) + _e234)*4, asuint(asuint(_e241)));
                }
            }
            return;
        }
        default: {
            uint2 loop_bound_25 = uint2(4294967295u, 4294967295u);
            bool loop_init_20 = true;
            while(true) {
                if (all(loop_bound_25 == uint2(0u, 0u))) { break; }
                loop_bound_25 -= uint2(loop_bound_25.y == 0u, 1u);
                if (!loop_init_20) {
                    uint _e257 = k_3;
                    k_3 = (_e257 + 1u);
                }
                loop_init_20 = false;
                uint _e248 = k_3;
                if ((_e248 < 8u)) {
                } else {
                    break;
                }
                {
                    uint _e252 = k_3;
                    nyq_values.Store((out_4 + _e252)*4, asuint(4294967295u));
                }
            }
            return;
        }
    }
}

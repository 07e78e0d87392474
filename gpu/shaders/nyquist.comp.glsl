#version 450 core
#extension GL_ARB_compute_shader : require
#extension GL_ARB_shader_storage_buffer_object : require
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct NyqCameraSample {
    vec2 p_film;
    vec2 lens;
    float time;
};
struct NyqSobol {
    uint dims;
    uint scrambled;
    uvec2 seed;
};
struct NyqOwenSobol {
    uint dims;
    uint shuffle_seed;
    uint key;
};
struct NyqOwenSobolSampler {
    uvec2 seed;
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
    uvec2 seed;
    uint digits;
    uint sample_digits;
    uint odd;
    uint morton;
    uint dim;
};
struct NyqPcg32_ {
    uvec2 state;
};
struct NyqRandomSampler {
    uvec2 seed;
    uvec2 base;
    NyqPcg32_ rng;
    uint dim;
};
struct NyqLatticeSampler {
    uint lattice;
    uint n;
    uint g;
    uvec2 seed;
    uvec2 pixel;
    uint index;
    uint dim;
};
struct NyqFillJob {
    uint kind;
    uint scramble;
    uint spp;
    uint frame;
    uvec2 seed;
    uvec2 resolution;
    uint dims;
    uint implicit;
    uint first;
    uint count;
    uint lattice;
    uint generator;
    uint pad0_;
    uint pad1_;
};
const uint NYQ_SCRAMBLE_NONE = 0u;
const uint NYQ_SCRAMBLE_PERMUTE_DIGITS = 1u;
const uint NYQ_SCRAMBLE_FAST_OWEN = 2u;
const uint NYQ_SCRAMBLE_OWEN = 3u;
const uint NYQ_SOBOL_DIMS = 1024u;
const uint NYQ_PERMUTATIONS_4_[24] = uint[24](228u, 180u, 216u, 120u, 156u, 108u, 225u, 177u, 201u, 57u, 141u, 45u, 210u, 114u, 198u, 54u, 78u, 30u, 147u, 99u, 135u, 39u, 75u, 27u);
const uvec2 NYQ_PCG_MULTIPLIER = uvec2(1284865837u, 1481765933u);
const uvec2 NYQ_RANDOM_INCREMENT = uvec2(2665069115u, 1250683170u);
const uint NYQ_LATTICE_FIBONACCI = 0u;
const uint NYQ_LATTICE_KOROBOV = 1u;
const uint NYQ_LATTICE_R2_ = 2u;
const uvec2 NYQ_R2_ALPHA[2] = uvec2[2](uvec2(44445696u, 3242174889u), uvec2(3349051392u, 2447445413u));
const uint NYQ_FILL_OWEN_SOBOL_SAMPLER = 0u;
const uint NYQ_FILL_ZSOBOL_SAMPLER = 1u;
const uint NYQ_FILL_RANDOM_SAMPLER = 2u;
const uint NYQ_FILL_LATTICE_SAMPLER = 3u;
const uint NYQ_FILL_SOBOL = 16u;
const uint NYQ_FILL_OWEN_SOBOL = 17u;

layout(std430, binding = 0) readonly buffer type_4_block_0Compute { uint _group_0_binding_0_cs[]; };

layout(std140, binding = 1) uniform NyqFillJob_block_1Compute { NyqFillJob _group_0_binding_1_cs; };

layout(std430, binding = 2) readonly buffer type_16_block_2Compute { uvec4 _group_0_binding_2_cs[]; };

layout(std430, binding = 3) buffer type_4_block_3Compute { uint _group_0_binding_3_cs[]; };


uvec2 nyq_mul_wide(uint a, uint b) {
    uint a0_ = (a & 65535u);
    uint a1_ = (a >> 16u);
    uint b0_ = (b & 65535u);
    uint b1_ = (b >> 16u);
    uint p00_ = (a0_ * b0_);
    uint p01_ = (a0_ * b1_);
    uint p10_ = (a1_ * b0_);
    uint p11_ = (a1_ * b1_);
    uint mid = (((p00_ >> 16u) + (p01_ & 65535u)) + (p10_ & 65535u));
    return uvec2(((p00_ & 65535u) | (mid << 16u)), (((p11_ + (p01_ >> 16u)) + (p10_ >> 16u)) + (mid >> 16u)));
}

uvec2 nyq_mul64_(uvec2 a_1, uvec2 b_1) {
    uvec2 _e4 = nyq_mul_wide(a_1.x, b_1.x);
    return uvec2(_e4.x, ((_e4.y + (a_1.x * b_1.y)) + (a_1.y * b_1.x)));
}

uvec2 nyq_add64_(uvec2 a_2, uvec2 b_2) {
    uint low = (a_2.x + b_2.x);
    return uvec2(low, ((a_2.y + b_2.y) + ((low < a_2.x) ? 1u : 0u)));
}

uvec2 nyq_shr64_(uvec2 a_3, uint s_4) {
    return uvec2(((a_3.x >> s_4) | (a_3.y << (32u - s_4))), (a_3.y >> s_4));
}

uvec2 nyq_shl64_(uvec2 a_4, uint s_5) {
    return uvec2((a_4.x << s_5), ((a_4.y << s_5) | (a_4.x >> (32u - s_5))));
}

uvec2 nyq_u64_(uint x) {
    return uvec2(x, 0u);
}

uint nyq_mix32_(uint x_in) {
    uint x_1 = 0u;
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

uvec2 nyq_mix64_(uvec2 x_in_1) {
    uvec2 x_2 = uvec2(0u);
    x_2 = x_in_1;
    uvec2 _e2 = x_2;
    uvec2 _e3 = x_2;
    uvec2 _e5 = nyq_shr64_(_e3, 30u);
    x_2 = (_e2 ^ _e5);
    uvec2 _e7 = x_2;
    uvec2 _e11 = nyq_mul64_(_e7, uvec2(484763065u, 3210233709u));
    x_2 = _e11;
    uvec2 _e12 = x_2;
    uvec2 _e13 = x_2;
    uvec2 _e15 = nyq_shr64_(_e13, 27u);
    x_2 = (_e12 ^ _e15);
    uvec2 _e17 = x_2;
    uvec2 _e21 = nyq_mul64_(_e17, uvec2(321982955u, 2496678331u));
    x_2 = _e21;
    uvec2 _e22 = x_2;
    uvec2 _e23 = x_2;
    uvec2 _e25 = nyq_shr64_(_e23, 31u);
    return (_e22 ^ _e25);
}

uvec2 nyq_hash2_(uvec2 a_5, uvec2 b_3) {
    uvec2 golden = uvec2(2135587861u, 2654435769u);
    uvec2 golden2_ = uvec2(4271175722u, 1013904242u);
    uvec2 _e8 = nyq_add64_(a_5, golden);
    uvec2 _e9 = nyq_mix64_(_e8);
    uvec2 _e10 = nyq_add64_(b_3, golden2_);
    uvec2 _e12 = nyq_mix64_((_e9 ^ _e10));
    return _e12;
}

uvec2 nyq_hash4_(uvec2 a_6, uvec2 b_4, uvec2 c, uvec2 d) {
    uvec2 golden_1 = uvec2(2135587861u, 2654435769u);
    uvec2 _e7 = nyq_hash2_(golden_1, a_6);
    uvec2 _e8 = nyq_hash2_(_e7, b_4);
    uvec2 _e9 = nyq_hash2_(_e8, c);
    uvec2 _e10 = nyq_hash2_(_e9, d);
    return _e10;
}

float nyq_fraction_to_f32_(uint v) {
    return (float((v >> 8u)) * 5.9604645e-8);
}

float nyq_rev_to_f32_(uint w_rev) {
    float _e2 = nyq_fraction_to_f32_(bitfieldReverse(w_rev));
    return _e2;
}

uint nyq_shr(uint x_3, uint s_6) {
    return ((s_6 >= 32u) ? 0u : (x_3 >> (s_6 & 31u)));
}

float nyq_film_coordinate(uint pixel, float offset) {
    float base_1 = float(pixel);
    float x_11 = (base_1 + offset);
    float edge = (base_1 + 1.0);
    if ((x_11 < edge)) {
        return x_11;
    }
    float below = uintBitsToFloat((floatBitsToUint(edge) - 1u));
    return ((below >= base_1) ? below : base_1);
}

uint nyq_lk_hash(uint x_rev, uint seed) {
    uint x_4 = 0u;
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

uint nyq_fast_owen_scramble(uint x_5, uint seed_1) {
    uint _e5 = nyq_mix32_((seed_1 ^ 1779033703u));
    uint _e6 = nyq_lk_hash(bitfieldReverse(x_5), _e5);
    return bitfieldReverse(_e6);
}

uint nyq_nested_uniform_shuffle(uint index, uint seed_2) {
    uint _e2 = nyq_fast_owen_scramble(index, seed_2);
    return _e2;
}

uint nyq_owen_scramble(uint x_6, uint seed_3) {
    uint out_ = 0u;
    uint k_3 = 0u;
    uint _e4 = nyq_mix32_((seed_3 ^ 3144134277u));
    out_ = x_6;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e41 = k_3;
            k_3 = (_e41 + 1u);
        }
        loop_init = false;
        uint _e8 = k_3;
        if ((_e8 < 32u)) {
        } else {
            break;
        }
        {
            uint _e12 = k_3;
            uint _e18 = k_3;
            uint prefix = ((_e18 == 0u) ? 0u : (x_6 >> ((32u - _e12) & 31u)));
            uint _e23 = k_3;
            uvec2 word = uvec2(((1u << _e23) | prefix), _e4);
            uvec2 _e27 = nyq_mix64_(word);
            if (((_e27.y >> 31u) == 1u)) {
                uint _e33 = out_;
                uint _e36 = k_3;
                out_ = (_e33 ^ (1u << (31u - _e36)));
            }
        }
    }
    uint _e43 = out_;
    return _e43;
}

uint nyq_scramble_u32_(uint x_7, uint seed_4, uint how) {
    switch(how) {
        case 1u: {
            uint _e5 = nyq_mix32_((seed_4 ^ 1013904242u));
            return (x_7 ^ _e5);
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

uint nyq_sobol_u32_(uint index_1, uint dim) {
    uint v_1 = 0u;
    uint bits = 0u;
    uint base_2 = ((dim % NYQ_SOBOL_DIMS) * 32u);
    bits = index_1;
    while(true) {
        uint _e9 = bits;
        if ((_e9 != 0u)) {
        } else {
            break;
        }
        {
            uint _e12 = v_1;
            uint _e14 = bits;
            uint _e18 = _group_0_binding_0_cs[(base_2 + min(uint(findLSB(_e14)), 32u))];
            v_1 = (_e12 ^ _e18);
            uint _e20 = bits;
            uint _e21 = bits;
            bits = (_e20 & (_e21 - 1u));
        }
    }
    uint _e25 = v_1;
    return _e25;
}

uint nyq_sobol_rev(uint r, uint dim_1) {
    uint _e3 = nyq_sobol_u32_(bitfieldReverse(r), dim_1);
    return bitfieldReverse(_e3);
}

NyqSobol nyq_sobol(uint dims, bool scrambled, uvec2 seed_5) {
    return NyqSobol(dims, (scrambled ? 1u : 0u), seed_5);
}

uint nyq_sobol_sample_u32_(NyqSobol s_7, uint index_2, uint dim_2) {
    uint shift = 0u;
    uint d_3 = (dim_2 % s_7.dims);
    if ((s_7.scrambled != 0u)) {
        uvec2 _e11 = nyq_u64_(d_3);
        uvec2 _e12 = nyq_hash2_(s_7.seed, _e11);
        shift = _e12.y;
    }
    uint _e14 = nyq_sobol_u32_(index_2, d_3);
    uint _e15 = shift;
    return (_e14 ^ _e15);
}

float nyq_sobol_sample(NyqSobol s_8, uint index_3, uint dim_3) {
    uint _e3 = nyq_sobol_sample_u32_(s_8, index_3, dim_3);
    float _e4 = nyq_fraction_to_f32_(_e3);
    return _e4;
}

uint nyq_dim_seed(uint key, uint dim_4) {
    uint _e5 = nyq_mix32_((key ^ (dim_4 * 2654435769u)));
    return _e5;
}

uint nyq_shuffle_rev(uint index_4, uint shuffle_seed) {
    uint _e3 = nyq_lk_hash(0u, shuffle_seed);
    uint fix = (_e3 & 65535u);
    uint _e7 = nyq_lk_hash(bitfieldReverse(index_4), shuffle_seed);
    return (_e7 ^ fix);
}

uint nyq_owen_sobol_rev(uint r_1, uint dim_5, uint dim_seed) {
    uint _e5 = nyq_sobol_rev(r_1, (dim_5 % NYQ_SOBOL_DIMS));
    uint _e6 = nyq_lk_hash(_e5, dim_seed);
    return _e6;
}

NyqOwenSobol nyq_owen_sobol(uint dims_1, uvec2 seed_6) {
    uvec2 _e3 = nyq_u64_(1331119438u);
    uvec2 _e4 = nyq_hash2_(seed_6, _e3);
    uint _e6 = nyq_mix32_(_e4.y);
    return NyqOwenSobol(dims_1, _e6, _e4.x);
}

uint nyq_owen_sobol_sample_u32_(NyqOwenSobol s_9, uint index_5, uint dim_6) {
    uint d_4 = (dim_6 % s_9.dims);
    uint _e6 = nyq_shuffle_rev(index_5, s_9.shuffle_seed);
    uint _e8 = nyq_dim_seed(s_9.key, d_4);
    uint _e9 = nyq_owen_sobol_rev(_e6, d_4, _e8);
    return bitfieldReverse(_e9);
}

float nyq_owen_sobol_sample(NyqOwenSobol s_10, uint index_6, uint dim_7) {
    uint _e3 = nyq_owen_sobol_sample_u32_(s_10, index_6, dim_7);
    float _e4 = nyq_fraction_to_f32_(_e3);
    return _e4;
}

vec4 nyq_owen_sobol_sample_4d(NyqOwenSobol s_11, uint index_7, uint first_dim) {
    vec4 out_1 = vec4(0.0);
    uint k_4 = 0u;
    uint _e4 = nyq_shuffle_rev(index_7, s_11.shuffle_seed);
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e22 = k_4;
            k_4 = (_e22 + 1u);
        }
        loop_init_1 = false;
        uint _e8 = k_4;
        if ((_e8 < 4u)) {
        } else {
            break;
        }
        {
            uint _e11 = k_4;
            uint d_5 = ((first_dim + _e11) % s_11.dims);
            uint _e15 = k_4;
            uint _e18 = nyq_dim_seed(s_11.key, d_5);
            uint _e19 = nyq_owen_sobol_rev(_e4, d_5, _e18);
            float _e20 = nyq_rev_to_f32_(_e19);
            out_1[_e15] = _e20;
        }
    }
    vec4 _e24 = out_1;
    return _e24;
}

NyqOwenSobolSampler nyq_owen_sobol_sampler(uvec2 seed_7, uint frame) {
    return NyqOwenSobolSampler(seed_7, frame, 0u, 0u, 0u);
}

void nyq_owen_sobol_start(inout NyqOwenSobolSampler s_12, uvec2 pixel_1, uint sample_index, uint dim_8) {
    uvec2 _e5 = nyq_u64_(pixel_1.x);
    uvec2 _e7 = nyq_u64_(pixel_1.y);
    uint _e9 = s_12.frame;
    uvec2 _e10 = nyq_u64_(_e9);
    uvec2 _e12 = s_12.seed;
    uvec2 _e13 = nyq_hash4_(_e5, _e7, _e10, _e12);
    s_12.key = _e13.x;
    uint _e18 = nyq_mix32_(_e13.y);
    uint _e19 = nyq_shuffle_rev(sample_index, _e18);
    s_12.r = _e19;
    s_12.dim = dim_8;
    return;
}

float nyq_owen_sobol_value(inout NyqOwenSobolSampler s_13, uint dim_9) {
    uint _e3 = s_13.r;
    uint _e5 = s_13.key;
    uint _e6 = nyq_dim_seed(_e5, dim_9);
    uint _e7 = nyq_owen_sobol_rev(_e3, dim_9, _e6);
    float _e8 = nyq_rev_to_f32_(_e7);
    return _e8;
}

float nyq_owen_sobol_get_1d(inout NyqOwenSobolSampler s_14) {
    uint d_6 = s_14.dim;
    s_14.dim = (d_6 + 1u);
    float _e6 = nyq_owen_sobol_value(s_14, d_6);
    return _e6;
}

vec2 nyq_owen_sobol_get_2d(inout NyqOwenSobolSampler s_15) {
    uint d_7 = s_15.dim;
    s_15.dim = (d_7 + 2u);
    float _e6 = nyq_owen_sobol_value(s_15, d_7);
    float _e9 = nyq_owen_sobol_value(s_15, (d_7 + 1u));
    return vec2(_e6, _e9);
}

vec2 nyq_owen_sobol_get_pixel_2d(inout NyqOwenSobolSampler s_16) {
    uint _e3 = s_16.dim;
    s_16.dim = max(_e3, 2u);
    float _e7 = nyq_owen_sobol_value(s_16, 0u);
    float _e9 = nyq_owen_sobol_value(s_16, 1u);
    return vec2(_e7, _e9);
}

NyqCameraSample nyq_owen_sobol_camera_sample(inout NyqOwenSobolSampler s_17, uvec2 pixel_2, uint sample_index_1) {
    float v_2[5] = float[5](0.0, 0.0, 0.0, 0.0, 0.0);
    uint d_1 = 0u;
    nyq_owen_sobol_start(s_17, pixel_2, sample_index_1, 0u);
    bool loop_init_2 = true;
    while(true) {
        if (!loop_init_2) {
            uint _e15 = d_1;
            d_1 = (_e15 + 1u);
        }
        loop_init_2 = false;
        uint _e7 = d_1;
        if ((_e7 < 5u)) {
        } else {
            break;
        }
        {
            uint _e10 = d_1;
            uint _e12 = d_1;
            float _e13 = nyq_owen_sobol_value(s_17, _e12);
            v_2[_e10] = _e13;
        }
    }
    s_17.dim = 5u;
    float _e21 = v_2[0];
    float _e22 = nyq_film_coordinate(pixel_2.x, _e21);
    float _e25 = v_2[1];
    float _e26 = nyq_film_coordinate(pixel_2.y, _e25);
    vec2 p = vec2(_e22, _e26);
    float _e29 = v_2[3];
    float _e31 = v_2[4];
    float _e34 = v_2[2];
    return NyqCameraSample(p, vec2(_e29, _e31), _e34);
}

NyqZSobolSampler nyq_zsobol_sampler(uvec2 resolution, uint spp_requested, uint scramble, uvec2 seed_8) {
    uint spp = ((spp_requested <= 1u) ? 1u : (1u << (32u - uint(31 - findMSB((spp_requested - 1u))))));
    uint side = max(resolution.x, resolution.y);
    uint log2_res = (32u - uint(31 - findMSB((side - 1u))));
    uint log2_spp = min(uint(findLSB(spp)), 32u);
    uint bits_1 = ((2u * log2_res) + log2_spp);
    return NyqZSobolSampler(spp, log2_spp, log2_res, scramble, seed_8, (bits_1 / 2u), (log2_spp / 2u), (log2_spp & 1u), 0u, 0u);
}

uint nyq_spread(uint x_in_2) {
    uint x_8 = 0u;
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

uint nyq_zsobol_morton(NyqZSobolSampler s_18, uvec2 pixel_3) {
    uint mask = ((s_18.log2_res == 0u) ? 0u : (4294967295u >> ((32u - s_18.log2_res) & 31u)));
    uint _e16 = nyq_spread((pixel_3.x & mask));
    uint _e19 = nyq_spread((pixel_3.y & mask));
    return (_e16 | (_e19 << 1u));
}

uint nyq_one_of_24_(uint h) {
    uvec2 _e2 = nyq_mul_wide(h, 24u);
    return _e2.y;
}

uvec2 nyq_zsobol_dim_key(uvec2 seed_9, uint dim_10) {
    uvec2 _e6 = nyq_hash2_(seed_9, uvec2((dim_10 ^ 1329745740u), 23123u));
    return _e6;
}

uint nyq_zsobol_pixel_node(uint higher, uvec2 key_1) {
    uvec2 _e4 = nyq_shr64_(key_1, 16u);
    uint _e7 = nyq_mix32_((higher ^ _e4.x));
    uint _e8 = nyq_one_of_24_(_e7);
    return NYQ_PERMUTATIONS_4_[_e8];
}

uint nyq_permuted_digit(uint perm, uint digit, uint shift_1) {
    return (((perm >> (2u * digit)) & 3u) << shift_1);
}

uvec2 nyq_zsobol_pixel_word(uint pixel_morton, uvec2 key_2) {
    uvec2 _e3 = nyq_shl64_(key_2, 17u);
    uvec2 rotated = (_e3 | uvec2((key_2.y >> 15u), 0u));
    uvec2 _e10 = nyq_u64_(pixel_morton);
    uvec2 _e12 = nyq_mix64_((_e10 ^ rotated));
    return _e12;
}

uvec2 nyq_zsobol_nested_word(uvec2 w, uint higher_1, uint shift_2) {
    uvec2 tag = uvec2(((higher_1 << 6u) | shift_2), (higher_1 >> 26u));
    uvec2 _e12 = nyq_mul64_(tag, uvec2(2135587861u, 2654435769u));
    uvec2 _e17 = nyq_mul64_((w ^ _e12), uvec2(3516067075u, 3518319154u));
    return _e17;
}

uint nyq_zsobol_index(NyqZSobolSampler s_19, uint morton, uvec2 key_3) {
    uint index_8 = 0u;
    uint i = 0u;
    uint i_1 = 0u;
    i = s_19.digits;
    bool loop_init_3 = true;
    while(true) {
        if (!loop_init_3) {
            uint _e28 = i;
            i = (_e28 - 1u);
        }
        loop_init_3 = false;
        uint _e7 = i;
        if ((_e7 > s_19.sample_digits)) {
        } else {
            break;
        }
        {
            uint _e11 = i;
            uint shift_3 = ((2u * (_e11 - 1u)) + s_19.odd);
            uint digit_1 = ((morton >> shift_3) & 3u);
            uint _e20 = index_8;
            uint _e23 = nyq_shr(morton, (shift_3 + 2u));
            uint _e24 = nyq_zsobol_pixel_node(_e23, key_3);
            uint _e25 = nyq_permuted_digit(_e24, digit_1, shift_3);
            index_8 = (_e20 | _e25);
        }
    }
    uint _e31 = nyq_shr(morton, s_19.log2_spp);
    uvec2 _e32 = nyq_zsobol_pixel_word(_e31, key_3);
    uint sample_ = (morton & (s_19.spp - 1u));
    i_1 = s_19.sample_digits;
    bool loop_init_4 = true;
    while(true) {
        if (!loop_init_4) {
            uint _e64 = i_1;
            i_1 = (_e64 - 1u);
        }
        loop_init_4 = false;
        uint _e39 = i_1;
        if ((_e39 > 0u)) {
        } else {
            break;
        }
        {
            uint _e43 = i_1;
            uint shift_4 = ((2u * (_e43 - 1u)) + s_19.odd);
            uint digit_2 = ((sample_ >> shift_4) & 3u);
            uint _e54 = nyq_shr(sample_, (shift_4 + 2u));
            uvec2 _e55 = nyq_zsobol_nested_word(_e32, _e54, shift_4);
            uint _e57 = nyq_one_of_24_(_e55.y);
            uint _e58 = index_8;
            uint _e61 = nyq_permuted_digit(NYQ_PERMUTATIONS_4_[_e57], digit_2, shift_4);
            index_8 = (_e58 | _e61);
        }
    }
    if ((s_19.odd == 1u)) {
        uint _e69 = index_8;
        uvec2 _e75 = nyq_zsobol_nested_word(_e32, (sample_ >> 1u), 0u);
        index_8 = (_e69 | ((sample_ & 1u) ^ (_e75.y >> 31u)));
    }
    uint _e81 = index_8;
    return _e81;
}

uint nyq_zsobol_sequence_index(NyqZSobolSampler s_20, uvec2 pixel_4, uint sample_index_2, uint dim_11) {
    uint _e4 = nyq_zsobol_morton(s_20, pixel_4);
    uint morton_1 = ((_e4 << s_20.log2_spp) | (sample_index_2 & (s_20.spp - 1u)));
    uvec2 _e13 = nyq_zsobol_dim_key(s_20.seed, dim_11);
    uint _e14 = nyq_zsobol_index(s_20, morton_1, _e13);
    return _e14;
}

uint nyq_zsobol_dim0_(uint index_9, uint seed_10, uint how_1) {
    if ((how_1 == NYQ_SCRAMBLE_FAST_OWEN)) {
        uint _e5 = nyq_lk_hash(index_9, seed_10);
        return bitfieldReverse(_e5);
    }
    uint _e8 = nyq_scramble_u32_(bitfieldReverse(index_9), seed_10, how_1);
    return _e8;
}

float nyq_zsobol_value_1d(inout NyqZSobolSampler s_21, uint dim_12) {
    uvec2 _e3 = s_21.seed;
    uvec2 _e4 = nyq_zsobol_dim_key(_e3, dim_12);
    NyqZSobolSampler _e5 = s_21;
    uint _e7 = s_21.morton;
    uint _e8 = nyq_zsobol_index(_e5, _e7, _e4);
    uint _e11 = s_21.scramble;
    uint _e12 = nyq_zsobol_dim0_(_e8, _e4.x, _e11);
    float _e13 = nyq_fraction_to_f32_(_e12);
    return _e13;
}

vec2 nyq_zsobol_value_2d(inout NyqZSobolSampler s_22, uint dim_13) {
    uint y = 0u;
    uvec2 _e3 = s_22.seed;
    uvec2 _e4 = nyq_zsobol_dim_key(_e3, dim_13);
    NyqZSobolSampler _e5 = s_22;
    uint _e7 = s_22.morton;
    uint _e8 = nyq_zsobol_index(_e5, _e7, _e4);
    uint _e11 = s_22.scramble;
    uint _e12 = nyq_zsobol_dim0_(_e8, _e4.x, _e11);
    uint _e15 = s_22.scramble;
    if ((_e15 == NYQ_SCRAMBLE_FAST_OWEN)) {
        uint _e19 = nyq_sobol_u32_(_e8, 1u);
        uint _e22 = nyq_lk_hash(bitfieldReverse(_e19), _e4.y);
        y = bitfieldReverse(_e22);
    } else {
        uint _e25 = nyq_sobol_u32_(_e8, 1u);
        uint _e28 = s_22.scramble;
        uint _e29 = nyq_scramble_u32_(_e25, _e4.y, _e28);
        y = _e29;
    }
    float _e30 = nyq_fraction_to_f32_(_e12);
    uint _e31 = y;
    float _e32 = nyq_fraction_to_f32_(_e31);
    return vec2(_e30, _e32);
}

void nyq_zsobol_start(inout NyqZSobolSampler s_23, uvec2 pixel_5, uint sample_index_3, uint dim_14) {
    NyqZSobolSampler _e5 = s_23;
    uint _e6 = nyq_zsobol_morton(_e5, pixel_5);
    uint _e8 = s_23.log2_spp;
    uint _e11 = s_23.spp;
    s_23.morton = ((_e6 << _e8) | (sample_index_3 & (_e11 - 1u)));
    s_23.dim = dim_14;
    return;
}

float nyq_zsobol_get_1d(inout NyqZSobolSampler s_24) {
    uint d_8 = s_24.dim;
    s_24.dim = (d_8 + 1u);
    float _e6 = nyq_zsobol_value_1d(s_24, d_8);
    return _e6;
}

vec2 nyq_zsobol_get_2d(inout NyqZSobolSampler s_25) {
    uint d_9 = s_25.dim;
    s_25.dim = (d_9 + 2u);
    vec2 _e6 = nyq_zsobol_value_2d(s_25, d_9);
    return _e6;
}

vec2 nyq_zsobol_get_pixel_2d(inout NyqZSobolSampler s_26) {
    uint _e3 = s_26.dim;
    s_26.dim = max(_e3, 2u);
    vec2 _e7 = nyq_zsobol_value_2d(s_26, 0u);
    return _e7;
}

NyqCameraSample nyq_zsobol_camera_sample(inout NyqZSobolSampler s_27, uvec2 pixel_6, uint sample_index_4) {
    nyq_zsobol_start(s_27, pixel_6, sample_index_4, 0u);
    vec2 _e5 = nyq_zsobol_value_2d(s_27, 0u);
    float _e7 = nyq_zsobol_value_1d(s_27, 2u);
    vec2 _e9 = nyq_zsobol_value_2d(s_27, 3u);
    s_27.dim = 5u;
    float _e14 = nyq_film_coordinate(pixel_6.x, _e5.x);
    float _e17 = nyq_film_coordinate(pixel_6.y, _e5.y);
    vec2 film = vec2(_e14, _e17);
    return NyqCameraSample(film, _e9, _e7);
}

NyqPcg32_ nyq_pcg32_(uvec2 state) {
    uvec2 _e2 = nyq_add64_(state, NYQ_RANDOM_INCREMENT);
    uvec2 _e4 = nyq_mul64_(_e2, NYQ_PCG_MULTIPLIER);
    uvec2 _e6 = nyq_add64_(_e4, NYQ_RANDOM_INCREMENT);
    return NyqPcg32_(_e6);
}

uint nyq_pcg32_next(inout NyqPcg32_ g) {
    uvec2 old = g.state;
    uvec2 _e5 = nyq_mul64_(old, NYQ_PCG_MULTIPLIER);
    uvec2 _e7 = nyq_add64_(_e5, NYQ_RANDOM_INCREMENT);
    g.state = _e7;
    uvec2 _e9 = nyq_shr64_(old, 18u);
    uvec2 _e12 = nyq_shr64_((_e9 ^ old), 27u);
    uint x_12 = _e12.x;
    uint rot = (old.y >> 27u);
    return ((x_12 >> rot) | (x_12 << ((32u - rot) & 31u)));
}

void nyq_pcg32_advance(inout NyqPcg32_ g_1, uint delta) {
    uvec2 acc_mult = uvec2(1u, 0u);
    uvec2 acc_plus = uvec2(0u, 0u);
    uvec2 cur_mult = NYQ_PCG_MULTIPLIER;
    uvec2 cur_plus = NYQ_RANDOM_INCREMENT;
    uint d_2 = 0u;
    d_2 = delta;
    while(true) {
        uint _e15 = d_2;
        if ((_e15 > 0u)) {
        } else {
            break;
        }
        {
            uint _e18 = d_2;
            if (((_e18 & 1u) != 0u)) {
                uvec2 _e23 = acc_mult;
                uvec2 _e24 = cur_mult;
                uvec2 _e25 = nyq_mul64_(_e23, _e24);
                acc_mult = _e25;
                uvec2 _e26 = acc_plus;
                uvec2 _e27 = cur_mult;
                uvec2 _e28 = nyq_mul64_(_e26, _e27);
                uvec2 _e29 = cur_plus;
                uvec2 _e30 = nyq_add64_(_e28, _e29);
                acc_plus = _e30;
            }
            uvec2 _e31 = cur_mult;
            uvec2 _e35 = nyq_add64_(_e31, uvec2(1u, 0u));
            uvec2 _e36 = cur_plus;
            uvec2 _e37 = nyq_mul64_(_e35, _e36);
            cur_plus = _e37;
            uvec2 _e38 = cur_mult;
            uvec2 _e39 = cur_mult;
            uvec2 _e40 = nyq_mul64_(_e38, _e39);
            cur_mult = _e40;
            uint _e41 = d_2;
            d_2 = (_e41 >> 1u);
        }
    }
    uvec2 _e45 = acc_mult;
    uvec2 _e47 = g_1.state;
    uvec2 _e48 = nyq_mul64_(_e45, _e47);
    uvec2 _e49 = acc_plus;
    uvec2 _e50 = nyq_add64_(_e48, _e49);
    g_1.state = _e50;
    return;
}

float nyq_unit_f32_(uint h_1) {
    return (float((h_1 >> 8u)) * 5.9604645e-8);
}

uvec2 nyq_hash3_(uvec2 a_7, uvec2 b_5, uvec2 c_1) {
    uvec2 _e3 = nyq_hash2_(a_7, b_5);
    uvec2 _e7 = nyq_add64_(c_1, uvec2(2111796287u, 3668340012u));
    uvec2 _e9 = nyq_mix64_((_e3 ^ _e7));
    return _e9;
}

NyqRandomSampler nyq_random_sampler(uvec2 seed_11) {
    return NyqRandomSampler(seed_11, uvec2(0u, 0u), NyqPcg32_(uvec2(0u, 0u)), 0u);
}

NyqPcg32_ nyq_random_at(inout NyqRandomSampler s_28, uint dim_15) {
    NyqPcg32_ g_2 = NyqPcg32_(uvec2(0u));
    uvec2 _e3 = s_28.base;
    NyqPcg32_ _e4 = nyq_pcg32_(_e3);
    g_2 = _e4;
    uint d_10 = (dim_15 & 65535u);
    if ((d_10 != 0u)) {
        nyq_pcg32_advance(g_2, d_10);
    }
    NyqPcg32_ _e10 = g_2;
    return _e10;
}

void nyq_random_start(inout NyqRandomSampler s_29, uvec2 pixel_7, uint sample_index_5, uint dim_16) {
    uvec2 _e5 = s_29.seed;
    uvec2 _e7 = nyq_u64_(1918987876u);
    uvec2 _e8 = nyq_hash3_(pixel_7, _e5, _e7);
    uvec2 golden_2 = uvec2(2135587861u, 2654435769u);
    uvec2 _e13 = nyq_u64_(sample_index_5);
    uvec2 _e14 = nyq_mul64_(_e13, golden_2);
    uvec2 _e16 = nyq_mix64_((_e8 ^ _e14));
    s_29.base = _e16;
    s_29.dim = dim_16;
    NyqPcg32_ _e19 = nyq_random_at(s_29, dim_16);
    s_29.rng = _e19;
    return;
}

float nyq_random_get_1d(inout NyqRandomSampler s_30) {
    NyqPcg32_ g_3 = NyqPcg32_(uvec2(0u));
    NyqPcg32_ _e2 = s_30.rng;
    g_3 = _e2;
    uint _e4 = nyq_pcg32_next(g_3);
    float _e5 = nyq_unit_f32_(_e4);
    NyqPcg32_ _e7 = g_3;
    s_30.rng = _e7;
    uint _e9 = s_30.dim;
    s_30.dim = (_e9 + 1u);
    uint _e13 = s_30.dim;
    if (((_e13 & 65535u) == 0u)) {
        NyqPcg32_ _e20 = nyq_random_at(s_30, 0u);
        s_30.rng = _e20;
    }
    return _e5;
}

vec2 nyq_random_get_2d(inout NyqRandomSampler s_31) {
    float _e1 = nyq_random_get_1d(s_31);
    float _e2 = nyq_random_get_1d(s_31);
    return vec2(_e1, _e2);
}

vec2 nyq_random_get_pixel_2d(inout NyqRandomSampler s_32) {
    NyqPcg32_ g_4 = NyqPcg32_(uvec2(0u));
    uint _e2 = s_32.dim;
    if ((_e2 == 0u)) {
        vec2 _e5 = nyq_random_get_2d(s_32);
        return _e5;
    }
    NyqPcg32_ _e7 = nyq_random_at(s_32, 0u);
    g_4 = _e7;
    uint _e9 = nyq_pcg32_next(g_4);
    float _e10 = nyq_unit_f32_(_e9);
    uint _e11 = nyq_pcg32_next(g_4);
    float _e12 = nyq_unit_f32_(_e11);
    vec2 p_1 = vec2(_e10, _e12);
    uint _e15 = s_32.dim;
    if ((_e15 < 2u)) {
        s_32.dim = 2u;
        NyqPcg32_ _e21 = g_4;
        s_32.rng = _e21;
    }
    return p_1;
}

NyqCameraSample nyq_random_camera_sample(inout NyqRandomSampler s_33, uvec2 pixel_8, uint sample_index_6) {
    nyq_random_start(s_33, pixel_8, sample_index_6, 0u);
    vec2 _e4 = nyq_random_get_pixel_2d(s_33);
    float _e5 = nyq_random_get_1d(s_33);
    vec2 _e6 = nyq_random_get_2d(s_33);
    float _e9 = nyq_film_coordinate(pixel_8.x, _e4.x);
    float _e12 = nyq_film_coordinate(pixel_8.y, _e4.y);
    vec2 film_1 = vec2(_e9, _e12);
    return NyqCameraSample(film_1, _e6, _e5);
}

uint nyq_mod64_(uvec2 x_9, uint n) {
    uint r_2 = 0u;
    uint i_2 = 0u;
    bool local = false;
    bool loop_init_5 = true;
    while(true) {
        if (!loop_init_5) {
            uint _e42 = i_2;
            i_2 = (_e42 + 1u);
        }
        loop_init_5 = false;
        uint _e6 = i_2;
        if ((_e6 < 64u)) {
        } else {
            break;
        }
        {
            uint _e11 = i_2;
            uint word_1 = ((_e11 < 32u) ? x_9.y : x_9.x);
            uint _e16 = i_2;
            uint bit = ((word_1 >> (31u - (_e16 & 31u))) & 1u);
            uint _e23 = r_2;
            uint carry = (_e23 >> 31u);
            uint _e26 = r_2;
            r_2 = ((_e26 << 1u) | bit);
            if (!((carry == 1u))) {
                uint _e35 = r_2;
                local = (_e35 >= n);
            } else {
                local = true;
            }
            bool _e38 = local;
            if (_e38) {
                uint _e39 = r_2;
                r_2 = (_e39 - n);
            }
        }
    }
    uint _e44 = r_2;
    return _e44;
}

uvec2 nyq_fixed_ratio(uint num, uint den) {
    uint r_3 = 0u;
    uvec2 q = uvec2(0u, 0u);
    uint i_3 = 0u;
    bool local_1 = false;
    r_3 = num;
    bool loop_init_6 = true;
    while(true) {
        if (!loop_init_6) {
            uint _e37 = i_3;
            i_3 = (_e37 + 1u);
        }
        loop_init_6 = false;
        uint _e9 = i_3;
        if ((_e9 < 64u)) {
        } else {
            break;
        }
        {
            uint _e12 = r_3;
            uint carry_1 = (_e12 >> 31u);
            uint _e15 = r_3;
            r_3 = (_e15 << 1u);
            uvec2 _e18 = q;
            uvec2 _e20 = nyq_shl64_(_e18, 1u);
            q = _e20;
            if (!((carry_1 == 1u))) {
                uint _e26 = r_3;
                local_1 = (_e26 >= den);
            } else {
                local_1 = true;
            }
            bool _e29 = local_1;
            if (_e29) {
                uint _e30 = r_3;
                r_3 = (_e30 - den);
                uint _e33 = q.x;
                q.x = (_e33 | 1u);
            }
        }
    }
    uvec2 _e39 = q;
    return _e39;
}

float nyq_fixed_to_f32_(uvec2 x_10) {
    return (float((x_10.y >> 8u)) * 5.9604645e-8);
}

NyqLatticeSampler nyq_lattice_sampler(uint lattice, uint n_1, uint g_5, uvec2 seed_12) {
    return NyqLatticeSampler(lattice, n_1, g_5, seed_12, uvec2(0u, 0u), 0u, 0u);
}

float nyq_lattice_value(inout NyqLatticeSampler s_34, uint dim_17) {
    uvec2 base = uvec2(0u);
    uint g_6 = 0u;
    uint n_2 = s_34.n;
    uint _e5 = s_34.index;
    uint k_5 = (_e5 % n_2);
    uint component = (dim_17 % 2u);
    uint _e11 = s_34.lattice;
    switch(_e11) {
        case 2u: {
            uvec2 _e15 = nyq_u64_(k_5);
            uvec2 _e18 = nyq_mul64_(_e15, NYQ_R2_ALPHA[component]);
            uvec2 _e19 = nyq_add64_(uvec2(0u, 2147483648u), _e18);
            base = _e19;
            break;
        }
        default: {
            uint _e21 = s_34.g;
            g_6 = _e21;
            if ((component == 0u)) {
                g_6 = (1u % n_2);
            }
            uint _e27 = g_6;
            uvec2 _e28 = nyq_mul_wide(k_5, _e27);
            uint _e29 = nyq_mod64_(_e28, n_2);
            uvec2 _e30 = nyq_fixed_ratio(_e29, n_2);
            base = _e30;
            break;
        }
    }
    uvec2 _e32 = s_34.pixel;
    uvec2 _e35 = nyq_u64_((dim_17 / 2u));
    uvec2 _e37 = s_34.seed;
    uvec2 _e38 = nyq_hash3_(_e32, _e35, _e37);
    uvec2 _e39 = base;
    uvec2 _e40 = nyq_u64_(component);
    uvec2 _e41 = nyq_hash2_(_e38, _e40);
    uvec2 _e42 = nyq_add64_(_e39, _e41);
    float _e43 = nyq_fixed_to_f32_(_e42);
    return _e43;
}

void nyq_lattice_start(inout NyqLatticeSampler s_35, uvec2 pixel_9, uint sample_index_7, uint dim_18) {
    s_35.pixel = pixel_9;
    s_35.index = sample_index_7;
    s_35.dim = dim_18;
    return;
}

float nyq_lattice_get_1d(inout NyqLatticeSampler s_36) {
    uint d_11 = s_36.dim;
    s_36.dim = (d_11 + 1u);
    float _e6 = nyq_lattice_value(s_36, d_11);
    return _e6;
}

vec2 nyq_lattice_get_2d(inout NyqLatticeSampler s_37) {
    uint d_12 = s_37.dim;
    s_37.dim = (d_12 + 2u);
    float _e6 = nyq_lattice_value(s_37, d_12);
    float _e9 = nyq_lattice_value(s_37, (d_12 + 1u));
    return vec2(_e6, _e9);
}

vec2 nyq_lattice_get_pixel_2d(inout NyqLatticeSampler s_38) {
    uint _e3 = s_38.dim;
    s_38.dim = max(_e3, 2u);
    float _e7 = nyq_lattice_value(s_38, 0u);
    float _e9 = nyq_lattice_value(s_38, 1u);
    return vec2(_e7, _e9);
}

NyqCameraSample nyq_lattice_camera_sample(inout NyqLatticeSampler s_39, uvec2 pixel_10, uint sample_index_8) {
    nyq_lattice_start(s_39, pixel_10, sample_index_8, 0u);
    vec2 _e4 = nyq_lattice_get_pixel_2d(s_39);
    float _e5 = nyq_lattice_get_1d(s_39);
    vec2 _e6 = nyq_lattice_get_2d(s_39);
    float _e9 = nyq_film_coordinate(pixel_10.x, _e4.x);
    float _e12 = nyq_film_coordinate(pixel_10.y, _e4.y);
    vec2 film_2 = vec2(_e9, _e12);
    return NyqCameraSample(film_2, _e6, _e5);
}

uvec4 nyq_fill_request(uint i_4) {
    uint _e3 = _group_0_binding_1_cs.implicit;
    if ((_e3 == 0u)) {
        uvec4 _e8 = _group_0_binding_2_cs[i_4];
        return _e8;
    }
    uint _e11 = _group_0_binding_1_cs.first;
    uint n_3 = (_e11 + i_4);
    uint _e15 = _group_0_binding_1_cs.spp;
    uint pixel_11 = (n_3 / _e15);
    uint _e20 = _group_0_binding_1_cs.resolution.x;
    uint _e25 = _group_0_binding_1_cs.resolution.x;
    uint _e29 = _group_0_binding_1_cs.spp;
    return uvec4((pixel_11 % _e20), (pixel_11 / _e25), (n_3 % _e29), 5u);
}

void nyq_fill_camera(uint out_2, NyqCameraSample c_2) {
    _group_0_binding_3_cs[out_2] = floatBitsToUint(c_2.p_film.x);
    _group_0_binding_3_cs[(out_2 + 1u)] = floatBitsToUint(c_2.p_film.y);
    _group_0_binding_3_cs[(out_2 + 2u)] = floatBitsToUint(c_2.time);
    _group_0_binding_3_cs[(out_2 + 3u)] = floatBitsToUint(c_2.lens.x);
    _group_0_binding_3_cs[(out_2 + 4u)] = floatBitsToUint(c_2.lens.y);
    return;
}

void nyq_fill_values(uint out_3, float one, vec2 two) {
    _group_0_binding_3_cs[(out_3 + 5u)] = floatBitsToUint(one);
    _group_0_binding_3_cs[(out_3 + 6u)] = floatBitsToUint(two.x);
    _group_0_binding_3_cs[(out_3 + 7u)] = floatBitsToUint(two.y);
    return;
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    NyqOwenSobolSampler s = NyqOwenSobolSampler(uvec2(0u), 0u, 0u, 0u, 0u);
    NyqZSobolSampler s_1 = NyqZSobolSampler(0u, 0u, 0u, 0u, uvec2(0u), 0u, 0u, 0u, 0u, 0u);
    NyqRandomSampler s_2 = NyqRandomSampler(uvec2(0u), uvec2(0u), NyqPcg32_(uvec2(0u)), 0u);
    NyqLatticeSampler s_3 = NyqLatticeSampler(0u, 0u, 0u, uvec2(0u), uvec2(0u), 0u, 0u);
    uint k = 0u;
    uint k_1 = 0u;
    uint k_2 = 0u;
    uint i_5 = id.x;
    uint _e4 = _group_0_binding_1_cs.count;
    if ((i_5 >= _e4)) {
        return;
    }
    uvec4 _e6 = nyq_fill_request(i_5);
    uvec2 pixel_12 = _e6.xy;
    uint out_4 = (8u * i_5);
    uint _e12 = _group_0_binding_1_cs.kind;
    switch(_e12) {
        case 0u: {
            uvec2 _e15 = _group_0_binding_1_cs.seed;
            uint _e18 = _group_0_binding_1_cs.frame;
            NyqOwenSobolSampler _e19 = nyq_owen_sobol_sampler(_e15, _e18);
            s = _e19;
            NyqCameraSample _e22 = nyq_owen_sobol_camera_sample(s, pixel_12, _e6.z);
            nyq_fill_camera(out_4, _e22);
            nyq_owen_sobol_start(s, pixel_12, _e6.z, _e6.w);
            float _e25 = nyq_owen_sobol_get_1d(s);
            vec2 _e26 = nyq_owen_sobol_get_2d(s);
            nyq_fill_values(out_4, _e25, _e26);
            return;
        }
        case 1u: {
            uvec2 _e29 = _group_0_binding_1_cs.resolution;
            uint _e32 = _group_0_binding_1_cs.spp;
            uint _e35 = _group_0_binding_1_cs.scramble;
            uvec2 _e38 = _group_0_binding_1_cs.seed;
            NyqZSobolSampler _e39 = nyq_zsobol_sampler(_e29, _e32, _e35, _e38);
            s_1 = _e39;
            NyqCameraSample _e42 = nyq_zsobol_camera_sample(s_1, pixel_12, _e6.z);
            nyq_fill_camera(out_4, _e42);
            nyq_zsobol_start(s_1, pixel_12, _e6.z, _e6.w);
            float _e45 = nyq_zsobol_get_1d(s_1);
            vec2 _e46 = nyq_zsobol_get_2d(s_1);
            nyq_fill_values(out_4, _e45, _e46);
            return;
        }
        case 2u: {
            uvec2 _e49 = _group_0_binding_1_cs.seed;
            NyqRandomSampler _e50 = nyq_random_sampler(_e49);
            s_2 = _e50;
            NyqCameraSample _e53 = nyq_random_camera_sample(s_2, pixel_12, _e6.z);
            nyq_fill_camera(out_4, _e53);
            nyq_random_start(s_2, pixel_12, _e6.z, _e6.w);
            float _e56 = nyq_random_get_1d(s_2);
            vec2 _e57 = nyq_random_get_2d(s_2);
            nyq_fill_values(out_4, _e56, _e57);
            return;
        }
        case 3u: {
            uint _e60 = _group_0_binding_1_cs.lattice;
            uint _e63 = _group_0_binding_1_cs.spp;
            uint _e66 = _group_0_binding_1_cs.generator;
            uvec2 _e69 = _group_0_binding_1_cs.seed;
            NyqLatticeSampler _e70 = nyq_lattice_sampler(_e60, _e63, _e66, _e69);
            s_3 = _e70;
            NyqCameraSample _e73 = nyq_lattice_camera_sample(s_3, pixel_12, _e6.z);
            nyq_fill_camera(out_4, _e73);
            nyq_lattice_start(s_3, pixel_12, _e6.z, _e6.w);
            float _e76 = nyq_lattice_get_1d(s_3);
            vec2 _e77 = nyq_lattice_get_2d(s_3);
            nyq_fill_values(out_4, _e76, _e77);
            return;
        }
        case 16u: {
            uint _e80 = _group_0_binding_1_cs.dims;
            uint _e83 = _group_0_binding_1_cs.scramble;
            uvec2 _e88 = _group_0_binding_1_cs.seed;
            NyqSobol _e89 = nyq_sobol(_e80, (_e83 != 0u), _e88);
            bool loop_init_7 = true;
            while(true) {
                if (!loop_init_7) {
                    uint _e117 = k;
                    k = (_e117 + 1u);
                }
                loop_init_7 = false;
                uint _e92 = k;
                if ((_e92 < 4u)) {
                } else {
                    break;
                }
                {
                    uint _e96 = k;
                    uint _e101 = k;
                    uint _e103 = nyq_sobol_sample_u32_(_e89, _e6.z, (_e6.w + _e101));
                    _group_0_binding_3_cs[(out_4 + _e96)] = _e103;
                    uint _e107 = k;
                    uint _e112 = k;
                    float _e114 = nyq_sobol_sample(_e89, _e6.z, (_e6.w + _e112));
                    _group_0_binding_3_cs[((out_4 + 4u) + _e107)] = floatBitsToUint(_e114);
                }
            }
            return;
        }
        case 17u: {
            uint _e121 = _group_0_binding_1_cs.dims;
            uvec2 _e124 = _group_0_binding_1_cs.seed;
            NyqOwenSobol _e125 = nyq_owen_sobol(_e121, _e124);
            vec4 _e128 = nyq_owen_sobol_sample_4d(_e125, _e6.z, _e6.w);
            bool loop_init_8 = true;
            while(true) {
                if (!loop_init_8) {
                    uint _e153 = k_1;
                    k_1 = (_e153 + 1u);
                }
                loop_init_8 = false;
                uint _e131 = k_1;
                if ((_e131 < 4u)) {
                } else {
                    break;
                }
                {
                    uint _e135 = k_1;
                    uint _e140 = k_1;
                    uint _e142 = nyq_owen_sobol_sample_u32_(_e125, _e6.z, (_e6.w + _e140));
                    _group_0_binding_3_cs[(out_4 + _e135)] = _e142;
                    uint _e146 = k_1;
                    uint _e149 = k_1;
                    _group_0_binding_3_cs[((out_4 + 4u) + _e146)] = floatBitsToUint(_e128[_e149]);
                }
            }
            return;
        }
        default: {
            bool loop_init_9 = true;
            while(true) {
                if (!loop_init_9) {
                    uint _e166 = k_2;
                    k_2 = (_e166 + 1u);
                }
                loop_init_9 = false;
                uint _e157 = k_2;
                if ((_e157 < 8u)) {
                } else {
                    break;
                }
                {
                    uint _e161 = k_2;
                    _group_0_binding_3_cs[(out_4 + _e161)] = 4294967295u;
                }
            }
            return;
        }
    }
}


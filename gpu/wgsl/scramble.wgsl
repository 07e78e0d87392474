// ---------------------------------------------------------------------------------------------
// scramble: base-2 scrambles (core/src/scramble.rs). A 32-bit value x is the binary fraction
// x / 2³², bit 31 its first digit.

// The scramble a sampler applies (core `Scramble`, in its order).
const NYQ_SCRAMBLE_NONE: u32 = 0u;
const NYQ_SCRAMBLE_PERMUTE_DIGITS: u32 = 1u;
const NYQ_SCRAMBLE_FAST_OWEN: u32 = 2u;
const NYQ_SCRAMBLE_OWEN: u32 = 3u;

// The Laine–Karras-style hash with Vegdahl's constants on a bit-reversed value: bit k of the
// result depends only on bits 0..=k of x_rev, so read backwards it is an Owen scramble. `seed`
// must already be mixed. core `lk_hash`.
fn nyq_lk_hash(x_rev: u32, seed: u32) -> u32 {
    var x = x_rev ^ (x_rev * 0x3d20adeau);
    x = (x + seed) * ((seed >> 16u) | 1u);
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// The fast (hash) Owen scramble of x under any seed: core `fast_owen_scramble`.
fn nyq_fast_owen_scramble(x: u32, seed: u32) -> u32 {
    return reverseBits(nyq_lk_hash(reverseBits(x), nyq_mix32(seed ^ 0x6a09e667u)));
}

// Burley's nested uniform shuffle of an index: core `nested_uniform_shuffle`.
fn nyq_nested_uniform_shuffle(index: u32, seed: u32) -> u32 {
    return nyq_fast_owen_scramble(index, seed);
}

// The exact Owen scramble: digit k flips when the top bit of mix64(K · 2³² + 2ᵏ + prefix) is
// set, K = mix32(seed ^ 0xbb67ae85), prefix the k digits before it. 32 hashes: core
// `owen_scramble`.
fn nyq_owen_scramble(x: u32, seed: u32) -> u32 {
    let key = nyq_mix32(seed ^ 0xbb67ae85u);
    var out = x;
    for (var k = 0u; k < 32u; k++) {
        let prefix = select(x >> ((32u - k) & 31u), 0u, k == 0u);
        let word = vec2<u32>((1u << k) | prefix, key);
        if (nyq_mix64(word).y >> 31u) == 1u {
            out ^= 1u << (31u - k);
        }
    }
    return out;
}

// x scrambled by `how` (NYQ_SCRAMBLE_*) under `seed`: core `scramble_u32`.
fn nyq_scramble_u32(x: u32, seed: u32, how: u32) -> u32 {
    switch how {
        case 1u: {
            return x ^ nyq_mix32(seed ^ 0x3c6ef372u);
        }
        case 2u: {
            return nyq_fast_owen_scramble(x, seed);
        }
        case 3u: {
            return nyq_owen_scramble(x, seed);
        }
        default: {
            return x;
        }
    }
}

//! The crate's one SSE2 kernel: the four-lane LK hash and float conversion of
//! [`OwenSobol::sample_4d`](crate::sequence::OwenSobol::sample_4d),
//! [`Pmj02::fill_2d`](crate::sequence::Pmj02::fill_2d) and the
//! [`Pmj02Sampler`](crate::sampler::Pmj02Sampler)'s camera samples, on x86-64 only.
//!
//! Plain lane-parallel Rust already compiles to SSE2 there, but LLVM multiplies 32-bit lanes
//! the only way SSE2 offers, two `pmuludq` and five shuffles per product. Here each pair of
//! lanes rides in the low halves of the two 64-bit lanes of its own register, where a product
//! is one `pmuludq` (which reads only the low halves); the high halves carry garbage that no
//! step reads, since a sum, XOR or low product of 32-bit words depends only on the low bits.
//! One shuffle at the end puts the four words back in order. The four multiplies of the hash
//! drop from 28 instructions to 8 plus 7 of splitting and merging; `owen` bench, interleaved
//! A/B (docs/design.md). Words stored premixed (the PMJ(0,2) table) skip the first multiply.
//!
//! The intrinsics are safe inside a function with `#[target_feature(enable = "sse2")]`; the
//! only `unsafe` is the call into it, sound because SSE2 is part of the x86-64 baseline.
#![allow(unsafe_code)]

use core::arch::x86_64::{
    __m128i, _mm_add_epi32, _mm_and_si128, _mm_castps_si128, _mm_castsi128_ps, _mm_cvtepi32_ps,
    _mm_cvtss_f32, _mm_mul_epu32, _mm_mul_ps, _mm_or_si128, _mm_packus_epi16, _mm_set_epi32,
    _mm_set1_epi8, _mm_set1_epi32, _mm_set1_ps, _mm_setzero_si128, _mm_shuffle_ps,
    _mm_shufflehi_epi16, _mm_shufflelo_epi16, _mm_slli_epi16, _mm_srli_epi16, _mm_srli_epi32,
    _mm_unpackhi_epi8, _mm_unpackhi_epi32, _mm_unpacklo_epi8, _mm_unpacklo_epi32, _mm_xor_si128,
};

/// `lk_hash(x[k], seeds[k])` (Vegdahl's constants, as [`crate::scramble::lk_hash`]), then the
/// top 24 bits of its bit reversal as an `f32` in `[0, 1)`, for the four lanes: equal to
/// `scramble_rev_f32x4_lanes` bit for bit (tested).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn scramble_rev_f32x4_sse2<const PREMIXED: bool>(
    x: [u32; 4],
    seeds: [u32; 4],
) -> [f32; 4] {
    // SAFETY: SSE2 is in every x86-64 target's baseline (`cfg(target_feature = "sse2")` holds
    // on x86-64), so the kernel's one required feature is present on any machine this runs on.
    unsafe { kernel::<PREMIXED>(x, seeds) }
}

#[target_feature(enable = "sse2")]
#[inline]
fn kernel<const PREMIXED: bool>(x: [u32; 4], seeds: [u32; 4]) -> [f32; 4] {
    let x = load(x);
    let s = load(seeds);
    let m = _mm_or_si128(_mm_srli_epi32::<16>(s), _mm_set1_epi32(1));
    // Lanes 0, 1 in the low halves of `lo`'s 64-bit lanes, lanes 2, 3 in `hi`'s.
    let (mut lo, mut hi) = (_mm_unpacklo_epi32(x, x), _mm_unpackhi_epi32(x, x));
    let (s_lo, s_hi) = (_mm_unpacklo_epi32(s, s), _mm_unpackhi_epi32(s, s));
    let (m_lo, m_hi) = (_mm_unpacklo_epi32(m, m), _mm_unpackhi_epi32(m, m));
    if !PREMIXED {
        let c1 = _mm_set1_epi32(0x3d20_adea);
        lo = _mm_xor_si128(lo, _mm_mul_epu32(lo, c1));
        hi = _mm_xor_si128(hi, _mm_mul_epu32(hi, c1));
    }
    lo = _mm_mul_epu32(_mm_add_epi32(lo, s_lo), m_lo);
    hi = _mm_mul_epu32(_mm_add_epi32(hi, s_hi), m_hi);
    let c2 = _mm_set1_epi32(0x0552_6c56);
    lo = _mm_xor_si128(lo, _mm_mul_epu32(lo, c2));
    hi = _mm_xor_si128(hi, _mm_mul_epu32(hi, c2));
    let c3 = _mm_set1_epi32(0x53a2_2864);
    lo = _mm_xor_si128(lo, _mm_mul_epu32(lo, c3));
    hi = _mm_xor_si128(hi, _mm_mul_epu32(hi, c3));
    // The low halves back in lane order: words 0 and 2 of `lo`, then of `hi`.
    let w = _mm_castps_si128(_mm_shuffle_ps::<0b10_00_10_00>(
        _mm_castsi128_ps(lo),
        _mm_castsi128_ps(hi),
    ));
    let v = _mm_srli_epi32::<8>(reverse_bits(w));
    let f = _mm_mul_ps(_mm_cvtepi32_ps(v), _mm_set1_ps(1.0 / 16_777_216.0));
    [
        _mm_cvtss_f32(f),
        _mm_cvtss_f32(_mm_shuffle_ps::<0b01_01_01_01>(f, f)),
        _mm_cvtss_f32(_mm_shuffle_ps::<0b10_10_10_10>(f, f)),
        _mm_cvtss_f32(_mm_shuffle_ps::<0b11_11_11_11>(f, f)),
    ]
}

/// The four words as one register, lane `k` = `a[k]`.
#[target_feature(enable = "sse2")]
#[inline]
fn load(a: [u32; 4]) -> __m128i {
    _mm_set_epi32(a[3] as i32, a[2] as i32, a[1] as i32, a[0] as i32)
}

/// Each 32-bit lane bit-reversed: bytes swapped (widen to 16-bit lanes, reverse the words of
/// each half, narrow), then bits swapped within bytes in three mask steps.
#[target_feature(enable = "sse2")]
#[inline]
fn reverse_bits(w: __m128i) -> __m128i {
    let z = _mm_setzero_si128();
    let lo = _mm_shufflehi_epi16::<0x1b>(_mm_shufflelo_epi16::<0x1b>(_mm_unpacklo_epi8(w, z)));
    let hi = _mm_shufflehi_epi16::<0x1b>(_mm_shufflelo_epi16::<0x1b>(_mm_unpackhi_epi8(w, z)));
    let mut b = _mm_packus_epi16(lo, hi);
    let m4 = _mm_set1_epi8(0x0f);
    b = _mm_or_si128(
        _mm_and_si128(_mm_srli_epi16::<4>(b), m4),
        _mm_slli_epi16::<4>(_mm_and_si128(b, m4)),
    );
    let m2 = _mm_set1_epi8(0x33);
    b = _mm_or_si128(
        _mm_and_si128(_mm_srli_epi16::<2>(b), m2),
        _mm_slli_epi16::<2>(_mm_and_si128(b, m2)),
    );
    let m1 = _mm_set1_epi8(0x55);
    _mm_or_si128(
        _mm_and_si128(_mm_srli_epi16::<1>(b), m1),
        _mm_slli_epi16::<1>(_mm_and_si128(b, m1)),
    )
}

//! The crate's x86-64 vector kernels: the four-lane LK hash and float conversion of
//! [`OwenSobol::sample_4d`](crate::sequence::OwenSobol::sample_4d),
//! [`Pmj02::fill_2d`](crate::sequence::Pmj02::fill_2d) and the
//! [`Pmj02Sampler`](crate::sampler::Pmj02Sampler)'s camera samples, on x86-64 only.
//!
//! Two kernels, one result. Where the CPU has SSSE3 and SSE4.1 ([`has_sse41`]: the target
//! promises them, or CPUID says so once), `pmulld` multiplies the 32-bit lanes and `pshufb`
//! reverses their bits through nibble tables. Elsewhere the SSE2 kernel runs: plain
//! lane-parallel Rust already compiles to SSE2, but LLVM multiplies 32-bit lanes the only way
//! SSE2 offers, two `pmuludq` and five shuffles per product; here each pair of lanes rides in the
//! low halves of the two 64-bit lanes of its own register, where a product is one `pmuludq`
//! (which reads only the low halves); the high halves carry garbage that no step reads, since a
//! sum, XOR or low product of 32-bit words depends only on the low bits. One shuffle at the end
//! puts the four words back in order. Words stored premixed (the PMJ(0,2) table) skip the first
//! multiply. Figures: docs/design.md.
//!
//! The intrinsics are safe inside a function with `#[target_feature]`; the only `unsafe` is the
//! call into one, sound because SSE2 is part of the x86-64 baseline and SSSE3 and SSE4.1 were
//! found present before the other kernel is called.
#![allow(unsafe_code)]

use core::sync::atomic::{AtomicU8, Ordering};

use core::arch::x86_64::{
    __cpuid, __m128, __m128i, _mm_add_epi32, _mm_and_si128, _mm_castps_si128, _mm_castsi128_ps,
    _mm_cvtepi32_ps, _mm_cvtss_f32, _mm_mul_epu32, _mm_mul_ps, _mm_mullo_epi32, _mm_or_si128,
    _mm_packus_epi16, _mm_set_epi32, _mm_set1_epi8, _mm_set1_epi32, _mm_set1_ps, _mm_setr_epi8,
    _mm_setzero_si128, _mm_shuffle_epi8, _mm_shuffle_ps, _mm_shufflehi_epi16, _mm_shufflelo_epi16,
    _mm_slli_epi16, _mm_srli_epi16, _mm_srli_epi32, _mm_unpackhi_epi8, _mm_unpackhi_epi32,
    _mm_unpacklo_epi8, _mm_unpacklo_epi32, _mm_xor_si128,
};

/// `lk_hash(x[k], seeds[k])` (Vegdahl's constants, as [`crate::scramble::lk_hash`]), then the
/// top 24 bits of its bit reversal as an `f32` in `[0, 1)`, for the four lanes: the SSSE3 and
/// SSE4.1 kernel where the CPU has both ([`has_sse41`]), else the SSE2 one. Both equal
/// `scramble_rev_f32x4_lanes` bit for bit (tested).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn scramble_rev_f32x4_x86<const PREMIXED: bool>(
    x: [u32; 4],
    seeds: [u32; 4],
) -> [f32; 4] {
    match scramble_rev_f32x4_sse41::<PREMIXED>(x, seeds) {
        Some(v) => v,
        None => scramble_rev_f32x4_sse2::<PREMIXED>(x, seeds),
    }
}

/// [`scramble_rev_f32x4_x86`] on the SSE2 kernel, which every x86-64 CPU runs.
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
    lanes(_mm_mul_ps(
        _mm_cvtepi32_ps(v),
        _mm_set1_ps(1.0 / 16_777_216.0),
    ))
}

/// [`scramble_rev_f32x4_x86`] on the SSSE3 and SSE4.1 kernel, `None` where the CPU lacks
/// either.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn scramble_rev_f32x4_sse41<const PREMIXED: bool>(
    x: [u32; 4],
    seeds: [u32; 4],
) -> Option<[f32; 4]> {
    if !has_sse41() {
        return None;
    }
    // Built here, in registers: a kernel the caller cannot inline takes its arguments through
    // memory, and four 32-bit stores read back as one 128-bit load would stall.
    let (x, seeds) = (load_sse2(x), load_sse2(seeds));
    // SAFETY: the kernel needs SSSE3 and SSE4.1, and `has_sse41` answered that this CPU has
    // both (the target promises them, or CPUID reported them).
    let f = unsafe { kernel_sse41::<PREMIXED>(x, seeds) };
    Some(lanes_sse2(f))
}

/// [`load`] in the caller's (baseline) context.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn load_sse2(a: [u32; 4]) -> __m128i {
    // SAFETY: SSE2 is in the x86-64 baseline.
    unsafe { load(a) }
}

/// The four lanes of `f` in order.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn lanes_sse2(f: __m128) -> [f32; 4] {
    // SAFETY: SSE2 is in the x86-64 baseline.
    unsafe { lanes(f) }
}

/// The four lanes of `f` in order.
#[target_feature(enable = "sse2")]
#[inline]
fn lanes(f: __m128) -> [f32; 4] {
    [
        _mm_cvtss_f32(f),
        _mm_cvtss_f32(_mm_shuffle_ps::<0b01_01_01_01>(f, f)),
        _mm_cvtss_f32(_mm_shuffle_ps::<0b10_10_10_10>(f, f)),
        _mm_cvtss_f32(_mm_shuffle_ps::<0b11_11_11_11>(f, f)),
    ]
}

/// Whether the CPU runs SSSE3 and SSE4.1: `true` at compile time where the target has both
/// (`-C target-cpu=x86-64-v2` and up), else asked of CPUID once and kept. Under Miri, which
/// cannot run CPUID, `false` unless the target has them.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn has_sse41() -> bool {
    if cfg!(all(target_feature = "ssse3", target_feature = "sse4.1")) {
        return true;
    }
    if cfg!(miri) {
        return false;
    }
    match SSE41.load(Ordering::Relaxed) {
        PRESENT => true,
        ABSENT => false,
        _ => detect_sse41(),
    }
}

/// [`has_sse41`]'s answer once asked: [`UNKNOWN`], [`ABSENT`] or [`PRESENT`]. Racing first
/// calls each ask CPUID and store the same answer.
static SSE41: AtomicU8 = AtomicU8::new(UNKNOWN);
const UNKNOWN: u8 = 0;
const ABSENT: u8 = 1;
const PRESENT: u8 = 2;

#[cold]
#[inline(never)]
fn detect_sse41() -> bool {
    // CPUID leaf 1, ECX: bit 9 SSSE3, bit 19 SSE4.1 (Intel SDM vol. 2A, CPUID).
    let ecx = __cpuid(1).ecx;
    let present = ecx & (1 << 9) != 0 && ecx & (1 << 19) != 0;
    SSE41.store(if present { PRESENT } else { ABSENT }, Ordering::Relaxed);
    present
}

/// The SSE2 kernel's result with SSE4.1's 32-bit lane multiply (`pmulld`, no splitting into
/// 64-bit halves) and SSSE3's byte shuffle (`pshufb`) for the reversal: one shuffle picks each
/// word's low three bytes in reverse order (the shift right by 8 folded in: the top byte is
/// zero), and two 16-entry nibble tables reverse the bits of every byte.
#[target_feature(enable = "ssse3,sse4.1")]
#[inline]
fn kernel_sse41<const PREMIXED: bool>(x: __m128i, s: __m128i) -> __m128 {
    let mut h = x;
    let m = _mm_or_si128(_mm_srli_epi32::<16>(s), _mm_set1_epi32(1));
    if !PREMIXED {
        h = _mm_xor_si128(h, _mm_mullo_epi32(h, _mm_set1_epi32(0x3d20_adea)));
    }
    h = _mm_mullo_epi32(_mm_add_epi32(h, s), m);
    h = _mm_xor_si128(h, _mm_mullo_epi32(h, _mm_set1_epi32(0x0552_6c56)));
    h = _mm_xor_si128(h, _mm_mullo_epi32(h, _mm_set1_epi32(0x53a2_2864)));
    // Bytes 2, 1, 0 of each word into bytes 0, 1, 2 (index −128 writes zero): the byte order of
    // `reverse_bits(h) >> 8` before the bits inside each byte are reversed.
    let picked = _mm_shuffle_epi8(
        h,
        _mm_setr_epi8(
            2, 1, 0, -128, 6, 5, 4, -128, 10, 9, 8, -128, 14, 13, 12, -128,
        ),
    );
    let nibble = _mm_set1_epi8(0x0f);
    // Nibble `n` reversed: `REV4[n] << 4` for the low nibble, `REV4[n]` for the high one.
    let low_up = _mm_setr_epi8(
        0, -128, 64, -64, 32, -96, 96, -32, 16, -112, 80, -48, 48, -80, 112, -16,
    );
    let high_down = _mm_setr_epi8(0, 8, 4, 12, 2, 10, 6, 14, 1, 9, 5, 13, 3, 11, 7, 15);
    let v = _mm_or_si128(
        _mm_shuffle_epi8(low_up, _mm_and_si128(picked, nibble)),
        _mm_shuffle_epi8(
            high_down,
            _mm_and_si128(_mm_srli_epi16::<4>(picked), nibble),
        ),
    );
    _mm_mul_ps(_mm_cvtepi32_ps(v), _mm_set1_ps(1.0 / 16_777_216.0))
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

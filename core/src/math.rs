//! Floating-point helpers. This is the only module that names `libm`: in a `no_std` crate the
//! inherent `f32::floor`, `sqrt`, `exp`, `sin`, … do not exist.

/// The largest `f32` below one, `0x1.fffffep-1`: every `f32` a generator returns is at most this.
///
/// ```
/// assert!(nyquist::ONE_MINUS_EPSILON < 1.0);
/// assert_eq!(nyquist::ONE_MINUS_EPSILON, 1.0 - f32::EPSILON / 2.0);
/// ```
pub const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// The largest `f64` below one, `0x1.fffffffffffffp-1`.
///
/// ```
/// assert_eq!(nyquist::ONE_MINUS_EPSILON_F64, 1.0 - f64::EPSILON / 2.0);
/// ```
pub const ONE_MINUS_EPSILON_F64: f64 = 1.0 - f64::EPSILON / 2.0;

/// `2⁻³²`, the scale from a 32-bit fixed-point fraction to a float.
pub const TWO_POW_MINUS_32: f64 = 1.0 / 4_294_967_296.0;

/// A 32-bit binary fraction (`v / 2³²`) as an `f32` in `[0, 1)`: its top 24 bits, truncated
/// (never rounded up to 1). The one conversion every base-2 generator uses.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn fraction_to_f32(v: u32) -> f32 {
    (v >> 8) as f32 * (1.0 / 16_777_216.0)
}

/// `x` clamped into `[0, 1)`; NaN maps to 0.
///
/// ```
/// use nyquist::math::clamp_unit;
/// assert_eq!(clamp_unit(1.0), nyquist::ONE_MINUS_EPSILON);
/// assert_eq!(clamp_unit(f32::NAN), 0.0);
/// assert_eq!(clamp_unit(-0.5), 0.0);
/// ```
#[inline]
pub fn clamp_unit(x: f32) -> f32 {
    if x >= 0.0 {
        if x < ONE_MINUS_EPSILON {
            x
        } else {
            ONE_MINUS_EPSILON
        }
    } else {
        0.0
    }
}

/// `x` clamped into `[0, 1)`; NaN maps to 0 (the `f64` twin of [`clamp_unit`]).
///
/// ```
/// assert_eq!(nyquist::math::clamp_unit_f64(2.0), nyquist::ONE_MINUS_EPSILON_F64);
/// ```
#[inline]
pub fn clamp_unit_f64(x: f64) -> f64 {
    if x >= 0.0 {
        if x < ONE_MINUS_EPSILON_F64 {
            x
        } else {
            ONE_MINUS_EPSILON_F64
        }
    } else {
        0.0
    }
}

macro_rules! forward {
    ($($(#[$m:meta])* $name:ident => $libm:ident ($($arg:ident : $t:ty),*) -> $r:ty;)*) => {$(
        $(#[$m])*
        #[inline]
        pub fn $name($($arg: $t),*) -> $r { libm::$libm($($arg),*) }
    )*};
}

forward! {
    /// `⌊x⌋` (`f32`).
    floor_f32 => floorf(x: f32) -> f32;
    /// `⌈x⌉` (`f32`).
    ceil_f32 => ceilf(x: f32) -> f32;
    /// `√x` (`f32`).
    sqrt_f32 => sqrtf(x: f32) -> f32;
    /// `eˣ` (`f32`).
    exp_f32 => expf(x: f32) -> f32;
    /// `sin x` (`f32`).
    sin_f32 => sinf(x: f32) -> f32;
    /// `cos x` (`f32`).
    cos_f32 => cosf(x: f32) -> f32;
    /// `⌊x⌋` (`f64`).
    floor => floor(x: f64) -> f64;
    /// `⌈x⌉` (`f64`).
    ceil => ceil(x: f64) -> f64;
    /// `√x` (`f64`).
    sqrt => sqrt(x: f64) -> f64;
    /// `eˣ` (`f64`).
    exp => exp(x: f64) -> f64;
    /// `ln x` (`f64`).
    ln => log(x: f64) -> f64;
    /// `log₂ x` (`f64`).
    log2 => log2(x: f64) -> f64;
    /// `sin x` (`f64`).
    sin => sin(x: f64) -> f64;
    /// `cos x` (`f64`).
    cos => cos(x: f64) -> f64;
    /// `xʸ` (`f64`).
    pow => pow(x: f64, y: f64) -> f64;
    /// `erf x` (`f64`).
    erf => erf(x: f64) -> f64;
}

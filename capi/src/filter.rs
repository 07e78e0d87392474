//! Reconstruction filters through an opaque handle: built-in filters from a spec string, or a
//! C plugin filter given as a callback and tabulated once on creation; table lookups
//! (nearest and linear), the integral, and filter importance sampling.
//!
//! Every handle holds two [`FilterTable`]s of [`NYQ_FILTER_TABLE_SIZE`] points per axis (the
//! core's default table size; the film keeps its own, finer table), one per [`NyqInterpolation`], and a [`FilterSampler`] on a
//! [`NYQ_FILTER_SAMPLER_GRID`]² grid. A callback filter's callback is called only inside
//! [`nyq_filter_create_callback`]; afterwards its linear table *is* the filter (its `eval`,
//! its importance sampling), and its integral is the core's numeric integral of the callback.

use core::ffi::{c_char, c_void};

use nyquist::filter::{
    Filter, FilterKind, FilterSampler, FilterTable, Interpolation, MAX_RADIUS, MIN_RADIUS,
};

use crate::NyqStatus;
use crate::ffi::{drop_box, need, put, put_array, put_box, query, run, text};

/// Points per axis of a handle's lookup tables (the core's default `FilterTable` size).
pub const NYQ_FILTER_TABLE_SIZE: u32 = 16;

/// Cells per axis of a handle's importance-sampling grid (the core's default
/// `FilterSampler` size).
pub const NYQ_FILTER_SAMPLER_GRID: u32 = 32;

/// How [`nyq_filter_lookup`] reads between table points.
///
/// ```
/// assert_eq!(nyquist_capi::NyqInterpolation::NYQ_INTERP_LINEAR as u32, 1);
/// ```
#[repr(u32)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NyqInterpolation {
    /// The nearest table point.
    NYQ_INTERP_NEAREST = 0,
    /// Linear (bilinear for 2D tables) between the neighbouring points.
    NYQ_INTERP_LINEAR = 1,
}

/// A user filter: `eval(user, x, y)` is the weight at offset `(x, y)` pixels from the pixel
/// centre. Called only for `|x| ≤ rx`, `|y| ≤ ry` (the handle returns 0 outside); a non-finite
/// result counts as 0. It must not unwind (no C++ exception or `longjmp` through it).
pub type NyqFilterEval = unsafe extern "C" fn(user: *mut c_void, x: f32, y: f32) -> f32;

/// A filter importance sample: an offset from the pixel centre and its weight.
///
/// ```
/// let s = nyquist_capi::NyqFilterSample { offset: [0.25, -0.5], weight: 1.0 };
/// assert_eq!(s.offset[1], -0.5);
/// ```
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NyqFilterSample {
    /// Offset `[x, y]` in pixels, inside the filter's support.
    pub offset: [f32; 2],
    /// `f(offset) / pdf(offset)`, sign included; finite.
    pub weight: f32,
}

/// A filter behind an opaque handle, made by [`nyq_filter_create`] or
/// [`nyq_filter_create_callback`] and released by [`nyq_filter_destroy`]. Immutable after
/// creation: any number of threads may read one handle at once.
#[derive(Debug)]
pub struct NyqFilter {
    /// The built-in filter, `None` for a callback filter.
    kind: Option<FilterKind>,
    nearest: FilterTable,
    linear: FilterTable,
    sampler: Importance,
}

// Both variants are a few KB and the handle that holds one is boxed as a whole.
#[allow(clippy::large_enum_variant)]
#[derive(Debug)]
enum Importance {
    Kind(FilterSampler<FilterKind>),
    Tabulated(FilterSampler<TabulatedFilter>),
}

/// A filter given by its table: what a callback filter handle evaluates after
/// [`nyq_filter_create_callback`] (its linear table, as weight, integral and importance
/// sampling). A Rust-only type, so Rust code can reproduce a callback handle's values.
///
/// ```
/// use nyquist::filter::{Filter, FilterKind, FilterTable, Interpolation};
/// use nyquist_capi::TabulatedFilter;
/// let k = FilterKind::parse("mitchell").unwrap();
/// let t: FilterTable = FilterTable::new(&k, Interpolation::Linear).unwrap();
/// let f = TabulatedFilter(t);
/// assert_eq!(f.eval(0.3, -1.1), t.weight(0.3, -1.1));
/// assert_eq!(f.radius(), k.radius());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TabulatedFilter(pub FilterTable);

impl Filter for TabulatedFilter {
    fn radius(&self) -> [f32; 2] {
        self.0.radius()
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        self.0.weight(x, y)
    }
    fn integral(&self) -> f32 {
        self.0.integral()
    }
}

/// The C callback as a core [`Filter`], used only while the handle is being built.
struct Callback {
    eval: NyqFilterEval,
    user: *mut c_void,
    radius: [f32; 2],
}

impl Filter for Callback {
    fn radius(&self) -> [f32; 2] {
        self.radius
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        if !(x.abs() <= self.radius[0] && y.abs() <= self.radius[1]) {
            return 0.0;
        }
        // SAFETY: `nyq_filter_create_callback`'s caller guarantees `eval` may be called with
        // `user` and any offset inside the radius, for the duration of that call, which is
        // the only time a `Callback` exists.
        let v = unsafe { (self.eval)(self.user, x, y) };
        if v.is_finite() { v } else { 0.0 }
    }
}

impl Importance {
    fn sample(&self, u: [f32; 2]) -> NyqFilterSample {
        let s = match self {
            Importance::Kind(s) => s.sample(u),
            Importance::Tabulated(s) => s.sample(u),
        };
        NyqFilterSample {
            offset: s.offset,
            weight: s.weight,
        }
    }

    fn pdf(&self, p: [f32; 2]) -> f32 {
        match self {
            Importance::Kind(s) => s.pdf(p),
            Importance::Tabulated(s) => s.pdf(p),
        }
    }
}

impl NyqFilter {
    /// The built-in filter's exact weight, or a callback filter's linear table.
    fn eval(&self, x: f32, y: f32) -> f32 {
        match &self.kind {
            Some(k) => k.eval(x, y),
            None => self.linear.weight(x, y),
        }
    }

    /// The built-in filter's closed form, or a callback filter's numeric integral.
    fn integral(&self) -> f32 {
        match &self.kind {
            Some(k) => k.integral(),
            None => self.linear.integral(),
        }
    }

    fn tables<F: Filter + ?Sized>(f: &F) -> Result<[FilterTable; 2], NyqStatus> {
        Ok([
            FilterTable::new(f, Interpolation::Nearest)?,
            FilterTable::new(f, Interpolation::Linear)?,
        ])
    }

    fn from_kind(kind: FilterKind) -> Result<NyqFilter, NyqStatus> {
        let [nearest, linear] = NyqFilter::tables(&kind)?;
        Ok(NyqFilter {
            kind: Some(kind),
            nearest,
            linear,
            sampler: Importance::Kind(FilterSampler::new(kind)?),
        })
    }

    fn from_callback(cb: &Callback) -> Result<NyqFilter, NyqStatus> {
        let [nearest, linear] = NyqFilter::tables(cb)?;
        Ok(NyqFilter {
            kind: None,
            nearest,
            linear,
            sampler: Importance::Tabulated(FilterSampler::new(TabulatedFilter(linear))?),
        })
    }
}

/// Creates a built-in filter from a spec `name[:key=value,…]` and writes the handle to `*out`.
/// Names `box` (`boxcar`), `triangle` (`tent`), `gaussian`, `mitchell`, `catmull-rom`,
/// `blackman-harris`, `lanczos`; keys `radius`, `rx`, `ry` (all), `alpha` or `sigma` (gaussian),
/// `b`, `c` (mitchell), `tau` (lanczos); e.g. `"mitchell:b=0.5,c=0.25"`: the core's
/// [`FilterKind::parse`](nyquist::filter::FilterKind::parse).
///
/// # Errors
/// `NYQ_ERR_NULL` if `spec` or `out` is null; `NYQ_ERR_PARSE` if the spec does not parse or a
/// value is rejected (unknown name or key, bad number, out-of-range parameter, not UTF-8).
///
/// # Safety
/// `spec` is null or a NUL-terminated string; `out` is null or valid for writing one pointer.
///
/// ```
/// use nyquist_capi::*;
/// let mut f: *mut NyqFilter = std::ptr::null_mut();
/// let mut w = 0.0f32;
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     assert_eq!(nyq_filter_create(c"triangle".as_ptr(), &mut f), NyqStatus::NYQ_OK);
///     assert_eq!(nyq_filter_eval(f, 0.0, 0.0, &mut w), NyqStatus::NYQ_OK);
///     nyq_filter_destroy(f);
///     assert_eq!(nyq_filter_create(c"mitchell:b=x".as_ptr(), &mut f), NyqStatus::NYQ_ERR_PARSE);
/// }
/// assert_eq!(w, 4.0);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_filter_create(
    spec: *const c_char,
    out: *mut *mut NyqFilter,
) -> NyqStatus {
    run(|| {
        // SAFETY: `spec` is null or NUL-terminated (caller).
        let spec = unsafe { text(spec)? };
        need(out)?;
        let kind = FilterKind::parse(spec).map_err(|_| NyqStatus::NYQ_ERR_PARSE)?;
        let f = NyqFilter::from_kind(kind)?;
        // SAFETY: `out` is writable (caller).
        unsafe { put_box(out, f) }
    })
}

/// Creates a plugin filter from a C callback with radius `[rx, ry]` pixels and writes the
/// handle to `*out`. The callback is tabulated here, once, into the core's table types (and
/// integrated numerically: about 2·(256² + 16²) + 32² calls); it is never called again, so
/// `user` need only live until this function returns. The filter should be even on each axis,
/// `f(x, y) = f(|x|, |y|)`, as the tables assume.
///
/// # Errors
/// `NYQ_ERR_NULL` if `eval` or `out` is null; `NYQ_ERR_NON_FINITE` if a radius is NaN or
/// infinite, or the callback's integral is not finite (it answers NaN or ∞);
/// `NYQ_ERR_OUT_OF_RANGE` if a radius is outside `[2⁻¹⁶, 1024]`, or the integral is 0, negative
/// or below `1e-12` (every sample would weigh almost nothing).
///
/// # Safety
/// `eval` is null or a function that may be called, on this thread and during this call, with
/// `user` and any `|x| ≤ rx`, `|y| ≤ ry`, and does not unwind; `out` is null or valid for
/// writing one pointer.
///
/// ```
/// use std::ffi::c_void;
/// use nyquist_capi::*;
/// unsafe extern "C" fn cone(user: *mut c_void, x: f32, y: f32) -> f32 {
///     // SAFETY: `user` is the `f32` passed below.
///     let scale = unsafe { *user.cast::<f32>() };
///     (scale * (1.0 - (x * x + y * y))).max(0.0)
/// }
/// let mut scale = 2.0f32;
/// let mut f: *mut NyqFilter = std::ptr::null_mut();
/// let mut w = 0.0f32;
/// // SAFETY: `cone` reads `scale`, alive during the call; the handle is destroyed once.
/// unsafe {
///     let user = (&raw mut scale).cast::<c_void>();
///     assert_eq!(nyq_filter_create_callback(Some(cone), user, 1.0, 1.0, &mut f), NyqStatus::NYQ_OK);
///     assert_eq!(nyq_filter_lookup(f, 0, 0.0, 0.0, &mut w), NyqStatus::NYQ_OK);
///     nyq_filter_destroy(f);
///     assert_eq!(nyq_filter_create_callback(None, user, 1.0, 1.0, &mut f), NyqStatus::NYQ_ERR_NULL);
/// }
/// assert_eq!(w, 2.0);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_filter_create_callback(
    eval: Option<unsafe extern "C" fn(user: *mut c_void, x: f32, y: f32) -> f32>,
    user: *mut c_void,
    rx: f32,
    ry: f32,
    out: *mut *mut NyqFilter,
) -> NyqStatus {
    run(|| {
        let eval = eval.ok_or(NyqStatus::NYQ_ERR_NULL)?;
        need(out)?;
        for r in [rx, ry] {
            if !r.is_finite() {
                return Err(NyqStatus::NYQ_ERR_NON_FINITE);
            }
            if !(MIN_RADIUS..=MAX_RADIUS).contains(&r) {
                return Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE);
            }
        }
        let f = NyqFilter::from_callback(&Callback {
            eval,
            user,
            radius: [rx, ry],
        })?;
        // SAFETY: `out` is writable (caller).
        unsafe { put_box(out, f) }
    })
}

/// Releases a handle from a `nyq_filter_create*` function. Null is a no-op.
///
/// # Safety
/// `filter` is null or a live handle, not used afterwards.
///
/// ```
/// // SAFETY: null is allowed.
/// unsafe { nyquist_capi::nyq_filter_destroy(std::ptr::null_mut()) };
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_filter_destroy(filter: *mut NyqFilter) {
    // SAFETY: `filter` is null or a live handle from `put_box`, dropped once (caller).
    unsafe { drop_box(filter) }
}

/// Writes the filter's radius `[rx, ry]` in pixels to `out[0]`, `out[1]`.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null.
///
/// # Safety
/// `filter` is null or a live handle; `out` is null or valid for writing two `float`s.
///
/// ```
/// use nyquist_capi::*;
/// let mut f: *mut NyqFilter = std::ptr::null_mut();
/// let mut r = [0.0f32; 2];
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_filter_create(c"gaussian:rx=1.5".as_ptr(), &mut f);
///     assert_eq!(nyq_filter_radius(f, r.as_mut_ptr()), NyqStatus::NYQ_OK);
///     nyq_filter_destroy(f);
/// }
/// assert_eq!(r, [1.5, 2.0]);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_filter_radius(filter: *const NyqFilter, out: *mut f32) -> NyqStatus {
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe { query(filter, out, |f| Ok(f.linear.radius()), put_array) }
}

/// Writes the filter's weight at offset `(x, y)` pixels to `*out`: the built-in filter's exact
/// value, or a callback filter's linear table. 0 past the radius and for NaN or infinite
/// offsets.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null.
///
/// # Safety
/// `filter` is null or a live handle; `out` is null or valid for writing one `float`.
///
/// ```
/// use nyquist_capi::*;
/// let mut f: *mut NyqFilter = std::ptr::null_mut();
/// let mut w = 1.0f32;
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_filter_create(c"box".as_ptr(), &mut f);
///     assert_eq!(nyq_filter_eval(f, 0.6, 0.0, &mut w), NyqStatus::NYQ_OK);
///     nyq_filter_destroy(f);
/// }
/// assert_eq!(w, 0.0);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_filter_eval(
    filter: *const NyqFilter,
    x: f32,
    y: f32,
    out: *mut f32,
) -> NyqStatus {
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe { query(filter, out, |f| Ok(f.eval(x, y)), put) }
}

/// Writes the table weight at offset `(x, y)` pixels to `*out`, read with `interpolation` (a
/// [`NyqInterpolation`] value): the core's
/// [`FilterTable::weight`](nyquist::filter::FilterTable::weight). Exact at the table points;
/// 0 past the radius and for NaN or infinite offsets.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_OUT_OF_RANGE` for an unknown interpolation.
///
/// # Safety
/// `filter` is null or a live handle; `out` is null or valid for writing one `float`.
///
/// ```
/// use nyquist::filter::{FilterKind, FilterTable, Interpolation};
/// use nyquist_capi::*;
/// let mut f: *mut NyqFilter = std::ptr::null_mut();
/// let mut w = 0.0f32;
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_filter_create(c"mitchell".as_ptr(), &mut f);
///     let linear = NyqInterpolation::NYQ_INTERP_LINEAR as u32;
///     assert_eq!(nyq_filter_lookup(f, linear, 0.3, -1.1, &mut w), NyqStatus::NYQ_OK);
///     assert_eq!(nyq_filter_lookup(f, 2, 0.3, -1.1, &mut w), NyqStatus::NYQ_ERR_OUT_OF_RANGE);
///     nyq_filter_destroy(f);
/// }
/// let k = FilterKind::parse("mitchell").unwrap();
/// let t: FilterTable = FilterTable::new(&k, Interpolation::Linear).unwrap();
/// assert_eq!(w, t.weight(0.3, -1.1));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_filter_lookup(
    filter: *const NyqFilter,
    interpolation: u32,
    x: f32,
    y: f32,
    out: *mut f32,
) -> NyqStatus {
    let lookup = |f: &NyqFilter| {
        let table = match interpolation {
            i if i == NyqInterpolation::NYQ_INTERP_NEAREST as u32 => &f.nearest,
            i if i == NyqInterpolation::NYQ_INTERP_LINEAR as u32 => &f.linear,
            _ => return Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE),
        };
        Ok(table.weight(x, y))
    };
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe { query(filter, out, lookup, put) }
}

/// Writes `∫∫ f(x, y) dx dy` over the support to `*out`: closed forms for the built-ins, the
/// core's numeric integral of the callback for plugin filters.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null.
///
/// # Safety
/// `filter` is null or a live handle; `out` is null or valid for writing one `float`.
///
/// ```
/// use nyquist_capi::*;
/// let mut f: *mut NyqFilter = std::ptr::null_mut();
/// let mut i = 0.0f32;
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_filter_create(c"box:radius=1".as_ptr(), &mut f);
///     assert_eq!(nyq_filter_integral(f, &mut i), NyqStatus::NYQ_OK);
///     nyq_filter_destroy(f);
/// }
/// assert_eq!(i, 4.0);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_filter_integral(filter: *const NyqFilter, out: *mut f32) -> NyqStatus {
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe { query(filter, out, |f| Ok(f.integral()), put) }
}

/// Draws a filter offset from `(u0, u1) ∈ [0, 1)²` (values outside are clamped; NaN counts as
/// 0) with density ∝ `|f|` and writes it with its weight `f/pdf` to `*out`: the core's
/// [`FilterSampler::sample`](nyquist::filter::FilterSampler::sample) on a 32 × 32 grid.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null.
///
/// # Safety
/// `filter` is null or a live handle; `out` is null or valid for writing one
/// `NyqFilterSample`.
///
/// ```
/// use nyquist_capi::*;
/// let mut f: *mut NyqFilter = std::ptr::null_mut();
/// let mut s = NyqFilterSample { offset: [9.0; 2], weight: 0.0 };
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_filter_create(c"box".as_ptr(), &mut f);
///     assert_eq!(nyq_filter_sample(f, 0.5, 0.25, &mut s), NyqStatus::NYQ_OK);
///     nyq_filter_destroy(f);
/// }
/// assert_eq!(s, NyqFilterSample { offset: [0.0, -0.25], weight: 1.0 });
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_filter_sample(
    filter: *const NyqFilter,
    u0: f32,
    u1: f32,
    out: *mut NyqFilterSample,
) -> NyqStatus {
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe { query(filter, out, |f| Ok(f.sampler.sample([u0, u1])), put) }
}

/// Writes the density [`nyq_filter_sample`] draws offset `(x, y)` with to `*out` (0 outside
/// the support, for NaN, and for a filter that is zero everywhere).
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null.
///
/// # Safety
/// `filter` is null or a live handle; `out` is null or valid for writing one `float`.
///
/// ```
/// use nyquist_capi::*;
/// let mut f: *mut NyqFilter = std::ptr::null_mut();
/// let mut p = 0.0f32;
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_filter_create(c"box".as_ptr(), &mut f);
///     assert_eq!(nyq_filter_pdf(f, 0.1, 0.1, &mut p), NyqStatus::NYQ_OK);
///     nyq_filter_destroy(f);
/// }
/// assert_eq!(p, 1.0);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_filter_pdf(
    filter: *const NyqFilter,
    x: f32,
    y: f32,
    out: *mut f32,
) -> NyqStatus {
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe { query(filter, out, |f| Ok(f.sampler.pdf([x, y])), put) }
}

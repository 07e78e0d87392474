//! The status code every function returns, and its messages.

use core::ffi::c_char;

use nyquist::Error;
use nyquist::sampler::NamedSamplerError;

/// What a `nyq_` function did: [`NyqStatus::NYQ_OK`] (0) or why it refused. On any status but
/// `NYQ_OK` the function has written nothing through its out-parameters.
///
/// ```
/// use nyquist_capi::NyqStatus;
/// assert_eq!(NyqStatus::NYQ_OK as i32, 0);
/// assert_eq!(NyqStatus::from(nyquist::Error::ZeroSize { what: "dims" }), NyqStatus::NYQ_ERR_ZERO_SIZE);
/// ```
#[repr(C)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NyqStatus {
    /// Success.
    NYQ_OK = 0,
    /// A required pointer (handle, out-parameter, buffer or string) was null.
    NYQ_ERR_NULL = 1,
    /// A count, size or buffer length was zero.
    NYQ_ERR_ZERO_SIZE = 2,
    /// A float parameter was NaN or infinite.
    NYQ_ERR_NON_FINITE = 3,
    /// A parameter (base index, dimension, point index, spp, radius, kind, …) was out of range.
    NYQ_ERR_OUT_OF_RANGE = 4,
    /// A buffer length did not fit the request (not a multiple of the point size, too short or
    /// too long), or a buffer was misaligned or larger than the address space allows.
    NYQ_ERR_BUFFER = 5,
    /// A count was too large (more points than fit, an index range past the end).
    NYQ_ERR_TOO_MANY = 6,
    /// A name or spec string did not parse (unknown sampler or filter, bad key or value, not
    /// UTF-8).
    NYQ_ERR_PARSE = 7,
    /// An error this version of the C API does not classify (a newer core error).
    NYQ_ERR_OTHER = 8,
}

impl From<Error> for NyqStatus {
    fn from(e: Error) -> NyqStatus {
        match e {
            Error::ZeroSize { .. } => NyqStatus::NYQ_ERR_ZERO_SIZE,
            Error::NonFinite { .. } => NyqStatus::NYQ_ERR_NON_FINITE,
            Error::OutOfRange { .. }
            | Error::NotInRange { .. }
            | Error::Invalid { .. }
            | Error::NotSeparable { .. }
            | Error::DimensionOutOfRange { .. } => NyqStatus::NYQ_ERR_OUT_OF_RANGE,
            Error::BufferLength { .. } | Error::BufferTooShort { .. } => NyqStatus::NYQ_ERR_BUFFER,
            Error::TooMany { .. } => NyqStatus::NYQ_ERR_TOO_MANY,
            _ => NyqStatus::NYQ_ERR_OTHER,
        }
    }
}

impl From<NamedSamplerError> for NyqStatus {
    fn from(e: NamedSamplerError) -> NyqStatus {
        match e {
            NamedSamplerError::UnknownName => NyqStatus::NYQ_ERR_PARSE,
            NamedSamplerError::SppAboveLimit { .. } => NyqStatus::NYQ_ERR_OUT_OF_RANGE,
            NamedSamplerError::Sampler(e) => e.into(),
            _ => NyqStatus::NYQ_ERR_OTHER,
        }
    }
}

/// A static, NUL-terminated English description of `status` (a [`NyqStatus`] value); unknown
/// values give `"unknown status"`. Never null; the caller must not free it. Total.
///
/// ```
/// use std::ffi::CStr;
/// use nyquist_capi::{NyqStatus, nyq_status_message};
/// let m = nyq_status_message(NyqStatus::NYQ_ERR_NULL as u32);
/// // SAFETY: the message is a static NUL-terminated string.
/// assert_eq!(unsafe { CStr::from_ptr(m) }.to_str(), Ok("null pointer"));
/// ```
#[unsafe(no_mangle)]
pub extern "C" fn nyq_status_message(status: u32) -> *const c_char {
    let s: &'static core::ffi::CStr = match status {
        0 => c"ok",
        1 => c"null pointer",
        2 => c"zero size",
        3 => c"non-finite parameter",
        4 => c"parameter out of range",
        5 => c"buffer length or alignment does not fit",
        6 => c"count too large",
        7 => c"name or spec does not parse",
        8 => c"other error",
        _ => c"unknown status",
    };
    s.as_ptr()
}

/// The version of this library, a static NUL-terminated string such as `"0.1.0"`. Never null.
///
/// ```
/// use std::ffi::CStr;
/// // SAFETY: the version is a static NUL-terminated string.
/// let v = unsafe { CStr::from_ptr(nyquist_capi::nyq_version()) };
/// assert_eq!(v.to_str(), Ok(env!("CARGO_PKG_VERSION")));
/// ```
#[unsafe(no_mangle)]
pub extern "C" fn nyq_version() -> *const c_char {
    const V: &str = concat!(env!("CARGO_PKG_VERSION"), "\0");
    V.as_ptr().cast()
}

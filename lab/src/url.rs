//! Percent-decoding of URL paths and query values, for the explorer's requests and the
//! command's static server.

/// Why [`percent_decode`] refused its text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DecodeError {
    /// A `%` not followed by two hex digits.
    BadEscape,
    /// The decoded bytes are not UTF-8.
    NotUtf8,
}

/// `%XX` decoding (no `+` rule: that belongs to query strings).
///
/// ```
/// use nyquist_lab::url::{DecodeError, percent_decode};
/// assert_eq!(percent_decode("a%20b+c").as_deref(), Ok("a b+c"));
/// assert_eq!(percent_decode("%zz"), Err(DecodeError::BadEscape));
/// assert_eq!(percent_decode("%ff"), Err(DecodeError::NotUtf8));
/// ```
///
/// # Errors
/// [`DecodeError`].
pub fn percent_decode(s: &str) -> Result<String, DecodeError> {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' {
            let hex = s
                .get(i + 1..i + 3)
                .and_then(|h| u8::from_str_radix(h, 16).ok())
                .ok_or(DecodeError::BadEscape)?;
            out.push(hex);
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    String::from_utf8(out).map_err(|_| DecodeError::NotUtf8)
}

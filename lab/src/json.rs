//! Numbers and strings for the JSON reports the front ends print.
//!
//! ```
//! use nyquist_lab::json::{json_number, json_string};
//! assert_eq!(json_number(f64::NAN), "null");
//! assert_eq!(json_string("a\"b"), "\"a\\\"b\"");
//! ```

/// A number for JSON: `null` where it is not finite.
pub fn json_number(x: f64) -> String {
    if x.is_finite() {
        format!("{x}")
    } else {
        "null".into()
    }
}

/// A string for JSON.
pub fn json_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

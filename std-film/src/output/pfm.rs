//! Portable float map (PFM): `PF\n<w> <h>\n-1.0\n` then little-endian `f32` RGB rows from the
//! bottom row up (the format's convention).

use crate::error::Error;
use crate::image::Image;
use std::io::{Read, Write};

/// Writes `image` as a little-endian colour PFM.
///
/// # Errors
/// [`Error::Io`] if writing fails.
///
/// ```
/// use nyquist_film::{output::pfm::{read_pfm, write_pfm}, Image};
/// let img = Image::from_fn(3, 2, |x, y| [x as f32, y as f32, 0.5]);
/// let mut bytes = Vec::new();
/// write_pfm(&mut bytes, &img).unwrap();
/// assert_eq!(read_pfm(&mut bytes.as_slice()).unwrap(), img);
/// ```
pub fn write_pfm(w: &mut dyn Write, image: &Image) -> Result<(), Error> {
    write!(w, "PF\n{} {}\n-1.0\n", image.width(), image.height())?;
    let row = image.width() as usize * 3;
    let mut bytes = Vec::with_capacity(row * 4);
    for y in (0..image.height() as usize).rev() {
        bytes.clear();
        for v in &image.data()[y * row..(y + 1) * row] {
            bytes.extend_from_slice(&v.to_le_bytes());
        }
        w.write_all(&bytes)?;
    }
    Ok(())
}

/// Reads a colour PFM (either byte order).
///
/// # Errors
/// [`Error::Format`] for a malformed header or short data, [`Error::Io`] for read failures.
///
/// ```
/// let bad = b"P5\n1 1\n255\n\0";
/// assert!(nyquist_film::output::pfm::read_pfm(&mut bad.as_slice()).is_err());
/// ```
pub fn read_pfm(r: &mut dyn Read) -> Result<Image, Error> {
    let mut all = Vec::new();
    r.read_to_end(&mut all)?;
    let bad = |m: &str| Error::Format(format!("PFM: {m}"));
    // Header: three whitespace-separated tokens after "PF", then exactly one whitespace byte.
    let mut tokens = Vec::new();
    let mut pos = 0;
    while tokens.len() < 4 {
        while pos < all.len() && all[pos].is_ascii_whitespace() {
            pos += 1;
        }
        let start = pos;
        while pos < all.len() && !all[pos].is_ascii_whitespace() {
            pos += 1;
        }
        if start == pos {
            return Err(bad("truncated header"));
        }
        tokens.push(String::from_utf8_lossy(&all[start..pos]).into_owned());
    }
    pos += 1; // the single whitespace byte after the scale
    if tokens[0] != "PF" {
        return Err(bad("not a colour PFM (expected 'PF')"));
    }
    let width: u32 = tokens[1].parse().map_err(|_| bad("bad width"))?;
    let height: u32 = tokens[2].parse().map_err(|_| bad("bad height"))?;
    let scale: f32 = tokens[3].parse().map_err(|_| bad("bad scale"))?;
    let little = scale < 0.0;
    let mut image = Image::new(width, height).map_err(|_| bad("bad size"))?;
    let row = width as usize * 3;
    let needed = row * height as usize * 4;
    let data = all
        .get(pos..pos + needed)
        .ok_or_else(|| bad("short data"))?;
    for (k, chunk) in data.chunks_exact(4).enumerate() {
        let b = [chunk[0], chunk[1], chunk[2], chunk[3]];
        let v = if little {
            f32::from_le_bytes(b)
        } else {
            f32::from_be_bytes(b)
        };
        let (file_row, col) = (k / row, k % row);
        let y = height as usize - 1 - file_row;
        image.data_mut()[y * row + col] = v;
    }
    Ok(image)
}

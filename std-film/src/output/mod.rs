//! Image writers and readers: PNG (8-bit sRGB), OpenEXR (f32 or f16) and PFM.
//!
//! Writers take any [`Write`]; [`write_image_file`] adds the safe file handling: the bytes go to a
//! temporary file in the target's folder, which is renamed into place only after a complete write,
//! so a failure never leaves a half-written image.

pub mod exr;
pub mod pfm;
pub mod png;

use crate::error::Error;
use crate::image::Image;
use std::io::Write;
use std::path::Path;

/// The image file formats, chosen by extension.
///
/// ```
/// use nyquist_film::ImageFormat;
/// assert_eq!(ImageFormat::from_path("a/b.PNG".as_ref()).unwrap(), ImageFormat::Png);
/// assert!(ImageFormat::from_path("a.tiff".as_ref()).is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageFormat {
    /// 8-bit sRGB PNG.
    Png,
    /// OpenEXR, 32-bit float channels.
    Exr,
    /// OpenEXR, 16-bit half-float channels.
    ExrHalf,
    /// Portable float map, 32-bit float RGB.
    Pfm,
}

impl ImageFormat {
    /// The format for a path's extension (`.png`, `.exr`, `.pfm`, case-insensitive).
    ///
    /// # Errors
    /// [`Error::Config`] for any other extension.
    pub fn from_path(path: &Path) -> Result<ImageFormat, Error> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("png") => Ok(ImageFormat::Png),
            Some("exr") => Ok(ImageFormat::Exr),
            Some("pfm") => Ok(ImageFormat::Pfm),
            _ => Err(Error::Config(format!(
                "{}: unknown image extension (expected .png, .exr or .pfm)",
                path.display()
            ))),
        }
    }
}

/// Writes `image` in `format` to `w` (PNG with default options).
///
/// # Errors
/// [`Error::Io`] if writing fails, [`Error::Format`] if the encoder rejects the image.
///
/// ```
/// use nyquist_film::{write_image, Image, ImageFormat};
/// let mut out = Vec::new();
/// write_image(&mut out, &Image::new(2, 2).unwrap(), ImageFormat::Pfm).unwrap();
/// assert!(out.starts_with(b"PF\n2 2\n"));
/// ```
pub fn write_image(w: &mut dyn Write, image: &Image, format: ImageFormat) -> Result<(), Error> {
    match format {
        ImageFormat::Png => png::write_png(w, image, &png::PngOptions::default()),
        ImageFormat::Exr => exr::write_exr(w, image, exr::ExrPrecision::F32),
        ImageFormat::ExrHalf => exr::write_exr(w, image, exr::ExrPrecision::F16),
        ImageFormat::Pfm => pfm::write_pfm(w, image),
    }
}

/// Writes `image` to `path` in the format its extension names, atomically: a temporary file in
/// the same folder, renamed into place after a complete write; on error nothing is left behind.
///
/// # Errors
/// [`Error::Config`] for an unknown extension, [`Error::File`] (naming `path`) when the file
/// cannot be created, written or renamed into place, [`Error::Format`] if the encoder fails.
///
/// ```
/// let dir = std::env::temp_dir();
/// let path = dir.join(format!("nyquist-doc-{}.pfm", std::process::id()));
/// let img = nyquist_film::Image::new(1, 1).unwrap();
/// nyquist_film::write_image_file(&path, &img).unwrap();
/// assert!(path.exists());
/// std::fs::remove_file(&path).unwrap();
/// let missing = dir.join("nyquist-no-such-folder/x.png");
/// let e = nyquist_film::write_image_file(&missing, &img).unwrap_err();
/// assert!(e.to_string().starts_with(&format!("{}: ", missing.display())), "{e}");
/// ```
pub fn write_image_file(path: &Path, image: &Image) -> Result<(), Error> {
    let format = ImageFormat::from_path(path)?;
    write_file_atomic(path, |w| write_image(w, image, format))
}

/// Runs `write` on a temporary file beside `path` and renames it into place on success; removes
/// it on failure. A `path` that exists and is neither a regular file nor a folder (a device
/// such as `/dev/null`, a FIFO) is written in place: it cannot be replaced atomically, and
/// renaming over it would replace the device with a regular file.
///
/// # Errors
/// Whatever `write` returns, with its stream errors as [`Error::File`] naming `path`;
/// [`Error::File`] for create, flush and rename failures; [`Error::Config`] if `path` has no
/// file name.
///
/// ```
/// use std::io::Write;
/// let path = std::env::temp_dir().join(format!("nyquist-atomic-{}.txt", std::process::id()));
/// let r = nyquist_film::output::write_file_atomic(&path, |_| {
///     Err(nyquist_film::Error::Format("refused".into()))
/// });
/// assert!(r.is_err() && !path.exists());
/// ```
pub fn write_file_atomic(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> Result<(), Error>,
) -> Result<(), Error> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let name = path
        .file_name()
        .ok_or_else(|| Error::Config(format!("{}: not a file name", path.display())))?;
    if std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
        return (|| {
            let file = std::fs::OpenOptions::new().write(true).open(path)?;
            let mut w = std::io::BufWriter::new(file);
            write(&mut w)?;
            Ok(w.flush()?)
        })()
        .map_err(|e: Error| e.at(path));
    }
    let tmp = dir.join(format!(
        ".{}.tmp-{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let result = (|| {
        let file = std::fs::File::create(&tmp)?;
        let mut w = std::io::BufWriter::new(file);
        write(&mut w)?;
        let file = w.into_inner().map_err(|e| Error::Io(e.into_error()))?;
        file.sync_all()?;
        std::fs::rename(&tmp, path)?;
        Ok(())
    })()
    .map_err(|e: Error| e.at(path));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

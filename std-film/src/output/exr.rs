//! OpenEXR output and read-back through the `exr` crate (single-threaded, so the bytes are
//! deterministic).

use crate::error::Error;
use crate::image::Image;
use ::exr::prelude::{self as x, ReadChannels, ReadLayers, ReadSpecificChannel, WritableImage};
use std::io::{Cursor, Read, Write};

/// Channel precision of an OpenEXR file.
///
/// ```
/// use nyquist_film::output::exr::ExrPrecision;
/// assert_ne!(ExrPrecision::F32, ExrPrecision::F16);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExrPrecision {
    /// 32-bit float channels (lossless for an [`Image`]).
    F32,
    /// 16-bit half-float channels.
    F16,
}

/// Writes `image` as an RGB OpenEXR file with ZIP compression.
///
/// # Errors
/// [`Error::Format`] if the encoder fails, [`Error::Io`] if writing fails.
///
/// ```
/// use nyquist_film::{output::exr::{read_exr, write_exr, ExrPrecision}, Image};
/// let img = Image::from_fn(3, 2, |x, y| [x as f32 * 0.25, y as f32, -1.5]);
/// let mut bytes = Vec::new();
/// write_exr(&mut bytes, &img, ExrPrecision::F32).unwrap();
/// assert_eq!(read_exr(&mut bytes.as_slice()).unwrap(), img);
/// ```
pub fn write_exr(w: &mut dyn Write, image: &Image, precision: ExrPrecision) -> Result<(), Error> {
    let size = (image.width() as usize, image.height() as usize);
    let mut buffer = Cursor::new(Vec::new());
    let encoding = x::Encoding::SMALL_LOSSLESS;
    match precision {
        ExrPrecision::F32 => {
            let channels = x::SpecificChannels::rgb(|p: x::Vec2<usize>| {
                let [r, g, b] = image.get(p.x() as u32, p.y() as u32);
                (r, g, b)
            });
            let layer = x::Layer::new(size, x::LayerAttributes::default(), encoding, channels);
            x::Image::from_layer(layer)
                .write()
                .non_parallel()
                .to_buffered(&mut buffer)
                .map_err(exr_error)?;
        }
        ExrPrecision::F16 => {
            let channels = x::SpecificChannels::rgb(|p: x::Vec2<usize>| {
                let [r, g, b] = image.get(p.x() as u32, p.y() as u32);
                (
                    x::f16::from_f32(r),
                    x::f16::from_f32(g),
                    x::f16::from_f32(b),
                )
            });
            let layer = x::Layer::new(size, x::LayerAttributes::default(), encoding, channels);
            x::Image::from_layer(layer)
                .write()
                .non_parallel()
                .to_buffered(&mut buffer)
                .map_err(exr_error)?;
        }
    }
    w.write_all(buffer.get_ref())?;
    Ok(())
}

/// Writes one layer of named 32-bit float channels (`planes`: name and row-major samples of
/// `width × height` each; for example a four-channel threshold mask as R, G, B, A), ZIP
/// compressed. Channels are stored in the alphabetical order OpenEXR requires.
///
/// # Errors
/// [`Error::Format`] if there are no planes, a plane's length is not `width · height`, or the
/// encoder fails; [`Error::Io`] if writing fails.
///
/// ```
/// use nyquist_film::output::exr::write_exr_planes;
/// let mut bytes = Vec::new();
/// write_exr_planes(&mut bytes, 2, 1, &[("R", &[0.25, 0.75]), ("A", &[0.5, 0.0])]).unwrap();
/// assert_eq!(&bytes[..4], &[0x76, 0x2f, 0x31, 0x01]); // the OpenEXR magic number
/// assert!(write_exr_planes(&mut bytes, 2, 1, &[("R", &[0.25])]).is_err());
/// ```
pub fn write_exr_planes(
    w: &mut dyn Write,
    width: u32,
    height: u32,
    planes: &[(&str, &[f32])],
) -> Result<(), Error> {
    let n = width as usize * height as usize;
    if planes.is_empty() || planes.iter().any(|(_, p)| p.len() != n) {
        return Err(Error::Format(format!(
            "OpenEXR: every plane needs {n} samples ({width}x{height})"
        )));
    }
    let list: x::SmallVec<[x::AnyChannel<x::FlatSamples>; 4]> = planes
        .iter()
        .map(|(name, p)| x::AnyChannel::new(*name, x::FlatSamples::F32(p.to_vec())))
        .collect();
    let layer = x::Layer::new(
        (width as usize, height as usize),
        x::LayerAttributes::default(),
        x::Encoding::SMALL_LOSSLESS,
        x::AnyChannels::sort(list),
    );
    let mut buffer = Cursor::new(Vec::new());
    x::Image::from_layer(layer)
        .write()
        .non_parallel()
        .to_buffered(&mut buffer)
        .map_err(exr_error)?;
    w.write_all(buffer.get_ref())?;
    Ok(())
}

/// Reads the first RGB layer of an OpenEXR file (any channel precision, converted to `f32`).
///
/// # Errors
/// [`Error::Format`] if the data is not a readable OpenEXR file with R, G and B channels.
///
/// ```
/// assert!(nyquist_film::output::exr::read_exr(&mut b"not exr".as_slice()).is_err());
/// ```
pub fn read_exr(r: &mut dyn Read) -> Result<Image, Error> {
    let mut all = Vec::new();
    r.read_to_end(&mut all)?;
    let read = x::read()
        .no_deep_data()
        .largest_resolution_level()
        .specific_channels()
        .required("R")
        .required("G")
        .required("B")
        .collect_pixels(
            |res: x::Vec2<usize>, _| (res.width(), vec![0.0f32; res.width() * res.height() * 3]),
            |(w, data): &mut (usize, Vec<f32>), p: x::Vec2<usize>, (r, g, b): (f32, f32, f32)| {
                let o = (p.y() * *w + p.x()) * 3;
                data[o..o + 3].copy_from_slice(&[r, g, b]);
            },
        )
        .first_valid_layer()
        .all_attributes()
        .non_parallel()
        .from_buffered(Cursor::new(all))
        .map_err(exr_error)?;
    let layer = read.layer_data;
    let size = layer.size;
    let (_, data) = layer.channel_data.pixels;
    let (w, h) = (
        u32::try_from(size.width()).map_err(|_| Error::Format("OpenEXR: too wide".into()))?,
        u32::try_from(size.height()).map_err(|_| Error::Format("OpenEXR: too tall".into()))?,
    );
    Image::from_rgb(w, h, data)
}

pub use crate::extras::Plane;

/// Reads every channel of the first layer of an OpenEXR file, by name in the file's
/// (alphabetical) order, each converted to `f32` and row-major: the reader for
/// [`write_exr_planes`] and for any single-part file with named layers (`variance.R`, …).
///
/// # Errors
/// [`Error::Format`] if the data is not a readable OpenEXR file or its size does not fit `u32`.
///
/// ```
/// use nyquist_film::output::exr::{read_exr_planes, write_exr_planes};
/// let mut bytes = Vec::new();
/// write_exr_planes(&mut bytes, 2, 1, &[("depth.Z", &[1.5, 2.0]), ("R", &[0.25, 0.75])]).unwrap();
/// let (w, h, planes) = read_exr_planes(&mut bytes.as_slice()).unwrap();
/// assert_eq!((w, h), (2, 1));
/// assert_eq!(planes, [("R".to_string(), vec![0.25, 0.75]), ("depth.Z".to_string(), vec![1.5, 2.0])]);
/// ```
pub fn read_exr_planes(r: &mut dyn Read) -> Result<(u32, u32, Vec<Plane>), Error> {
    let mut all = Vec::new();
    r.read_to_end(&mut all)?;
    let read = x::read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .non_parallel()
        .from_buffered(Cursor::new(all))
        .map_err(exr_error)?;
    let layer = read.layer_data;
    let size = layer.size;
    let (w, h) = (
        u32::try_from(size.width()).map_err(|_| Error::Format("OpenEXR: too wide".into()))?,
        u32::try_from(size.height()).map_err(|_| Error::Format("OpenEXR: too tall".into()))?,
    );
    let planes = layer
        .channel_data
        .list
        .into_iter()
        .map(|c| {
            let values = match c.sample_data {
                x::FlatSamples::F16(v) => v.into_iter().map(f32::from).collect(),
                x::FlatSamples::F32(v) => v,
                x::FlatSamples::U32(v) => v.into_iter().map(|v| v as f32).collect(),
            };
            (c.name.to_string(), values)
        })
        .collect();
    Ok((w, h, planes))
}

/// An OpenEXR error as the film's: the stream's I/O errors as [`Error::Io`], the rest as
/// [`Error::Format`].
fn exr_error(e: ::exr::error::Error) -> Error {
    match e {
        ::exr::error::Error::Io(e) => Error::Io(e),
        e => Error::Format(format!("OpenEXR: {e}")),
    }
}

//! A linear-RGB `f32` image.

use crate::Error;

/// A linear-RGB image, `f32` per channel, rows top to bottom, pixels left to right.
///
/// ```
/// let mut img = nyquist_film::Image::new(4, 3).unwrap();
/// img.set(1, 2, [0.5, 0.25, 1.0]);
/// assert_eq!(img.get(1, 2), [0.5, 0.25, 1.0]);
/// assert_eq!(img.data().len(), 4 * 3 * 3);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    width: u32,
    height: u32,
    data: Vec<f32>,
}

impl Image {
    /// A black image.
    ///
    /// # Errors
    /// [`Error::Config`] if a side is zero or the pixel count overflows memory limits;
    /// [`Error::OutOfMemory`] if the allocator cannot provide the pixels.
    pub fn new(width: u32, height: u32) -> Result<Image, Error> {
        let len = Self::data_len(width, height)?;
        Ok(Image {
            width,
            height,
            data: crate::error::try_filled(len, 0.0, "an image")?,
        })
    }

    fn data_len(width: u32, height: u32) -> Result<usize, Error> {
        if width == 0 || height == 0 {
            return Err(Error::Config(format!(
                "image size {width}x{height}: both sides must be positive"
            )));
        }
        (width as usize)
            .checked_mul(height as usize)
            .and_then(|n| n.checked_mul(3))
            .filter(|&n| n <= isize::MAX as usize / 4)
            .ok_or_else(|| Error::Config(format!("image size {width}x{height} is too large")))
    }

    /// An image whose pixel `(x, y)` is `f(x, y)`.
    ///
    /// # Panics
    /// If a side is zero (use [`Image::new`] to get an error instead).
    ///
    /// ```
    /// let img = nyquist_film::Image::from_fn(2, 2, |x, y| [x as f32, y as f32, 0.0]);
    /// assert_eq!(img.get(1, 0), [1.0, 0.0, 0.0]);
    /// ```
    pub fn from_fn(width: u32, height: u32, mut f: impl FnMut(u32, u32) -> [f32; 3]) -> Image {
        let mut img = Image::new(width, height).expect("positive image size");
        for y in 0..height {
            for x in 0..width {
                img.set(x, y, f(x, y));
            }
        }
        img
    }

    /// An image over existing RGB data (`width × height × 3` floats).
    ///
    /// # Errors
    /// [`Error::Config`] if the length does not match.
    ///
    /// ```
    /// assert!(nyquist_film::Image::from_rgb(1, 1, vec![0.0; 3]).is_ok());
    /// assert!(nyquist_film::Image::from_rgb(1, 1, vec![0.0; 4]).is_err());
    /// ```
    pub fn from_rgb(width: u32, height: u32, data: Vec<f32>) -> Result<Image, Error> {
        let len = Self::data_len(width, height)?;
        if data.len() != len {
            return Err(Error::Config(format!(
                "{} floats given for a {width}x{height} RGB image ({len} needed)",
                data.len()
            )));
        }
        Ok(Image {
            width,
            height,
            data,
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The RGB floats, row-major from the top row.
    pub fn data(&self) -> &[f32] {
        &self.data
    }

    /// The RGB floats, mutable.
    pub fn data_mut(&mut self) -> &mut [f32] {
        &mut self.data
    }

    fn offset(&self, x: u32, y: u32) -> usize {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside the image"
        );
        (y as usize * self.width as usize + x as usize) * 3
    }

    /// Pixel `(x, y)`.
    ///
    /// # Panics
    /// If `(x, y)` is outside the image.
    pub fn get(&self, x: u32, y: u32) -> [f32; 3] {
        let o = self.offset(x, y);
        [self.data[o], self.data[o + 1], self.data[o + 2]]
    }

    /// Sets pixel `(x, y)`.
    ///
    /// # Panics
    /// If `(x, y)` is outside the image.
    pub fn set(&mut self, x: u32, y: u32, rgb: [f32; 3]) {
        let o = self.offset(x, y);
        self.data[o..o + 3].copy_from_slice(&rgb);
    }
}

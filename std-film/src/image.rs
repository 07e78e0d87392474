//! A linear-RGB `f32` image.

use crate::error::Error;

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
    /// [`Error::OutOfRange`] if a side is zero; [`Error::Config`] if the pixel count overflows
    /// memory limits; [`Error::OutOfMemory`] if the allocator cannot provide the pixels.
    ///
    /// ```
    /// let e = nyquist_film::Image::new(0, 3).unwrap_err();
    /// assert_eq!(e.to_string(), "image width 0 is outside 1..=4294967295");
    /// ```
    pub fn new(width: u32, height: u32) -> Result<Image, Error> {
        let len = Self::data_len(width, height)?;
        Ok(Image {
            width,
            height,
            data: crate::error::try_filled(len, 0.0, "an image")?,
        })
    }

    fn data_len(width: u32, height: u32) -> Result<usize, Error> {
        for (what, side) in [("image width", width), ("image height", height)] {
            if side == 0 {
                return Err(Error::below_one(what, 0, f64::from(u32::MAX)));
            }
        }
        // The floats of the image, at most what one allocation can hold.
        const LIMIT: usize = isize::MAX as usize / 4;
        let floats = u128::from(width) * u128::from(height) * 3;
        usize::try_from(floats)
            .ok()
            .filter(|&n| n <= LIMIT)
            .ok_or_else(|| {
                Error::Config(format!(
                    "image size {width}x{height} needs {floats} floats, more than the {LIMIT} \
                     an allocation can hold"
                ))
            })
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
    ///
    /// ```
    /// assert_eq!(nyquist_film::Image::new(4, 3).unwrap().width(), 4);
    /// ```
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    ///
    /// ```
    /// assert_eq!(nyquist_film::Image::new(4, 3).unwrap().height(), 3);
    /// ```
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The RGB floats, row-major from the top row.
    ///
    /// ```
    /// let img = nyquist_film::Image::from_fn(2, 1, |x, _| [x as f32, 0.5, 0.25]);
    /// assert_eq!(img.data(), &[0.0, 0.5, 0.25, 1.0, 0.5, 0.25]);
    /// ```
    pub fn data(&self) -> &[f32] {
        &self.data
    }

    /// The RGB floats, mutable.
    ///
    /// ```
    /// let mut img = nyquist_film::Image::new(2, 1).unwrap();
    /// img.data_mut()[3] = 1.0;
    /// assert_eq!(img.get(1, 0), [1.0, 0.0, 0.0]);
    /// ```
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
    ///
    /// ```
    /// let img = nyquist_film::Image::from_fn(3, 2, |x, y| [x as f32, y as f32, 0.0]);
    /// assert_eq!(img.get(2, 1), [2.0, 1.0, 0.0]);
    /// ```
    pub fn get(&self, x: u32, y: u32) -> [f32; 3] {
        let o = self.offset(x, y);
        [self.data[o], self.data[o + 1], self.data[o + 2]]
    }

    /// Sets pixel `(x, y)`.
    ///
    /// # Panics
    /// If `(x, y)` is outside the image.
    ///
    /// ```
    /// let mut img = nyquist_film::Image::new(3, 2).unwrap();
    /// img.set(2, 1, [0.5; 3]);
    /// assert_eq!(img.get(2, 1), [0.5; 3]);
    /// ```
    pub fn set(&mut self, x: u32, y: u32, rgb: [f32; 3]) {
        let o = self.offset(x, y);
        self.data[o..o + 3].copy_from_slice(&rgb);
    }
}

//! The request: the page's URL query (`view=points&sampler=halton&count=256`), decoded, with
//! typed getters whose errors name the parameter, the value and the limit.

use anyhow::{Result, anyhow, bail};

/// Decoded `key=value` pairs; every key must be read (see [`Query::finish`]).
#[derive(Debug)]
pub struct Query {
    /// In the order given (a handful: a list keeps the ordered-map code out of the module).
    values: Vec<(String, String)>,
    used: std::cell::RefCell<Vec<String>>,
}

/// `%XX` and `+` decoding of one query component (`+` is a space in a query string).
fn decode(s: &str) -> Result<String> {
    use nyquist_lab::url::{DecodeError, percent_decode};
    percent_decode(&s.replace('+', " ")).map_err(|e| match e {
        DecodeError::BadEscape => anyhow!("query: bad escape in {s:?}"),
        DecodeError::NotUtf8 => anyhow!("query: {s:?} is not UTF-8"),
    })
}

impl Query {
    /// Parses `a=1&b=x%2Cy` (a leading `?` is allowed; empty pairs are skipped).
    ///
    /// ```
    /// let q = nyquist_web::query::Query::parse("?view=filters&filter=mitchell%3Ab%3D0.5").unwrap();
    /// assert_eq!(q.text("filter", "box"), "mitchell:b=0.5");
    /// assert_eq!(q.text("view", ""), "filters");
    /// q.finish().unwrap();
    /// assert!(nyquist_web::query::Query::parse("a=1&a=2").is_err());
    /// ```
    ///
    /// # Errors
    /// A bad `%` escape, non-UTF-8 text, or a key given twice.
    pub fn parse(s: &str) -> Result<Query> {
        let mut values: Vec<(String, String)> = Vec::new();
        for pair in s
            .trim_start_matches('?')
            .split('&')
            .filter(|p| !p.is_empty())
        {
            let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
            let k = decode(k)?;
            if values.iter().any(|(seen, _)| *seen == k) {
                bail!("{k}: given twice");
            }
            values.push((k, decode(v)?));
        }
        Ok(Query {
            values,
            used: Default::default(),
        })
    }

    fn get(&self, key: &str) -> Option<&str> {
        self.used.borrow_mut().push(key.to_owned());
        self.values
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
            .filter(|v| !v.is_empty())
    }

    /// The text of `key`, or `default`.
    pub fn text(&self, key: &str, default: &str) -> String {
        self.get(key).unwrap_or(default).to_owned()
    }

    /// Whether `key` is present with a value.
    pub fn has(&self, key: &str) -> bool {
        self.get(key).is_some()
    }

    /// An integer in `lo ..= hi`, or `default` when absent.
    ///
    /// # Errors
    /// `key=value: need lo ..= hi` for text that is not such an integer.
    pub fn int(&self, key: &str, default: u64, lo: u64, hi: u64) -> Result<u64> {
        match self.get(key) {
            None => Ok(default),
            Some(v) => match v.trim().parse::<u64>() {
                Ok(n) if (lo..=hi).contains(&n) => Ok(n),
                _ => bail!("{key}={v}: need an integer in {lo} ..= {hi}"),
            },
        }
    }

    /// A comma-separated list (empty items dropped), or `default` when absent.
    pub fn list(&self, key: &str, default: &str) -> Vec<String> {
        self.text(key, default)
            .split(',')
            .map(|s| s.trim().to_owned())
            .filter(|s| !s.is_empty())
            .collect()
    }

    /// A clap value name (`zero-two`, `zoneplate`, …) of `T`, or `default`.
    ///
    /// # Errors
    /// `key=value: not one of …` listing the names.
    pub fn choice<T: clap::ValueEnum>(&self, key: &str, default: &str) -> Result<T> {
        let v = self.text(key, default);
        choice(key, &v)
    }

    /// Fails on a key no getter asked for (a typo in a hand-edited link).
    ///
    /// # Errors
    /// `key: unknown parameter`.
    pub fn finish(&self) -> Result<()> {
        let used = self.used.borrow();
        match self
            .values
            .iter()
            .map(|(k, _)| k)
            .find(|k| !used.contains(k))
        {
            Some(k) => bail!("{k}: unknown parameter"),
            None => Ok(()),
        }
    }
}

/// `v` as a clap value name of `T`.
///
/// # Errors
/// `key=v: not one of …`.
pub fn choice<T: clap::ValueEnum>(key: &str, v: &str) -> Result<T> {
    T::from_str(v, false).map_err(|_| anyhow!("{key}={v}: not one of {}", names::<T>().join(", ")))
}

/// The value names of `T` in declaration order.
pub fn names<T: clap::ValueEnum>() -> Vec<String> {
    T::value_variants()
        .iter()
        .filter_map(|v| v.to_possible_value())
        .map(|p| p.get_name().to_owned())
        .collect()
}

/// The value names of `T` with their one-line help.
pub fn described<T: clap::ValueEnum>() -> Vec<(String, String)> {
    T::value_variants()
        .iter()
        .filter_map(|v| v.to_possible_value())
        .map(|p| {
            // The raw text: these help strings carry no styling, and the styled `Display` would
            // bring clap's ANSI stripper (and its 4 KiB state table) into the module.
            let help = p
                .get_help()
                .map(|h| h.ansi().to_string())
                .unwrap_or_default();
            (p.get_name().to_owned(), help)
        })
        .collect()
}

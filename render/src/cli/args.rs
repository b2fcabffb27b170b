//! Argument parsers and the input error of the CLI.

pub fn parse_res(s: &str) -> Result<(usize, usize), String> {
    let bad = || format!("`{s}`: expected WIDTHxHEIGHT, e.g. 256x256 (each 1..=16384)");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: usize = w.trim().parse().map_err(|_| bad())?;
    let h: usize = h.trim().parse().map_err(|_| bad())?;
    if !(1..=16384).contains(&w) || !(1..=16384).contains(&h) {
        return Err(bad());
    }
    Ok((w, h))
}

/// A positive integer no larger than `max`.
pub fn positive_at_most<T: std::str::FromStr + PartialOrd + From<u8> + std::fmt::Display>(
    s: &str,
    max: T,
) -> Result<T, String> {
    match s.parse::<T>() {
        Ok(n) if n >= T::from(1) && n <= max => Ok(n),
        _ => Err(format!(
            "`{s}`: expected a positive integer (at most {max})"
        )),
    }
}

/// Samples per pixel.
pub fn positive_u32(s: &str) -> Result<u32, String> {
    positive_at_most(s, u32::MAX)
}

/// Threads and rounds: more than a few thousand is a typo, not a request.
pub fn positive_usize(s: &str) -> Result<usize, String> {
    positive_at_most(s, 4096)
}

/// Input problems: printed, exit status 2.
pub struct InputError(pub String);

impl<E: std::fmt::Display> From<E> for InputError {
    fn from(e: E) -> Self {
        InputError(e.to_string())
    }
}

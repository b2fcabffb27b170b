//! Argument parsers and the input error of the CLI.

use lpe_render::bench::BenchError;
use lpe_render::inputs::SourceError;
use lpe_render::integrator::RenderError;
use lpe_render::output::OutputError;
use lpe_render::scene::SceneError;
use lpe_render::verify::VerifyError;

/// A command-line value clap rejects.
#[derive(Debug, thiserror::Error)]
pub enum ArgError {
    #[error("`{arg}`: expected WIDTHxHEIGHT, e.g. 256x256 (each 1..=16384)")]
    Resolution { arg: String },
    #[error("`{arg}`: expected a positive integer (at most {max})")]
    NotPositive { arg: String, max: u64 },
}

/// Input problems: printed, exit status 2.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    #[error(transparent)]
    Sources(#[from] SourceError),
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error(transparent)]
    Render(#[from] RenderError),
    #[error(transparent)]
    Output(#[from] OutputError),
    #[error(transparent)]
    Verify(#[from] VerifyError),
    #[error(transparent)]
    Bench(#[from] BenchError),
    /// `--renderer`: an unknown name (with the known ones), or one the render cannot
    /// show or that contradicts `--dialect`.
    #[error("{0}")]
    Renderer(String),
}

pub fn parse_res(s: &str) -> Result<(usize, usize), ArgError> {
    let bad = || ArgError::Resolution { arg: s.into() };
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: usize = w.trim().parse().map_err(|_| bad())?;
    let h: usize = h.trim().parse().map_err(|_| bad())?;
    if !(1..=16384).contains(&w) || !(1..=16384).contains(&h) {
        return Err(bad());
    }
    Ok((w, h))
}

/// A positive integer no larger than `max`.
pub fn positive_at_most<T: std::str::FromStr + PartialOrd + From<u8> + Into<u64> + Copy>(
    s: &str,
    max: T,
) -> Result<T, ArgError> {
    match s.parse::<T>() {
        Ok(n) if n >= T::from(1) && n <= max => Ok(n),
        _ => Err(ArgError::NotPositive {
            arg: s.into(),
            max: max.into(),
        }),
    }
}

/// Samples per pixel.
pub fn positive_u32(s: &str) -> Result<u32, ArgError> {
    positive_at_most(s, u32::MAX)
}

/// Threads and rounds: more than a few thousand is a typo, not a request.
pub fn positive_usize(s: &str) -> Result<usize, ArgError> {
    positive_at_most(s, 4096u32).map(|n| n as usize)
}

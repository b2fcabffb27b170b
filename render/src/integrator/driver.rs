//! The driver: the row loop. Rows render in parallel, each pixel's samples in order, and
//! the film commits each finished sample.

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::time::Instant;

use super::contributions::Tally;
use super::settings::{Render, RenderError};
use super::setup::Integrator;
use crate::aov::matcher::RenderMatcher;
use crate::film::{Film, SampleValues, MAX_FILM_BYTES};
use crate::rng::Rng;

impl<M: RenderMatcher> Integrator<'_, M> {
    /// Renders the whole image; rows in parallel, each pixel's samples in order.
    pub fn render(&self) -> Result<Render, RenderError> {
        let s = self.settings;
        let (w, h) = (s.width, s.height);
        let n = self.weighting.len();
        let bytes = Film::bytes(w, h, 1 + n);
        if bytes > MAX_FILM_BYTES {
            return Err(RenderError::FilmTooLarge {
                width: w,
                height: h,
                aovs: n,
                bytes,
            });
        }
        let mut film = Film::new(w, h, s.spp, self.weighting.overwrite(), s.accumulation);
        let mut builder = rayon::ThreadPoolBuilder::new();
        if let Some(t) = s.threads {
            builder = builder.num_threads(t);
        }
        let pool = builder.build()?;
        let bar = if s.progress {
            ProgressBar::new(h as u64).with_style(
                ProgressStyle::with_template(
                    "{spinner} rendering [{bar:40}] {pos}/{len} rows {elapsed} (eta {eta})",
                )
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
            )
        } else {
            ProgressBar::hidden()
        };
        let start = Instant::now();
        let cpu_start = process_cpu_seconds();
        let (rejected, aov_rejected, rays) = pool.install(|| {
            film.rows_mut()
                .map(|(y, mut row)| {
                    let mut acc = Tally {
                        values: SampleValues::new(n),
                        rays: 0,
                    };
                    let mut rejected = 0;
                    let matches = |state| self.matcher.matches(state);
                    for x in 0..w {
                        for sample in 0..s.spp {
                            let index = (y * w + x) as u64;
                            let mut rng = Rng::for_sample(s.seed, index, sample as u64);
                            self.sample(x, y, &mut rng, &mut acc);
                            rejected +=
                                row.commit(&mut acc.values, &self.weighting, matches) as u64;
                        }
                        row.finish_pixel(x, &mut acc.values, &self.weighting, matches);
                    }
                    bar.inc(1);
                    (rejected, acc.values.aov_rejected, acc.rays)
                })
                .reduce(|| (0, 0, 0), |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2))
        });
        bar.finish_and_clear();
        film.rejected = rejected;
        film.aov_rejected = aov_rejected;
        Ok(Render {
            film,
            plan: self.plan,
            seconds: start.elapsed().as_secs_f64(),
            cpu_seconds: process_cpu_seconds() - cpu_start,
            paths: (w * h) as u64 * s.spp as u64,
            rays,
        })
    }
}

/// CPU time this process has used so far, all threads.
fn process_cpu_seconds() -> f64 {
    let t = rustix::time::clock_gettime(rustix::time::ClockId::ProcessCPUTime);
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

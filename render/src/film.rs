//! The film: per-pixel sums for beauty and every AOV.
//!
//! The renderer sums in f64: `sum of 10^7 samples of mixed magnitude` stays within about
//! 1e-13 relative of the exact sum, far inside the 1e-5 partition tolerance. `converge`
//! and `stress` compare it against the two f32 films a renderer might ship instead: a
//! naive one (drifts by ~1e-3 at that count, and the basic-AOV partition visibly fails)
//! and a compensated one (an f32 sum plus an f32 running error, renormalized after each
//! addition, so the stored estimate is within an f32 rounding or two of the exact sum
//! at any count).
//! The film owns accumulation: the integrator hands it [`Contribution`]s with the final
//! matcher state of their path, which a [`SampleValues`] weighs into beauty and the
//! matched AOVs by their prefixes ([`Weighting`]), and a [`FilmRow`] commits each
//! finished sample to its pixel with the film's [`Accumulation`], so the integrator does
//! not care which film it writes. Plain AOVs are summed per final state and expanded
//! into their layers once per pixel ([`by_state`]); AOVs with prefixes are routed per
//! contribution.

use glam::{DVec3, Vec3};
use rayon::prelude::*;

use crate::aov::matcher::AovMask;
use crate::aov::AovFlags;
use crate::sampling::max_component;

mod by_state;

use by_state::ByState;

/// How a film adds samples into its pixel sums (`converge` and `stress` compare them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub enum Accumulation {
    /// f64 sums: the renderer's film.
    #[default]
    F64,
    /// A naive f32 film: every running sum is rounded to f32 after each addition (stored
    /// in the f64 buffer, where an f32 value is exact), to show what f64 buys.
    F32,
    /// An f32 film with compensated summation: each sum carries an f32 compensation
    /// term holding the rounding error of the additions so far (a double-f32 pair,
    /// renormalized after every addition); the estimate is `sum + compensation` rounded
    /// to f32. Twice the memory of the naive f32 film, about the accuracy of a sum
    /// rounded once.
    F32Compensated,
}

impl Accumulation {
    pub const ALL: [Accumulation; 3] = [
        Accumulation::F64,
        Accumulation::F32,
        Accumulation::F32Compensated,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Accumulation::F64 => "f64",
            Accumulation::F32 => "f32 naive",
            Accumulation::F32Compensated => "f32 compensated",
        }
    }

    /// Values stored per layer: the sum, and for the compensated film its compensation.
    fn slots(self) -> usize {
        match self {
            Accumulation::F32Compensated => 2,
            _ => 1,
        }
    }

    /// Adds `x` to layer `layer` of one pixel's storage (`layers` sums, then for the
    /// compensated film `layers` compensations).
    #[inline]
    pub fn add(self, pixel: &mut [DVec3], layers: usize, layer: usize, x: DVec3) {
        match self {
            Accumulation::F64 => pixel[layer] += x,
            Accumulation::F32 => pixel[layer] = (pixel[layer].as_vec3() + x.as_vec3()).as_dvec3(),
            Accumulation::F32Compensated => {
                let (sum, comp) = compensated_add(
                    pixel[layer].as_vec3(),
                    pixel[layers + layer].as_vec3(),
                    x.as_vec3(),
                );
                pixel[layer] = sum.as_dvec3();
                pixel[layers + layer] = comp.as_dvec3();
            }
        }
    }

    /// The stored total of layer `layer` of one pixel: its sum, for the compensated film
    /// too. Its pair is renormalized at every addition (`compensated_add`: the
    /// compensation stays below half an ulp of the sum), so the pair rounded to one f32
    /// is the sum itself; adding the compensation back would change nothing but turn an
    /// overflowed sum's `(inf, NaN)` pair into NaN instead of inf.
    #[inline]
    fn total(pixel: &[DVec3], layer: usize) -> DVec3 {
        pixel[layer]
    }
}

/// `a + b` rounded, and its exact rounding error (Knuth's TwoSum: no branch, no
/// assumption on which operand is larger).
fn two_sum(a: Vec3, b: Vec3) -> (Vec3, Vec3) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Adds `x` to the pair `(sum, comp)`, whose exact value is `sum + comp` with `comp`
/// below half an f32 ulp of `sum`: the addition's rounding error joins the compensation
/// and the pair is renormalized at once, so `comp` never outgrows its ulp and its own
/// roundings are 2^-24 of an ulp of the total.
///
/// Neumaier's form (one compensation that grows unrenormalized) is not enough here: on
/// the `stress` pixel, whose naive f32 sum drifts by 1.4e-3, the compensation grows to
/// ~1e-3 of the sum, its additions round at that scale, and the basic-AOV partition
/// missed beauty by 1.3e-6 after 10^7 samples (`cargo test --release -p lpe-render
/// --test hard_cases ten_million`); renormalized, it stays far inside 1e-6.
fn compensated_add(sum: Vec3, comp: Vec3, x: Vec3) -> (Vec3, Vec3) {
    let (t, e) = two_sum(sum, x);
    two_sum(t, comp + e)
}

/// Accumulated samples for an image.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    pub width: usize,
    pub height: usize,
    pub spp: u32,
    /// `1 + number of AOVs`.
    pub layers: usize,
    pub accumulation: Accumulation,
    /// Pixel-major: pixel `(x, y)` holds [`Film::stride`] consecutive values, `layers`
    /// sums (layer 0 beauty, `1 + i` AOV `i`) and, for the compensated film, `layers`
    /// compensations.
    pub(crate) data: Vec<DVec3>,
    /// AOVs whose pixel holds the last value written, not a sum (`overwrite;`).
    pub(crate) overwrite: Vec<bool>,
    /// Samples rejected for beauty and every AOV because light transport was not finite.
    pub rejected: u64,
    /// AOV-only values (unoccluded, shadows, nothruput) dropped as non-finite.
    pub aov_rejected: u64,
}

/// Most bytes a render's film may take.
pub const MAX_FILM_BYTES: u128 = 8 << 30;

impl Film {
    /// Bytes of the sums of a `width` x `height` film of `layers` layers (f64 RGB each).
    pub fn bytes(width: usize, height: usize, layers: usize) -> u128 {
        // In u128 from the start: the product of the three can pass `usize` on the
        // sizes this guard exists to refuse.
        width as u128 * height as u128 * layers as u128 * 24
    }

    pub fn new(
        width: usize,
        height: usize,
        spp: u32,
        overwrite: Vec<bool>,
        accumulation: Accumulation,
    ) -> Film {
        let layers = overwrite.len() + 1;
        Film {
            width,
            height,
            spp,
            layers,
            accumulation,
            data: vec![DVec3::ZERO; width * height * layers * accumulation.slots()],
            overwrite,
            rejected: 0,
            aov_rejected: 0,
        }
    }

    /// Values stored per pixel.
    pub fn stride(&self) -> usize {
        self.layers * self.accumulation.slots()
    }

    fn total(&self, pixel: usize, layer: usize) -> DVec3 {
        let s = self.stride();
        Accumulation::total(&self.data[pixel * s..(pixel + 1) * s], layer)
    }

    /// The estimate at pixel `(x, y)` of `layer` (0 = beauty, `1 + i` = AOV `i`): the
    /// mean over all samples (rejected samples count as zero), or the last value for
    /// `overwrite;` AOVs.
    pub fn pixel(&self, x: usize, y: usize, layer: usize) -> DVec3 {
        let s = self.total(y * self.width + x, layer);
        if layer > 0 && self.overwrite[layer - 1] {
            s
        } else {
            s / self.spp as f64
        }
    }

    /// A whole layer, row-major.
    pub fn layer(&self, layer: usize) -> Vec<DVec3> {
        (0..self.height)
            .flat_map(|y| (0..self.width).map(move |x| (x, y)))
            .map(|(x, y)| self.pixel(x, y, layer))
            .collect()
    }

    /// The rows, for workers to fill in parallel (row `y`, its pixels).
    pub fn rows_mut(&mut self) -> impl IndexedParallelIterator<Item = (usize, FilmRow<'_>)> {
        let (stride, layers, accumulation) = (self.stride(), self.layers, self.accumulation);
        self.data
            .par_chunks_mut(self.width * stride)
            .enumerate()
            .map(move |(y, pixels)| {
                (
                    y,
                    FilmRow {
                        pixels,
                        stride,
                        layers,
                        accumulation,
                        scratch: vec![DVec3::ZERO; stride],
                    },
                )
            })
    }

    /// Bitwise equality of one layer with another film's (determinism checks).
    pub fn layer_bits_equal(&self, layer: usize, other: &Film, other_layer: usize) -> bool {
        self.width == other.width
            && self.height == other.height
            && (0..self.width * self.height).all(|p| {
                let a = self.total(p, layer);
                let b = other.total(p, other_layer);
                a.to_array().map(f64::to_bits) == b.to_array().map(f64::to_bits)
            })
    }
}

/// How a contribution was found (the integrator's module docs say how each AOV prefix weighs it).
#[derive(Clone, Copy, Debug)]
pub enum Strategy {
    /// The path itself reached the emitter; `w` is its MIS weight and `nee_could` says
    /// whether light sampling also estimates this connection.
    Hit { w: f32, nee_could: bool },
    /// A light sample with MIS weight `w` and its visibility.
    Nee { w: f32, visible: bool },
}

impl Strategy {
    /// The weight of this contribution in an AOV with these prefixes (beauty: none).
    pub fn weight(self, f: &AovFlags) -> f32 {
        let unshadowed = f.unoccluded || f.shadows;
        match self {
            Strategy::Hit {
                nee_could: true, ..
            } if unshadowed => 0.0,
            Strategy::Hit { .. } if f.shadows => 0.0,
            Strategy::Hit { w, .. } => w,
            Strategy::Nee { visible, .. } if f.shadows => (!visible) as u8 as f32,
            Strategy::Nee { .. } if f.unoccluded => 1.0,
            Strategy::Nee { w, visible } => w * visible as u8 as f32,
        }
    }
}

/// A hit on an emitter that no other strategy estimates: full weight.
pub const ONLY_STRATEGY: Strategy = Strategy::Hit {
    w: 1.0,
    nee_could: false,
};

/// One contribution reaching an emitter, as the film weighs it.
#[derive(Clone, Copy, Debug)]
pub struct Contribution {
    /// Throughput up to the last scattering vertex.
    pub beta: Vec3,
    /// Estimate at the last scattering vertex (or the emitted radiance, for `C E`).
    pub local: Vec3,
    pub strategy: Strategy,
    pub holdout: bool,
}

/// How contributions weigh into each AOV: its prefixes, and the scene's clamp.
#[derive(Clone, Debug)]
pub struct Weighting {
    flags: Vec<AovFlags>,
    /// AOVs with no prefix that changes a contribution's value: they receive beauty's.
    like_beauty: AovMask,
    /// Like beauty, and neither `overwrite;` nor `noinfinitecheck;`: summed per final
    /// matcher state ([`by_state`]).
    plain: AovMask,
    /// The others: routed per contribution.
    direct: AovMask,
    clamp: Option<f32>,
}

impl Weighting {
    /// The weighting of AOVs that accumulate as `flags` say (one per AOV, in order).
    pub fn new(flags: Vec<AovFlags>, clamp: Option<f32>) -> Weighting {
        let which = |keep: &dyn Fn(&AovFlags) -> bool| -> AovMask {
            (flags.iter().enumerate())
                .filter(|(_, f)| keep(f))
                .map(|(i, _)| i)
                .collect()
        };
        let plain = |f: &AovFlags| f.values_like_beauty() && !f.overwrite && !f.noinfinitecheck;
        Weighting {
            like_beauty: which(&|f| f.values_like_beauty()),
            plain: which(&plain),
            direct: which(&|f| !plain(f)),
            flags,
            clamp,
        }
    }

    /// Number of AOVs.
    pub fn len(&self) -> usize {
        self.flags.len()
    }

    pub fn is_empty(&self) -> bool {
        self.flags.is_empty()
    }

    /// Per AOV: whether its pixel keeps the last value written (`overwrite;`).
    pub fn overwrite(&self) -> Vec<bool> {
        self.flags.iter().map(|f| f.overwrite).collect()
    }
}

/// The values of one camera sample, before they join the pixel, for a matcher whose
/// path states are `K`; and the plain AOVs' per-state sums of the pixel's samples so far.
#[derive(Clone, Debug)]
pub struct SampleValues<K> {
    beauty: DVec3,
    /// Per AOV routed per contribution (and user-lobe signals): this sample's value.
    aov: Vec<DVec3>,
    touched: AovMask,
    /// Beauty values by final state for the plain AOVs: the pixel's committed samples
    /// (f64 film) and this sample's.
    arrivals: ByState<K>,
    /// All light-transport contributions were finite.
    finite: bool,
    /// AOV-only values dropped as non-finite, over every sample this accumulator saw.
    pub aov_rejected: u64,
}

impl<K: Copy + PartialEq> SampleValues<K> {
    pub fn new(aovs: usize) -> SampleValues<K> {
        SampleValues {
            beauty: DVec3::ZERO,
            aov: vec![DVec3::ZERO; aovs],
            touched: AovMask::EMPTY,
            arrivals: ByState::default(),
            finite: true,
            aov_rejected: 0,
        }
    }

    /// Adds one contribution whose path ended in state `state` to beauty and to the AOVs
    /// whose expressions match its path (`matches(state)`), each weighed by its
    /// prefixes. Plain AOVs only note the state: which of them match is asked once per
    /// state when the film expands the sums.
    pub fn add(
        &mut self,
        w: &Weighting,
        a: &Contribution,
        state: K,
        matches: impl Fn(K) -> AovMask,
    ) {
        let clamp = w.clamp;
        let clamped = |v: Vec3, f: &AovFlags| match clamp {
            Some(c) if !f.noclamp && max_component(v) > c => v * (c / max_component(v)),
            _ => v,
        };
        let full = a.beta * a.local;
        let none = AovFlags::default();
        let wb = a.strategy.weight(&none);
        let beauty = clamped(full * wb, &none);
        let beauty_d = beauty.as_dvec3();
        let counts_in_beauty = wb > 0.0 && !a.holdout;
        if wb > 0.0 {
            self.finite &= beauty.is_finite();
        }
        if counts_in_beauty {
            self.beauty += beauty_d;
            if !w.plain.is_empty() {
                self.arrivals.push(state, beauty_d);
            }
        }
        if w.direct.is_empty() {
            return;
        }
        for i in matches(state).iter().filter(|&i| w.direct.contains(i)) {
            if w.like_beauty.contains(i) {
                if counts_in_beauty {
                    self.aov[i] += beauty_d;
                    self.touched.insert(i);
                }
                continue;
            }
            let f = &w.flags[i];
            if f.holdouts != a.holdout {
                continue;
            }
            let wi = a.strategy.weight(f);
            if !(wi > 0.0) {
                continue;
            }
            let v = clamped(if f.nothruput { a.local } else { full } * wi, f);
            // Values beauty also received were judged with the sample; AOV-only values
            // (other weights or no throughput) are dropped alone if not finite.
            let aov_only = wi != wb || f.nothruput;
            if aov_only && !v.is_finite() && !f.noinfinitecheck {
                self.aov_rejected += 1;
                continue;
            }
            self.aov[i] += v.as_dvec3();
            self.touched.insert(i);
        }
    }

    /// A material signal (user-lobe pseudo path) for AOV `i`: not light transport, so
    /// never in beauty; `overwrite;` AOVs keep the last value.
    pub fn add_signal(&mut self, w: &Weighting, i: usize, value: DVec3) {
        if w.flags[i].overwrite {
            self.aov[i] = value;
        } else {
            self.aov[i] += value;
        }
        self.touched.insert(i);
    }
}

/// One row of the film, handed to one worker.
///
/// A pixel is summed in a scratch copy (one pixel's storage: 792 bytes with 32 AOVs,
/// in L1) and written to the film once, in address order, when it is finished: the
/// scattered layer additions of its samples and states never wait for the film's
/// memory, and the film is written as one stream instead of read and written back.
pub struct FilmRow<'a> {
    pixels: &'a mut [DVec3],
    stride: usize,
    layers: usize,
    accumulation: Accumulation,
    /// The pixel being rendered, all zero between pixels.
    scratch: Vec<DVec3>,
}

impl FilmRow<'_> {
    /// Adds a finished sample to the pixel being rendered and clears it (`matches`: the
    /// AOVs a final state matches); returns whether the sample was rejected as
    /// non-finite. On the f64 film the plain AOVs' share waits, summed per state, for
    /// [`FilmRow::finish_pixel`]; the f32 films add it to the pixel with the sample, as a
    /// renderer with an f32 film would.
    pub fn commit<K: Copy + PartialEq>(
        &mut self,
        acc: &mut SampleValues<K>,
        w: &Weighting,
        matches: impl Fn(K) -> AovMask,
    ) -> bool {
        let rejected = !(acc.finite && acc.beauty.is_finite());
        let (layers, accumulation) = (self.layers, self.accumulation);
        let pixel = &mut self.scratch[..];
        let add = |pixel: &mut [DVec3], layer, x| accumulation.add(pixel, layers, layer, x);
        if rejected {
            acc.arrivals.drop_sample();
        } else {
            add(pixel, 0, acc.beauty);
            if accumulation == Accumulation::F64 {
                acc.arrivals.commit_sample();
            } else {
                let (aov, touched) = (&mut acc.aov, &mut acc.touched);
                acc.arrivals.expand_sample(&w.plain, matches, |i, v| {
                    aov[i] += v;
                    touched.insert(i);
                });
            }
        }
        for i in acc.touched.iter() {
            let f = &w.flags[i];
            if !rejected || f.noinfinitecheck {
                if f.overwrite {
                    pixel[1 + i] = acc.aov[i];
                } else {
                    add(pixel, 1 + i, acc.aov[i]);
                }
            }
            acc.aov[i] = DVec3::ZERO;
        }
        acc.touched = AovMask::EMPTY;
        acc.beauty = DVec3::ZERO;
        acc.finite = true;
        rejected
    }

    /// Adds the plain AOVs' per-state sums of the pixel's committed samples to its
    /// layers, empties them and writes the pixel to `x`, replacing what was there: call
    /// once per pixel, after all of its samples are committed.
    pub fn finish_pixel<K: Copy + PartialEq>(
        &mut self,
        x: usize,
        acc: &mut SampleValues<K>,
        w: &Weighting,
        matches: impl Fn(K) -> AovMask,
    ) {
        let (layers, accumulation, stride) = (self.layers, self.accumulation, self.stride);
        let pixel = &mut self.scratch[..];
        acc.arrivals.expand(&w.plain, matches, |i, v| {
            accumulation.add(pixel, layers, 1 + i, v)
        });
        self.pixels[x * stride..(x + 1) * stride].copy_from_slice(&self.scratch);
        self.scratch.fill(DVec3::ZERO);
        if let Some(next) = self.pixels.get((x + 1) * stride..(x + 2) * stride) {
            prefetch(next);
        }
    }
}

/// Asks for `data`'s cache lines ahead of writing it. A pixel's storage (792 bytes with
/// 32 AOVs) is written once, as one copy, when the pixel is finished; the film (7 MB at
/// 96x96) is far larger than the core's caches, and a copy that waits for each line to
/// be fetched before it can write it was about a quarter of what 32 AOVs cost over
/// beauty (`lpe-render bench`, means of 20 runs on a 2-core Xeon VM: +2.4-2.7 % without,
/// +1.9-2.1 % with). Fetched while the pixel's samples are traced, the lines are there
/// when the copy comes.
#[inline]
fn prefetch(data: &[DVec3]) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        // One prefetch per line: x86_64 CPUs have 64-byte cache lines.
        const LINE: usize = 64;
        let start = data.as_ptr().cast::<i8>();
        for offset in (0..std::mem::size_of_val(data)).step_by(LINE) {
            // SAFETY: `_mm_prefetch` is unsafe only as an SSE function, and SSE is part of
            // every x86_64 CPU; a prefetch reads nothing the program sees and never
            // faults, and the address stays inside `data`.
            unsafe { _mm_prefetch::<_MM_HINT_T0>(start.wrapping_add(offset)) };
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = data;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aov::AovList;

    /// One AOV per prefix combination under test, each matching every path (`C.*L`
    /// stands in: routing never looks at the expression, only at the flags and at the
    /// matched mask the caller hands over).
    const ROUTED: [&str; 9] = [
        "plain",
        "shadows;",
        "unoccluded;",
        "holdouts;",
        "nothruput;",
        "noclamp;",
        "holdouts;unoccluded;",
        "holdouts;shadows;",
        "nothruput;noclamp;",
    ];

    fn weighting(clamp: Option<f32>) -> Weighting {
        weighting_of(&ROUTED, clamp)
    }

    /// One AOV `C.*L` per entry of `prefixes` ("plain": none).
    fn weighting_of(prefixes: &[&str], clamp: Option<f32>) -> Weighting {
        let config = lpe::renderman::Config::default();
        let parser = lpe::renderman::Parser::new(config.limits.clone(), config.macros.clone());
        let mut aovs = AovList::<lpe::renderman::RenderMan>::new();
        for (i, prefixes) in prefixes.iter().enumerate() {
            let prefixes = if *prefixes == "plain" { "" } else { prefixes };
            aovs.push(&format!("a{i}"), &format!("{prefixes}C.*L"), &parser)
                .unwrap();
        }
        Weighting::new(aovs.flags(), clamp)
    }

    /// Commits `v` as the only sample of the one-pixel film `film` (rows: 1) and
    /// finishes the pixel; states are their own masks.
    fn commit_only_sample(film: &mut Film, v: &mut SampleValues<AovMask>, w: &Weighting) {
        let mut rows: Vec<_> = film.rows_mut().collect();
        let row = &mut rows[0].1;
        assert!(!row.commit(v, w, |m| m));
        row.finish_pixel(0, v, w, |m| m);
    }

    /// Routes one contribution, whose path every AOV of [`ROUTED`] matches, through a
    /// one-sample, one-pixel film of each kind (all must agree); beauty and each AOV's
    /// value.
    fn route(c: Contribution, clamp: Option<f32>) -> (DVec3, Vec<Option<DVec3>>) {
        let w = weighting(clamp);
        let films = Accumulation::ALL.map(|a| {
            let mut film = Film::new(1, 1, 1, w.overwrite(), a);
            let mut v = SampleValues::new(w.len());
            let all: AovMask = (0..w.len()).collect();
            v.add(&w, &c, all, |m| m);
            commit_only_sample(&mut film, &mut v, &w);
            film
        });
        for f in &films[1..] {
            for layer in 0..=w.len() {
                assert_eq!(
                    f.layer(layer),
                    films[0].layer(layer),
                    "{:?}",
                    f.accumulation
                );
            }
        }
        let aovs = (0..w.len())
            .map(|i| Some(films[0].pixel(0, 0, 1 + i)))
            .collect();
        (films[0].pixel(0, 0, 0), aovs)
    }

    /// Throughput and local estimate chosen so that every product below is exact in f32.
    const BETA: Vec3 = Vec3::splat(0.5);
    const LOCAL: Vec3 = Vec3::new(1.0, 2.0, 4.0);

    fn c(strategy: Strategy, holdout: bool) -> Contribution {
        Contribution {
            beta: BETA,
            local: LOCAL,
            strategy,
            holdout,
        }
    }

    fn d(x: f64, y: f64, z: f64) -> Option<DVec3> {
        Some(DVec3::new(x, y, z))
    }

    /// Asserts beauty and every AOV of [`ROUTED`], naming the AOV that differs.
    #[track_caller]
    fn expect(got: (DVec3, Vec<Option<DVec3>>), beauty: DVec3, want: [Option<DVec3>; 9]) {
        let close =
            |a: DVec3, b: DVec3| (a - b).abs().max_element() <= 1e-6 * b.abs().max_element();
        assert!(close(got.0, beauty), "beauty: {} != {beauty}", got.0);
        for (i, (g, e)) in got.1.iter().zip(want).enumerate() {
            let ok = match (g, e) {
                (Some(g), Some(e)) => close(*g, e),
                (None, None) => true,
                // Touched with zero is the same image as not touched.
                (Some(g), None) => *g == DVec3::ZERO,
                (None, Some(e)) => e == DVec3::ZERO,
            };
            assert!(ok, "{:?}: got {g:?}, want {e:?}", ROUTED[i]);
        }
    }

    // Expected values below are worked out by hand from the integrator's "Prefixes"
    // docs: value = thru * local * weight, thru = beta = 0.5 (1 with `nothruput;`),
    // local = (1, 2, 4), so beta * local = (0.5, 1, 2).

    /// A film's bytes worked out by hand (3 f64 per layer and pixel), and a film too
    /// large for `usize` counted without wrapping: width * height alone is 2^64 here.
    /// Fails when the product is taken in `usize` first (it wraps to 0 in release).
    #[test]
    fn film_bytes_are_counted_without_wrapping() {
        assert_eq!(Film::bytes(2, 3, 4), 2 * 3 * 4 * 24);
        assert_eq!(Film::bytes(1 << 32, 1 << 32, 2), (1u128 << 64) * 48);
        assert!(Film::bytes(1 << 32, 1 << 32, 2) > MAX_FILM_BYTES);
    }

    #[test]
    fn visible_light_sample() {
        // MIS weight 1/4, unblocked: the plain value is (0.5, 1, 2) / 4; `unoccluded;`
        // drops the MIS weight (weight 1); `shadows;` gets nothing (not blocked);
        // `holdouts;` AOVs nothing (not a holdout path).
        let got = route(
            c(
                Strategy::Nee {
                    w: 0.25,
                    visible: true,
                },
                false,
            ),
            None,
        );
        expect(
            got,
            DVec3::new(0.125, 0.25, 0.5),
            [
                d(0.125, 0.25, 0.5),
                None,
                d(0.5, 1.0, 2.0),
                None,
                d(0.25, 0.5, 1.0),
                d(0.125, 0.25, 0.5),
                None,
                None,
                d(0.25, 0.5, 1.0),
            ],
        );
    }

    #[test]
    fn blocked_light_sample() {
        // Blocked: beauty and the plain AOVs get nothing; `unoccluded;` and `shadows;`
        // both get the whole unshadowed value with weight 1 (not the MIS weight).
        let got = route(
            c(
                Strategy::Nee {
                    w: 0.25,
                    visible: false,
                },
                false,
            ),
            None,
        );
        expect(
            got,
            DVec3::ZERO,
            [
                None,
                d(0.5, 1.0, 2.0),
                d(0.5, 1.0, 2.0),
                None,
                None,
                None,
                None,
                None,
                None,
            ],
        );
    }

    #[test]
    fn bsdf_hit_light_sampling_could_have_made() {
        // A BSDF-sampled hit on a light NEE samples, MIS weight 3/4: beauty and the
        // plain-weighted AOVs get 3/4 of it; `unoccluded;` and `shadows;` get nothing
        // (light sampling alone estimates that connection for them).
        let got = route(
            c(
                Strategy::Hit {
                    w: 0.75,
                    nee_could: true,
                },
                false,
            ),
            None,
        );
        expect(
            got,
            DVec3::new(0.375, 0.75, 1.5),
            [
                d(0.375, 0.75, 1.5),
                None,
                None,
                None,
                d(0.75, 1.5, 3.0),
                d(0.375, 0.75, 1.5),
                None,
                None,
                d(0.75, 1.5, 3.0),
            ],
        );
    }

    #[test]
    fn bsdf_hit_only_that_strategy_finds() {
        // Glow, a light seen through a delta lobe: full weight everywhere but `shadows;`
        // (nothing to be blocked) and the `holdouts;` AOVs.
        let got = route(c(ONLY_STRATEGY, false), None);
        expect(
            got,
            DVec3::new(0.5, 1.0, 2.0),
            [
                d(0.5, 1.0, 2.0),
                None,
                d(0.5, 1.0, 2.0),
                None,
                d(1.0, 2.0, 4.0),
                d(0.5, 1.0, 2.0),
                None,
                None,
                d(1.0, 2.0, 4.0),
            ],
        );
    }

    #[test]
    fn holdout_light_samples_go_only_to_holdouts_aovs() {
        // The same contributions on a holdout path: beauty and every AOV without
        // `holdouts;` get nothing, and the `holdouts;` AOVs get what they would get
        // from a path without holdout, under their other prefixes.
        let got = route(
            c(
                Strategy::Nee {
                    w: 0.25,
                    visible: true,
                },
                true,
            ),
            None,
        );
        let holdouts =
            |v: [Option<DVec3>; 3]| [None, None, None, v[0], None, None, v[1], v[2], None];
        expect(
            got,
            DVec3::ZERO,
            holdouts([d(0.125, 0.25, 0.5), d(0.5, 1.0, 2.0), None]),
        );
        let got = route(
            c(
                Strategy::Nee {
                    w: 0.25,
                    visible: false,
                },
                true,
            ),
            None,
        );
        expect(
            got,
            DVec3::ZERO,
            holdouts([None, d(0.5, 1.0, 2.0), d(0.5, 1.0, 2.0)]),
        );
    }

    #[test]
    fn holdout_bsdf_hits_go_only_to_holdouts_aovs() {
        let got = route(
            c(
                Strategy::Hit {
                    w: 0.75,
                    nee_could: true,
                },
                true,
            ),
            None,
        );
        let holdouts =
            |v: [Option<DVec3>; 3]| [None, None, None, v[0], None, None, v[1], v[2], None];
        expect(
            got,
            DVec3::ZERO,
            holdouts([d(0.375, 0.75, 1.5), None, None]),
        );
        let got = route(c(ONLY_STRATEGY, true), None);
        expect(
            got,
            DVec3::ZERO,
            holdouts([d(0.5, 1.0, 2.0), d(0.5, 1.0, 2.0), None]),
        );
    }

    #[test]
    fn clamp_scales_by_the_max_component_except_with_noclamp() {
        // Clamp 1: a contribution whose max component m exceeds 1 is scaled by 1/m,
        // after its weight and throughput (so `nothruput;` clamps (1, 2, 4), not (0.5,
        // 1, 2)); `noclamp;` AOVs keep the unclamped value.
        let got = route(c(ONLY_STRATEGY, false), Some(1.0));
        expect(
            got,
            DVec3::new(0.25, 0.5, 1.0),
            [
                d(0.25, 0.5, 1.0),
                None,
                d(0.25, 0.5, 1.0),
                None,
                d(0.25, 0.5, 1.0),
                d(0.5, 1.0, 2.0),
                None,
                None,
                d(1.0, 2.0, 4.0),
            ],
        );
        // The clamp sees the weighted value: MIS weight 1/4 brings (0.5, 1, 2) to
        // (0.125, 0.25, 0.5), under the clamp; `unoccluded;` (weight 1) and `shadows;`
        // are clamped; a clamp above every value changes nothing.
        let got = route(
            c(
                Strategy::Nee {
                    w: 0.25,
                    visible: false,
                },
                false,
            ),
            Some(1.0),
        );
        expect(
            got,
            DVec3::ZERO,
            [
                None,
                d(0.25, 0.5, 1.0),
                d(0.25, 0.5, 1.0),
                None,
                None,
                None,
                None,
                None,
                None,
            ],
        );
        let got = route(
            c(
                Strategy::Nee {
                    w: 0.25,
                    visible: true,
                },
                false,
            ),
            Some(1.0),
        );
        expect(
            got,
            DVec3::new(0.125, 0.25, 0.5),
            [
                d(0.125, 0.25, 0.5),
                None,
                d(0.25, 0.5, 1.0),
                None,
                d(0.25, 0.5, 1.0),
                d(0.125, 0.25, 0.5),
                None,
                None,
                d(0.25, 0.5, 1.0),
            ],
        );
        let got = route(
            c(
                Strategy::Hit {
                    w: 0.75,
                    nee_could: true,
                },
                false,
            ),
            Some(8.0),
        );
        expect(
            got,
            DVec3::new(0.375, 0.75, 1.5),
            [
                d(0.375, 0.75, 1.5),
                None,
                None,
                None,
                d(0.75, 1.5, 3.0),
                d(0.375, 0.75, 1.5),
                None,
                None,
                d(0.75, 1.5, 3.0),
            ],
        );
    }

    #[test]
    fn only_matched_aovs_receive_and_values_add_up() {
        // AOVs outside the matched mask get nothing, even beauty-like ones; beauty does
        // not depend on the mask; two contributions to one sample add.
        let w = weighting(None);
        let mut v = SampleValues::new(w.len());
        let matched: AovMask = [1usize, 2, 4].into_iter().collect();
        v.add(
            &w,
            &c(
                Strategy::Nee {
                    w: 0.25,
                    visible: true,
                },
                false,
            ),
            matched,
            |m| m,
        );
        v.add(
            &w,
            &c(
                Strategy::Nee {
                    w: 0.5,
                    visible: false,
                },
                false,
            ),
            matched,
            |m| m,
        );
        assert_eq!(v.beauty, DVec3::new(0.125, 0.25, 0.5));
        let touched: Vec<usize> = v.touched.iter().collect();
        assert_eq!(touched, [1, 2, 4]);
        assert_eq!(v.aov[1], DVec3::new(0.5, 1.0, 2.0)); // shadows: the blocked one
        assert_eq!(v.aov[2], DVec3::new(1.0, 2.0, 4.0)); // unoccluded: both, weight 1
        assert_eq!(v.aov[4], DVec3::new(0.25, 0.5, 1.0)); // nothruput: the visible one
        let mut film = Film::new(1, 1, 1, w.overwrite(), Accumulation::F64);
        commit_only_sample(&mut film, &mut v, &w);
        assert_eq!(film.pixel(0, 0, 0), DVec3::new(0.125, 0.25, 0.5));
        // The plain AOV 0 is not in the mask: nothing, though its value is beauty's.
        assert_eq!(film.pixel(0, 0, 1), DVec3::ZERO);
        assert_eq!(film.pixel(0, 0, 1 + 1), DVec3::new(0.5, 1.0, 2.0));
        assert_eq!(film.pixel(0, 0, 1 + 4), DVec3::new(0.25, 0.5, 1.0));
    }

    #[test]
    fn plain_aovs_get_every_committed_sample_of_the_pixel_by_final_state() {
        // Three samples of one pixel, states standing for their own masks: AOV 0 is
        // plain (summed per state), AOV 5 (`noclamp;`, no clamp set) is routed per
        // contribution, both with beauty's values. The second sample is not finite:
        // rejected from beauty and both AOVs, on every film, and none of it may reach
        // the sample committed after it.
        let w = weighting(None);
        let mask = |ids: &[usize]| -> AovMask { ids.iter().copied().collect() };
        let (s0, s5, s05) = (mask(&[0]), mask(&[5]), mask(&[0, 5]));
        let nee = |wt| {
            c(
                Strategy::Nee {
                    w: wt,
                    visible: true,
                },
                false,
            )
        };
        let samples: [Vec<(Contribution, AovMask)>; 3] = [
            vec![(nee(0.25), s0), (nee(0.5), s5)],
            vec![(
                Contribution {
                    beta: Vec3::splat(f32::NAN),
                    ..c(ONLY_STRATEGY, false)
                },
                s0,
            )],
            vec![(c(ONLY_STRATEGY, false), s05)],
        ];
        for a in Accumulation::ALL {
            let mut film = Film::new(1, 1, 3, w.overwrite(), a);
            let mut v = SampleValues::new(w.len());
            let mut rejected = Vec::new();
            {
                let mut rows: Vec<_> = film.rows_mut().collect();
                let row = &mut rows[0].1;
                for sample in &samples {
                    for (contribution, state) in sample {
                        v.add(&w, contribution, *state, |m| m);
                    }
                    rejected.push(row.commit(&mut v, &w, |m| m));
                }
                row.finish_pixel(0, &mut v, &w, |m| m);
            }
            assert_eq!(rejected, [false, true, false], "{a:?}");
            // (0.5, 1, 2) per unit weight: 1/4 + 1 for AOV 0, 1/2 + 1 for AOV 5.
            let third = |x: f64| DVec3::new(0.5, 1.0, 2.0) * x / 3.0;
            assert_eq!(film.pixel(0, 0, 0), third(1.75), "{a:?}");
            assert_eq!(film.pixel(0, 0, 1), third(1.25), "{a:?}");
            assert_eq!(film.pixel(0, 0, 1 + 5), third(1.5), "{a:?}");
            assert!((1..=w.len())
                .filter(|&l| l != 1 && l != 6)
                .all(|l| film.pixel(0, 0, l) == DVec3::ZERO));
        }
    }

    #[test]
    fn each_pixel_of_a_row_gets_only_its_own_samples() {
        // Pixel 0 gets a plain-AOV sample (AOV 0) and a routed one (AOV 5); pixel 1 a
        // sample matching only AOV 0. Nothing of pixel 0 may leak into pixel 1, and
        // pixel 1 must not overwrite pixel 0.
        let w = weighting(None);
        let mask = |ids: &[usize]| -> AovMask { ids.iter().copied().collect() };
        let unit = c(ONLY_STRATEGY, false); // (0.5, 1, 2)
        for a in Accumulation::ALL {
            let mut film = Film::new(2, 1, 1, w.overwrite(), a);
            let mut v = SampleValues::new(w.len());
            {
                let mut rows: Vec<_> = film.rows_mut().collect();
                let row = &mut rows[0].1;
                v.add(&w, &unit, mask(&[0, 5]), |m| m);
                assert!(!row.commit(&mut v, &w, |m| m));
                row.finish_pixel(0, &mut v, &w, |m| m);
                v.add(&w, &unit, mask(&[0]), |m| m);
                v.add(&w, &unit, mask(&[0]), |m| m);
                assert!(!row.commit(&mut v, &w, |m| m));
                row.finish_pixel(1, &mut v, &w, |m| m);
            }
            let unit = DVec3::new(0.5, 1.0, 2.0);
            for (layer, want) in [(0, [1.0, 2.0]), (1, [1.0, 2.0]), (1 + 5, [1.0, 0.0])] {
                assert_eq!(
                    film.layer(layer),
                    want.map(|x| unit * x),
                    "{a:?} layer {layer}"
                );
            }
        }
    }

    /// Adds `xs` to a one-layer pixel with `a`; the stored total.
    fn sum(a: Accumulation, xs: impl Iterator<Item = f64>) -> f64 {
        let mut px = vec![DVec3::ZERO; a.slots()];
        for x in xs {
            a.add(&mut px, 1, 0, DVec3::splat(x));
        }
        Accumulation::total(&px, 0).x
    }

    #[test]
    fn compensated_f32_keeps_what_naive_f32_loses() {
        // One large value then 10^6 values each below half an f32 ulp of the running
        // sum: naive f32 drops every one of them; the exact sum (f32 inputs, f64 adds
        // exact here) is 1 + 10^6 * 2^-25.
        let xs = || std::iter::once(1.0).chain(std::iter::repeat_n(2f64.powi(-25), 1_000_000));
        let exact: f64 = xs().sum();
        assert_eq!(sum(Accumulation::F32, xs()), 1.0);
        let c = sum(Accumulation::F32Compensated, xs());
        // Within one f32 rounding of the exact total.
        assert!(
            ((c - exact) / exact).abs() <= f32::EPSILON as f64,
            "{c} vs {exact}"
        );
        assert_eq!(sum(Accumulation::F64, xs()), exact);
    }

    #[test]
    fn compensation_survives_a_smaller_sum_meeting_a_larger_sample() {
        // The branch where the sample outweighs the running sum: 2^-30 then 1 then -1
        // leaves exactly 2^-30, which naive f32 loses at the second addition.
        let xs = || [2f64.powi(-30), 1.0, -1.0].into_iter();
        assert_eq!(sum(Accumulation::F32, xs()), 0.0);
        assert_eq!(sum(Accumulation::F32Compensated, xs()), 2f64.powi(-30));
    }

    #[test]
    fn films_store_layers_apart() {
        for a in Accumulation::ALL {
            let mut f = Film::new(2, 1, 2, vec![false], a);
            let s = f.stride();
            for (p, x) in [(0usize, 1.0), (1, 3.0)] {
                let px = &mut f.data[p * s..(p + 1) * s];
                a.add(px, f.layers, 1, DVec3::splat(x));
                a.add(px, f.layers, 1, DVec3::splat(x));
            }
            assert_eq!(
                f.layer(1),
                vec![DVec3::splat(1.0), DVec3::splat(3.0)],
                "{a:?}"
            );
            assert_eq!(f.layer(0), vec![DVec3::ZERO; 2], "{a:?}");
        }
    }

    #[test]
    fn accumulation_names_tell_the_films_apart() {
        // The verify reports label their rows with these names.
        let names = Accumulation::ALL.map(Accumulation::name);
        assert_eq!(names, ["f64", "f32 naive", "f32 compensated"]);
    }

    #[test]
    fn weighting_is_empty_only_without_aovs() {
        assert!(weighting_of(&[], None).is_empty());
        assert!(!weighting_of(&["plain"], None).is_empty());
    }

    #[test]
    fn compensated_total_is_the_pair_rounded_once() {
        // 1 + 2^-24 lies halfway between the f32 neighbours 1 and 1 + 2^-23: the pair
        // keeps (1, 2^-24), its sum already the tie rounded to the even 1, which is what
        // the film reads (not 1 - 2^-24 or 1 + 2^-23).
        let a = Accumulation::F32Compensated;
        let mut px = vec![DVec3::ZERO; a.slots()];
        a.add(&mut px, 1, 0, DVec3::ONE);
        a.add(&mut px, 1, 0, DVec3::splat(2f64.powi(-24)));
        assert_eq!(px, [DVec3::ONE, DVec3::splat(2f64.powi(-24))]);
        assert_eq!(Accumulation::total(&px, 0), DVec3::ONE);
    }

    /// Adds each `(contribution, mask)` as a sample of its own to a one-pixel film with
    /// `spp` samples (states are their own masks); the film, whether each sample was
    /// rejected, and the count of AOV-only values dropped.
    fn film_of_samples(
        w: &Weighting,
        a: Accumulation,
        spp: u32,
        samples: &[&[(Contribution, AovMask)]],
    ) -> (Film, Vec<bool>, u64) {
        let mut film = Film::new(1, 1, spp, w.overwrite(), a);
        let mut v = SampleValues::new(w.len());
        let mut rejected = Vec::new();
        {
            let mut rows: Vec<_> = film.rows_mut().collect();
            let row = &mut rows[0].1;
            for sample in samples {
                for (contribution, state) in *sample {
                    v.add(w, contribution, *state, |m| m);
                }
                rejected.push(row.commit(&mut v, w, |m| m));
            }
            row.finish_pixel(0, &mut v, w, |m| m);
        }
        (film, rejected, v.aov_rejected)
    }

    #[test]
    fn overwrite_aovs_keep_the_last_sample_that_reached_them() {
        // AOV 0 plain, AOV 1 `overwrite;` (routed per contribution, beauty's values).
        // Samples: (0.5, 1, 2), then (0.125, 0.25, 0.5), then a blocked light sample
        // (MIS weight 0 in beauty: it reaches neither beauty nor AOV 1).
        let w = weighting_of(&["plain", "overwrite;"], None);
        let both: AovMask = [0usize, 1].into_iter().collect();
        let eighth = Contribution {
            beta: Vec3::splat(0.125),
            ..c(ONLY_STRATEGY, false)
        };
        let blocked = c(
            Strategy::Nee {
                w: 0.25,
                visible: false,
            },
            false,
        );
        for a in Accumulation::ALL {
            let samples: [&[_]; 3] = [
                &[(c(ONLY_STRATEGY, false), both)],
                &[(eighth, both)],
                &[(blocked, both)],
            ];
            let (film, rejected, _) = film_of_samples(&w, a, 3, &samples);
            assert_eq!(rejected, [false; 3], "{a:?}");
            let mean = DVec3::new(0.625, 1.25, 2.5) / 3.0;
            assert_eq!(film.pixel(0, 0, 0), mean, "{a:?}");
            assert_eq!(film.pixel(0, 0, 1), mean, "{a:?}");
            assert_eq!(film.pixel(0, 0, 2), DVec3::new(0.125, 0.25, 0.5), "{a:?}");
        }
    }

    #[test]
    fn a_non_finite_holdout_contribution_rejects_the_sample() {
        // A holdout path's contribution is in no beauty sum, yet its light transport
        // (weight 1, infinite throughput) is not finite: the whole sample goes,
        // including the `holdouts;` AOVs that would have received it. It is not an
        // AOV-only value: nothing is counted in `aov_rejected`.
        let w = weighting(None);
        let all: AovMask = (0..w.len()).collect();
        let inf = Contribution {
            beta: Vec3::splat(f32::INFINITY),
            ..c(ONLY_STRATEGY, true)
        };
        for a in Accumulation::ALL {
            let (film, rejected, aov_rejected) = film_of_samples(&w, a, 1, &[&[(inf, all)]]);
            assert_eq!(rejected, [true], "{a:?}");
            assert_eq!(aov_rejected, 0, "{a:?}");
            for layer in 0..=w.len() {
                assert_eq!(film.pixel(0, 0, layer), DVec3::ZERO, "{a:?} layer {layer}");
            }
        }
    }

    #[test]
    fn zero_weight_values_are_not_judged_and_aov_only_ones_are_dropped_alone() {
        // A blocked light sample with an infinite local estimate: beauty weight 0, so
        // its (NaN) beauty value neither counts nor rejects the sample. `shadows;` and
        // `unoccluded;` weigh it 1: infinite AOV-only values, each dropped and counted
        // (2 per sample). The MIS-weighted AOVs (`nothruput;`, `noclamp;`, ...) weigh
        // it 0 and never look at it. Every layer stays zero.
        let w = weighting(None);
        let all: AovMask = (0..w.len()).collect();
        let blocked_inf = Contribution {
            local: Vec3::splat(f32::INFINITY),
            ..c(
                Strategy::Nee {
                    w: 0.25,
                    visible: false,
                },
                false,
            )
        };
        for a in Accumulation::ALL {
            let sample: &[_] = &[(blocked_inf, all)];
            let (film, rejected, aov_rejected) = film_of_samples(&w, a, 2, &[sample, sample]);
            assert_eq!(rejected, [false, false], "{a:?}");
            assert_eq!(aov_rejected, 4, "{a:?}");
            for layer in 0..=w.len() {
                assert_eq!(film.pixel(0, 0, layer), DVec3::ZERO, "{a:?} layer {layer}");
            }
        }
    }

    #[test]
    fn signals_add_up_unless_the_aov_overwrites() {
        let w = weighting_of(&["plain", "overwrite;"], None);
        let mut film = Film::new(1, 1, 1, w.overwrite(), Accumulation::F64);
        let mut v = SampleValues::<AovMask>::new(w.len());
        for i in 0..2 {
            v.add_signal(&w, i, DVec3::new(1.0, 2.0, 3.0));
            v.add_signal(&w, i, DVec3::splat(0.5));
        }
        commit_only_sample(&mut film, &mut v, &w);
        assert_eq!(film.pixel(0, 0, 0), DVec3::ZERO);
        assert_eq!(film.pixel(0, 0, 1), DVec3::new(1.5, 2.5, 3.5));
        assert_eq!(film.pixel(0, 0, 2), DVec3::splat(0.5));
    }

    #[test]
    fn f32_films_add_plain_aovs_sample_by_sample_like_beauty() {
        // Samples 1, 2^-24, 2^-24 to a plain AOV matching every path. The naive f32
        // film rounds after each sample: 1 + 2^-24 is a tie that rounds to the even 1,
        // twice, so beauty and the AOV both read 1 (summing the AOV per state first
        // would read 1 + 2^-23). The f64 and compensated films keep 1 + 2^-23.
        let w = weighting_of(&["plain"], None);
        let all: AovMask = [0usize].into_iter().collect();
        let one = Contribution {
            beta: Vec3::ONE,
            local: Vec3::ONE,
            strategy: ONLY_STRATEGY,
            holdout: false,
        };
        let tiny = Contribution {
            beta: Vec3::splat(2f32.powi(-24)),
            ..one
        };
        for (a, want) in [
            (Accumulation::F32, 1.0),
            (Accumulation::F64, 1.0 + 2f64.powi(-23)),
            (Accumulation::F32Compensated, 1.0 + 2f64.powi(-23)),
        ] {
            let samples: [&[_]; 3] = [&[(one, all)], &[(tiny, all)], &[(tiny, all)]];
            let (film, _, _) = film_of_samples(&w, a, 1, &samples);
            assert_eq!(film.pixel(0, 0, 0), DVec3::splat(want), "{a:?} beauty");
            assert_eq!(film.pixel(0, 0, 1), DVec3::splat(want), "{a:?} AOV");
        }
    }
}

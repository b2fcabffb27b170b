//! Paths drawn the way a path tracer draws them: a camera vertex, 0..=10 bounces with
//! Russian roulette, then a light (mostly, with its group) or an emissive object.

use lpe::renderman::{Event, EventKind, Path, Vertex, VertexType};
use lpe::rng::SplitMix64 as Rng;

use super::workload::{LIGHT_GROUPS, OBJECT_GROUPS};

/// Draws on lpe's SplitMix64 generator, so every engine sees the same paths for a seed.
trait Draw {
    /// Uniform in `0..100`.
    fn percent(&mut self) -> u64;
    fn pick<'a>(&mut self, xs: &[&'a str]) -> &'a str;
}

impl Draw for Rng {
    fn percent(&mut self) -> u64 {
        self.next_u64() % 100
    }

    fn pick<'a>(&mut self, xs: &[&'a str]) -> &'a str {
        xs[(self.next_u64() % xs.len() as u64) as usize]
    }
}

fn ev(kind: EventKind, lobe: u8) -> Event {
    Event::new(kind, lobe).expect("lobe numbers below are in range")
}

/// One scattering vertex: a realistic lobe mix (mostly diffuse, then rough and primary
/// specular, some clearcoat, glass and subsurface), labelled most of the time.
fn bounce(rng: &mut Rng) -> Vertex {
    let p = rng.percent();
    let (ty, e) = match p {
        0..=44 => (VertexType::R, ev(EventKind::D, 2)),
        45..=49 => (VertexType::R, ev(EventKind::D, 1)),
        50..=64 => (VertexType::R, ev(EventKind::S, 3)),
        65..=74 => (VertexType::R, ev(EventKind::S, 2)),
        75..=79 => (VertexType::R, ev(EventKind::S, 4)),
        80..=84 => (VertexType::T, ev(EventKind::D, 3)),
        85..=91 => (VertexType::T, ev(EventKind::S, 8)),
        92..=95 => (VertexType::R, ev(EventKind::S, 8)),
        _ => (VertexType::T, ev(EventKind::S, 7)),
    };
    let label = (rng.percent() < 80).then(|| rng.pick(&OBJECT_GROUPS));
    Vertex::scatter(ty, e, label)
}

/// A user-lobe pseudo path `C <R Un> L`, as renderers emit once per camera hit.
fn user_path(rng: &mut Rng) -> Vec<Vertex> {
    let lobe = [2u8, 3, 6][(rng.next_u64() % 3) as usize];
    vec![
        Vertex::camera(),
        Vertex::scatter(VertexType::R, ev(EventKind::U, lobe), None),
        Vertex::light(None),
    ]
}

/// Paths until their vertices add up to at least `vertices`.
pub fn paths(vertices: usize, seed: u64) -> Vec<Path> {
    let mut rng = Rng::new(seed);
    let mut out = Vec::new();
    let mut total = 0;
    while total < vertices {
        let vs = if rng.percent() < 3 {
            user_path(&mut rng)
        } else {
            let mut vs = vec![Vertex::camera()];
            // Up to 10 bounces, continuing with probability 0.7: lengths 2..=12.
            while vs.len() < 11 && rng.percent() < 70 {
                vs.push(bounce(&mut rng));
            }
            vs.push(if rng.percent() < 85 {
                Vertex::light((rng.percent() < 90).then(|| rng.pick(&LIGHT_GROUPS)))
            } else {
                Vertex::emissive((rng.percent() < 50).then(|| rng.pick(&OBJECT_GROUPS)))
            });
            vs
        };
        total += vs.len();
        out.push(Path::new(vs).expect("the sampler follows the path shape"));
    }
    out
}

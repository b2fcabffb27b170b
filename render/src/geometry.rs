//! Rays, shapes (sphere, quad, triangle) and a bounding volume hierarchy over them.

use glam::Vec3;

/// A ray `o + t d`, `d` normalized.
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    pub o: Vec3,
    pub d: Vec3,
}

impl Ray {
    /// A ray leaving surface point `p` (normal `n`, position error bound `err` as in
    /// [`Hit::err`]) in direction `d`: the origin moves off the surface along the normal,
    /// to the side the ray travels to, by more than the point's rounding error, so the
    /// ray cannot hit its own surface again; and by no more than a few ulps of the
    /// coordinates, so it does not jump over nearby geometry at any scale.
    pub fn spawn(p: Vec3, n: Vec3, err: f32, d: Vec3) -> Ray {
        Ray {
            o: offset(p, n, err, d),
            d,
        }
    }
}

/// `p` moved off its surface (normal `n`) by twice its error bound `err`, toward the
/// side of `d`.
pub fn offset(p: Vec3, n: Vec3, err: f32, d: Vec3) -> Vec3 {
    let o = if d.dot(n) >= 0.0 { n } else { -n };
    p + o * (2.0 * err)
}

/// Error bound of a point computed from coordinates of magnitude up to `magnitude`, with
/// a few roundings, plus an absolute floor for points at the origin. 64 ulps: the
/// reprojected hit points below are within ~4 ulps, and the plane and sphere tests of a
/// spawned ray round `o - corner` and `o - center` once more (tested at scales 1e-6..1e6).
pub fn error_bound(magnitude: f32) -> f32 {
    64.0 * f32::EPSILON * magnitude + 1e-30
}

/// A geometric primitive.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    Sphere {
        center: Vec3,
        radius: f32,
    },
    /// The parallelogram `corner + a u + b v`, `a, b` in `[0, 1]`; normal `u x v`.
    Quad {
        corner: Vec3,
        u: Vec3,
        v: Vec3,
    },
    /// Triangle `p0, p0 + e1, p0 + e2`; normal `e1 x e2` (counter-clockwise front).
    Triangle {
        p0: Vec3,
        e1: Vec3,
        e2: Vec3,
    },
}

/// Where a ray meets a primitive.
#[derive(Clone, Copy, Debug)]
pub struct Hit {
    pub t: f32,
    pub p: Vec3,
    /// Geometric normal, unit, pointing to the shape's outside (spheres) or front.
    pub n: Vec3,
    /// Bound on the distance of `p` from the true surface (see [`Shape::surface_point`]).
    pub err: f32,
    /// Index of the object the primitive belongs to.
    pub object: u32,
}

impl Shape {
    pub fn bounds(&self) -> Aabb {
        match *self {
            Shape::Sphere { center, radius } => Aabb {
                min: center - Vec3::splat(radius),
                max: center + Vec3::splat(radius),
            },
            Shape::Quad { corner, u, v } => Aabb::point(corner)
                .with(corner + u)
                .with(corner + v)
                .with(corner + u + v),
            Shape::Triangle { p0, e1, e2 } => Aabb::point(p0).with(p0 + e1).with(p0 + e2),
        }
    }

    /// The hit point of `ray` at `t`, recomputed from the primitive's own parameters and
    /// its error bound. `o + t d` is off the surface by rounding relative to the ray's
    /// origin and length (a camera 1e6 away from a 1e-6 sphere misses it by 0.06);
    /// reprojecting onto the sphere, or re-evaluating the plane point from its (u, v)
    /// coordinates, leaves only rounding relative to the primitive's own coordinates.
    pub fn surface_point(&self, ray: &Ray, t: f32) -> (Vec3, f32) {
        let raw = ray.o + t * ray.d;
        match *self {
            Shape::Sphere { center, radius } => {
                let p = center + (raw - center).normalize_or(Vec3::Z) * radius;
                (p, error_bound(center.abs().max_element() + radius))
            }
            Shape::Quad { corner, u, v } => {
                let (a, b) = plane_coords(raw - corner, u, v);
                let p = corner + u * a + v * b;
                let m = corner.abs().max_element() + u.abs().max_element() + v.abs().max_element();
                (p, error_bound(m))
            }
            Shape::Triangle { p0, e1, e2 } => {
                let (a, b) = plane_coords(raw - p0, e1, e2);
                let p = p0 + e1 * a + e2 * b;
                let m = p0.abs().max_element() + e1.abs().max_element() + e2.abs().max_element();
                (p, error_bound(m))
            }
        }
    }

    pub fn centroid(&self) -> Vec3 {
        let b = self.bounds();
        (b.min + b.max) * 0.5
    }

    /// Nearest intersection in `(0, t_max)`: `(t, normal)`.
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<(f32, Vec3)> {
        let t = self.hit_t(ray, t_max)?;
        Some((t, self.normal(ray.o + t * ray.d)))
    }

    /// Unit geometric normal at a point on the surface (outward for spheres, `u x v` for
    /// quads, `e1 x e2` for triangles). Separate from [`Shape::hit_t`] so traversal pays
    /// for it once per ray, not once per candidate hit.
    pub fn normal(&self, p: Vec3) -> Vec3 {
        match *self {
            Shape::Sphere { center, .. } => (p - center).normalize(),
            Shape::Quad { u, v, .. } => u.cross(v).normalize(),
            Shape::Triangle { e1, e2, .. } => e1.cross(e2).normalize(),
        }
    }

    /// Distance to the nearest intersection in `(0, t_max)`.
    pub fn hit_t(&self, ray: &Ray, t_max: f32) -> Option<f32> {
        let t = match *self {
            Shape::Sphere { center, radius } => {
                // |o + t d - c|^2 = r^2 in the numerically stable form of pbrt-v4: the
                // discriminant from the perpendicular distance, the far root from the
                // product of the roots (no cancellation).
                let oc = ray.o - center;
                let b = oc.dot(ray.d);
                let perp = oc - b * ray.d;
                let disc = radius * radius - perp.length_squared();
                if disc < 0.0 {
                    return None;
                }
                let q = -b - disc.sqrt().copysign(b);
                let c = oc.length_squared() - radius * radius;
                let other = if q != 0.0 { c / q } else { -b };
                let (t0, t1) = if q < other { (q, other) } else { (other, q) };
                if t0 > 0.0 {
                    t0
                } else {
                    t1
                }
            }
            Shape::Quad { corner, u, v } => {
                let n = u.cross(v);
                let denom = n.dot(ray.d);
                if denom == 0.0 {
                    return None;
                }
                let t = n.dot(corner - ray.o) / denom;
                if !(t > 0.0 && t < t_max) {
                    return None;
                }
                let w = ray.o + t * ray.d - corner;
                // Coordinates in the (u, v) basis via the dual vectors, each scaled by
                // |n|^2 (compared against it instead of divided by it).
                let nn = n.length_squared();
                let a = n.dot(w.cross(v));
                let b = n.dot(u.cross(w));
                if !(0.0..=nn).contains(&a) || !(0.0..=nn).contains(&b) {
                    return None;
                }
                t
            }
            Shape::Triangle { p0, e1, e2 } => {
                // Möller–Trumbore.
                let pv = ray.d.cross(e2);
                let det = e1.dot(pv);
                if det == 0.0 {
                    return None;
                }
                let inv = 1.0 / det;
                let tv = ray.o - p0;
                let a = tv.dot(pv) * inv;
                if !(0.0..=1.0).contains(&a) {
                    return None;
                }
                let qv = tv.cross(e1);
                let b = ray.d.dot(qv) * inv;
                if b < 0.0 || a + b > 1.0 {
                    return None;
                }
                e2.dot(qv) * inv
            }
        };
        (t > 0.0 && t < t_max).then_some(t)
    }
}

/// Coordinates `(a, b)` of `w` in the basis `(u, v)` of its plane (via the dual vectors).
fn plane_coords(w: Vec3, u: Vec3, v: Vec3) -> (f32, f32) {
    let n = u.cross(v);
    let nn = n.length_squared();
    (n.dot(w.cross(v)) / nn, n.dot(u.cross(w)) / nn)
}

/// Axis-aligned bounding box.
#[derive(Clone, Copy, Debug)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb {
        min: Vec3::splat(f32::INFINITY),
        max: Vec3::splat(f32::NEG_INFINITY),
    };

    pub fn point(p: Vec3) -> Aabb {
        Aabb { min: p, max: p }
    }

    pub fn with(self, p: Vec3) -> Aabb {
        Aabb {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    pub fn union(self, o: Aabb) -> Aabb {
        Aabb {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }

    /// Slab test against `(0, t_max)`, with the ray's reciprocal direction.
    fn hit(&self, o: Vec3, inv_d: Vec3, t_max: f32) -> bool {
        let t0 = (self.min - o) * inv_d;
        let t1 = (self.max - o) * inv_d;
        let near = t0.min(t1).max_element().max(0.0);
        let far = t0.max(t1).min_element().min(t_max);
        // `near <= far` is false for NaN (0 * inf in a flat box), which would miss a
        // hit, so flat slabs get a little tolerance through the min/max order above.
        near <= far * (1.0 + 2.0 * f32::EPSILON)
    }
}

#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    /// Leaf: first primitive; inner: index of the second child (the first is next).
    offset: u32,
    /// Primitives in a leaf; 0 for an inner node.
    count: u32,
}

/// Primitives with their object ids under a BVH (centroid median splits on the widest
/// axis: simple, and the scenes here have at most a few thousand primitives).
#[derive(Clone, Debug)]
pub struct Bvh {
    prims: Vec<(Shape, u32)>,
    nodes: Vec<Node>,
}

const LEAF_SIZE: usize = 4;

impl Bvh {
    pub fn new(mut prims: Vec<(Shape, u32)>) -> Bvh {
        let mut nodes = Vec::with_capacity(2 * prims.len() / LEAF_SIZE + 1);
        if !prims.is_empty() {
            let n = prims.len();
            build(&mut prims, 0, n, &mut nodes);
        }
        Bvh { prims, nodes }
    }

    /// Nearest hit in `(0, t_max)`.
    pub fn intersect(&self, ray: &Ray, mut t_max: f32) -> Option<Hit> {
        let mut best: Option<(f32, Shape, u32)> = None;
        self.traverse(ray, &mut t_max, |shape, obj, ray, t_max| {
            if let Some(t) = shape.hit_t(ray, *t_max) {
                *t_max = t;
                best = Some((t, *shape, obj));
            }
            false
        });
        best.map(|(t, shape, object)| {
            let (p, err) = shape.surface_point(ray, t);
            Hit {
                t,
                p,
                n: shape.normal(p),
                err,
                object,
            }
        })
    }

    /// Whether anything lies in `(0, t_max)` along the ray.
    pub fn occluded(&self, ray: &Ray, mut t_max: f32) -> bool {
        let mut hit = false;
        self.traverse(ray, &mut t_max, |shape, _, ray, t_max| {
            hit = shape.hit_t(ray, *t_max).is_some();
            hit
        });
        hit
    }

    /// Visits the primitives whose boxes the ray enters; `visit` returns true to stop.
    /// Generic rather than `dyn` so the per-primitive test inlines (traversal is most of
    /// the render time).
    fn traverse(
        &self,
        ray: &Ray,
        t_max: &mut f32,
        mut visit: impl FnMut(&Shape, u32, &Ray, &mut f32) -> bool,
    ) {
        if self.nodes.is_empty() {
            return;
        }
        let inv_d = ray.d.recip();
        let mut stack = [0u32; 64];
        let mut sp = 1;
        while sp > 0 {
            sp -= 1;
            let i = stack[sp];
            let node = self.nodes[i as usize];
            if !node.bounds.hit(ray.o, inv_d, *t_max) {
                continue;
            }
            if node.count > 0 {
                let start = node.offset as usize;
                for (shape, obj) in &self.prims[start..start + node.count as usize] {
                    if visit(shape, *obj, ray, t_max) {
                        return;
                    }
                }
            } else {
                // Children: the first follows its parent, the second is at `offset`.
                // Median splits keep the depth near log2(primitives), far below 32.
                stack[sp] = i + 1;
                stack[sp + 1] = node.offset;
                sp += 2;
            }
        }
    }
}

/// Builds the subtree over `prims[start..end]` and returns its node index.
fn build(prims: &mut [(Shape, u32)], start: usize, end: usize, nodes: &mut Vec<Node>) -> u32 {
    let bounds = prims[start..end]
        .iter()
        .fold(Aabb::EMPTY, |b, (s, _)| b.union(s.bounds()));
    let index = nodes.len() as u32;
    nodes.push(Node {
        bounds,
        offset: start as u32,
        count: (end - start) as u32,
    });
    if end - start <= LEAF_SIZE {
        return index;
    }
    let centroids = prims[start..end]
        .iter()
        .fold(Aabb::EMPTY, |b, (s, _)| b.with(s.centroid()));
    let extent = centroids.max - centroids.min;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mid = (start + end) / 2;
    prims[start..end].select_nth_unstable_by(mid - start, |a, b| {
        a.0.centroid()[axis].total_cmp(&b.0.centroid()[axis])
    });
    let first = build(prims, start, mid, nodes);
    debug_assert_eq!(first, index + 1);
    let second = build(prims, mid, end, nodes);
    nodes[index as usize].offset = second;
    nodes[index as usize].count = 0;
    index
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute(prims: &[(Shape, u32)], ray: &Ray) -> Option<(f32, u32)> {
        let mut best: Option<(f32, u32)> = None;
        for (s, o) in prims {
            if let Some((t, _)) = s.intersect(ray, f32::INFINITY) {
                if best.is_none_or(|b| t < b.0) {
                    best = Some((t, *o));
                }
            }
        }
        best
    }

    #[test]
    fn bvh_agrees_with_brute_force() {
        let mut rng = crate::rng::Rng::for_sample(3, 0, 0);
        let mut r3 = || Vec3::new(rng.f32(), rng.f32(), rng.f32()) * 2.0 - 1.0;
        let mut prims = Vec::new();
        for i in 0..200u32 {
            let c = r3() * 5.0;
            let shape = match i % 3 {
                0 => Shape::Sphere {
                    center: c,
                    radius: 0.2,
                },
                1 => Shape::Quad {
                    corner: c,
                    u: r3() * 0.5,
                    v: r3() * 0.5,
                },
                _ => Shape::Triangle {
                    p0: c,
                    e1: r3(),
                    e2: r3(),
                },
            };
            prims.push((shape, i));
        }
        let bvh = Bvh::new(prims.clone());
        let mut hits = 0;
        for i in 0..500 {
            // Every other ray aims at a primitive, so the hit branches are exercised too.
            let o = r3() * 6.0;
            let d = if i % 2 == 0 {
                prims[i % prims.len()].0.centroid() - o
            } else {
                r3()
            };
            let ray = Ray {
                o,
                d: d.normalize(),
            };
            let want = brute(&prims, &ray);
            let got = bvh.intersect(&ray, f32::INFINITY).map(|h| (h.t, h.object));
            assert_eq!(want.map(|w| w.1), got.map(|g| g.1));
            assert_eq!(want.is_some(), bvh.occluded(&ray, f32::INFINITY));
            hits += want.is_some() as usize;
        }
        // Both sides share `Shape::intersect`: agreeing on misses alone would prove nothing.
        assert!(hits >= 250, "only {hits} of 500 rays hit anything");
    }

    #[test]
    fn sphere_hits_from_inside_and_outside() {
        let s = Shape::Sphere {
            center: Vec3::ZERO,
            radius: 1.0,
        };
        let out = Ray {
            o: Vec3::new(0.0, 0.0, -3.0),
            d: Vec3::Z,
        };
        let (t, n) = s.intersect(&out, f32::INFINITY).unwrap();
        assert!((t - 2.0).abs() < 1e-5 && (n + Vec3::Z).length() < 1e-5);
        let inside = Ray {
            o: Vec3::ZERO,
            d: Vec3::X,
        };
        let (t, n) = s.intersect(&inside, f32::INFINITY).unwrap();
        assert!((t - 1.0).abs() < 1e-5 && (n - Vec3::X).length() < 1e-5);
    }
}

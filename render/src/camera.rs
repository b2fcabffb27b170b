//! Pinhole camera.

use crate::geometry::Ray;
use glam::Vec3;

#[derive(Clone, Copy, Debug)]
pub struct Camera {
    pub position: Vec3,
    /// Forward, right and up scaled so that film coordinates in `[-1, 1]` span the view.
    forward: Vec3,
    right: Vec3,
    up: Vec3,
}

impl Camera {
    /// `fov_y_deg` is the vertical field of view; `aspect` = width / height.
    pub fn new(position: Vec3, look_at: Vec3, up: Vec3, fov_y_deg: f32, aspect: f32) -> Camera {
        let forward = (look_at - position).normalize();
        let right = forward.cross(up).normalize();
        let up = right.cross(forward);
        let h = (fov_y_deg.to_radians() * 0.5).tan();
        Camera {
            position,
            forward,
            right: right * h * aspect,
            up: up * h,
        }
    }

    /// The ray through film point `(sx, sy)` in `[0, 1]^2`, `(0, 0)` the top-left corner.
    pub fn ray(&self, sx: f32, sy: f32) -> Ray {
        let d = self.forward + self.right * (2.0 * sx - 1.0) + self.up * (1.0 - 2.0 * sy);
        Ray {
            o: self.position,
            d: d.normalize(),
        }
    }
}

//! The perspective camera of the vista and perspective views.

use glam::{Vec2, Vec3, Vec4};

/// A single-point perspective camera, in world units (x right, y towards
/// the front, z up).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Camera {
    eye: Vec3,
    up: Vec3,
    forward: Vec3,
    near: f32,
    /// Depth of the middle of the back edge at sea level.
    back_depth: f32,
}

/// A camera's projection along one grid row ([`Camera::along_row`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct RowCamera {
    eye: Vec3,
    forward: Vec3,
    up: Vec3,
    /// The row's share of the depth and of the height above the eye.
    forward_y: f32,
    up_y: f32,
    near: f32,
}

impl RowCamera {
    /// Unscaled screen position of the point at world x `x`, height `z`.
    #[inline]
    pub(crate) fn project(&self, x: f32, z: f32) -> Vec2 {
        let (dx, dz) = (x - self.eye.x, z - self.eye.z);
        let depth = (dx * self.forward.x + self.forward_y + dz * self.forward.z).max(self.near);
        let up = dx * self.up.x + self.up_y + dz * self.up.z;
        Vec2::new(dx / depth, -up / depth)
    }

    /// [`RowCamera::project`] of four points at once (their world x and
    /// height in lanes): the same operations lane by lane, so the same bits.
    #[inline]
    pub(crate) fn project4(&self, x: Vec4, z: Vec4) -> [Vec4; 2] {
        let (dx, dz) = (x - Vec4::splat(self.eye.x), z - Vec4::splat(self.eye.z));
        let depth = dx * self.forward.x + Vec4::splat(self.forward_y) + dz * self.forward.z;
        // `f32::max`'s choice on every platform (a vector max may keep a
        // NaN on one and drop it on another): `near` unless the depth is
        // greater.
        let near = Vec4::splat(self.near);
        let depth = Vec4::select(depth.cmpgt(near), depth, near);
        let up = dx * self.up.x + Vec4::splat(self.up_y) + dz * self.up.z;
        [dx / depth, -up / depth]
    }
}

impl Camera {
    /// How high the camera stands, in world units.
    pub(crate) fn eye_height(&self) -> f32 {
        self.eye.z
    }

    /// At `eye`, level sideways, looking towards `-y` and down by `pitch`
    /// radians, for a grid `extent` units wide.
    pub(crate) fn looking_back(eye: Vec3, pitch: f32, extent: f32) -> Self {
        let (sin, cos) = pitch.sin_cos();
        let forward = Vec3::new(0.0, -cos, -sin);
        let up = Vec3::new(0.0, -sin, cos);
        Camera::aimed(eye, up, forward, extent)
    }

    /// At `eye` looking along `forward` with `up` up, for a grid `extent`
    /// units wide: depths are measured against the back edge's middle.
    fn aimed(eye: Vec3, up: Vec3, forward: Vec3, extent: f32) -> Self {
        let mut cam = Camera {
            eye,
            up,
            forward,
            near: 1e-3 * extent,
            back_depth: 1.0,
        };
        cam.back_depth = cam.depth(Vec3::new(0.5 * extent, 0.0, 0.0)).max(cam.near);
        cam
    }

    /// How far `p` lies in front of the camera.
    #[inline]
    pub(crate) fn depth(&self, p: Vec3) -> f32 {
        (p - self.eye).dot(self.forward).max(self.near)
    }

    /// In front of the mountain's middle, above it, looking down at its centre.
    pub(crate) fn new(extent: f32, zmax: f32) -> Self {
        let eye = Vec3::new(0.5 * extent, 1.75 * extent, 0.4 * extent + 0.8 * zmax);
        let target = Vec3::new(0.5 * extent, 0.45 * extent, 0.0);
        let forward = (target - eye).normalize();
        let up = (Vec3::Z - forward * forward.z).normalize();
        Camera::aimed(eye, up, forward, extent)
    }

    /// Unscaled screen position (x right, y down).
    #[inline]
    pub(crate) fn project(&self, p: Vec3) -> Vec2 {
        let d = p - self.eye;
        let depth = self.depth(p);
        Vec2::new(d.x / depth, -d.dot(self.up) / depth)
    }

    /// The sight line (not of unit length) through unscaled screen point
    /// `u`: what [`Camera::project`] sends to `u` lies along it.
    pub(crate) fn sight(&self, u: Vec2) -> Vec3 {
        // The screen's x is the world's x (the camera is level sideways).
        self.forward + Vec3::X * u.x - self.up * u.y
    }

    /// [`Camera::project`] for the points of one line of world y `y` (a
    /// grid row): the terms that do not change along it, worked out once.
    /// The same sums in the same order, so the same bits.
    pub(crate) fn along_row(&self, y: f32) -> RowCamera {
        let dy = y - self.eye.y;
        RowCamera {
            eye: self.eye,
            forward: self.forward,
            up: self.up,
            forward_y: dy * self.forward.y,
            up_y: dy * self.up.y,
            near: self.near,
        }
    }

    /// How far `p` lies in front of the camera, as a share of the back
    /// edge's middle (1 there).
    pub(crate) fn relative_depth(&self, p: Vec3) -> f32 {
        self.depth(p) / self.back_depth
    }

    /// Where the eye is, in world units.
    pub(crate) fn eye(&self) -> Vec3 {
        self.eye
    }

    /// Unscaled screen position where lines along `dir` vanish (their
    /// point at infinity); `None` for directions not in front of the camera.
    pub(crate) fn vanishing(&self, dir: Vec3) -> Option<Vec2> {
        let depth = dir.dot(self.forward);
        (depth > 1e-6 * dir.length()).then(|| Vec2::new(dir.x / depth, -dir.dot(self.up) / depth))
    }

    /// Where the eye stands across the grid, in world units.
    pub(crate) fn eye_x(&self) -> f32 {
        self.eye.x
    }

    /// Where the eye stands over the ground (across, towards the front),
    /// in world units.
    pub(crate) fn eye_ground(&self) -> Vec2 {
        Vec2::new(self.eye.x, self.eye.y)
    }
}

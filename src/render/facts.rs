//! What a prepared scene is, in terms that do not depend on the frame's size
//! or the grid: its light, its sky, its sea and where it puts the land in
//! the frame (as fractions of the frame). For tests and tools that hold one
//! mountain's scene at several frame sizes, details and `low_detail`
//! against each other: only the grid may differ between them.

use glam::{Vec2, Vec3};

use super::base::size::Size;
use super::scene::{FieldRef, Scene};
use super::shade::light::Lighting;
use crate::settings::Settings;
use crate::terrain::Heightfield;

/// The scene of one mountain in one frame, as a drawing would have it.
#[derive(Debug, Clone)]
pub struct SceneFacts {
    /// The light on the land (sun, colours) and the sky's colours.
    pub lighting: Lighting,
    /// The sky's colours as drawn, packed `0x00RRGGBB`: top and horizon.
    pub sky: (u32, u32),
    /// The sea's wind streaks, if the look has them.
    pub ripples: Option<RippleFacts>,
    view: super::framing::view::View,
    /// The sky as drawn: its gradient, the sun's glow and the clouds.
    backdrop: super::shade::sky::Sky,
    /// Grid steps a side.
    cells: f32,
    width: f32,
    height: f32,
}

/// The wind on a scene's sea.
#[derive(Debug, Clone)]
pub struct RippleFacts {
    /// What the pattern is drawn from.
    pub seed: u64,
    ripples: super::shade::ripples::Ripples,
    cells: f32,
}

impl SceneFacts {
    /// Prepares `field` as `settings` ask in a frame of `size`,
    /// exactly as drawing it would, and reports the scene.
    pub fn of(field: &Heightfield, settings: &Settings, size: Size) -> Self {
        let scene = Scene::new(FieldRef::Borrowed(field), settings, size);
        let cells = scene.cells().max(1) as f32;
        SceneFacts {
            lighting: scene.palette.lighting().clone(),
            sky: scene.palette.sky(),
            ripples: scene.ripples.as_ref().map(|r| RippleFacts {
                seed: r.seed(),
                ripples: r.clone(),
                cells,
            }),
            view: scene.view.clone(),
            backdrop: scene.sky.clone(),
            cells,
            width: size.width.max(1) as f32,
            height: size.height.max(1) as f32,
        }
    }

    /// Where the point `x` of the field's width and `y` of its depth (both
    /// 0..=1, from the back left corner) at height `z` appears, as fractions
    /// of the frame's width and height from its top left corner.
    pub fn place(&self, x: f32, y: f32, z: f32) -> Vec2 {
        let p = self.view.project(x * self.cells, y * self.cells, z);
        p / Vec2::new(self.width, self.height)
    }
}

impl SceneFacts {
    /// The eye and the unit sight line through `x` of the frame's width
    /// and `y` of its height from its top left corner, in world units (x
    /// right, y towards the front, z up; point (`gx`, `gy`) of the grid
    /// drawn ([`drawn_field`]) at height `z` lies at (`gx`, `gy`) times
    /// [`SceneFacts::cell`], `z`); `None` in the oblique view, which has
    /// no eye. For measurements that trace lines of their own, as the
    /// reflections' figure does.
    pub fn sight_line(&self, x: f32, y: f32) -> Option<(Vec3, Vec3)> {
        let eye = self.view.eye()?;
        let sight = self.view.sight(x * self.width, y * self.height)?;
        Some((eye, sight))
    }

    /// Width of one step of the grid drawn (see [`drawn_field`]) in world
    /// units (heights' units). Unlike the rest of the facts it depends on
    /// the grid: it is for tracing lines over the ground drawn.
    pub fn cell(&self) -> f32 {
        self.view.cell()
    }
}

/// The field as drawing `field` with `settings` in a frame of `size` lays
/// it out, which [`SceneFacts::sight_line`] and [`SceneFacts::cell`] go
/// with: turned by `rotation` (and the essay's turn), a data set at its
/// drawn scale, Sonar's and Outline's coarser grid; `field` itself
/// otherwise.
pub fn drawn_field(field: &Heightfield, settings: &Settings, size: Size) -> Heightfield {
    let (drawn, _, _) = super::scene::laid_out(FieldRef::Borrowed(field), settings, size);
    (*drawn).clone()
}

impl SceneFacts {
    /// The sky's colour (undithered, packed) at `x` of the frame's width
    /// and `y` of its height from its top left corner: the gradient with
    /// the sun's glow and the clouds over it.
    pub fn sky_at(&self, x: f32, y: f32) -> u32 {
        self.backdrop.colour_at(x * self.width, y * self.height)
    }

    /// Whether the sky holds anything over its gradient (glow or cloud).
    pub fn has_weather(&self) -> bool {
        self.backdrop.weather().is_some()
    }
}

impl RippleFacts {
    /// The ripple (-1..1) at `x` of the field's width and `y` of its depth
    /// (both 0..=1): above 0 the water mirrors the sky, below it is darker.
    pub fn at(&self, x: f32, y: f32) -> f32 {
        self.ripples.value(x * self.cells, y * self.cells)
    }
}

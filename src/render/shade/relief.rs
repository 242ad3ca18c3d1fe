//! The land's relief below the grid: where a cell covers more than a couple
//! of pixels, the light of each pixel is taken from a finer terrain than
//! the one drawn (as iq's *Elevated* takes its normals from more octaves
//! than it marches).
//!
//! The finer terrain goes on with the generator's own rule below the
//! grid's last level: each level of half the spacing, its bumps half as
//! tall. A level is value noise on a lattice of its spacing, turned by its
//! own angle so that no level lines up with the grid, from the mountain's
//! seed and the level's number in land coordinates. The same seed has the
//! same relief at every grid size, every thread count and strip budget;
//! only the levels the grid does not draw itself are added.
//!
//! Only the light changes: the mesh, its heights and its outline are the
//! grid's, so the refinement opens no crack and the coarse land stays the
//! same. A level shows in full where its bumps are at least
//! [`FULL_PX`] pixels across and fades out by [`NONE_PX`]: far land,
//! whose cells are a pixel or less, is drawn as before.

use glam::{Vec2, Vec3, Vec4};

use super::strata;
use crate::terrain::Heightfield;
use crate::terrain::splitmix::mix;

/// Levels below the grid at most: at 4K the nearest cells are about 40
/// pixels across, and the fifth level's bumps there are a pixel or so.
const LEVELS: usize = 5;

/// A level's bumps at least this many pixels across show in full.
const FULL_PX: f32 = 2.0;
/// A level whose bumps are at most this many pixels across is left out:
/// finer, its light would only sparkle.
const NONE_PX: f32 = 0.8;

/// How much ground seen at a slant (its unit normal's cosine to the line
/// of sight, `facing`) narrows the levels that show on it: its cells count
/// `facing` to this power of their face-on size. Bumps on ground seen at a
/// slant are squeezed on screen across the slant, and there a level's
/// light would sparkle long before it does face-on; in full (a power of 1)
/// the near land would lose its finest level where it is seen edge-on.
/// Measured over the quality seeds at 1080p against the 4x reference and
/// the near land's detail against a `detail = 12` grid (1080p, before the
/// worlds drew their heights per mountain; BENCHMARKS.md has today's): 0
/// gave 44.2 dB and 1.21 of the finer grid's detail, 0.15 45.1 dB and
/// 0.90, 0.5 46.6 dB and 0.79.
const FORESHORTENING: f32 = 0.15;
/// Least `facing` counted: ground seen edge-on keeps some of its size.
const LEAST_FACING: f32 = 0.05;

/// A face is drawn with its relief when one of its corners' cells is at
/// least this many pixels across: the first level fades in above it (its
/// lattice has at least two steps a cell), so a face drawn plain and a
/// refined neighbour agree where they meet.
const MIN_CELL_PX: f32 = 2.0 * NONE_PX;

/// How tall the first level's bumps are against the grid's own last
/// level's: the generator halves its cragginess at every level.
const FIRST: f32 = 0.5;

/// Values a grid point hands the pixels of the faces around it
/// ([`FinePoint::lanes`]), and [`Relief::gains`] reads of each pixel.
pub(crate) const LANES: usize = 9;

/// What a grid point tells the pixels of the faces around it about its
/// relief, blended across each face as its colour is.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct FinePoint {
    /// The point's smooth normal as slopes: the normal runs along
    /// `(x, y, 1)` (the palette's frame).
    pub slope: Vec2,
    /// How much of the point's colour comes from the direct light per
    /// unit of its cosine, and from the sky per unit of the normal's
    /// upward part (the haze's share left out).
    pub shares: Vec2,
    /// How many pixels a cell spans here.
    pub cell_px: f32,
    /// How tall the grid's last level's bumps are here, in height units.
    pub rough: f32,
}

impl FinePoint {
    /// The point's values as a face blends them: grid x and y, the
    /// slopes, the shares, the cell's pixels, the roughness and the
    /// ground's height `h` (in height units: where the side views read
    /// their bumps, see [`Relief::gains`]).
    #[inline]
    pub(crate) fn lanes(&self, g: Vec2, h: f32) -> [f32; LANES] {
        [
            g.x,
            g.y,
            self.slope.x,
            self.slope.y,
            self.shares.x,
            self.shares.y,
            self.cell_px,
            self.rough,
            h,
        ]
    }

    /// The point a share `f` of the way from `self` to `other`.
    pub(crate) fn lerp(&self, other: &FinePoint, f: f32) -> FinePoint {
        FinePoint {
            slope: self.slope.lerp(other.slope, f),
            shares: self.shares.lerp(other.shares, f),
            cell_px: self.cell_px + (other.cell_px - self.cell_px) * f,
            rough: self.rough + (other.rough - self.rough) * f,
        }
    }
}

/// The finer terrain of one mountain, and the light that falls on it.
#[derive(Clone, Debug)]
pub(crate) struct Relief {
    lattice: Lattice,
    /// Lattice steps of the first level below the grid per grid step.
    first_step: f32,
    /// Number of the first level below the grid (the land's side is one
    /// step of level 0).
    first_level: u32,
    /// Each level's turn and offset.
    turns: [Turn; LEVELS],
    /// The side views' levels' ([`SIDE_LEVELS`], coarsest first).
    side_turns: [Turn; SIDE_LEVELS],
    /// Unit vector towards the light, in the palette's frame.
    sun: Vec3,
    /// Height units per grid step.
    cell: f32,
    /// How tall the grid's last level's bumps are around each block of
    /// [`BLOCK`] points a side (their root mean square), a block's value
    /// at its first point: what the finer levels go on from.
    rough: Vec<f32>,
    /// Blocks a side, plus one.
    blocks: usize,
    /// The frame's pixels per pixel of the frame the relief is for: 1,
    /// but in a reference drawn k times finer (see [`Relief::for_finer`]).
    finer: f32,
    /// [`Relief::levels_shown`] at steps of the cells' pixels.
    shown: ShownTable,
}

/// [`Relief::levels_shown`] at every [`SHOWN_STEP`] of the cells' pixels
/// up to where every level shows in full, on faces that may take the
/// plan's bumps and on walls: the count grows with the cells' pixels, so
/// the values at the two steps around a cell's pixels bound its own.
#[derive(Clone, Debug, Default)]
struct ShownTable {
    open: Vec<f32>,
    walls: Vec<f32>,
}

/// The table's step, in cell pixels: a power of two, so that a cell's
/// step is found without rounding.
const SHOWN_STEP: f32 = 0.25;
/// How much wider than the table's two values the bounds are taken: far
/// more than the rounding of the count's sums and smooth steps.
const SHOWN_MARGIN: f32 = 1e-4;

impl ShownTable {
    /// The table of `relief`.
    fn of(relief: &Relief) -> Self {
        // The finest plan level shows in full from FULL_PX of its bumps,
        // 2^(LEVELS - 1) first-level steps; the side views' sooner.
        let full = FULL_PX * (1 << (LEVELS - 1)) as f32 * relief.first_step;
        let steps = (full / SHOWN_STEP).ceil() as usize + 2;
        let at = |walls: bool| {
            (0..steps)
                .map(|j| relief.levels_shown(j as f32 * SHOWN_STEP, walls))
                .collect()
        };
        ShownTable {
            open: at(false),
            walls: at(true),
        }
    }

    /// The least and the most [`Relief::levels_shown`] of cells spanning
    /// `cell_px` pixels, if within the table.
    #[inline]
    fn bounds(&self, cell_px: f32, walls: bool) -> Option<(f32, f32)> {
        let table = if walls { &self.walls } else { &self.open };
        let at = cell_px / SHOWN_STEP;
        if !(at >= 0.0 && at < table.len().saturating_sub(1) as f32) {
            return None;
        }
        let j = at as usize;
        Some((
            table[j] * (1.0 - SHOWN_MARGIN),
            table[j + 1] * (1.0 + SHOWN_MARGIN),
        ))
    }
}

/// Points a side of the blocks whose roughness is measured together: one
/// point's own stands out or not by chance.
const BLOCK: usize = 8;

impl Relief {
    /// The relief below the grid of `field` (`seed` its mountain's), lit
    /// from `sun`, with cells `cell` height units wide.
    pub(crate) fn new(field: &Heightfield, seed: u64, sun: Vec3, cell: f32) -> Self {
        let cells = field.size().max(2) - 1;
        // The land's side is one step of level 0; the grid's own last
        // level has steps of one cell. In integers: a library's log2 may
        // round 1024's to just over 10.
        let first_level = cells.next_power_of_two().trailing_zeros() + 1;
        let first_step = 2f32.powi(first_level as i32) / cells as f32;
        let (rough, blocks) = roughness(field);
        let turns = std::array::from_fn(|k| Turn::of(seed ^ mix(first_level as u64 + k as u64)));
        let side_turns = std::array::from_fn(|j| {
            Turn::of(seed ^ mix(SIDE_KEY ^ (first_level as u64 + j as u64)))
        });
        let mut relief = Relief {
            lattice: Lattice::new(seed),
            first_step,
            first_level,
            turns,
            side_turns,
            sun,
            cell,
            rough,
            blocks,
            finer: 1.0,
            shown: ShownTable::default(),
        };
        relief.shown = ShownTable::of(&relief);
        relief
    }

    /// This relief in a frame `k` times as wide and tall as the one it is
    /// for: its levels stop where that frame's pixels would, so that the
    /// frame averaged down k times is the smaller one's scene (as a
    /// reference drawn with the smaller frame's grid is its land).
    pub(crate) fn for_finer(mut self, k: f32) -> Self {
        self.finer = k.max(1.0);
        self
    }

    /// Whether the relief can show on a face whose corners are `points`
    /// with colours `colours`: at its strongest it changes a channel of
    /// some pixel by a level or more (a dark, hazed, smooth or far face is
    /// drawn plain). A pixel's values are blended from its corners', so
    /// each factor is bounded by its greatest at a corner; along an edge of
    /// a face drawn plain, a refined neighbour's light differs from its own
    /// by under a level.
    #[inline]
    pub(crate) fn shows(&self, points: [&FinePoint; 3], colours: [u32; 3]) -> bool {
        let most = |f: &dyn Fn(&FinePoint) -> f32| points.iter().map(|p| f(p)).fold(0.0, f32::max);
        let cell_px = most(&|p| p.cell_px);
        if cell_px < MIN_CELL_PX {
            return false;
        }
        // The most a pixel's light changes per unit of its shares and
        // roughness: a level's slope at its steepest, over the cell, for
        // as much of each level as shows at the face's largest cells.
        let walls = steepest_everywhere(points.map(|p| p.slope));
        let (shares, rough) = (
            most(&|p| p.shares.x + p.shares.y * (1.0 + HOLLOW)),
            most(&|p| p.rough),
        );
        let bright = colours
            .iter()
            .flat_map(|c| [16, 8, 0].map(|s| (c >> s) & 0xff))
            .max()
            .unwrap_or(0);
        let reaches = |levels: f32| {
            let per = STEEPEST * FIRST * self.first_step * levels / self.cell;
            shares * rough * per * bright as f32 >= 1.0
        };
        // The levels' count is worked out only where its table's bounds
        // leave the answer open: the same answer, for a fraction of the
        // faces' cost (`most` is never negative or NaN, so `reaches` grows
        // with the count).
        match self.shown.bounds(cell_px, walls) {
            Some((_, most_levels)) if !reaches(most_levels) => false,
            Some((least_levels, _)) if reaches(least_levels) => true,
            _ => reaches(self.levels_shown(cell_px, walls)),
        }
    }

    /// How many levels show where a cell spans `cell_px` pixels, each
    /// counted by how much of it shows (as [`Relief::slopes`] fades them):
    /// the plan's or the side views', whichever the more (a pixel's share
    /// of the plan's bumps and of the side views' make at most one); the
    /// side views' alone on `walls`, faces too steep for the plan's.
    fn levels_shown(&self, cell_px: f32, walls: bool) -> f32 {
        let px = Vec4::splat(cell_px);
        let side: f32 = self.side_fades(px).map(|(_, _, w)| w.x).sum::<f32>() * SIDE_BUMPS;
        if walls {
            return side;
        }
        let plan: f32 = self.fades(px).map(|(_, w)| w.x).sum();
        plan.max(side)
    }

    /// Each level that shows where cells span `cell_px` pixels (a pixel a
    /// lane), with how much of it shows: finer levels until none shows in
    /// any lane.
    #[inline(always)]
    fn fades(&self, cell_px: Vec4) -> impl Iterator<Item = (usize, Vec4)> {
        let px = cell_px / self.first_step;
        (0..LEVELS)
            .map(move |k| (k, fade(px / (1 << k) as f32)))
            .take_while(|(_, w)| w.cmpne(Vec4::ZERO).any())
    }

    /// [`Relief::fades`] of the side views' levels, coarsest first: each
    /// level's number among them, its spacing against the first level
    /// below the grid's, and its weight ([`SIDE_WEIGHTS`]) times how much
    /// of it shows. The levels coarser than that first one fade in with
    /// it, so a face drawn plain and a refined neighbour agree where they
    /// meet.
    #[inline(always)]
    fn side_fades(&self, cell_px: Vec4) -> impl Iterator<Item = (usize, f32, Vec4)> {
        let px = cell_px / self.first_step;
        (0..SIDE_LEVELS)
            .map(move |j| {
                let scale = 2f32.powi(j as i32 - SIDE_COARSER as i32);
                (j, scale, fade(px / scale.max(1.0)) * SIDE_WEIGHTS[j])
            })
            .take_while(|(_, _, w)| w.cmpne(Vec4::ZERO).any())
    }

    /// Whether a point whose cells span `cell_px` of the relief's pixels
    /// needs what the relief asks of it: a face around it may be refined
    /// (the cells of neighbouring points span under twice as many).
    #[inline]
    pub(crate) fn needs(&self, cell_px: f32) -> bool {
        cell_px >= 0.5 * MIN_CELL_PX
    }

    /// How many of the relief's pixels a cell spans where it spans
    /// `frame_px` of the frame's.
    #[inline]
    pub(crate) fn cell_px(&self, frame_px: f32) -> f32 {
        frame_px / self.finer
    }

    /// [`Relief::cell_px`] of a cell `frame_px` across seen face-on, on
    /// ground of unit normal `normal` (palette frame) seen along
    /// `from_eye` (from the eye to it; `None` without an eye): narrowed by
    /// its foreshortening to the [`FORESHORTENING`] power.
    pub(crate) fn cell_px_seen(&self, frame_px: f32, normal: Vec3, from_eye: Option<Vec3>) -> f32 {
        let facing = from_eye.map_or(1.0, |v| normal.dot(v.normalize_or_zero()).abs());
        self.cell_px(frame_px) * facing.max(LEAST_FACING).powf(FORESHORTENING)
    }

    /// How tall the grid's last level's bumps are at grid point (`x`, `y`):
    /// its blocks' roughness, blended.
    pub(crate) fn rough_at(&self, x: usize, y: usize) -> f32 {
        let (bx, by) = (x / BLOCK, y / BLOCK);
        let (fx, fy) = (
            (x % BLOCK) as f32 / BLOCK as f32,
            (y % BLOCK) as f32 / BLOCK as f32,
        );
        let at = |i: usize, j: usize| {
            let (i, j) = ((bx + i).min(self.blocks - 1), (by + j).min(self.blocks - 1));
            self.rough[j * self.blocks + i]
        };
        let top = at(0, 0) + (at(1, 0) - at(0, 0)) * fx;
        let bottom = at(0, 1) + (at(1, 1) - at(0, 1)) * fx;
        top + (bottom - top) * fy
    }

    /// The finer terrain's slope (height units per grid step, x and y) at
    /// grid position `g`, of bumps `rough` tall at the first level, with
    /// the levels that show where a cell spans `cell_px` pixels; and (z)
    /// each level's height over its width, summed: how far the point lies
    /// in a hollow (below 0) or on a knoll.
    #[cfg(test)]
    fn slope(&self, g: Vec2, cell_px: f32, rough: f32) -> Vec3 {
        let [x, y, z] = self.slopes(
            [Vec4::splat(g.x), Vec4::splat(g.y)],
            Vec4::splat(cell_px),
            Vec4::splat(rough),
        );
        Vec3::new(x.x, y.x, z.x)
    }

    /// [`Relief::slope`] of four pixels at once, a pixel a lane: grid x
    /// and y `g`, the cells' pixels and the roughness.
    #[inline]
    fn slopes(&self, g: [Vec4; 2], cell_px: Vec4, rough: Vec4) -> [Vec4; 3] {
        let mut slope = [Vec4::ZERO; 3];
        // Each level's bumps are half as tall and half as wide: the same
        // slope, faded by how many pixels they span.
        for (k, w) in self.fades(cell_px) {
            let step = self.first_step * (1 << k) as f32;
            let level = self.plan_level(k, [g[0] * step, g[1] * step]);
            for (s, l) in slope.iter_mut().zip(level) {
                *s += l * w;
            }
        }
        // A level's slope in grid steps: its bumps' height over its step.
        slope.map(|s| s * (rough * (FIRST * self.first_step)))
    }

    /// [`Relief::slopes`] of a side view: its levels from
    /// [`SIDE_COARSER`] above the first below the grid, each weighed by
    /// [`SIDE_WEIGHTS`], on the plane of `g` (a grid direction and the
    /// height in grid steps).
    #[inline]
    fn side_slopes(&self, g: [Vec4; 2], cell_px: Vec4, rough: Vec4) -> [Vec4; 3] {
        let mut slope = [Vec4::ZERO; 3];
        for (j, scale, w) in self.side_fades(cell_px) {
            let step = self.first_step * scale;
            let number = self.first_level + j as u32 - SIDE_COARSER;
            let level = self.level(self.side_turns[j], number, [g[0] * step, g[1] * step]);
            for (s, l) in slope.iter_mut().zip(level) {
                *s += l * w;
            }
        }
        slope.map(|s| s * (rough * (FIRST * self.first_step)))
    }

    /// [`Relief::level`] of the plan's level `k` below the grid.
    #[inline(always)]
    fn plan_level(&self, k: usize, p: [Vec4; 2]) -> [Vec4; 3] {
        self.level(self.turns[k], self.first_level + k as u32, p)
    }

    /// The slope of the level numbered `number` (turned by `turn`) at `p`
    /// (in its lattice steps, before its turn; four pixels, a pixel a
    /// lane), in its bumps' height per lattice step, and the height there
    /// in the same unit.
    #[inline]
    fn level(&self, turn: Turn, number: u32, p: [Vec4; 2]) -> [Vec4; 3] {
        let (t, o) = (turn.turn, turn.offset);
        let u = [
            p[0] * t.x - p[1] * t.y + Vec4::splat(o.x),
            p[0] * t.y + p[1] * t.x + Vec4::splat(o.y),
        ];
        let [dx, dy, v] = self.lattice.value_slope(number, u);
        // Back from the turned lattice to the grid's directions.
        [dx * t.x + dy * t.y, dy * t.x - dx * t.y, v]
    }

    /// How much brighter (over 1) or darker the finer terrain makes four
    /// pixels, a pixel a lane, whose blended [`FinePoint::lanes`] are `q`
    /// (grid x and y, the slopes, the shares, the cells' pixels, the
    /// roughness and the ground's height).
    ///
    /// The change of the light is taken to first order in the finer
    /// slopes: bumps as often up as down then lighten and darken about
    /// the grid's own light, and seen from afar the land keeps its light
    /// (the whole change would darken ground square to the sun, where any
    /// turn lowers the cosine, and lighten faces turned away).
    ///
    /// Bumps laid over the ground's plan run down a steep face as
    /// streaks, and tilt its normal less the steeper it is: the plan's
    /// bumps fade with the square of the normal's upward part, and a steep
    /// face takes its bumps from a side view instead ([`Relief::sides`]),
    /// as a triplanar texture does.
    #[inline]
    pub(crate) fn gains(&self, q: [Vec4; LANES]) -> Vec4 {
        let [gx, gy, nx, ny, direct, sky, cell_px, rough, height] = q;
        let len = Vec4::from_array((nx * nx + ny * ny + Vec4::ONE).to_array().map(f32::sqrt));
        let inv = Vec4::ONE / len;
        let upward = inv * inv;
        let sine = Vec4::from_array(
            (Vec4::ONE - upward)
                .max(Vec4::ZERO)
                .to_array()
                .map(f32::sqrt),
        );
        let side = ramp(sine, SIDE_FROM, SIDE_FULL);
        // The plan's bumps give way to the side views' (a wall reads none).
        let plan = upward * (Vec4::ONE - side);
        let (mut turn, mut depth) = ([Vec4::ZERO; 3], Vec4::ZERO);
        if plan.cmpgt(Vec4::ZERO).any() {
            let [sx, sy, d] = self.slopes([gx, gy], cell_px, rough * plan);
            // The palette's y runs to the back, the grid's to the front:
            // the normal (x, y, 1) turns by (-sx, sy, 0).
            (turn, depth) = ([-sx / self.cell, sy / self.cell, Vec4::ZERO], d / self.cell);
        }
        if side.cmpgt(Vec4::ZERO).any() {
            let bumps = rough * side * SIDE_BUMPS;
            let (side_turn, side_depth) = self.sides([gy, gx, height], [nx, ny], cell_px, bumps);
            // A side view's slope tilts the unit normal; (x, y, 1) is
            // `len` long.
            for (t, s) in turn.iter_mut().zip(side_turn) {
                *t += s * len;
            }
            depth += side_depth;
        }
        self.light_change([nx, ny, inv], turn, depth, [direct, sky])
    }

    /// The factor of four pixels whose normals (`nx`, `ny`, 1) are `1/inv`
    /// long, turned by `turn` and lying `depth` in a hollow, that take
    /// `shares` of their light from the direct light and the sky.
    #[inline(always)]
    fn light_change(
        &self,
        [nx, ny, inv]: [Vec4; 3],
        [tx, ty, tz]: [Vec4; 3],
        depth: Vec4,
        [direct, sky]: [Vec4; 2],
    ) -> Vec4 {
        let l = self.sun;
        let cos = (nx * l.x + ny * l.y + Vec4::splat(l.z)) * inv;
        // d/dturn of n.sun / |n| and of 1 / |n| (the normal's upward part).
        let along = (tx * nx + ty * ny + tz) * inv * inv;
        let d_cos = (tx * l.x + ty * l.y + tz * l.z) * inv - cos * along;
        let d_up = (tz - along) * inv;
        // Faces turned from the light get none of it; the change fades in
        // past the terminator, so no line is drawn there.
        let lit = (cos * TERMINATOR).clamp(Vec4::ZERO, Vec4::ONE);
        // A hollow sees less of the sky than a knoll.
        let sky = sky * (d_up + depth * HOLLOW);
        let gain = (Vec4::ONE + direct * lit * d_cos + sky)
            .clamp(Vec4::splat(GAIN.0), Vec4::splat(GAIN.1));
        // A clamp keeps NaN (a point's normal gone wrong), and a pixel
        // would turn white: such a pixel keeps the grid's light.
        Vec4::select(gain.is_finite_mask(), gain, Vec4::ONE)
    }

    /// The turn of the unit normal (palette x, y and z) and the hollows'
    /// depth that the side views give four pixels: grid y, grid x and the
    /// ground's height `h`, their normals' slopes `n`, with bumps `rough`
    /// tall at the first level.
    ///
    /// A face turned along x is seen from x: its bumps lie on the plane
    /// of grid y and height; one turned along y, on grid x and height (a
    /// face turned between the two blends them). Each view's bumps stand
    /// out from the face, so they tilt its normal across the face and up
    /// it, whatever its steepness.
    #[inline]
    fn sides(
        &self,
        [gy, gx, h]: [Vec4; 3],
        [nx, ny]: [Vec4; 2],
        cell_px: Vec4,
        rough: Vec4,
    ) -> ([Vec4; 3], Vec4) {
        let z = h / self.cell;
        let (ax, ay) = (nx.abs(), ny.abs());
        let lean = (ax - ay) / (ax + ay).max(Vec4::splat(1e-6));
        let from_x = ramp(lean, -SIDE_BLEND, SIDE_BLEND);
        let from_y = Vec4::ONE - from_x;
        let (mut turn, mut depth) = ([Vec4::ZERO; 3], Vec4::ZERO);
        if from_x.cmpgt(Vec4::ZERO).any() {
            let [a, b, d] = self.side_slopes([gy, z], cell_px, rough * from_x);
            // Grid y runs to the palette's front.
            turn[1] += a / self.cell;
            turn[2] -= b / self.cell;
            depth += d / self.cell;
        }
        if from_y.cmpgt(Vec4::ZERO).any() {
            let [a, b, d] = self.side_slopes([gx, z], cell_px, rough * from_y);
            turn[0] -= a / self.cell;
            turn[2] -= b / self.cell;
            depth += d / self.cell;
        }
        (turn, depth)
    }
}

/// Where the side views take over from the plan's: the sine of the slope
/// (the unit normal's level part) from which they show, and from which in
/// full (51 and 59 degrees). Below, the plan's bumps stretch by at most
/// 1.6 down the slope; the band is narrow, as in it both views are worked
/// out.
const SIDE_FROM: f32 = 0.78;
const SIDE_FULL: f32 = 0.86;
/// How tall a side view's bumps stand out from a face, against the
/// plan's over the ground: a rock face is fractured finer than its slope
/// is rough, and at the plan's height its light would read as sandpaper.
const SIDE_BUMPS: f32 = 0.4;
/// A side view's levels: from this many above the first below the grid
/// (a steep face's cells span few pixels across but many down, and down
/// it the grid draws nothing finer than the face), each level's slope
/// weighed, coarsest first (the finest only a grain).
const SIDE_COARSER: u32 = 2;
const SIDE_LEVELS: usize = 3;
const SIDE_WEIGHTS: [f32; SIDE_LEVELS] = [1.0, 0.7, 0.45];
/// Mixed into the seed for the side views' turns.
const SIDE_KEY: u64 = 0x7369_6465_7669_6577;
/// A face turned between x and y (its normal's |x| - |y| over their sum
/// within this either way) blends the two side views.
const SIDE_BLEND: f32 = 0.2;

/// Whether every pixel of a face whose corners' normals have the slopes
/// `slopes` is steep enough to take no bumps from the plan: a pixel's
/// slopes are blended from its corners' and held within their range, so
/// they lie in the corners' box, whose nearest point to level is tested.
fn steepest_everywhere(slopes: [Vec2; 3]) -> bool {
    let lo = slopes[0].min(slopes[1]).min(slopes[2]);
    let hi = slopes[0].max(slopes[1]).max(slopes[2]);
    if !(lo.is_finite() && hi.is_finite()) {
        return false;
    }
    let nearest = Vec2::ZERO.clamp(lo, hi);
    // The sine of the slope is SIDE_FULL or more where |s|^2 (1 - f^2) >= f^2.
    nearest.length_squared() * (1.0 - SIDE_FULL * SIDE_FULL) >= SIDE_FULL * SIDE_FULL
}

/// 0 up to `from`, 1 from `full` on, smooth between (a pixel a lane).
#[inline(always)]
fn ramp(x: Vec4, from: f32, full: f32) -> Vec4 {
    let t = ((x - Vec4::splat(from)) * (1.0 / (full - from))).clamp(Vec4::ZERO, Vec4::ONE);
    t * t * (Vec4::splat(3.0) - t * 2.0)
}

/// A bound on how much a level changes a pixel's light, per unit of its
/// bumps' height over its step and of the pixel's share of the light
/// ([`Relief::shows`]). A level's value noise is at most 3 steep (its
/// gradient peaks along an axis); the direct light's cosine changes by at
/// most the normal's turn, the sky's upward part by under 0.4 of it under
/// the plan's bumps and by at most the turn under a side view's (3 against
/// the bound's 2 x 5 for the sky's share), and a hollow's depth is at
/// most 1. The strata can make a pixel up to
/// 1 + [`strata::DEPTH`] times the corner colours `shows` reads: 3 x 1.2 is
/// still under this.
const STEEPEST: f32 = 5.0;
const _: () = assert!(3.0 * (1.0 + strata::DEPTH) <= STEEPEST);

/// Over how much of the cosine past the terminator the direct light's
/// change fades in (its inverse).
const TERMINATOR: f32 = 10.0;
/// How much less of the sky a hollow of the finer terrain sees, per unit
/// of its depth over its width (against the change of the sky's light
/// with the normal's upward part).
const HOLLOW: f32 = 1.0;
/// The darkest and the lightest the finer terrain makes a pixel.
const GAIN: (f32, f32) = (0.3, 1.7);

/// How much of a level shows whose bumps span `px` pixels (a pixel a
/// lane).
#[inline]
fn fade(px: Vec4) -> Vec4 {
    ramp(px, NONE_PX, FULL_PX)
}

/// How a level's lattice lies over the land: turned, so that no level
/// lines up with the grid or another, and moved.
#[derive(Clone, Copy, Debug)]
struct Turn {
    /// The turn's cosine and sine.
    turn: Vec2,
    /// The offset, in lattice steps.
    offset: Vec2,
}

impl Turn {
    /// The turn drawn from `h`.
    fn of(h: u64) -> Self {
        let h = mix(h);
        let angle = (h & 0xffff) as f32 / 65536.0 * std::f32::consts::TAU;
        Turn {
            turn: Vec2::new(angle.cos(), angle.sin()),
            offset: Vec2::new(((h >> 16) & 0xff) as f32, ((h >> 24) & 0xff) as f32),
        }
    }
}

/// 1.5 x 2^23: a float from 2^23 on has no fraction, so a number of
/// magnitude under 2^22 added to this is rounded to the nearest whole
/// number (ties to even), kept in the sum's low bits; `value_slope` takes
/// half a step off first, for the floor. Lattice positions stay under
/// 2^18 (a 4097 grid's fifth level below it, turned and offset).
const ROUND: f32 = 12_582_912.0;

/// Lattice points a side of the table of values: a level repeats after
/// this many of its steps (the first below the grid every 128 cells, the
/// fifth every 8, where a cell spans tens of pixels and the five are
/// summed, each turned unlike the others).
const SIDE: usize = 256;

/// The values (-1..=1) at the lattice points of every level of one
/// mountain's finer terrain: a table of [`SIDE`] points a side that each
/// level reads from a place of its own (a hash a point would cost a pixel
/// tens of multiplications; a table a side, one read a point). Each entry
/// holds the four corners of the cell whose first corner it is, so a
/// pixel's cell is one read.
#[derive(Clone, Debug)]
struct Lattice {
    // An array of the table's size: an index masked to it needs no check.
    cells: Box<[[i8; 4]; SIDE * SIDE]>,
}

impl Lattice {
    /// The lattice of the mountain `seed`.
    fn new(seed: u64) -> Self {
        let m = SIDE - 1;
        let values: Vec<i8> = (0..(SIDE * SIDE) as u64)
            .map(|i| ((mix(seed ^ mix(i)) >> 56) as u8 as i8).max(-127))
            .collect();
        let value = |x: usize, y: usize| values[(y & m) * SIDE + (x & m)];
        let mut cells = vec![[0; 4]; SIDE * SIDE].into_boxed_slice();
        for (i, c) in cells.iter_mut().enumerate() {
            let (x, y) = (i % SIDE, i / SIDE);
            *c = [
                value(x, y),
                value(x + 1, y),
                value(x, y + 1),
                value(x + 1, y + 1),
            ];
        }
        Lattice {
            cells: cells.try_into().expect("the table's size"),
        }
    }

    /// The value at lattice point (`x`, `y`) of level `level`.
    #[cfg(test)]
    fn at(&self, level: u32, x: i32, y: i32) -> f32 {
        self.cell(level, x, y).x
    }

    /// [`Lattice::cell_at`] of signed lattice coordinates.
    #[cfg(test)]
    fn cell(&self, level: u32, x: i32, y: i32) -> Vec4 {
        self.cell_at(level, x as usize, y as usize)
    }

    /// The values at the corners of the lattice cell of level `level`
    /// whose first corner is (`x`, `y`) (modulo the table's side): that
    /// corner, the next across, the next down and the one across and down.
    #[inline(always)]
    fn cell_at(&self, level: u32, x: usize, y: usize) -> Vec4 {
        let m = SIDE - 1;
        // Each level reads the table from a place of its own.
        let x = x.wrapping_add(level as usize * 97) & m;
        let y = y.wrapping_add(level as usize * 59) & m;
        Vec4::from_array(self.cells[y * SIDE + x].map(f32::from)) * (1.0 / 127.0)
    }

    /// The slope of level `level`'s value noise at lattice position `u`
    /// (four pixels, a pixel a lane), in units of its bumps' height per
    /// lattice step, and its value: each lattice point a value in -1..=1,
    /// blended between them along a smooth step.
    #[inline]
    fn value_slope(&self, level: u32, u: [Vec4; 2]) -> [Vec4; 3] {
        // Rounded half a step down by the float adder: a number past
        // [`ROUND`] keeps no fraction, and its low bits are its whole part
        // (the cell, of any sign, modulo the table; a NaN reads some cell).
        let half = Vec4::splat(0.5);
        let (rx, ry) = ((u[0] - half) + ROUND, (u[1] - half) + ROUND);
        let (tx, ty) = (u[0] - (rx - ROUND), u[1] - (ry - ROUND));
        let (ix, iy) = (
            rx.to_array().map(f32::to_bits),
            ry.to_array().map(f32::to_bits),
        );
        // The four corners of each pixel's lattice cell, a pixel a lane.
        let cell = |i: usize| self.cell_at(level, ix[i] as usize, iy[i] as usize);
        let cells = glam::Mat4::from_cols(cell(0), cell(1), cell(2), cell(3)).transpose();
        let (v00, v10, v01, v11) = (cells.x_axis, cells.y_axis, cells.z_axis, cells.w_axis);
        let three = Vec4::splat(3.0);
        let (sx, sy) = (tx * tx * (three - tx * 2.0), ty * ty * (three - ty * 2.0));
        let (dsx, dsy) = (tx * (Vec4::ONE - tx) * 6.0, ty * (Vec4::ONE - ty) * 6.0);
        let k = v00 - v10 - v01 + v11;
        let value = v00 + (v10 - v00) * sx + (v01 - v00) * sy + k * sx * sy;
        [
            dsx * (v10 - v00 + k * sy),
            dsy * (v01 - v00 + k * sx),
            value,
        ]
    }
}

/// How far grid point (`x`, `y`) stands from the mean of its four
/// neighbours (its own where the field ends), in height units.
fn laplacian(field: &Heightfield, x: usize, y: usize) -> f32 {
    let last = field.size() - 1;
    let h = |x: usize, y: usize| finite_or(field.get(x, y), 0.0);
    let own = h(x, y);
    let sum = h(x.saturating_sub(1), y)
        + h((x + 1).min(last), y)
        + h(x, y.saturating_sub(1))
        + h(x, (y + 1).min(last));
    (own - 0.25 * sum).abs()
}

/// How far the points of each block of [`BLOCK`] a side around a block
/// corner (every other point each way) stand from their neighbours
/// ([`laplacian`], by its median), on a lattice of blocks
/// `(n - 1) / BLOCK + 2` a side: how tall the grid's last level's bumps
/// are there.
fn roughness(field: &Heightfield) -> (Vec<f32>, usize) {
    let n = field.size();
    let blocks = (n - 1) / BLOCK + 2;
    // Rows of blocks, half on each of two cores: the scene's start waits
    // for it, and at 4K it is some milliseconds of the frame. Each writes
    // its half in place, with no vector of its own.
    let fill = |out: &mut [f32], first_row: usize| {
        let half = BLOCK / 2;
        let mut sample = [0.0f32; BLOCK * BLOCK / 4];
        for (i, r) in out.iter_mut().enumerate() {
            let (cy, cx) = ((first_row + i / blocks) * BLOCK, (i % blocks) * BLOCK);
            // At least the field's last point: past the field's end a
            // block's window would be empty.
            let window = |c: usize| c.saturating_sub(half).min(n - 1)..(c + half).clamp(1, n);
            let mut count = 0;
            for y in window(cy).step_by(2) {
                for x in window(cx).step_by(2) {
                    sample[count] = laplacian(field, x, y);
                    count += 1;
                }
            }
            *r = median(&mut sample[..count]) * MEDIAN_TO_RMS;
        }
    };
    let mut rough = vec![0.0; blocks * blocks];
    let middle = blocks / 2;
    let (front, back) = rough.split_at_mut(middle * blocks);
    crate::threads::both_if(
        crate::cores::cores() >= 2,
        || fill(front, 0),
        || fill(back, middle),
    );
    // A block on a crest or a cliff's rim measures the grid's own bend
    // there, not its finest bumps: each is held to a little over the
    // typical block's.
    let mut all: Vec<f32> = rough.iter().copied().filter(|&r| r > 0.0).collect();
    let cap = median(&mut all) * CAP;
    rough.iter_mut().for_each(|r| *r = r.min(cap));
    (rough, blocks)
}

/// The most a block's roughness may be, as a share of the typical
/// (median) block's.
const CAP: f32 = 1.5;

/// The root mean square of a normal spread over its median absolute
/// value: a block's bumps measured by their median, so that the few
/// points of a rim or a crest in it do not count.
const MEDIAN_TO_RMS: f32 = 1.4826;

/// The middle of `values` (reordered), 0 for none.
fn median(values: &mut [f32]) -> f32 {
    match values.len() {
        0 => 0.0,
        len => *values.select_nth_unstable_by(len / 2, f32::total_cmp).1,
    }
}

fn finite_or(v: f32, or: f32) -> f32 {
    if v.is_finite() { v } else { or }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stream of draws from `state` on, for tests that try many cases.
    fn draws(mut state: u64) -> impl FnMut() -> u64 {
        move || {
            state = mix(state);
            state
        }
    }

    #[test]
    fn a_level_fades_in_between_its_two_sizes() {
        let px = Vec4::new(NONE_PX, 0.5 * NONE_PX, FULL_PX, 40.0);
        assert_eq!(fade(px), Vec4::new(0.0, 0.0, 1.0, 1.0));
        let mid = fade(Vec4::splat(0.5 * (NONE_PX + FULL_PX))).x;
        assert!((mid - 0.5).abs() < 1e-6, "{mid}");
    }

    #[test]
    fn ground_seen_at_a_slant_counts_its_cells_narrower() {
        let field = Heightfield::flat(10, 250.0);
        let relief = Relief::new(&field, 42, Vec3::Z, 0.25);
        let face_on = relief.cell_px(12.0);
        let up = Vec3::Z;
        // Seen from straight above, or without an eye: its own size.
        assert_eq!(
            relief.cell_px_seen(12.0, up, Some(Vec3::NEG_Z * 7.0)),
            face_on
        );
        assert_eq!(relief.cell_px_seen(12.0, up, None), face_on);
        // Lower and lower lines of sight narrow it, down to the least facing.
        let seen = |deg: f32| {
            let a = deg.to_radians();
            relief.cell_px_seen(12.0, up, Some(Vec3::new(0.0, a.cos(), -a.sin())))
        };
        let slants = [90.0, 60.0, 30.0, 10.0, 2.0, 0.0].map(seen);
        assert!(slants[..5].windows(2).all(|w| w[1] < w[0]), "{slants:?}");
        let least = face_on * LEAST_FACING.powf(FORESHORTENING);
        assert!((slants[4] - least).abs() < 1e-4 && slants[5] == slants[4]);
        // At 30 degrees a cell counts half its size to the power.
        assert!((slants[2] - face_on * 0.5f32.powf(FORESHORTENING)).abs() < 1e-4);
    }

    #[test]
    fn a_face_too_small_for_the_relief_meets_a_refined_one_without_a_seam() {
        // Faces whose corners' cells all span less than MIN_CELL_PX are
        // drawn plain; where a refined face's pixels come down to that
        // size, its first level has faded out, so the two agree.
        let field = Heightfield::flat(10, 250.0);
        let relief = Relief::new(&field, 42, Vec3::new(0.3, 0.2, 0.9).normalize(), 0.25);
        for i in 0..100 {
            let g = Vec2::new(i as f32 * 0.37 + 0.13, i as f32 * 0.71 + 0.29);
            assert_eq!(relief.slope(g, MIN_CELL_PX, 1.0), Vec3::ZERO);
            assert_ne!(relief.slope(g, 4.0 * MIN_CELL_PX, 1.0), Vec3::ZERO);
        }
    }

    #[test]
    fn the_gain_is_the_first_order_change_of_the_light_on_the_finer_slope() {
        let sun = Vec3::new(-0.4, 0.5, 0.6).normalize();
        let cell = 0.25;
        let relief = Relief::new(&Heightfield::flat(10, 250.0), 3, sun, cell);
        let cos = |n: Vec3| n.normalize().dot(sun);
        for i in 0..40 {
            let g = Vec2::new(0.37 * i as f32 + 0.11, 3.0 - 0.23 * i as f32);
            let (nx, ny) = (0.3 - 0.02 * i as f32, 0.1 + 0.01 * i as f32);
            // Direct light alone, bumps small enough for the first order.
            let q = |rough: f32| [g.x, g.y, nx, ny, 1.0, 0.0, 24.0, rough, 3.0].map(Vec4::splat);
            assert_eq!(relief.gains(q(0.0)), Vec4::ONE, "no bumps, no change");
            let rough = 1e-5;
            // The plan's bumps, faded by the normal's upward part squared
            // (these slopes are gentle: no side view).
            let upward = 1.0 / (1.0 + nx * nx + ny * ny);
            let s = relief.slope(g, 24.0, rough * upward) / cell;
            // The palette's y runs to the back, the grid's to the front.
            let exact = cos(Vec3::new(nx - s.x, ny + s.y, 1.0)) - cos(Vec3::new(nx, ny, 1.0));
            let got = relief.gains(q(rough)).x - 1.0;
            assert!(
                (got - exact).abs() <= 0.05 * exact.abs() + 2e-7,
                "{i}: gain - 1 = {got}, the light's change {exact}"
            );
        }
    }

    /// The factor of one pixel at grid position `g`, height `h`, whose
    /// normal runs along (`n.x`, `n.y`, 1), with bumps `rough` tall.
    fn gain_at(relief: &Relief, g: Vec2, h: f32, n: Vec2, rough: f32) -> f32 {
        let q = [g.x, g.y, n.x, n.y, 0.7, 0.3, 24.0, rough, h];
        relief.gains(q.map(Vec4::splat)).x
    }

    /// The standard deviation of `values`.
    fn spread(values: &[f32]) -> f32 {
        let mean = values.iter().sum::<f32>() / values.len() as f32;
        let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f32>() / values.len() as f32;
        var.sqrt()
    }

    #[test]
    fn a_steep_face_has_bumps_down_it_as_across_it() {
        // Bumps laid over the ground's plan would not change down a wall
        // (its plan is a line): its light would run down it in streaks.
        let (sun, cell) = (Vec3::new(-0.3, 0.6, 0.5).normalize(), 0.25);
        let relief = Relief::new(&Heightfield::flat(10, 250.0), 11, sun, cell);
        let (g, h) = (Vec2::new(300.0, 400.0), 30.0);
        // Walls turned towards the front, the back and either side.
        for n in [
            Vec2::new(0.0, 8.0),
            Vec2::new(0.0, -8.0),
            Vec2::new(8.0, 0.0),
            Vec2::new(-7.0, 2.0),
        ] {
            // Along the wall: across its normal, level.
            let across = Vec2::new(-n.y, n.x).normalize() * 0.05;
            let down: Vec<f32> = (0..400)
                .map(|i| gain_at(&relief, g, h - i as f32 * 0.05 * cell, n, 0.1))
                .collect();
            let along: Vec<f32> = (0..400)
                .map(|i| gain_at(&relief, g + across * i as f32, h, n, 0.1))
                .collect();
            let (down, along) = (spread(&down), spread(&along));
            assert!(
                down > 0.01 && along > 0.01,
                "{n}: spread {down} down, {along} across"
            );
            assert!(
                down < 3.0 * along && along < 3.0 * down,
                "{n}: spread {down} down, {along} across"
            );
        }
    }

    #[test]
    fn a_face_said_too_steep_for_the_plan_is_so_at_every_pixel() {
        let sine = |s: Vec2| s.length() / (1.0 + s.length_squared()).sqrt();
        let mut draw = draws(9);
        let mut next = || crate::terrain::splitmix::signed_unit(draw());
        let (mut walls, mut not) = (0, 0);
        for face in 0..4000 {
            // Corners turned about one way, steeper or gentler.
            let (base, spread) = (Vec2::new(next(), next()) * 4.0, [0.3, 1.5][face % 2]);
            let slopes: [Vec2; 3] =
                std::array::from_fn(|_| base + Vec2::new(next(), next()) * spread);
            if !steepest_everywhere(slopes) {
                not += 1;
                continue;
            }
            walls += 1;
            for _ in 0..20 {
                // A pixel's slopes: blended, or held to the corners' box.
                let (a, b) = ((next() + 1.0) / 2.0, (next() + 1.0) / 2.0);
                let blend = slopes[0] * a * b + slopes[1] * a * (1.0 - b) + slopes[2] * (1.0 - a);
                let lo = slopes[0].min(slopes[1]).min(slopes[2]);
                let hi = slopes[0].max(slopes[1]).max(slopes[2]);
                let held = (blend + Vec2::new(next(), next()) * 2.0).clamp(lo, hi);
                for s in [blend, held] {
                    assert!(sine(s) >= SIDE_FULL - 1e-5, "{slopes:?}: {s} is gentler");
                }
            }
        }
        assert!(walls > 500 && not > 500, "{walls} walls, {not} not");
        // Corners steep every way round a gentle middle are not walls.
        let round = [
            Vec2::new(3.0, 0.0),
            Vec2::new(-3.0, 0.1),
            Vec2::new(0.0, 3.0),
        ];
        assert!(!steepest_everywhere(round));
        assert!(!steepest_everywhere([
            Vec2::NAN,
            Vec2::X * 3.0,
            Vec2::Y * 3.0
        ]));
    }

    #[test]
    fn the_light_turns_smoothly_from_the_plan_to_the_side_views() {
        let (sun, cell) = (Vec3::new(-0.3, 0.6, 0.5).normalize(), 0.25);
        let relief = Relief::new(&Heightfield::flat(10, 250.0), 11, sun, cell);
        let (g, h) = (Vec2::new(123.4, 567.8), 20.0);
        let check = |what: &str, normal: &dyn Fn(f32) -> Vec2| {
            let gains: Vec<f32> = (0..=4000)
                .map(|i| gain_at(&relief, g, h, normal(i as f32 / 4000.0), 0.1))
                .collect();
            let jump = gains
                .windows(2)
                .map(|w| (w[1] - w[0]).abs())
                .fold(0.0, f32::max);
            let most = gains.iter().map(|g| (g - 1.0).abs()).fold(0.0, f32::max);
            assert!(
                most > 0.05,
                "{what}: the bumps change the light by {most} at most"
            );
            assert!(jump < 0.01, "{what}: the light jumps by {jump}");
        };
        // From gentle to a wall (past the side views' start and end),
        // and round a steep face from turned along x to along y.
        check("steeper", &|t| Vec2::new(0.3, 0.5 + 7.5 * t));
        check("turned", &|t| {
            let a = t * std::f32::consts::FRAC_PI_2;
            Vec2::new(a.cos(), a.sin()) * 4.0
        });
    }

    #[test]
    fn the_relief_is_the_same_land_at_every_grid_size() {
        // A level's lattice is laid over the land, not the grid: the
        // second level below a grid of 513 points is the first below one
        // of 1025 (which draws the other itself), at every land position.
        let sun = Vec3::Z;
        let coarse = Relief::new(&Heightfield::flat(9, 250.0), 7, sun, 0.5);
        let fine = Relief::new(&Heightfield::flat(10, 250.0), 7, sun, 0.25);
        assert_eq!(coarse.first_level + 1, fine.first_level);
        for i in 0..50 {
            let land = Vec2::new(0.013 * i as f32, 0.5 - 0.007 * i as f32);
            let (a, b) = (land * 512.0, land * 1024.0);
            let (pa, pb) = (a * coarse.first_step * 2.0, b * fine.first_step);
            assert_eq!(pa, pb);
            let lanes = |p: Vec2| [Vec4::splat(p.x), Vec4::splat(p.y)];
            assert_eq!(
                coarse.plan_level(1, lanes(pa)),
                fine.plan_level(0, lanes(pb))
            );
            assert_ne!(
                coarse.plan_level(0, lanes(pa)),
                fine.plan_level(0, lanes(pb))
            );
        }
    }

    #[test]
    fn the_value_noise_slope_is_the_change_of_its_value() {
        // The slope against a finite difference of the blended values.
        let lattice = Lattice::new(7);
        let value = |u: Vec2| {
            let (fx, fy) = (u.x.floor(), u.y.floor());
            let (tx, ty) = (u.x - fx, u.y - fy);
            let c = |dx: i32, dy: i32| lattice.at(3, fx as i32 + dx, fy as i32 + dy);
            let (sx, sy) = (tx * tx * (3.0 - 2.0 * tx), ty * ty * (3.0 - 2.0 * ty));
            let top = c(0, 0) + (c(1, 0) - c(0, 0)) * sx;
            let bottom = c(0, 1) + (c(1, 1) - c(0, 1)) * sx;
            top + (bottom - top) * sy
        };
        // Whole lattice positions (where the float adder's rounding lands
        // on the cell before, at its far edge), either sign, and far out.
        let points = [(0.3, 0.7), (5.5, -2.25), (-3.9, 8.1), (4.0, -3.0)];
        for &(x, y) in points
            .iter()
            .chain(&[(-1000.5, 2047.25), (-3000.25, 1500.75)])
        {
            let u = Vec2::new(x, y);
            let e = 1e-3;
            // Far out, the steps are rounded to the floats there.
            let (ex, ey) = ((x + e) - (x - e), (y + e) - (y - e));
            let dx = (value(u + Vec2::X * e) - value(u - Vec2::X * e)) / ex;
            let dy = (value(u + Vec2::Y * e) - value(u - Vec2::Y * e)) / ey;
            // Each lane a pixel of its own: the same point in lane 2.
            let lanes = [Vec4::new(0.0, 1.5, x, -7.25), Vec4::new(0.0, 2.5, y, 3.75)];
            let [sx, sy, v] = lattice.value_slope(3, lanes);
            let d = Vec3::new(sx.z, sy.z, v.z);
            assert!(
                (d.x - dx).abs() < 2e-2 && (d.y - dy).abs() < 2e-2,
                "{d} against ({dx}, {dy})"
            );
            assert!((d.z - value(u)).abs() < 1e-5, "{d} against {}", value(u));
        }
        // A NaN (a point gone wrong) reads some cell and gives NaN, which
        // the gain turns back to 1.
        let [_, _, v] = lattice.value_slope(3, [Vec4::splat(f32::NAN), Vec4::ZERO]);
        assert!(v.x.is_nan());
    }

    #[test]
    fn a_face_the_relief_is_said_not_to_show_on_changes_no_pixel_by_a_level() {
        let sun = Vec3::new(0.3, -0.4, 0.8).normalize();
        let relief = Relief::new(&Heightfield::flat(10, 250.0), 5, sun, 0.25);
        let mut draw = draws(1);
        let mut next = || crate::terrain::splitmix::unit(draw());
        let (mut plain, mut refined) = (0, 0);
        for face in 0..2000 {
            // Every other face steep: its pixels take the side views.
            let steep = if face % 2 == 0 { 1.0 } else { 8.0 };
            let corners: [(FinePoint, Vec2, u32, f32); 3] = std::array::from_fn(|_| {
                let point = FinePoint {
                    slope: Vec2::new(next() * 2.0 - 1.0, next() * 2.0 - 1.0) * steep,
                    shares: Vec2::new(next(), next() * 0.6),
                    cell_px: 1.0 + next() * 30.0,
                    rough: 10f32.powf(-6.0 * next()) * 0.02,
                };
                let grey = (next() * 255.0) as u32;
                let height = next() * 75.0;
                (
                    point,
                    Vec2::new(next(), next()) * 1024.0,
                    grey * 0x10101,
                    height,
                )
            });
            let shows = relief.shows(corners.each_ref().map(|c| &c.0), corners.map(|c| c.2));
            if shows {
                refined += 1;
                continue;
            }
            plain += 1;
            let bright = corners.iter().map(|c| c.2 & 0xff).max().unwrap() as f32;
            for _ in 0..20 {
                // A pixel's values, blended from its corners'.
                let (a, b) = (next(), next());
                let w = [a * b, a * (1.0 - b), 1.0 - a];
                let lanes = corners.map(|c| c.0.lanes(c.1, c.3));
                let q = std::array::from_fn(|i| {
                    Vec4::splat((0..3).map(|k| w[k] * lanes[k][i]).sum::<f32>())
                });
                let change = (relief.gains(q).x - 1.0).abs() * bright;
                assert!(
                    change < 1.0,
                    "a plain face's pixel would change by {change}"
                );
            }
        }
        assert!(
            plain > 200 && refined > 200,
            "{plain} plain, {refined} refined"
        );
    }

    #[test]
    fn the_levels_tables_bounds_hold_the_count_of_every_cell() {
        let mut draw = draws(4);
        let mut next = || crate::terrain::splitmix::unit(draw());
        // A grid whose cells are not a power of two has a wider first step.
        for size in [10, 7] {
            let field = Heightfield::flat(size, 250.0);
            let relief = Relief::new(&field, 9, Vec3::Z, 0.25);
            let (mut within, mut past) = (0, 0);
            for i in 0..20_000 {
                let cell_px = [next() * 8.0, next() * 200.0][i % 2];
                for walls in [false, true] {
                    let exact = relief.levels_shown(cell_px, walls);
                    let Some((least, most)) = relief.shown.bounds(cell_px, walls) else {
                        past += 1;
                        continue;
                    };
                    within += 1;
                    assert!(
                        least <= exact && exact <= most,
                        "{cell_px} px: {exact} outside {least}..{most}"
                    );
                }
            }
            assert!(
                within > 20_000 && past > 5_000,
                "{within} within, {past} past"
            );
        }
    }

    #[test]
    fn a_face_shows_the_relief_as_its_exact_count_says() {
        let relief = Relief::new(&Heightfield::flat(10, 250.0), 5, Vec3::Z, 0.25);
        let exact = |points: [&FinePoint; 3], colours: [u32; 3]| {
            let most =
                |f: &dyn Fn(&FinePoint) -> f32| points.iter().map(|p| f(p)).fold(0.0, f32::max);
            let cell_px = most(&|p| p.cell_px);
            if cell_px < MIN_CELL_PX {
                return false;
            }
            let walls = steepest_everywhere(points.map(|p| p.slope));
            let per = STEEPEST * FIRST * relief.first_step * relief.levels_shown(cell_px, walls)
                / relief.cell;
            let shares = most(&|p| p.shares.x + p.shares.y * (1.0 + HOLLOW));
            let bright = colours.iter().map(|c| c & 0xff).max().unwrap();
            shares * most(&|p| p.rough) * per * bright as f32 >= 1.0
        };
        let mut draw = draws(6);
        let mut next = || crate::terrain::splitmix::unit(draw());
        let (mut shown, mut plain) = (0, 0);
        for face in 0..50_000 {
            let steep = if face % 2 == 0 { 1.0 } else { 8.0 };
            // Roughness about where a face tips between plain and refined.
            let odd = match face % 20 {
                17 => 0.0,
                18 => f32::NAN,
                19 => f32::INFINITY,
                _ => 1.0,
            };
            let rough = 10f32.powf(-3.5 + next()) * odd;
            let points: [FinePoint; 3] = std::array::from_fn(|_| FinePoint {
                slope: Vec2::new(next() * 2.0 - 1.0, next() * 2.0 - 1.0) * steep,
                shares: Vec2::new(next(), next() * 0.6),
                cell_px: [next() * 6.0, next() * 150.0][face % 3 / 2],
                rough,
            });
            let colours = [0x10101 * (next() * 255.0) as u32; 3];
            let want = exact(points.each_ref(), colours);
            assert_eq!(relief.shows(points.each_ref(), colours), want, "{points:?}");
            if want { shown += 1 } else { plain += 1 }
        }
        assert!(
            shown > 5_000 && plain > 5_000,
            "{shown} shown, {plain} plain"
        );
    }

    #[test]
    fn the_lattice_values_spread_over_minus_one_to_one() {
        let lattice = Lattice::new(1);
        let values: Vec<f32> = (0..1000).map(|i| lattice.at(11, i, -i)).collect();
        assert!(values.iter().all(|v| (-1.0..=1.0).contains(v)));
        let mean = values.iter().sum::<f32>() / 1000.0;
        assert!(mean.abs() < 0.1, "{mean}");
        assert!(values.iter().any(|&v| v > 0.8) && values.iter().any(|&v| v < -0.8));
    }
}

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

use crate::terrain::Heightfield;

/// Levels below the grid at most: at 4K the nearest cells are about 40
/// pixels across, and the fifth level's bumps there are a pixel or so.
pub(crate) const LEVELS: usize = 5;

/// A level's bumps at least this many pixels across show in full.
const FULL_PX: f32 = 2.0;
/// A level whose bumps are at most this many pixels across is left out:
/// finer, its light would only sparkle.
const NONE_PX: f32 = 0.8;

/// A face is drawn with its relief when one of its corners' cells is at
/// least this many pixels across: the first level then shows.
pub(crate) const MIN_CELL_PX: f32 = 2.0 * NONE_PX;

/// How tall the first level's bumps are against the grid's own last
/// level's: the generator halves its cragginess at every level.
const FIRST: f32 = 0.5;

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
    /// The point's values in two lanes of four: grid x and y, the slopes;
    /// the shares, the cell's pixels and the roughness.
    #[inline]
    pub(crate) fn lanes(&self, g: Vec2) -> [Vec4; 2] {
        [
            Vec4::new(g.x, g.y, self.slope.x, self.slope.y),
            Vec4::new(self.shares.x, self.shares.y, self.cell_px, self.rough),
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
    /// Each level's turn (cosine, sine) and offset in lattice steps.
    turns: [Vec2; LEVELS],
    offsets: [Vec2; LEVELS],
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
}

/// Points a side of the blocks whose roughness is measured together: one
/// point's own stands out or not by chance.
const BLOCK: usize = 8;

impl Relief {
    /// The relief below the grid of `field` (`seed` its mountain's), lit
    /// from `sun`, with cells `cell` height units wide.
    pub(crate) fn new(field: &Heightfield, seed: u64, sun: Vec3, cell: f32) -> Self {
        let cells = (field.size().max(2) - 1) as f32;
        // The land's side is one step of level 0; the grid's own last
        // level has steps of one cell.
        let first_level = cells.log2().ceil() as u32 + 1;
        let first_step = 2f32.powi(first_level as i32) / cells;
        let (rough, blocks) = roughness(field);
        let mut turns = [Vec2::X; LEVELS];
        let mut offsets = [Vec2::ZERO; LEVELS];
        for (k, (t, o)) in turns.iter_mut().zip(&mut offsets).enumerate() {
            let h = mix(seed ^ mix(first_level as u64 + k as u64));
            let angle = (h & 0xffff) as f32 / 65536.0 * std::f32::consts::TAU;
            *t = Vec2::new(angle.cos(), angle.sin());
            *o = Vec2::new(((h >> 16) & 0xff) as f32, ((h >> 24) & 0xff) as f32);
        }
        Relief {
            lattice: Lattice::new(seed),
            first_step,
            first_level,
            turns,
            offsets,
            sun,
            cell,
            rough,
            blocks,
            finer: 1.0,
        }
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
    /// with colours `colours`: it changes some channel of some corner by
    /// a level or more at its strongest (a dark, hazed or smooth face is
    /// drawn plain). Along an edge of such a face a refined neighbour's
    /// light differs from its own by under that level.
    #[inline]
    pub(crate) fn shows(&self, points: [&FinePoint; 3], colours: [u32; 3]) -> bool {
        // The most a pixel's light changes per unit of a point's shares
        // and roughness: a level's slope at its steepest, over the cell.
        let per = 1.5 * FIRST * self.first_step * LEVELS as f32 / self.cell;
        points.iter().zip(colours).any(|(p, c)| {
            let bright = [16, 8, 0]
                .map(|s| (c >> s) & 0xff)
                .into_iter()
                .max()
                .unwrap_or(0);
            let change = (p.shares.x + p.shares.y * (1.0 + HOLLOW)) * p.rough * per;
            p.cell_px >= MIN_CELL_PX && change * bright as f32 >= 1.0
        })
    }

    /// How many of the relief's pixels a cell spans where it spans
    /// `frame_px` of the frame's.
    #[inline]
    pub(crate) fn cell_px(&self, frame_px: f32) -> f32 {
        frame_px / self.finer
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
    #[inline]
    pub(crate) fn slope(&self, g: Vec2, cell_px: f32, rough: f32) -> Vec3 {
        let mut slope = Vec3::ZERO;
        let mut step = self.first_step;
        let mut px = cell_px / self.first_step;
        // Each level's bumps are half as tall and half as wide: the same
        // slope, faded by how many pixels they span.
        for k in 0..LEVELS {
            let w = fade(px);
            if w == 0.0 {
                break;
            }
            slope += self.level(k, g * step) * w;
            step *= 2.0;
            px *= 0.5;
        }
        // A level's slope in grid steps: its bumps' height over its step.
        slope * (FIRST * rough * self.first_step)
    }

    /// The slope of level `k` below the grid at `p` (in its lattice
    /// steps, before its turn), in its bumps' height per lattice step, and
    /// the height there in the same unit.
    #[inline]
    fn level(&self, k: usize, p: Vec2) -> Vec3 {
        let t = self.turns[k];
        let u = Vec2::new(p.x * t.x - p.y * t.y, p.x * t.y + p.y * t.x) + self.offsets[k];
        let d = self.lattice.value_slope(self.first_level + k as u32, u);
        // Back from the turned lattice to the grid's directions.
        Vec3::new(d.x * t.x + d.y * t.y, -d.x * t.y + d.y * t.x, d.z)
    }

    /// How much brighter (over 1) or darker the finer terrain makes a
    /// pixel whose blended [`FinePoint::lanes`] are `q`.
    ///
    /// The change of the light is taken to first order in the finer
    /// slopes: bumps as often up as down then lighten and darken about
    /// the grid's own light, and seen from afar the land keeps its light
    /// (the whole change would darken ground square to the sun, where any
    /// turn lowers the cosine, and lighten faces turned away).
    #[inline]
    pub(crate) fn gain(&self, q: [Vec4; 2]) -> f32 {
        let [a, b] = q;
        let fine = self.slope(Vec2::new(a.x, a.y), b.z, b.w) / self.cell;
        let d = Vec2::new(fine.x, fine.y);
        // The palette's y runs to the back, the grid's to the front: the
        // normal (x, y, 1) turns to (x - dx, y + dy, 1).
        let turn = Vec2::new(-d.x, d.y);
        let n = Vec3::new(a.z, a.w, 1.0);
        let inv = n.length_recip();
        let cos = n.dot(self.sun) * inv;
        // d/dturn of n.sun / |n| and of 1 / |n| (the normal's upward part).
        let along = turn.dot(Vec2::new(n.x, n.y)) * inv * inv;
        let d_cos = (turn.dot(Vec2::new(self.sun.x, self.sun.y)) - cos * along * (1.0 / inv)) * inv;
        let d_up = -along * inv;
        // Faces turned from the light get none of it; the change fades in
        // past the terminator, so no line is drawn there.
        let lit = (cos * TERMINATOR).clamp(0.0, 1.0);
        // A hollow sees less of the sky than a knoll.
        let sky = b.y * (d_up + HOLLOW * fine.z);
        (1.0 + b.x * lit * d_cos + sky).clamp(GAIN.0, GAIN.1)
    }
}

/// Over how much of the cosine past the terminator the direct light's
/// change fades in (its inverse).
const TERMINATOR: f32 = 10.0;
/// How much less of the sky a hollow of the finer terrain sees, per unit
/// of its depth over its width (against the change of the sky's light
/// with the normal's upward part).
const HOLLOW: f32 = 1.0;
/// The darkest and the lightest the finer terrain makes a pixel.
const GAIN: (f32, f32) = (0.3, 1.7);

/// How much of a level shows whose bumps span `px` pixels.
#[inline]
fn fade(px: f32) -> f32 {
    let t = ((px - NONE_PX) / (FULL_PX - NONE_PX)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Lattice points a side of the table of values: a level repeats after
/// this many of its steps, over a hundred cells even for the first level
/// below the grid, and turned unlike any other level.
const SIDE: usize = 256;

/// The values (-1..=1) at the lattice points of every level of one
/// mountain's finer terrain: a table of [`SIDE`] points a side that each
/// level reads from a place of its own (a hash a point would cost a pixel
/// tens of multiplications; a table a side, one read a point).
#[derive(Clone, Debug)]
struct Lattice {
    // An array of the table's size: an index masked to it needs no check.
    values: Box<[i8; SIDE * SIDE]>,
}

impl Lattice {
    /// The lattice of the mountain `seed`.
    fn new(seed: u64) -> Self {
        let mut values = Box::new([0i8; SIDE * SIDE]);
        for (v, i) in values.iter_mut().zip(0u64..) {
            *v = ((mix(seed ^ mix(i)) >> 56) as u8 as i8).max(-127);
        }
        Lattice { values }
    }

    /// The value at lattice point (`x`, `y`) of level `level`.
    #[inline(always)]
    fn at(&self, level: u32, x: i32, y: i32) -> f32 {
        let m = SIDE - 1;
        let (x, y) = (x as usize, y as usize);
        let (lx, ly) = (level as usize * 97, level as usize * 59);
        let i = (y.wrapping_add(ly) & m) * SIDE + (x.wrapping_add(lx) & m);
        f32::from(self.values[i]) * (1.0 / 127.0)
    }

    /// The slope of level `level`'s value noise at lattice position `u`,
    /// in units of its bumps' height per lattice step, and (z) its value:
    /// each lattice point a value in -1..=1, blended between them along a
    /// smooth step.
    #[inline]
    fn value_slope(&self, level: u32, u: Vec2) -> Vec3 {
        let (ix, iy) = (floor(u.x), floor(u.y));
        let (tx, ty) = (u.x - ix as f32, u.y - iy as f32);
        let corner = |dx: i32, dy: i32| self.at(level, ix.wrapping_add(dx), iy.wrapping_add(dy));
        let v = Vec4::new(corner(0, 0), corner(1, 0), corner(0, 1), corner(1, 1));
        let (sx, sy) = (tx * tx * (3.0 - 2.0 * tx), ty * ty * (3.0 - 2.0 * ty));
        let (dsx, dsy) = (6.0 * tx * (1.0 - tx), 6.0 * ty * (1.0 - ty));
        let k = v.x - v.y - v.z + v.w;
        let value = v.x + (v.y - v.x) * sx + (v.z - v.x) * sy + k * sx * sy;
        Vec3::new(
            dsx * (v.y - v.x + k * sy),
            dsy * (v.z - v.x + k * sx),
            value,
        )
    }
}

/// The greatest integer at most `v` (`f32::floor` is a call into the C
/// library on the baseline x86-64 target, and this runs a few times a
/// pixel).
#[inline(always)]
fn floor(v: f32) -> i32 {
    let i = v as i32;
    i - i32::from(v < i as f32)
}

/// A 64-bit mix (splitmix64's finaliser).
#[inline]
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
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
    let mut rough = vec![0.0; blocks * blocks];
    let half = BLOCK / 2;
    let mut sample = Vec::with_capacity(BLOCK * BLOCK / 4);
    for by in 0..blocks {
        for bx in 0..blocks {
            let (cx, cy) = (bx * BLOCK, by * BLOCK);
            sample.clear();
            let ys = cy.saturating_sub(half)..(cy + half).min(n);
            for y in ys.step_by(2) {
                for x in (cx.saturating_sub(half)..(cx + half).min(n)).step_by(2) {
                    sample.push(laplacian(field, x, y));
                }
            }
            rough[by * blocks + bx] = median(&mut sample) * MEDIAN_TO_RMS;
        }
    }
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

    #[test]
    fn a_level_fades_in_between_its_two_sizes() {
        assert_eq!(fade(NONE_PX), 0.0);
        assert_eq!(fade(0.5 * NONE_PX), 0.0);
        assert_eq!(fade(FULL_PX), 1.0);
        assert_eq!(fade(40.0), 1.0);
        let mid = fade(0.5 * (NONE_PX + FULL_PX));
        assert!((mid - 0.5).abs() < 1e-6, "{mid}");
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
            assert_eq!(coarse.level(1, pa), fine.level(0, pb));
            assert_ne!(coarse.level(0, pa), fine.level(0, pb));
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
        for &(x, y) in &[(0.3, 0.7), (5.5, -2.25), (-3.9, 8.1)] {
            let u = Vec2::new(x, y);
            let e = 1e-3;
            let dx = (value(u + Vec2::X * e) - value(u - Vec2::X * e)) / (2.0 * e);
            let dy = (value(u + Vec2::Y * e) - value(u - Vec2::Y * e)) / (2.0 * e);
            let d = lattice.value_slope(3, u);
            assert!(
                (d.x - dx).abs() < 2e-2 && (d.y - dy).abs() < 2e-2,
                "{d} against ({dx}, {dy})"
            );
            assert!((d.z - value(u)).abs() < 1e-5, "{d} against {}", value(u));
        }
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

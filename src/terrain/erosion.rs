//! Hydraulic erosion by droplets (H. T. Beyer, *Implementation of a method
//! for hydraulic erosion*, 2015): rain drops run downhill, pick up soil where
//! they speed up and drop it where they slow down, carving gullies into the
//! slopes and laying fans of silt at their feet. No peer program has it.
//!
//! The droplets run on a coarse copy of the field (at most [`COARSE_CELLS`]
//! cells a side) and the change they make is added to the fine field,
//! bilinearly: the gullies they carve are several cells wide anyway, and a
//! fine grid would take many times as long. One droplet after another, from
//! a generator seeded by the mountain's seed: the result does not depend on
//! the thread count.

use super::heightfield::Heightfield;
use super::splitmix::{GOLDEN, mix};

/// Cells a side of the grid the droplets run on.
pub(crate) const COARSE_CELLS: usize = 128;
/// Droplets per coarse cell at full strength.
const DROPLETS_PER_CELL: f32 = 0.5;
/// Steps a droplet lives.
const LIFETIME: usize = 30;
/// How much a droplet keeps its direction (0: follows the slope at once).
const INERTIA: f32 = 0.05;
/// Sediment a droplet can carry per unit of speed, water and drop.
const CAPACITY: f32 = 4.0;
/// Least capacity, so flat ground still erodes a little.
const MIN_CAPACITY: f32 = 0.01;
/// Share of the excess sediment dropped per step.
const DEPOSITION: f32 = 0.3;
/// Share of the spare capacity taken from the ground per step.
const EROSION: f32 = 0.5;
/// Share of the water evaporating per step.
const EVAPORATION: f32 = 0.01;
/// Acceleration downhill.
const GRAVITY: f32 = 4.0;
/// Radius in coarse cells of the soil a droplet loosens around it.
const RADIUS: i32 = 2;
/// The coarse field's relief, in cells: the droplets' constants are tuned for
/// slopes of this order whatever the generator's height units.
const RELIEF_CELLS: f32 = 24.0;

/// Erodes `field` with `strength` in `0..=1` (0 leaves it as it is);
/// `seed` chooses where the rain falls. The droplets run one after another;
/// only adding their work to the fine grid uses `threads`.
pub(crate) fn erode(field: &mut Heightfield, strength: f32, seed: u64, threads: usize) {
    let lattice = field.coarsened(levels_above(field.exponent()));
    if let Some(change) = wear(lattice, strength, seed) {
        add(field, &change, threads);
    }
}

/// How many levels coarser than a field of `exponent` the droplets' grid
/// is: its points are every `2^levels`-th of the field's, and a subdivided
/// field's are final once the level that makes them is done.
pub(crate) fn levels_above(exponent: u32) -> u32 {
    exponent.saturating_sub(COARSE_CELLS.ilog2())
}
// `Heightfield::coarsened` takes these levels whole (it keeps at least
// 2^COARSENED_LEAST_EXPONENT cells a side), so the lattice's points are
// every 2^levels-th, as the subdivision is staged by.
const _: () = assert!(COARSE_CELLS.ilog2() >= super::heightfield::COARSENED_LEAST_EXPONENT);

/// The change the droplets make to `coarse` (a field's
/// [`levels_above`]-coarsened copy), as heights on its grid: [`add`] adds
/// it to the field. `None` where nothing wears (no strength, a flat field).
pub(crate) fn wear(mut coarse: Heightfield, strength: f32, seed: u64) -> Option<Heightfield> {
    // NaN too: no erosion.
    if strength.is_nan() || strength <= 0.0 {
        return None;
    }
    let (lo, hi) = finite_range(coarse.heights());
    let unit = (hi - lo) / RELIEF_CELLS;
    if !(unit > 0.0 && unit.is_finite()) {
        return None;
    }
    let n = coarse.size();
    let before: Vec<f32> = coarse
        .heights()
        .iter()
        .map(|&h| clean(h, lo) / unit)
        .collect();
    let mut ground = before.clone();
    let droplets = (strength.min(1.0) * DROPLETS_PER_CELL * ((n - 1) * (n - 1)) as f32) as usize;
    let brush = Brush::new(RADIUS);
    let mut rng = SplitMix(seed ^ 0x6572_6f73_696f_6e21);
    for _ in 0..droplets {
        let start = (rng.unit() * (n - 1) as f32, rng.unit() * (n - 1) as f32);
        Droplet::new(start).run(&mut ground, n, &brush);
    }
    for (h, (&b, &a)) in coarse
        .heights_mut()
        .iter_mut()
        .zip(before.iter().zip(&ground))
    {
        *h = (a - b) * unit;
    }
    Some(coarse)
}

/// Adds `change`, what [`wear`] made of the field's coarse copy, to
/// `field`, rows shared out among `threads`.
pub(crate) fn add(field: &mut Heightfield, change: &Heightfield, threads: usize) {
    let stride = 1 << (field.exponent() - change.exponent());
    add_upsampled(field, change, stride, threads);
}

/// Lowest and highest finite heights (0, 0 if none).
fn finite_range(h: &[f32]) -> (f32, f32) {
    let finite = h.iter().copied().filter(|v| v.is_finite());
    let lo = finite.clone().fold(f32::INFINITY, f32::min);
    let hi = finite.fold(f32::NEG_INFINITY, f32::max);
    if lo <= hi { (lo, hi) } else { (0.0, 0.0) }
}

/// A height the droplets can use: broken values count as the lowest ground.
fn clean(h: f32, lo: f32) -> f32 {
    if h.is_finite() { h } else { lo }
}

/// Adds `change` (a coarse grid, `stride` fine cells per coarse cell) to
/// `field`, bilinearly between coarse points, rows shared out among
/// `threads` (each point's sum is the same whoever computes it). Each
/// column's coarse neighbours and weight are found once, not once per row.
fn add_upsampled(field: &mut Heightfield, change: &Heightfield, stride: usize, threads: usize) {
    let n = field.size();
    let last = change.size() - 1;
    let inv = 1.0 / stride as f32;
    let between = |i: usize| {
        let i0 = (i / stride).min(last);
        (i0, (i0 + 1).min(last), (i % stride) as f32 * inv)
    };
    let columns: Vec<(usize, usize, f32)> = (0..n).map(between).collect();
    let rows_each = n.div_ceil(threads.max(1));
    let add_rows = |first: usize, rows: &mut [f32]| {
        let mut blend = vec![0.0f32; change.size()];
        for (dy, row) in rows.chunks_exact_mut(n).enumerate() {
            let (y0, y1, ty) = between(first + dy);
            let (top, bottom) = (change.row(y0), change.row(y1));
            for ((b, &t), &d) in blend.iter_mut().zip(top).zip(bottom) {
                *b = t + (d - t) * ty;
            }
            for (h, &(x0, x1, tx)) in row.iter_mut().zip(&columns) {
                *h += blend[x0] + (blend[x1] - blend[x0]) * tx;
            }
        }
    };
    std::thread::scope(|s| {
        for (i, part) in field.heights_mut().chunks_mut(rows_each * n).enumerate() {
            let add_rows = &add_rows;
            s.spawn(move || add_rows(i * rows_each, part));
        }
    });
}

/// Cells within a radius of a point, with weights summing to one.
struct Brush {
    cells: Vec<(i32, i32, f32)>,
}

impl Brush {
    fn new(radius: i32) -> Self {
        let r = radius as f32;
        let mut cells = Vec::new();
        for dy in -radius..=radius {
            for dx in -radius..=radius {
                let d = ((dx * dx + dy * dy) as f32).sqrt();
                if d <= r {
                    cells.push((dx, dy, 1.0 - d / (r + 1.0)));
                }
            }
        }
        let total: f32 = cells.iter().map(|c| c.2).sum();
        cells.iter_mut().for_each(|c| c.2 /= total);
        Brush { cells }
    }
}

/// One drop of rain running downhill.
struct Droplet {
    pos: (f32, f32),
    dir: (f32, f32),
    speed: f32,
    water: f32,
    sediment: f32,
}

impl Droplet {
    fn new(pos: (f32, f32)) -> Self {
        Droplet {
            pos,
            dir: (0.0, 0.0),
            speed: 1.0,
            water: 1.0,
            sediment: 0.0,
        }
    }

    /// Moves until it leaves the grid, stops, or dries up. What it still
    /// carries then goes with it, as in Beyer's method: settling a whole
    /// load on one point raised spikes at the feet of the slopes.
    fn run(mut self, ground: &mut [f32], n: usize, brush: &Brush) {
        for _ in 0..LIFETIME {
            if !self.step(ground, n, brush) {
                return;
            }
        }
    }

    /// One step downhill; false once the droplet has left the grid or
    /// found no way down.
    fn step(&mut self, ground: &mut [f32], n: usize, brush: &Brush) -> bool {
        let (x, y) = self.pos;
        let (height, gx, gy) = slope(ground, n, x, y);
        if !self.turn(gx, gy) {
            return false;
        }
        let next = (x + self.dir.0, y + self.dir.1);
        let edge = (n - 1) as f32;
        if !(next.0 >= 0.0 && next.0 < edge && next.1 >= 0.0 && next.1 < edge) {
            return false;
        }
        let drop = height_at(ground, n, next.0, next.1) - height;
        self.exchange(ground, n, brush, drop);
        self.speed = (self.speed * self.speed + drop * -GRAVITY).max(0.0).sqrt();
        self.water *= 1.0 - EVAPORATION;
        self.pos = next;
        true
    }

    /// Turns towards the downhill gradient (`gx`, `gy`), keeping a little of
    /// the old direction; false where there is no way down.
    fn turn(&mut self, gx: f32, gy: f32) -> bool {
        let dir = (
            self.dir.0 * INERTIA - gx * (1.0 - INERTIA),
            self.dir.1 * INERTIA - gy * (1.0 - INERTIA),
        );
        // Not `hypot`: libm's careful version was a tenth of the time.
        let len = (dir.0 * dir.0 + dir.1 * dir.1).sqrt();
        if len.is_nan() || len <= 1e-6 {
            return false;
        }
        self.dir = (dir.0 / len, dir.1 / len);
        true
    }

    /// Drops soil where the droplet slows or climbs (`drop` > 0), picks it
    /// up where it runs fast downhill with room to carry more.
    fn exchange(&mut self, ground: &mut [f32], n: usize, brush: &Brush, drop: f32) {
        let (x, y) = self.pos;
        let capacity = (-drop * self.speed * self.water * CAPACITY).max(MIN_CAPACITY);
        if self.sediment > capacity || drop > 0.0 {
            let amount = if drop > 0.0 {
                drop.min(self.sediment)
            } else {
                (self.sediment - capacity) * DEPOSITION
            };
            self.sediment -= amount;
            deposit(ground, n, x, y, amount);
        } else {
            let amount = ((capacity - self.sediment) * EROSION).min(-drop);
            self.sediment += take(ground, n, x, y, amount, brush);
        }
    }
}

/// Height and gradient at (`x`, `y`), bilinear within its cell.
fn slope(ground: &[f32], n: usize, x: f32, y: f32) -> (f32, f32, f32) {
    let (cx, cy) = (x as usize, y as usize);
    let (u, v) = (x - cx as f32, y - cy as f32);
    let i = cy * n + cx;
    let (nw, ne, sw, se) = (ground[i], ground[i + 1], ground[i + n], ground[i + n + 1]);
    let gx = (ne - nw) * (1.0 - v) + (se - sw) * v;
    let gy = (sw - nw) * (1.0 - u) + (se - ne) * u;
    let h = nw * (1.0 - u) * (1.0 - v) + ne * u * (1.0 - v) + sw * (1.0 - u) * v + se * u * v;
    (h, gx, gy)
}

/// Height at (`x`, `y`), bilinear within its cell.
fn height_at(ground: &[f32], n: usize, x: f32, y: f32) -> f32 {
    let (cx, cy) = (x as usize, y as usize);
    let (u, v) = (x - cx as f32, y - cy as f32);
    let i = cy * n + cx;
    let top = ground[i] + (ground[i + 1] - ground[i]) * u;
    let bottom = ground[i + n] + (ground[i + n + 1] - ground[i + n]) * u;
    top + (bottom - top) * v
}

/// Lays `amount` of soil on the corners of the cell holding (`x`, `y`).
fn deposit(ground: &mut [f32], n: usize, x: f32, y: f32, amount: f32) {
    let (cx, cy) = (x as usize, y as usize);
    let (u, v) = (x - cx as f32, y - cy as f32);
    let i = cy * n + cx;
    ground[i] += amount * (1.0 - u) * (1.0 - v);
    ground[i + 1] += amount * u * (1.0 - v);
    ground[i + n] += amount * (1.0 - u) * v;
    ground[i + n + 1] += amount * u * v;
}

/// Takes `amount` of soil from around (`x`, `y`), spread over the brush
/// (the caller keeps it below the drop ahead, so no pit is dug); returns
/// what was taken (less at the grid's edge).
fn take(ground: &mut [f32], n: usize, x: f32, y: f32, amount: f32, brush: &Brush) -> f32 {
    let (cx, cy) = (x as usize, y as usize);
    let r = RADIUS as usize;
    if cx >= r && cy >= r && cx + r < n && cy + r < n {
        // Away from the edges (nearly always): no checks per cell.
        let centre = (cy * n + cx) as isize;
        for &(dx, dy, w) in &brush.cells {
            let i = centre + (dy as isize) * n as isize + dx as isize;
            ground[i as usize] -= amount * w;
        }
        return amount;
    }
    let mut taken = 0.0;
    for &(dx, dy, w) in &brush.cells {
        let (px, py) = (cx as i32 + dx, cy as i32 + dy);
        if px < 0 || py < 0 || px >= n as i32 || py >= n as i32 {
            continue;
        }
        ground[py as usize * n + px as usize] -= amount * w;
        taken += amount * w;
    }
    taken
}

/// SplitMix64 as a stream (the terrain's own mixer): the same numbers on
/// every platform.
struct SplitMix(u64);

impl SplitMix {
    /// A number in `0..1`.
    fn unit(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(GOLDEN);
        super::splitmix::unit(mix(self.0))
    }
}

//! The level-by-level subdivision every generator shares.
//!
//! Level `depth` halves squares of `step` points a side. Its new points lie on
//! the rows that are multiples of `half = step / 2`:
//! - *centre rows* (odd multiples of `half`) get the square centres (or the
//!   triangles' diagonal midpoints) and the vertical edge midpoints;
//! - *edge rows* (multiples of `step`) get the horizontal edge midpoints.
//!
//! A generator (a [`Rule`]) says how one row's new points follow from the
//! rows `half` above and below. Each point is written once, from points set
//! before it, with a random value keyed by its position, so the result does
//! not depend on visiting order: rows are cut into bands that run on
//! separate threads and give the same bits as one thread.
//!
//! Rules see rows through the level's *lattice*: every `half`-th point, as a
//! contiguous slice of `2 * squares + 1` values. On the finest level (which
//! holds three quarters of all points) that is the row itself; on coarser
//! levels the driver gathers the lattice into a scratch row and scatters the
//! new points back.

use std::sync::atomic::{AtomicUsize, Ordering};

use super::noise::Noise;

/// Where a generator writes its points; an audited writer counts rewrites.
pub(crate) trait Put: Sync {
    /// Whether stores check their target, which then must hold its true
    /// value (else the driver may hand a rule stale scratch to overwrite).
    const CHECKS: bool;

    /// Stores `value` into a grid point.
    fn put(&self, slot: &mut f32, value: f32);
}

/// The production writer: a plain store.
pub(crate) struct Plain;

impl Put for Plain {
    const CHECKS: bool = false;

    #[inline(always)]
    fn put(&self, slot: &mut f32, value: f32) {
        *slot = value;
    }
}

/// The audit writer: the field starts as NaN, and a store onto a point that
/// is no longer NaN is a second write of that point (a crack in the making).
#[derive(Default)]
pub(crate) struct Audited {
    /// Stores onto points already set.
    pub(crate) rewrites: AtomicUsize,
}

impl Put for Audited {
    const CHECKS: bool = true;

    fn put(&self, slot: &mut f32, value: f32) {
        if !slot.is_nan() {
            self.rewrites.fetch_add(1, Ordering::Relaxed);
        }
        *slot = value;
    }
}

/// One level of the subdivision.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Level {
    /// Side of the squares being split, in points.
    pub(crate) step: usize,
    /// `step / 2`: distance from a new point to its parents.
    pub(crate) half: usize,
    /// Index of the last row and column (`size - 1`).
    pub(crate) last: usize,
    /// Largest random offset of a new point at this depth.
    pub(crate) amp: f32,
}

impl Level {
    /// Squares across the grid; the lattice has `2 * squares + 1` points a side.
    pub(crate) fn squares(&self) -> usize {
        self.last / self.step
    }
}

/// How a generator sets the new points of one lattice row of a level.
///
/// Lattice rows hold `2m + 1` points, `m` = squares across; `offsets` are
/// the new points' random offsets, already scaled by the level's amplitude.
pub(crate) trait Rule: Sync {
    /// Largest random offset of a new point at `depth`.
    fn amplitude(&self, depth: u32) -> f32;

    /// Fills every point of a centre row from the edge rows above and below
    /// (whose even lattice points are set). `offsets[k]` is point `k`'s.
    fn centre_row<P: Put>(&self, rows: CentreRows<'_>, offsets: &[f32], put: &P);

    /// Fills the odd lattice points of an edge row; its neighbours are this
    /// level's centre rows (absent at the border). `offsets[j]` belongs to
    /// lattice point `2j + 1`.
    fn edge_row<P: Put>(&self, rows: EdgeRows<'_>, offsets: &[f32], put: &P);
}

/// The edge row every generator but diamond-square uses: each new point is
/// the mean of its neighbours on the row plus its offset.
pub(crate) fn edge_row_of_ends<P: Put>(row: &mut [f32], offsets: &[f32], put: &P) {
    let Some((first, rest)) = row.split_first_mut() else {
        return;
    };
    // Each pair is (new point 2j+1, old point 2j+2); `left` is point 2j.
    let mut left = *first;
    for (r, o) in rest.chunks_exact_mut(2).zip(offsets) {
        let right = r[1];
        put.put(&mut r[0], 0.5 * (left + right) + o);
        left = right;
    }
}

/// A centre row and its two neighbour rows, as lattices.
pub(crate) struct CentreRows<'a> {
    /// The row `half` above.
    pub(crate) above: &'a [f32],
    /// The row being filled.
    pub(crate) row: &'a mut [f32],
    /// The row `half` below.
    pub(crate) below: &'a [f32],
}

/// An edge row and its neighbour rows, as lattices; the border lacks one.
pub(crate) struct EdgeRows<'a> {
    /// The centre row `half` above, if any.
    pub(crate) above: Option<&'a [f32]>,
    /// The row being filled.
    pub(crate) row: &'a mut [f32],
    /// The centre row `half` below, if any.
    pub(crate) below: Option<&'a [f32]>,
}

/// What every level of one subdivision shares.
pub(crate) struct Job<'a, R, P> {
    /// The generator.
    pub(crate) rule: &'a R,
    /// Where points are stored.
    pub(crate) put: &'a P,
    /// Random values of this seed and grid.
    pub(crate) noise: Noise,
    /// Most threads a level may use.
    pub(crate) threads: usize,
    /// Least work (lattice points x grid columns) worth more than one
    /// thread: below it, starting threads costs more than it saves.
    pub(crate) parallel_work: usize,
    /// Whether to fold the field's extremes on the finest level.
    pub(crate) extremes: bool,
}

impl<'a, R, P> Job<'a, R, P> {
    /// A job with the usual [`PARALLEL_WORK`].
    pub(crate) fn new(
        rule: &'a R,
        put: &'a P,
        noise: Noise,
        threads: usize,
        extremes: bool,
    ) -> Self {
        Job {
            rule,
            put,
            noise,
            threads,
            parallel_work: PARALLEL_WORK,
            extremes,
        }
    }
}

/// The usual [`Job::parallel_work`].
pub(crate) const PARALLEL_WORK: usize = 1 << 17;

/// The lowest and highest height seen, folded in any order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Extremes {
    /// Lowest height.
    pub(crate) lo: f32,
    /// Highest height.
    pub(crate) hi: f32,
}

impl Extremes {
    /// Nothing seen yet.
    pub(crate) const NONE: Extremes = Extremes {
        lo: f32::INFINITY,
        hi: f32::NEG_INFINITY,
    };

    /// These and `other` together.
    pub(crate) fn with(self, other: Extremes) -> Extremes {
        Extremes {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }

    /// These and every value of `values` (eight SIMD-friendly lanes).
    pub(crate) fn with_all(self, values: &[f32]) -> Extremes {
        let (mut lo, mut hi) = ([self.lo; 8], [self.hi; 8]);
        let mut lanes = values.chunks_exact(8);
        for c in &mut lanes {
            for i in 0..8 {
                lo[i] = lo[i].min(c[i]);
                hi[i] = hi[i].max(c[i]);
            }
        }
        let lanes_seen = lo.iter().zip(&hi).map(|(&lo, &hi)| Extremes { lo, hi });
        let rest = lanes.remainder().iter().map(|&v| Extremes { lo: v, hi: v });
        lanes_seen.chain(rest).fold(Extremes::NONE, Extremes::with)
    }
}

/// Runs the levels from `first_depth` on `heights`, a row-major square of
/// `size` points a side whose coarser points are already set. If the job
/// asks, returns the extremes of the finished field: every row is folded,
/// in cache, right after the finest level writes it.
pub(crate) fn subdivide<R: Rule, P: Put>(
    heights: &mut [f32],
    size: usize,
    first_depth: u32,
    job: &Job<'_, R, P>,
) -> Option<Extremes> {
    subdivide_down_to(heights, size, first_depth, 2, job).1
}

/// The levels from `first_depth` on whose step is at least `least_step`
/// (2 for every level): afterwards every point of the lattice of half
/// that step is set, and no later level writes to it. Returns the depth
/// of the next level, and the field's extremes if the last level run was
/// the finest (and the job asked for them).
pub(crate) fn subdivide_down_to<R: Rule, P: Put>(
    heights: &mut [f32],
    size: usize,
    first_depth: u32,
    least_step: usize,
    job: &Job<'_, R, P>,
) -> (u32, Option<Extremes>) {
    let last = size - 1;
    let mut depth = first_depth;
    let mut extremes = None;
    while let Some(lv) = level(last, depth, job.rule).filter(|lv| lv.step >= least_step) {
        extremes = Some(run_level(heights, size, &lv, job));
        depth += 1;
    }
    let finest = level(last, depth, job.rule).is_none();
    (depth, extremes.filter(|_| job.extremes && finest))
}

/// Level `depth` of a grid whose last index is `last`, if it has new points.
fn level<R: Rule>(last: usize, depth: u32, rule: &R) -> Option<Level> {
    let step = last.checked_shr(depth)?;
    (step >= 2).then(|| Level {
        step,
        half: step / 2,
        last,
        amp: rule.amplitude(depth),
    })
}

/// One level: bands of rows in parallel, then the edge rows between bands.
/// On the finest level, returns the extremes of the whole field.
fn run_level<R: Rule, P: Put>(
    heights: &mut [f32],
    size: usize,
    lv: &Level,
    job: &Job<'_, R, P>,
) -> Extremes {
    let squares = lv.squares();
    let bands = if squares * size >= job.parallel_work {
        job.threads.clamp(1, squares)
    } else {
        1
    };
    // Band boundaries are edge rows: every `2 * half`-th row.
    let bounds: Vec<usize> = (0..=bands)
        .map(|t| (t * squares / bands) * lv.step)
        .collect();
    let (edges, bodies) = split_bands(heights, size, &bounds);
    let mut extremes = std::thread::scope(|scope| {
        let mut bands = bodies.into_iter().zip(edges.windows(2));
        let first = bands.next();
        let others: Vec<_> = bands
            .map(|(body, pair)| {
                let (top, bottom) = (pair[0], pair[1]);
                scope.spawn(move || run_band(job, lv, body, top, bottom))
            })
            .collect();
        let mut extremes = first.map_or(Extremes::NONE, |(body, pair)| {
            run_band(job, lv, body, pair[0], pair[1])
        });
        for other in others {
            extremes = extremes.with(other.join().expect("a generator thread panicked"));
        }
        extremes
    });
    let mut scratch = Scratch::new(lv);
    for &y in &bounds {
        let mut whole = Body {
            first: 0,
            size,
            rows: &mut *heights,
        };
        let (above, row, below) = whole.neighbours(y, lv.half);
        fill_edge_row(job, lv, y, (above, row, below), &mut scratch);
        if job.extremes {
            extremes = extremes.with_all(&heights[y * size..(y + 1) * size]);
        }
    }
    extremes
}

/// The rows strictly between two band boundaries, starting at row `first`.
struct Body<'a> {
    first: usize,
    size: usize,
    rows: &'a mut [f32],
}

impl Body<'_> {
    /// Row `y`, mutable, with rows `y - h` and `y + h` when the body holds them.
    fn neighbours(&mut self, y: usize, h: usize) -> (Option<&[f32]>, &mut [f32], Option<&[f32]>) {
        let size = self.size;
        let (head, tail) = self.rows.split_at_mut((y - self.first) * size);
        let (row, after) = tail.split_at_mut(size);
        let above = (y >= self.first + h).then(|| {
            let a = y - h - self.first;
            &head[a * size..(a + 1) * size]
        });
        let below = after.get((h - 1) * size..h * size);
        (above, row, below)
    }
}

/// Cuts `heights` into the boundary rows (shared) and the bodies between
/// them (mutable), so bands can run at once without sharing a writable row.
fn split_bands<'a>(
    heights: &'a mut [f32],
    size: usize,
    bounds: &[usize],
) -> (Vec<&'a [f32]>, Vec<Body<'a>>) {
    let mut edges = Vec::with_capacity(bounds.len());
    let mut bodies = Vec::with_capacity(bounds.len());
    let mut rest = heights;
    let mut first = 0;
    for (t, &y) in bounds.iter().enumerate() {
        let (body, tail) = std::mem::take(&mut rest).split_at_mut((y - first) * size);
        if t > 0 {
            bodies.push(Body {
                first,
                size,
                rows: body,
            });
        }
        let (edge, tail) = tail.split_at_mut(size);
        edges.push(&*edge);
        rest = tail;
        first = y + 1;
    }
    (edges, bodies)
}

/// Fills the centre rows of one band, each followed by the edge row above
/// it when that row lies inside the band (its centre rows are then ready).
fn run_band<R: Rule, P: Put>(
    job: &Job<'_, R, P>,
    lv: &Level,
    mut body: Body<'_>,
    top: &[f32],
    bottom: &[f32],
) -> Extremes {
    if lv.half > 1 {
        run_band_through_lattices(job, lv, body, top, bottom);
        return Extremes::NONE;
    }
    let top_row = body.first - 1;
    let bottom_row = body.first + body.rows.len() / body.size;
    let mut scratch = Scratch::new(lv);
    let mut extremes = Extremes::NONE;
    let mut y = top_row + 1;
    while y < bottom_row {
        let (above, row, below) = body.neighbours(y, 1);
        let rows = CentreRows {
            above: above.unwrap_or(top),
            row,
            below: below.unwrap_or(bottom),
        };
        job.noise.fill_row(y, 0, 1, lv.amp, &mut scratch.offsets);
        job.rule.centre_row(rows, &scratch.offsets, job.put);
        if job.extremes {
            extremes = extremes.with_all(body.neighbours(y, 1).1);
        }
        if y - 1 > top_row {
            let (above, row, below) = body.neighbours(y - 1, 1);
            fill_edge_row(job, lv, y - 1, (above, &mut *row, below), &mut scratch);
            if job.extremes {
                extremes = extremes.with_all(row);
            }
        }
        y += 2;
    }
    extremes
}

/// [`run_band`] on a coarse level: each row's lattice is gathered once into
/// a rolling set of buffers and its new points scattered back once.
fn run_band_through_lattices<R: Rule, P: Put>(
    job: &Job<'_, R, P>,
    lv: &Level,
    mut body: Body<'_>,
    top: &[f32],
    bottom: &[f32],
) {
    let (h, squares) = (lv.half, lv.squares());
    let top_row = body.first - 1;
    let bottom_row = body.first + body.rows.len() / body.size;
    let points = 2 * squares + 1;
    let mut offsets = vec![0.0; points];
    // Lattices of the edge rows above and below the current centre row,
    // and of the previous and current centre rows.
    let [mut edge_above, mut edge_below, mut centre_above, mut centre] =
        std::array::from_fn(|_| vec![0.0; points]);
    gather(top, h, &mut edge_above);
    let mut y = top_row + h;
    while y < bottom_row {
        let (_, row, below) = body.neighbours(y, h);
        gather(below.unwrap_or(bottom), h, &mut edge_below);
        // Every lattice point of a centre row is new: the rule overwrites all.
        if P::CHECKS {
            gather(row, h, &mut centre);
        }
        job.noise.fill_row(y, 0, h, lv.amp, &mut offsets);
        let rows = CentreRows {
            above: &edge_above,
            row: &mut centre,
            below: &edge_below,
        };
        job.rule.centre_row(rows, &offsets, job.put);
        for (r, &v) in row.chunks_mut(h).zip(&centre) {
            r[0] = v;
        }
        if y - h > top_row {
            let edge_offsets = &mut offsets[..squares];
            job.noise.fill_row(y - h, h, 2 * h, lv.amp, edge_offsets);
            let rows = EdgeRows {
                above: Some(&centre_above),
                row: &mut edge_above,
                below: Some(&centre),
            };
            job.rule.edge_row(rows, edge_offsets, job.put);
            let (_, row, _) = body.neighbours(y - h, h);
            scatter_odd(&edge_above, h, row);
        }
        std::mem::swap(&mut centre_above, &mut centre);
        std::mem::swap(&mut edge_above, &mut edge_below);
        y += 2 * h;
    }
}

/// Per-band buffers: the random offsets of a row and, on coarse levels,
/// the lattices of three rows.
struct Scratch {
    offsets: Vec<f32>,
    above: Vec<f32>,
    row: Vec<f32>,
    below: Vec<f32>,
}

impl Scratch {
    fn new(lv: &Level) -> Self {
        let points = 2 * lv.squares() + 1;
        let lattice = if lv.half == 1 { 0 } else { points };
        Scratch {
            offsets: vec![0.0; points],
            above: vec![0.0; lattice],
            row: vec![0.0; lattice],
            below: vec![0.0; lattice],
        }
    }
}

/// Copies every `h`-th point of `row` into `lattice`.
fn gather(row: &[f32], h: usize, lattice: &mut [f32]) {
    for (l, c) in lattice.iter_mut().zip(row.chunks(h)) {
        *l = c[0];
    }
}

/// Copies the odd points of `lattice` (an edge row's new ones) into `row`.
fn scatter_odd(lattice: &[f32], h: usize, row: &mut [f32]) {
    for (r, v) in row[h..].chunks_mut(2 * h).zip(lattice[1..].chunks(2)) {
        r[0] = v[0];
    }
}

/// Gives the rule edge row `y`, through a gathered lattice if `half > 1`.
fn fill_edge_row<R: Rule, P: Put>(
    job: &Job<'_, R, P>,
    lv: &Level,
    y: usize,
    (above, row, below): (Option<&[f32]>, &mut [f32], Option<&[f32]>),
    s: &mut Scratch,
) {
    let (h, squares) = (lv.half, lv.squares());
    let offsets = &mut s.offsets[..squares];
    job.noise.fill_row(y, h, 2 * h, lv.amp, offsets);
    if h == 1 {
        let rows = EdgeRows { above, row, below };
        job.rule.edge_row(rows, offsets, job.put);
        return;
    }
    if let Some(a) = above {
        gather(a, h, &mut s.above);
    }
    if let Some(b) = below {
        gather(b, h, &mut s.below);
    }
    gather(row, h, &mut s.row);
    let rows = EdgeRows {
        above: above.map(|_| &s.above[..]),
        row: &mut s.row,
        below: below.map(|_| &s.below[..]),
    };
    job.rule.edge_row(rows, offsets, job.put);
    scatter_odd(&s.row, h, row);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A rule that writes every point of its rows from the row mean, with
    /// faults switched on by flags, to show the audit catches them.
    struct Faulty {
        write_twice: bool,
        skip_one: bool,
    }

    impl Rule for Faulty {
        fn amplitude(&self, _depth: u32) -> f32 {
            1.0
        }

        fn centre_row<P: Put>(&self, rows: CentreRows<'_>, offsets: &[f32], put: &P) {
            let start = usize::from(self.skip_one);
            for (k, slot) in rows.row.iter_mut().enumerate().skip(start) {
                put.put(slot, rows.above[k & !1] + offsets[k]);
            }
            if self.write_twice {
                put.put(&mut rows.row[0], 0.0);
            }
        }

        fn edge_row<P: Put>(&self, rows: EdgeRows<'_>, offsets: &[f32], put: &P) {
            edge_row_of_ends(rows.row, offsets, put);
        }
    }

    fn audit(rule: &Faulty, threads: usize) -> (usize, usize, Vec<f32>) {
        let size = 33;
        let mut heights = vec![f32::NAN; size * size];
        for i in [0, size - 1, size * (size - 1), size * size - 1] {
            heights[i] = 0.0;
        }
        let put = Audited::default();
        let job = Job {
            rule,
            put: &put,
            noise: Noise::new(1, 5),
            threads,
            parallel_work: 0,
            extremes: false,
        };
        subdivide(&mut heights, size, 0, &job);
        let unset = heights.iter().filter(|h| h.is_nan()).count();
        (put.rewrites.into_inner(), unset, heights)
    }

    #[test]
    fn a_sound_rule_passes_the_audit_on_any_thread_count() {
        let rule = Faulty {
            write_twice: false,
            skip_one: false,
        };
        let (rewrites, unset, one) = audit(&rule, 1);
        assert_eq!((rewrites, unset), (0, 0));
        let (_, _, many) = audit(&rule, 4);
        let bits = |v: &[f32]| v.iter().map(|h| h.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&one), bits(&many));
    }

    #[test]
    fn the_audit_counts_a_second_write() {
        let rule = Faulty {
            write_twice: true,
            skip_one: false,
        };
        let (rewrites, _, _) = audit(&rule, 1);
        // One extra store per centre row of every level: 1 + 2 + 4 + 8 + 16.
        assert_eq!(rewrites, 31);
    }

    #[test]
    fn the_audit_sees_a_point_left_unset() {
        let rule = Faulty {
            write_twice: false,
            skip_one: true,
        };
        let (_, unset, _) = audit(&rule, 1);
        assert!(unset > 0);
    }
}

//! Triangle fill with an exact top-left rule, and one-pixel lines.
//!
//! Vertices are in 24.8 fixed point (`SUBPIXEL` steps per pixel); a pixel is
//! covered when its centre is inside the triangle, or exactly on a top or left
//! edge. Neighbouring triangles that share an edge therefore cover every pixel
//! along it exactly once, whatever the sub-pixel positions.

pub use crate::render::base::fixed::{Clip, Fixed2, SUBPIXEL, to_fixed};

const HALF: i64 = SUBPIXEL / 2;

/// Largest fixed-point coordinate kept (2^21 pixels): edge-function products
/// of clamped coordinates stay far inside i64. Only absurd frames (over two
/// million pixels wide) ever have vertices this far out.
const LIMIT: i64 = 1 << 29;

/// Clamps a vertex to +-`LIMIT`; independent of any clip, so a triangle is
/// the same shape in every band.
#[inline]
fn clamp(p: Fixed2) -> Fixed2 {
    [p[0].clamp(-LIMIT, LIMIT), p[1].clamp(-LIMIT, LIMIT)]
}

/// Floor of a fixed-point value in pixels (a shift: `SUBPIXEL` is 2^8).
#[inline]
fn floor_px(n: i64) -> i64 {
    n >> 8
}

/// Ceiling of a fixed-point value in pixels.
#[inline]
fn ceil_px(n: i64) -> i64 {
    -((-n) >> 8)
}

/// First and last pixel index whose centre lies in `lo..=hi` (fixed point).
#[inline]
fn centres_within(lo: i64, hi: i64) -> (i64, i64) {
    (ceil_px(lo - HALF), floor_px(hi - HALF))
}

/// One edge `a -> b` of a counter-clockwise (in y-down screen space) triangle.
#[derive(Clone, Copy)]
struct Edge {
    ax: i64,
    ay: i64,
    dx: i64,
    dy: i64,
    /// 0 on a top or left edge (points on it are inside), -1 otherwise.
    bias: i64,
}

impl Edge {
    fn new(a: Fixed2, b: Fixed2) -> Self {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let top_left = dy > 0 || (dy == 0 && dx < 0);
        Edge {
            ax: a[0],
            ay: a[1],
            dx,
            dy,
            bias: if top_left { 0 } else { -1 },
        }
    }

    /// The edge function plus bias at a fixed-point point: inside when >= 0.
    #[inline]
    fn eval(&self, px: i64, py: i64) -> i64 {
        (px - self.ax) * self.dy - (py - self.ay) * self.dx + self.bias
    }
}

/// Bounding boxes at most this many columns wide are scanned pixel by pixel,
/// four centres a row; larger ones (but see [`WIDE_SCAN_WIDTH`]) get their
/// span ends by division (identical results).
const SCAN_WIDTH: i64 = 4;
/// Boxes up to this wide and [`WIDE_SCAN_ROWS`] tall are scanned too, eight
/// centres a row ([`SLIVER_SCAN_WIDTH`] up to that width): the far land's
/// cells are flat slivers a row or two high and three to six pixels wide,
/// and setting up a [`Walk`] costs each edge two 64-bit divisions.
const WIDE_SCAN_WIDTH: i64 = 8;
/// Most of those boxes are five or six columns wide: they test six centres
/// a row, not eight.
const SLIVER_SCAN_WIDTH: i64 = 6;
/// See [`WIDE_SCAN_WIDTH`]: past this many rows the walk's cheaper rows
/// repay its set-up.
const WIDE_SCAN_ROWS: i64 = 4;

/// Calls `span(y, x0, x1)` for every row of pixels the triangle covers
/// (columns `x0..x1`, exclusive end), top to bottom, within `clip`.
///
/// Degenerate (zero-area) triangles cover nothing.
#[inline]
pub fn fill_triangle(v: [Fixed2; 3], clip: &Clip, span: impl FnMut(u32, u32, u32)) {
    if let Some(t) = Triangle::new(v, clip) {
        t.spans(span);
    }
}

/// A triangle with a pixel centre in its bounding box, within a clip: what
/// it may cover is known before its edges are set up.
pub struct Triangle {
    v: [Fixed2; 3],
    area: i64,
    box_: [i64; 4],
}

impl Triangle {
    /// `v` clamped and boxed; `None` when no pixel centre of `clip` lies in
    /// its bounding box or it has no area.
    #[inline]
    pub fn new(v: [Fixed2; 3], clip: &Clip) -> Option<Self> {
        let [a, b, c] = v.map(clamp);
        let (xmin, xmax) = (a[0].min(b[0]).min(c[0]), a[0].max(b[0]).max(c[0]));
        let (ymin, ymax) = (a[1].min(b[1]).min(c[1]), a[1].max(b[1]).max(c[1]));
        let (ix0, ix1) = centres_in(xmin, xmax, clip.x0, clip.x1)?;
        let (iy0, iy1) = centres_in(ymin, ymax, clip.y0, clip.y1)?;
        let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        (area != 0).then_some(Triangle {
            v: [a, b, c],
            area,
            box_: [ix0, ix1, iy0, iy1],
        })
    }

    /// First and last column and row of the pixels it may cover
    /// (`[x0, x1, y0, y1]`, within the clip).
    #[inline]
    pub fn bounds(&self) -> [i64; 4] {
        self.box_
    }

    /// Calls `span(y, x0, x1)` for every row of pixels it covers, top to
    /// bottom.
    #[inline]
    pub fn spans(&self, mut span: impl FnMut(u32, u32, u32)) {
        let [a, mut b, mut c] = self.v;
        let [ix0, ix1, iy0, iy1] = self.box_;
        // Edge functions below are positive inside when `area` is negative.
        if self.area > 0 {
            std::mem::swap(&mut b, &mut c);
        }
        let edges = [Edge::new(a, b), Edge::new(b, c), Edge::new(c, a)];
        let (w, h) = (ix1 - ix0 + 1, iy1 - iy0 + 1);
        if w <= SCAN_WIDTH {
            scan::<{ SCAN_WIDTH as usize }>(&edges, self.box_, span);
            return;
        }
        if w <= WIDE_SCAN_WIDTH && h <= WIDE_SCAN_ROWS {
            if w <= SLIVER_SCAN_WIDTH {
                scan::<{ SLIVER_SCAN_WIDTH as usize }>(&edges, self.box_, span);
            } else {
                scan::<{ WIDE_SCAN_WIDTH as usize }>(&edges, self.box_, span);
            }
            return;
        }
        // Wider ones: each edge's bound on the row's columns, stepped row by row.
        let py0 = iy0 * SUBPIXEL + HALF;
        let mut walks = edges.map(|e| Walk::new(&e, py0));
        for iy in iy0..iy1 + 1 {
            let (mut lo, mut hi) = (ix0, ix1);
            for w in &mut walks {
                w.bound(&mut lo, &mut hi);
                w.step();
            }
            if lo <= hi {
                span(iy as u32, lo as u32, hi as u32 + 1);
            }
        }
    }
}

/// One edge's limit on the covered columns, row after row, in exact integer
/// steps: `floor(m / d)` kept as quotient and remainder while `m` moves by a
/// fixed amount per row.
#[derive(Clone, Copy)]
struct Walk {
    /// +1: the edge bounds the row from the left (first column `-q`);
    /// -1: from the right (last column `q`); 0: horizontal (`q >= 0` inside).
    side: i8,
    q: i64,
    r: i64,
    d: i64,
    step_q: i64,
    step_r: i64,
}

impl Walk {
    /// Inside a row at centre `py`: `(ix * S + HALF - ax) * dy >= k`, with
    /// `k = (py - ay) * dx - bias`, which moves by `S * dx` per row.
    fn new(e: &Edge, py: i64) -> Self {
        let k = (py - e.ay) * e.dx - e.bias;
        let per_row = -SUBPIXEL * e.dx;
        if e.dy == 0 {
            // Inside iff -k >= 0.
            return Walk {
                side: 0,
                q: -k,
                r: 0,
                d: 1,
                step_q: per_row,
                step_r: 0,
            };
        }
        let d = SUBPIXEL * e.dy.abs();
        // Left: ix >= ceil((k + (ax - HALF) * dy) / d) = -floor(m / d).
        // Right: ix <= floor((-k + (ax - HALF) * -dy) / d) = floor(m / d).
        // Either way m = -k - (ax - HALF) * dy, moving by -S * dx per row.
        let m = -k - (e.ax - HALF) * e.dy;
        Walk {
            side: if e.dy > 0 { 1 } else { -1 },
            q: m.div_euclid(d),
            r: m.rem_euclid(d),
            d,
            step_q: per_row.div_euclid(d),
            step_r: per_row.rem_euclid(d),
        }
    }

    #[inline]
    fn bound(&self, lo: &mut i64, hi: &mut i64) {
        match self.side {
            1 => *lo = (*lo).max(-self.q),
            -1 => *hi = (*hi).min(self.q),
            _ if self.q < 0 => *hi = *lo - 1,
            _ => {}
        }
    }

    #[inline]
    fn step(&mut self) {
        self.q += self.step_q;
        self.r += self.step_r;
        if self.r >= self.d {
            self.r -= self.d;
            self.q += 1;
        }
    }
}

/// Calls `span` for each covered row of a triangle whose box (`[x0, x1, y0,
/// y1]`) is at most `N` columns wide, testing the few centres and stepping
/// the edge functions by additions row to row.
#[inline(always)]
fn scan<const N: usize>(edges: &[Edge; 3], box_: [i64; 4], mut span: impl FnMut(u32, u32, u32)) {
    let [ix0, ix1, iy0, iy1] = box_;
    let (px, py) = (ix0 * SUBPIXEL + HALF, iy0 * SUBPIXEL + HALF);
    let mut row = edges.map(|e| e.eval(px, py));
    let down = edges.map(|e| -e.dx * SUBPIXEL);
    let across = edges.map(|e| e.dy * SUBPIXEL);
    for iy in iy0..iy1 + 1 {
        let (lo, hi) = scan_row::<N>(row, across, ix0, ix1);
        if lo <= hi {
            span(iy as u32, lo as u32, hi as u32 + 1);
        }
        row = [row[0] + down[0], row[1] + down[1], row[2] + down[2]];
    }
}

/// The inside columns of one row, found by testing each pixel centre.
/// `start` holds the three edge functions at column `ix0`, `step` their
/// change per column; the row holds at most `N` columns.
///
/// Every centre is tested without branching (the tiny triangles of a fine
/// grid made a scanning loop mispredict at every turn); the inside of a row
/// of a triangle is one run, so its first and last inside column give it.
#[inline]
fn scan_row<const N: usize>(start: [i64; 3], step: [i64; 3], ix0: i64, ix1: i64) -> (i64, i64) {
    let [mut e0, mut e1, mut e2] = start;
    let [s0, s1, s2] = step;
    let columns = ix1 - ix0 + 1;
    let mut inside = 0u32;
    for k in 0..N as i64 {
        let hit = (k < columns) & ((e0 | e1 | e2) >= 0);
        inside |= (hit as u32) << k;
        (e0, e1, e2) = (e0 + s0, e1 + s1, e2 + s2);
    }
    if inside == 0 {
        return (ix0 + 1, ix0);
    }
    let first = inside.trailing_zeros() as i64;
    let last = 31 - inside.leading_zeros() as i64;
    (ix0 + first, ix0 + last)
}

/// The pixels inside `clip` whose centres lie in the bounding box of a
/// cell's corners, as first and last column and row (`[x0, x1, y0, y1]`),
/// if any: a cheap test that skips most cells of a fine grid, and the cells
/// of other bands (both triangles lie inside that box).
#[inline]
pub(crate) fn centre_box(p: [Fixed2; 4], clip: &Clip) -> Option<[i64; 4]> {
    let lo = |i: usize| p[0][i].min(p[1][i]).min(p[2][i]).min(p[3][i]);
    let hi = |i: usize| p[0][i].max(p[1][i]).max(p[2][i]).max(p[3][i]);
    let (x0, x1) = centres_in(lo(0), hi(0), clip.x0, clip.x1)?;
    let (y0, y1) = centres_in(lo(1), hi(1), clip.y0, clip.y1)?;
    Some([x0, x1, y0, y1])
}

/// The first and last pixel n in `first..end` whose centre (n + 1/2) lies
/// in `lo..=hi` (fixed point), if any.
#[inline]
fn centres_in(lo: i64, hi: i64, first: i64, end: i64) -> Option<(i64, i64)> {
    let (a, b) = centres_within(lo, hi);
    let (a, b) = (a.max(first), b.min(end - 1));
    (a <= b).then_some((a, b))
}

/// Calls `plot(x, y)` for each pixel of the one-pixel-wide (8-connected)
/// line between the pixels holding `a` and `b`, both ends included, within `clip`.
///
/// The endpoints are put in a fixed order first, so a line drawn from either
/// end covers the same pixels: a shared edge drawn twice never thickens.
pub fn draw_line(a: Fixed2, b: Fixed2, clip: &Clip, plot: impl FnMut(u32, u32)) {
    let line = Line::new(a, b);
    line.walk(0, line.steps, clip, plot);
}

/// Calls `plot` for the pixels of `draw_line(a, b)` next to `b`'s end (its
/// last two steps), without walking the rest of the line.
pub fn draw_line_end(a: Fixed2, b: Fixed2, clip: &Clip, plot: impl FnMut(u32, u32)) {
    let line = Line::new(a, b);
    if line.reversed {
        line.walk(0, line.steps.min(1), clip, plot);
    } else {
        line.walk(line.steps.saturating_sub(1), line.steps, clip, plot);
    }
}

/// A line between two pixels: step `k` of `steps` is at
/// `start + round(k * delta / steps)` on each axis (halves rounded up).
struct Line {
    x0: i64,
    y0: i64,
    dx: i64,
    dy: i64,
    steps: i64,
    /// Whether the ends were swapped into the fixed order.
    reversed: bool,
}

impl Line {
    fn new(a: Fixed2, b: Fixed2) -> Self {
        let (a, b) = (clamp(a), clamp(b));
        let reversed = (a[1], a[0]) > (b[1], b[0]);
        let (a, b) = if reversed { (b, a) } else { (a, b) };
        let (x0, y0) = (floor_px(a[0]), floor_px(a[1]));
        let (dx, dy) = (floor_px(b[0]) - x0, floor_px(b[1]) - y0);
        Line {
            x0,
            y0,
            dx,
            dy,
            steps: dx.abs().max(dy.abs()),
            reversed,
        }
    }

    /// Plots steps `from..=to`.
    fn walk(&self, from: i64, to: i64, clip: &Clip, mut plot: impl FnMut(u32, u32)) {
        let x1 = self.x0 + self.dx;
        let y1 = self.y0 + self.dy;
        let outside = self.x0.max(x1) < clip.x0
            || self.x0.min(x1) >= clip.x1
            || self.y0.max(y1) < clip.y0
            || self.y0.min(y1) >= clip.y1;
        if outside || from > to {
            return;
        }
        let mut put = |px: i64, py: i64| {
            if px >= clip.x0 && px < clip.x1 && py >= clip.y0 && py < clip.y1 {
                plot(px as u32, py as u32);
            }
        };
        if self.steps <= 1 {
            // Most lines of a fine grid: just their end pixels (step 1 of 1
            // is the end itself).
            for k in from..=to {
                put(self.x0 + k * self.dx, self.y0 + k * self.dy);
            }
            return;
        }
        let mut x = Axis::new(self.x0, self.dx, self.steps, from);
        let mut y = Axis::new(self.y0, self.dy, self.steps, from);
        for _ in from..=to {
            put(x.pos(), y.pos());
            x.step();
            y.step();
        }
    }
}

/// One coordinate of a line, stepped exactly with an integer remainder:
/// `start + sign * floor((2 k |delta| + steps) / (2 steps))`.
struct Axis {
    pos: i64,
    sign: i64,
    twice_delta: i64,
    twice_steps: i64,
    remainder: i64,
}

impl Axis {
    fn new(start: i64, delta: i64, steps: i64, k: i64) -> Self {
        let twice_steps = (2 * steps).max(1);
        let twice_delta = 2 * delta.abs();
        let sign = delta.signum();
        let mut axis = Axis {
            pos: start,
            sign,
            twice_delta,
            twice_steps,
            // Step 0: floor(steps / (2 steps)) = 0, remainder `steps`.
            remainder: steps,
        };
        // Division is slow and most lines are a few pixels long: step there.
        if k <= 8 {
            (0..k).for_each(|_| axis.step());
        } else {
            let num = k * twice_delta + steps;
            axis.pos = start + sign * (num / twice_steps);
            axis.remainder = num % twice_steps;
        }
        axis
    }

    #[inline]
    fn pos(&self) -> i64 {
        self.pos
    }

    #[inline]
    fn step(&mut self) {
        self.remainder += self.twice_delta;
        // |delta| <= steps, so at most one carry per step.
        if self.remainder >= self.twice_steps {
            self.remainder -= self.twice_steps;
            self.pos += self.sign;
        }
    }
}

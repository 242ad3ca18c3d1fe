//! Colours blended across a screen triangle (as `blend`), each pixel made
//! lighter or darker by a tone of the ground's height there: the rock's
//! strata on a steep face, bands finer than the grid's cells that follow
//! the contours across it.

use glam::{Vec2, Vec4};

use super::blend::{Blend, RowStart};
use super::fine::{Fine, FineRow, Gain, PIECE};
use super::gradient::Gradient;
use crate::render::base::canvas::Canvas;
use crate::render::base::colour::packed_lanes;
use crate::render::base::fixed::Fixed2;
use crate::render::shade::strata::Sampler;

/// What lightens or darkens each height: its tone, -1..=1.
pub(crate) trait Tone {
    /// The tone at height `h`.
    fn tone(&self, h: f32) -> f32;
}

impl<F: Fn(f32) -> f32> Tone for F {
    #[inline(always)]
    fn tone(&self, h: f32) -> f32 {
        self(h)
    }
}

/// The rock's strata at one level of detail.
impl Tone for Sampler<'_> {
    #[inline(always)]
    fn tone(&self, h: f32) -> f32 {
        Sampler::tone(self, h)
    }
}

/// A blended triangle with a plane of (height, band strength) beside its
/// colours, and the relief below the grid where it shows.
pub(crate) struct Banded<T, G> {
    blend: Blend,
    /// Height and strength at the first corner, their change per pixel to
    /// the right and per row down, and their least and greatest corner
    /// values (a sliver's planes may overshoot its corners).
    at0: Vec2,
    dx: Vec2,
    dy: Vec2,
    lo: Vec2,
    hi: Vec2,
    origin: [f32; 2],
    /// The tone (-1..=1) at a height.
    tone: T,
    fine: Option<Fine<G>>,
}

/// A face blended plain, lit by the relief below the grid, or with bands
/// across it (and that relief, where it shows).
pub(crate) enum Fill<T, G> {
    Plain(Blend),
    Fine(Blend, Fine<G>),
    Banded(Banded<T, G>),
}

impl<T: Tone, G: Gain> Fill<T, G> {
    /// Sets the pixels `x0..x1` of row `y`.
    #[inline]
    pub(crate) fn fill(&self, canvas: &mut Canvas, y: u32, x0: u32, x1: u32) {
        match (self, self.fine()) {
            (_, Some(fine)) => in_pieces(fine, &fine.row(y), x0, x1, |x0, x1, gains| {
                self.fill_lit(canvas, y, x0, x1, gains)
            }),
            (Fill::Banded(b), None) => {
                let row = b.row(y);
                canvas.fill_with(y, x0, x1, |x| b.at(&row, x, 1.0))
            }
            (Fill::Plain(b) | Fill::Fine(b, _), None) => {
                let row = b.row(y);
                canvas.fill_with(y, x0, x1, |x| b.at(&row, x));
            }
        }
    }

    /// The relief below the grid over the face, where it shows.
    #[inline(always)]
    fn fine(&self) -> Option<&Fine<G>> {
        match self {
            Fill::Plain(_) => None,
            Fill::Fine(_, fine) => Some(fine),
            Fill::Banded(b) => b.fine.as_ref(),
        }
    }

    /// Sets the pixels `x0..x1` of row `y`, each `gains[x - x0]` times as
    /// bright as the face makes it.
    #[inline(always)]
    fn fill_lit(&self, canvas: &mut Canvas, y: u32, x0: u32, x1: u32, gains: &[f32]) {
        let gain = |x: u32| gains[(x - x0) as usize];
        match self {
            Fill::Plain(b) | Fill::Fine(b, _) => {
                let row = b.row(y);
                canvas.fill_with(y, x0, x1, |x| {
                    packed_lanes(lighter(b.lanes_at(&row, x), gain(x)))
                });
            }
            Fill::Banded(b) => {
                let row = b.row(y);
                canvas.fill_with(y, x0, x1, |x| b.at(&row, x, gain(x)));
            }
        }
    }
}

/// Spans of one face held back at most.
const HELD: usize = 8;

/// A face's fill whose short spans are held back, so that the relief's
/// factors of their pixels are worked out four at a time across rows: a
/// refined face is often a few pixels across, and a span alone would leave
/// most of its four lanes idle.
pub(crate) struct FaceFill<T, G> {
    fill: Fill<T, G>,
    /// Row, first and one past the last pixel of each span held.
    spans: [(u32, u32, u32); HELD],
    count: usize,
    pixels: usize,
}

impl<T: Tone, G: Gain> FaceFill<T, G> {
    /// `fill`, its spans not yet held.
    #[inline]
    pub(crate) fn new(fill: Fill<T, G>) -> Self {
        FaceFill {
            fill,
            spans: [(0, 0, 0); HELD],
            count: 0,
            pixels: 0,
        }
    }

    /// Sets the pixels `x0..x1` of row `y`, now or by [`FaceFill::finish`]:
    /// under the relief, only those a write would change (on a canvas
    /// drawn front to back, most of a far face's are nearer land's).
    #[inline]
    pub(crate) fn fill(&mut self, canvas: &mut Canvas, y: u32, x0: u32, x1: u32) {
        if self.fill.fine().is_none() {
            return self.fill.fill(canvas, y, x0, x1);
        }
        let mut from = x0;
        while let Some((a, b)) = canvas.next_open(y, from, x1) {
            self.hold(canvas, y, a, b);
            from = b;
        }
    }

    /// Sets the pixels `x0..x1` of row `y`, held if few.
    #[inline]
    fn hold(&mut self, canvas: &mut Canvas, y: u32, x0: u32, x1: u32) {
        let len = (x1 - x0) as usize;
        if len >= PIECE {
            return self.fill.fill(canvas, y, x0, x1);
        }
        if self.count == HELD || self.pixels + len > PIECE {
            self.finish(canvas);
        }
        self.spans[self.count] = (y, x0, x1);
        self.count += 1;
        self.pixels += len;
    }

    /// Sets the pixels of the spans held.
    #[inline]
    pub(crate) fn finish(&mut self, canvas: &mut Canvas) {
        let Some(fine) = self.fill.fine() else {
            return;
        };
        let (mut xs, mut ys) = ([0u32; PIECE], [0u32; PIECE]);
        let mut n = 0;
        for &(y, x0, x1) in &self.spans[..self.count] {
            for x in x0..x1 {
                (xs[n], ys[n]) = (x, y);
                n += 1;
            }
        }
        let mut gains = [0.0f32; PIECE];
        fine.gains_at(&xs[..n], &ys[..n], &mut gains[..n]);
        let mut at = 0;
        for &(y, x0, x1) in &self.spans[..self.count] {
            let next = at + (x1 - x0) as usize;
            self.fill.fill_lit(canvas, y, x0, x1, &gains[at..next]);
            at = next;
        }
        (self.count, self.pixels) = (0, 0);
    }
}

/// Calls `fill(x0, x1, gains)` for each piece of at most [`PIECE`] pixels
/// of the span `x0..x1` of a row (whose start is `row`), with the pieces' factors of `fine`
/// (`gains[i]` pixel `x0 + i`'s).
#[inline(always)]
fn in_pieces<G: Gain>(
    fine: &Fine<G>,
    row: &FineRow,
    x0: u32,
    x1: u32,
    mut fill: impl FnMut(u32, u32, &[f32]),
) {
    let mut gains = [0.0f32; PIECE];
    let mut start = x0;
    while start < x1 {
        let end = x1.min(start + PIECE as u32);
        let gains = &mut gains[..(end - start) as usize];
        fine.gains(row, start, gains);
        fill(start, end, gains);
        start = end;
    }
}

impl<T: Tone, G: Gain> Fill<T, G> {
    /// The colour of pixel (`x`, `y`) alone (a span's pixels are set by
    /// [`Fill::fill`]).
    pub(crate) fn pixel(&self, x: u32, y: u32) -> u32 {
        let gain = |fine: &Fine<G>| {
            let mut g = [1.0];
            fine.gains(&fine.row(y), x, &mut g);
            g[0]
        };
        match self {
            Fill::Plain(b) => b.at(&b.row(y), x),
            Fill::Fine(b, fine) => packed_lanes(lighter(b.lanes_at(&b.row(y), x), gain(fine))),
            Fill::Banded(b) => b.at(&b.row(y), x, b.fine.as_ref().map_or(1.0, gain)),
        }
    }
}

/// A pixel's channels `gain` times as bright, held to 255 and rounded.
#[inline(always)]
fn lighter(colour: Vec4, gain: f32) -> Vec4 {
    // +0.5 rounds.
    (colour * gain).min(Vec4::splat(255.0)) + 0.5
}

/// One row's colour and (height, strength) where it crosses the first
/// corner's column.
pub(crate) type BandedRow = (RowStart, Vec2);

impl<T: Tone, G: Gain> Banded<T, G> {
    /// The triangle of corners `v` (24.8 fixed point), their packed
    /// `colours`, ground `heights` and band `strengths` (0..=1: how much
    /// of the tone shows), toned by `tone(per_pixel, strongest)`, given the
    /// height one pixel spans (the larger of its steps across and down) and
    /// the largest strength: `None` where the bands would not show (too
    /// faint, or blurred away), and the face is blended plain. `fine`
    /// gives the relief below the grid over the triangle, if it shows.
    #[inline]
    pub(crate) fn or_plain(
        v: [Fixed2; 3],
        colours: [u32; 3],
        heights: [f32; 3],
        strengths: [f32; 3],
        tone: impl FnOnce(f32, f32) -> Option<T>,
        fine: impl FnOnce(&Gradient) -> Option<Fine<G>>,
    ) -> Fill<T, G> {
        let gradient = Gradient::new(v);
        let blend = Blend::over(&gradient, colours);
        let fine = fine(&gradient);
        let q = [0, 1, 2].map(|i| Vec2::new(heights[i], strengths[i]));
        let (dx, dy) = gradient.slopes(q[1] - q[0], q[2] - q[0]);
        let per_pixel = dx.x.abs().max(dy.x.abs());
        let hi = q[0].max(q[1]).max(q[2]);
        let Some(tone) = tone(per_pixel, hi.y) else {
            return match fine {
                Some(fine) => Fill::Fine(blend, fine),
                None => Fill::Plain(blend),
            };
        };
        Fill::Banded(Banded {
            blend,
            at0: q[0],
            dx,
            dy,
            lo: q[0].min(q[1]).min(q[2]),
            hi,
            origin: gradient.origin,
            tone,
            fine,
        })
    }

    /// Row `y`'s start, for [`Banded::at`].
    #[inline]
    pub(crate) fn row(&self, y: u32) -> BandedRow {
        let oy = y as f32 + 0.5 - self.origin[1];
        (self.blend.row(y), self.at0 + self.dy * oy)
    }

    /// The packed colour at the centre of pixel `x` of a row, `fine`
    /// times as bright (the relief below the grid's factor there, 1
    /// without it).
    #[inline(always)]
    pub(crate) fn at(&self, row: &BandedRow, x: u32, fine: f32) -> u32 {
        let colour = self.blend.lanes_at(&row.0, x);
        let ox = x as f32 + 0.5 - self.origin[0];
        let q = (row.1 + self.dx * ox).max(self.lo).min(self.hi);
        let gain = 1.0 + q.y * self.tone.tone(q.x);
        // Without the relief the factor is the strata's alone, as before it.
        let gain = if fine == 1.0 { gain } else { gain * fine };
        packed_lanes(lighter(colour, gain))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::base::fixed::to_fixed;
    use crate::render::scan::fine::LANES;

    #[test]
    fn no_strength_is_the_plain_blend_and_full_strength_the_tone() {
        let v = [to_fixed(0.5, 0.5), to_fixed(20.5, 0.5), to_fixed(0.5, 20.5)];
        let colours = [0x404040, 0x606060, 0x505050];
        let plain = Blend::new(v, colours);
        let banded = |strength: f32, tone: fn(f32) -> f32| match Banded::or_plain(
            v,
            colours,
            [0.0, 0.0, 20.0],
            [strength; 3],
            |_, _| Some(tone),
            |_| None::<Fine<fn([Vec4; LANES]) -> Vec4>>,
        ) {
            Fill::Banded(b) => b,
            _ => panic!("not banded"),
        };
        let none = banded(0.0, |_| 1.0);
        let full = banded(0.5, |h| if h < 10.0 { 0.5 } else { -0.5 });
        for y in 0..20 {
            for x in 0..20 - y {
                let c = plain.at(&plain.row(y), x);
                assert_eq!(none.at(&none.row(y), x, 1.0), c);
                let g = (c & 0xff) as f32;
                let want = if (y as f32 + 0.5) < 10.0 { 1.25 } else { 0.75 };
                let got = (full.at(&full.row(y), x, 1.0) & 0xff) as f32;
                assert!((got - (g * want).round()).abs() <= 1.0, "({x}, {y}): {got}");
            }
        }
    }

    #[test]
    fn a_faces_held_spans_set_what_its_spans_would_and_keep_what_is_written() {
        let v = [to_fixed(0.5, 0.5), to_fixed(90.5, 0.5), to_fixed(0.5, 30.5)];
        let colours = [0x806040, 0x406080, 0x608040];
        // A factor of each pixel's own position.
        let gain = |q: [Vec4; LANES]| {
            Vec4::from_array((q[0] * 0.37 + q[1] * 1.3).to_array().map(f32::sin)) * 0.3 + 1.0
        };
        let fine = |gradient: &Gradient| {
            let mut q = [[0.0; LANES]; 3];
            (q[1][0], q[2][1]) = (90.0, 30.0);
            Fine::new(gradient, q, gain)
        };
        // The relief alone, and with the strata's bands across the face.
        let tone: fn(f32) -> f32 = |h| if h < 10.0 { 0.5 } else { -0.5 };
        let fill = |banded: bool| match banded {
            false => Fill::Fine(Blend::new(v, colours), fine(&Gradient::new(v))),
            true => Banded::or_plain(
                v,
                colours,
                [0.0, 0.0, 20.0],
                [0.3; 3],
                |_, _| Some(tone),
                |g| Some(fine(g)),
            ),
        };
        assert!(matches!(
            fill(true),
            Fill::Banded(Banded { fine: Some(_), .. })
        ));
        for banded in [false, true] {
            held_spans_match(&fill(banded), || fill(banded));
        }
    }

    /// A face filled span by span (`plain`) and by [`FaceFill`] (`fill()`)
    /// sets the same pixels, and the latter keeps what was written before
    /// on a first-write canvas.
    fn held_spans_match<T: Tone, G: Gain>(plain: &Fill<T, G>, fill: impl Fn() -> Fill<T, G>) {
        // Short spans and long ones, as a face's rows come.
        let spans: Vec<(u32, u32, u32)> = (0..30)
            .map(|y| {
                (
                    y,
                    (y * 7) % 5,
                    (y * 7) % 5 + [1, 3, 2, 70, 5][y as usize % 5],
                )
            })
            .collect();
        let (w, h) = (96, 32);
        let mut direct = vec![0u32; w * h];
        let mut canvas = Canvas::new(&mut direct, w as u32, 0);
        for &(y, x0, x1) in &spans {
            plain.fill(&mut canvas, y, x0, x1);
        }
        let mut held = vec![0u32; w * h];
        let mut canvas = Canvas::new(&mut held, w as u32, 0);
        let mut face = FaceFill::new(fill());
        for &(y, x0, x1) in &spans {
            face.fill(&mut canvas, y, x0, x1);
        }
        face.finish(&mut canvas);
        assert_eq!(held, direct);
        // Front to back: what nearer land wrote stays.
        let mut first = vec![0u32; w * h];
        let mut canvas = Canvas::new(&mut first, w as u32, 0).keeping_first();
        for y in (0..30).step_by(3) {
            canvas.fill(y, 2, 4 + y % 7, 0x123456);
        }
        let mut face = FaceFill::new(fill());
        for &(y, x0, x1) in &spans {
            face.fill(&mut canvas, y, x0, x1);
        }
        face.finish(&mut canvas);
        for &(y, x0, x1) in &spans {
            for x in x0..x1 {
                let i = y as usize * w + x as usize;
                let nearer = y % 3 == 0 && (2..4 + y % 7).contains(&x);
                let want = if nearer { 0x123456 } else { direct[i] };
                assert_eq!(first[i] & 0xffffff, want & 0xffffff, "({x}, {y})");
            }
        }
    }

    #[test]
    fn the_tone_is_told_the_height_a_pixel_spans_and_the_strongest_band() {
        let v = [to_fixed(0.0, 0.0), to_fixed(10.0, 0.0), to_fixed(0.0, 10.0)];
        let mut told = (0.0, 0.0);
        let fill = Banded::or_plain(
            v,
            [0; 3],
            [0.0, 5.0, 20.0],
            [0.5, 0.25, 0.0],
            |p, s| {
                told = (p, s);
                None::<fn(f32) -> f32>
            },
            |_| None::<Fine<fn([Vec4; LANES]) -> Vec4>>,
        );
        assert!(matches!(fill, Fill::Plain(_)), "no tone: blended plain");
        assert!((told.0 - 2.0).abs() < 1e-5, "{told:?}");
        assert_eq!(told.1, 0.5);
    }
}

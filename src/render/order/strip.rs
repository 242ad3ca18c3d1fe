//! One strip of filled faces: two triangles per cell, split at the water
//! line, with the cut faces (skirts) of the right and front edges.

use glam::{Vec2, Vec3};

use super::mirrored::Streak;
use crate::render::base::canvas::Canvas;
use crate::render::base::colour::blend_packed;
use crate::render::base::colour::mix_packed;
use crate::render::base::fixed::{Fixed2, SUBPIXEL};
use crate::render::scan::banded::{Banded, FaceFill, Fill};
use crate::render::scan::blend::Blend;
use crate::render::scan::fine::Fine;
use crate::render::scan::gradient::Gradient;
use crate::render::scan::outline::{Crossing, Whole};
use crate::render::scan::raster::{Triangle, centre_box};
use crate::render::scan::shore::{ShoreLine, ShorePoint};
use crate::render::scene::{Scene, Style, Vert};
use crate::render::shade::dither;
use crate::render::shade::mirror::{Mirror, Mirrored};
use crate::render::shade::relief::{FinePoint, Relief};
use crate::render::shade::strata::{RockStrata, Sampler};

/// White and black, the only two colours of Mono.
const WHITE: u32 = 0x00ff_ffff;
const BLACK: u32 = 0;

/// How a face's pixels are set.
#[derive(Clone, Copy)]
enum Paint {
    Solid(u32),
    Dither(u8),
}

/// A triangle corner: grid position, true height, screen position, light.
#[derive(Clone, Copy)]
pub(super) struct Corner {
    pub(super) g: Vec2,
    pub(super) h: f32,
    /// The water surface over the corner (see `Vert::w`).
    pub(super) w: f32,
    pub(super) p: Fixed2,
    pub(super) lit: f32,
    pub(super) sky: f32,
    /// Where water runs here (see `Vert::wet`).
    pub(super) wet: f32,
    pub(super) haze: u32,
    /// Under smooth shading, the land's colour here.
    pub(super) colour: u32,
    /// Under smooth shading, how strongly the rock's strata show here.
    pub(super) rock: f32,
    /// Under smooth shading, what the relief below the grid needs here.
    pub(super) fine: FinePoint,
    /// Outside the land (see `Vert::off`).
    pub(super) off: bool,
    /// Whether `lit` and `sky` are worked out (see `Vert::lit_known`): a
    /// land face's corners always are.
    pub(super) lit_known: bool,
}

impl Corner {
    fn at(x: usize, y: usize, v: &Vert) -> Self {
        Corner {
            g: Vec2::new(x as f32, y as f32),
            h: v.h,
            w: v.w,
            p: v.p,
            lit: v.lit,
            sky: v.sky,
            wet: v.wet,
            haze: v.haze,
            colour: v.colour,
            rock: v.rock,
            fine: v.fine,
            off: v.off,
            lit_known: v.lit_known,
        }
    }
}

impl ShorePoint for Corner {
    fn screen(&self) -> Fixed2 {
        self.p
    }
    fn land(&self) -> u32 {
        self.colour
    }
}

/// The widest and tallest a water cell drawn in one colour under smooth
/// shading may be on the screen (see `fill_water_cell`): 2 px, fixed point.
const SMALL: i64 = 2 * SUBPIXEL;

/// Whether a cell of screen corners `p` is at most [`SMALL`] wide and tall.
fn small(p: [Fixed2; 4]) -> bool {
    let span = |i: usize| {
        let lo = p.iter().map(|q| q[i]).min().unwrap_or(0);
        let hi = p.iter().map(|q| q[i]).max().unwrap_or(0);
        hi - lo
    };
    span(0) <= SMALL && span(1) <= SMALL
}

/// A grid triangle's corners, in drawing order.
pub(super) type Face<'c> = [&'c Corner; 3];

/// A strip's two projected grid rows: `y` are their grid rows, back first.
struct StripRows<'r> {
    y: [usize; 2],
    top: &'r mut [Vert],
    bottom: &'r mut [Vert],
}

impl StripRows<'_> {
    /// The corners at column `x` of the back and the front row, their
    /// points shaded first, each once: lit if `land` (a land face may touch
    /// them) or the water mirrors, coloured if `land` under smooth shading
    /// (see [`Scene::shade`]).
    #[inline(always)]
    fn column(&mut self, scene: &Scene, x: usize, land: bool) -> [Corner; 2] {
        let [y0, y1] = self.y;
        scene.shade(&mut self.top[x], x, y0, land);
        scene.shade(&mut self.bottom[x], x, y1, land);
        [
            Corner::at(x, y0, &self.top[x]),
            Corner::at(x, y1, &self.bottom[x]),
        ]
    }
}

impl Scene<'_> {
    /// Draws `cells` of strip `s` filled, in drawing order, then the skirts
    /// below them. `top` and `bottom` are grid rows `s` and `s + 1`,
    /// projected at least at the points of `cells`; their points are shaded
    /// as drawn faces need them.
    pub(crate) fn fill_strip(
        &self,
        canvas: &mut Canvas,
        s: usize,
        cells: std::ops::Range<usize>,
        top: &mut [Vert],
        bottom: &mut [Vert],
    ) {
        let last = self.cells();
        let (y0, y1) = self.strip_grid_rows(s);
        let split = self.split.clamp(cells.start, cells.end);
        let mut rows = StripRows {
            y: [y0, y1],
            top,
            bottom,
        };
        let part = |canvas: &mut Canvas, part: usize| match part {
            0 => painter_order(canvas, cells.start..split, |c, x| {
                self.fill_cell(c, &mut rows, x, true)
            }),
            1 => painter_order(canvas, (split..cells.end).rev(), |c, x| {
                self.fill_cell(c, &mut rows, x, false)
            }),
            2 if self.sees_right && cells.end == last => {
                let [a, b] = rows.column(self, last, false);
                self.fill_skirt(canvas, a, b, Vec3::X);
            }
            3 if self.sees_front && s + 1 == self.strips() => {
                painter_order(canvas, cells.clone(), |canvas, x| {
                    let [_, a] = rows.column(self, x, false);
                    let [_, b] = rows.column(self, x + 1, false);
                    self.fill_skirt(canvas, a, b, Vec3::NEG_Y);
                });
            }
            _ => {}
        };
        painter_order(canvas, 0..4, part);
    }

    /// The two triangles of the cell at column `x` of `rows`, the farther
    /// one first. With the camera to the right (`rightward`) the diagonal
    /// runs from the back right, so the front-right triangle is the nearer;
    /// mirrored otherwise. The oblique view splits as seed 000's listing
    /// does (`DrawTriangle(x,y, x,y+1, x+1,y+1)` and `(x,y, x+1,y+1,
    /// x+1,y)`): from the back left, the short diagonal of its
    /// parallelogram's cells, so its faces are the triangle generator's
    /// own. The listing paints the front-left face first; we paint it
    /// last, as it is the nearer (faces turned away are skipped, so the
    /// two orders differ in no pixel of a face turned to the viewer).
    fn fill_cell(&self, canvas: &mut Canvas, rows: &mut StripRows, x: usize, rightward: bool) {
        let (top, bottom) = (&rows.top, &rows.bottom);
        let v = [&top[x], &top[x + 1], &bottom[x], &bottom[x + 1]];
        // A cell wholly outside the land (the essay's turned square).
        if self.holes() && v.iter().all(|v| v.off) {
            return;
        }
        // A cell crossing the water line puts its shore points on the
        // water's plane, possibly outside its corners' box: never skip those.
        let crosses = v.iter().any(|v| v.h < v.w) && v.iter().any(|v| v.h > v.w);
        // A cell on the land's edge is cut along the square's side, whose
        // corners may lie outside its own corners' box.
        let cut = self.holes() && v.iter().any(|v| v.off);
        let corners = [top[x].p, top[x + 1].p, bottom[x].p, bottom[x + 1].p];
        if !crosses && !cut {
            match centre_box(corners, canvas.clip()) {
                Some([x0, x1, y0, _]) if !canvas.hidden(x0, x1, y0) => {}
                _ => return,
            }
        }
        // Each corner at or under its water: every face is water, which
        // needs no corner colours (nor light, unless it mirrors). A cut
        // cell's pieces take their heights from the square's side, which
        // may stand above the water its corners lie under.
        let land = cut || !v.iter().all(|v| v.h <= v.w);
        // Every corner under one surface: the water of one lake, or the sea.
        let one_water = !land && v.iter().all(|k| k.w == v[0].w);
        let surface = v[0].w;
        // Every corner above every corner's water: both faces are land.
        let top_water = v.iter().fold(f32::NEG_INFINITY, |w, v| w.max(v.w));
        let dry = v.iter().all(|v| v.h > top_water);
        let [tl, bl] = rows.column(self, x, land);
        let [tr, br] = rows.column(self, x + 1, land);
        let [far, near] = match self.eye {
            Some(eye) => split_by_heights(eye, [&tl, &tr, &bl, &br]),
            None if rightward && !self.listing_diagonal => [[&tl, &tr, &bl], [&tr, &br, &bl]],
            None => [[&tl, &tr, &br], [&tl, &br, &bl]],
        };
        // The farther face first (reversed on a canvas keeping the first
        // write), each drawn the way the cell's kind needs.
        let faces = [far, near].into_iter();
        if cut {
            // On the edge of the land: each face's part inside the square.
            return painter_order(canvas, faces, |canvas, face| match &self.outline {
                _ if face.iter().all(|c| c.off) => {}
                Some(outline) if face.iter().any(|c| c.off) => self.fill_cut(canvas, outline, face),
                _ if face.iter().all(|c| !c.off) => self.fill_face(canvas, face),
                _ => {}
            });
        }
        if one_water && self.mirror.is_some() {
            return self.fill_water_cell(canvas, rows, x, [&tl, &tr, &bl, &br], faces);
        }
        painter_order(canvas, faces, |canvas, face| {
            if one_water {
                // Water under one surface: `fill_face`'s choice made.
                self.fill_water(canvas, face, surface);
            } else if dry && self.smooth() {
                // Land alone: the corners blended, without `fill_face`'s
                // look for water.
                self.fill_smooth_land(canvas, face);
            } else {
                self.fill_face(canvas, face);
            }
        });
    }

    /// One grid triangle: water, land, or both split at the water line
    /// (seed 000's DrawTriangle). The face's water is a lake's where a
    /// corner lies under one (its other corners then stand at or above the
    /// lake's lip), else the sea's.
    pub(super) fn fill_face(&self, canvas: &mut Canvas, c: Face) {
        let level = c[0].w.max(c[1].w).max(c[2].w);
        let wet = c.map(|k| k.h < level);
        if c.iter().all(|k| k.h <= level) {
            self.fill_water(canvas, c, level);
        } else if !wet.iter().any(|&w| w) {
            self.fill_land(canvas, c, || self.face_normal(&c), lit_of(&c));
        } else {
            self.fill_split(canvas, c, wet, level);
        }
    }

    /// A triangle crossing the water line (at `level`), cut into its land
    /// and water parts.
    fn fill_split(&self, canvas: &mut Canvas, c: Face, wet: [bool; 3], level: f32) {
        // `odd` is the corner alone on its side; keep the winding of `c`.
        let odd = if wet[0] != wet[1] && wet[0] != wet[2] {
            0
        } else if wet[1] != wet[0] {
            1
        } else {
            2
        };
        let a = c[odd];
        let (s0, s1) = (c[(odd + 1) % 3], c[(odd + 2) % 3]);
        let m0 = self.shore(a, s0, level);
        let m1 = self.shore(a, s1, level);
        let normal = self.face_normal(&c);
        let lit = lit_of(&c);
        // The odd corner's part first, then the other side's two: the
        // quadrilateral cut from `m0` to `s1`, or, as seed 000's listing
        // cuts it (its corners in the other winding), from `m1` to `s0`.
        // Each part has its own colour (its own mean height).
        let parts = if self.listing_cuts {
            [[a, &m0, &m1], [&m1, s0, s1], [&m1, &m0, s0]]
        } else {
            [[a, &m0, &m1], [&m0, s0, s1], [&m0, s1, &m1]]
        };
        let coast = self.clean_edges.then(|| ShoreLine::new(&m0, &m1)).flatten();
        painter_order(
            canvas,
            parts.into_iter().enumerate(),
            |canvas, (i, part)| {
                let water = (i == 0) == wet[odd];
                let Some(coast) = &coast else {
                    return if water {
                        self.fill_water(canvas, part, level);
                    } else {
                        self.fill_land(canvas, part, || normal, lit);
                    };
                };
                if !water && faces_away([part[0].p, part[1].p, part[2].p]) {
                    return;
                }
                // The part across the shore line from this one.
                let across = parts[if i == 0 { 2 } else { 0 }];
                self.paint_pixels(canvas, part.map(|k| k.p), || {
                    let (own, other) = if water {
                        (
                            Side::One(self.water_colour(&part, level)),
                            self.land_side(&across, normal, lit),
                        )
                    } else {
                        (
                            self.land_side(&part, normal, lit),
                            Side::One(self.water_colour(&across, level)),
                        )
                    };
                    move |x, y| {
                        let (own, other) =
                            (own.at(x, y, coast, false), other.at(x, y, coast, true));
                        blend_packed(own, other, coast.weight(x, y))
                    }
                });
            },
        );
    }

    /// Where the edge from `a` to `b` (one wet, one dry) meets the water
    /// surface at `level` (sea level, or a lake's).
    fn shore(&self, a: &Corner, b: &Corner, level: f32) -> Corner {
        let f = (a.h - level) / (a.h - b.h);
        let g = a.g + (b.g - a.g) * f;
        Corner {
            g,
            h: level,
            w: level,
            p: self.project_water(g, level),
            lit: a.lit + (b.lit - a.lit) * f,
            sky: a.sky + (b.sky - a.sky) * f,
            wet: a.wet + (b.wet - a.wet) * f,
            haze: (a.haze as f32 + (b.haze as f32 - a.haze as f32) * f) as u32,
            colour: mix_packed(a.colour, b.colour, f),
            rock: a.rock + (b.rock - a.rock) * f,
            fine: a.fine.lerp(&b.fine, f),
            off: false,
            lit_known: a.lit_known && b.lit_known,
        }
    }

    /// Upward unit normal of a grid triangle, in the palette's frame (z up,
    /// y towards the back), of the parallelogram when the normals are
    /// sheared (the classic light in the oblique view).
    fn face_normal(&self, c: &Face) -> Vec3 {
        let cell = self.view.cell();
        let shear = self.normal_shear;
        // The heights as the view draws them (seed 000's relief in its look).
        let relief = self.view.relief();
        let world =
            |k: &Corner| Vec3::new((k.g.x - shear * k.g.y) * cell, -k.g.y * cell, k.h * relief);
        let (p0, p1, p2) = (world(c[0]), world(c[1]), world(c[2]));
        let n = (p1 - p0).cross(p2 - p0);
        let n = if n.z < 0.0 { -n } else { n };
        n.try_normalize().unwrap_or(Vec3::Z)
    }

    /// A land triangle; `normal` is only called if a pixel is covered.
    ///
    /// Faces turned away from the viewer are skipped: seen from above, the
    /// first surface a sight line meets always faces it (or is a skirt), so
    /// those faces would only be painted over. On rugged ground that is a
    /// good share of the triangles, and the tallest, thinnest ones.
    fn fill_land(&self, canvas: &mut Canvas, c: Face, normal: impl FnOnce() -> Vec3, lit: f32) {
        if self.smooth() {
            return self.fill_smooth_land(canvas, c);
        }
        if faces_away([c[0].p, c[1].p, c[2].p]) {
            return;
        }
        self.paint(canvas, [c[0].p, c[1].p, c[2].p], || {
            self.land_colour(&c, normal(), lit)
        });
    }

    /// A land triangle under smooth shading ([`Scene::fill_land`]'s).
    #[inline(always)]
    fn fill_smooth_land(&self, canvas: &mut Canvas, c: Face) {
        if faces_away([c[0].p, c[1].p, c[2].p]) {
            return;
        }
        let v = [c[0].p, c[1].p, c[2].p];
        // Whether the relief shows is decided once a face.
        let relief = self.fine_relief(&c);
        if self.rock(&c).is_none() && relief.is_none() {
            return self.paint_blend(canvas, v, [c[0].colour, c[1].colour, c[2].colour]);
        }
        if relief.is_none() {
            return paint_spans(
                canvas,
                v,
                || self.land_fill(&c, None),
                |canvas, f, y, x0, x1| f.fill(canvas, y, x0, x1),
            );
        }
        paint_spans_then(
            canvas,
            v,
            || FaceFill::new(self.land_fill(&c, relief)),
            |canvas, f, y, x0, x1| f.fill(canvas, y, x0, x1),
            |canvas, f| f.finish(canvas),
        );
    }

    /// The land face `c` under smooth shading: its corners blended, with
    /// the rock's strata across it where they show and `relief` (the
    /// relief below the grid, where [`Scene::fine_relief`] says it shows).
    fn land_fill<'s>(&'s self, c: &Face, relief: Option<&'s Relief>) -> LandFill<'s> {
        if let Some(strata) = self.rock(c) {
            return banded(strata, c, relief);
        }
        let gradient = Gradient::new(c.map(|k| k.p));
        let blend = Blend::over(&gradient, c.map(|k| k.colour));
        match relief {
            Some(r) => Fill::Fine(blend, fine(&gradient, c, r)),
            None => Fill::Plain(blend),
        }
    }

    /// The relief below the grid, if it can show on the land face `c`
    /// ([`Relief::shows`]: its largest cells span enough pixels for the
    /// first level, and its corners are light and rough enough).
    #[inline]
    fn fine_relief(&self, c: &Face) -> Option<&Relief> {
        self.relief
            .as_ref()
            .filter(|r| r.shows(c.map(|k| &k.fine), c.map(|k| k.colour)))
    }

    /// The strata, if the land face `c` shows them (a corner on steep rock).
    #[inline]
    fn rock(&self, c: &Face) -> Option<&RockStrata> {
        self.strata
            .as_ref()
            .filter(|_| c.iter().any(|k| k.rock > 0.0))
    }

    /// The one colour of a land face (flat shading).
    fn land_colour(&self, c: &Face, normal: Vec3, lit: f32) -> u32 {
        debug_assert!(
            c.iter().all(|k| k.lit_known),
            "a land face's corner is unlit"
        );
        let mean = (c[0].h + c[1].h + c[2].h) / 3.0;
        let sky = (c[0].sky + c[1].sky + c[2].sky) / 3.0;
        let wet = (c[0].wet + c[1].wet + c[2].wet) / 3.0;
        let land = self.palette.land_in(mean.max(0.0), normal, lit, sky, wet);
        self.hazed_face(land, c)
    }

    /// How the land part `c` of a face crossing the shore is coloured next
    /// to the shore line: its corners blended (smooth shading, where the
    /// land beside a water pixel is the shore line's own colour), or one
    /// colour.
    fn land_side(&self, c: &Face, normal: Vec3, lit: f32) -> Side<'_> {
        if self.smooth() {
            Side::Land(Box::new(self.land_fill(c, self.fine_relief(c))))
        } else {
            Side::One(self.land_colour(c, normal, lit))
        }
    }

    fn fill_water(&self, canvas: &mut Canvas, c: Face, level: f32) {
        self.paint(canvas, [c[0].p, c[1].p, c[2].p], || {
            self.water_colour(&c, level)
        });
    }

    /// A cell all under one water surface, in a scene with a mirror,
    /// worked out once a pixel is covered. Under smooth shading its faces
    /// blend what the water at its corners shows (each its own depth,
    /// streak and mirror, kept by the corner for the cells around it), and
    /// the mirrored outline of the land against the sky runs across them
    /// where the corners' margins say (`scan::outline`): one colour a cell
    /// drew that outline as a staircase of cells, steps several pixels long
    /// near the viewer at 4K. The sun's glitter stays a cell's: a facet of
    /// the streaked water that sparkles, not a blur between corners. Flat
    /// shading keeps one colour a cell, its middle's. Plain water (the
    /// classic looks, `reflections = false`) keeps a colour a face.
    /// A cell at most [`SMALL`] wide and tall keeps one colour too: its
    /// steps are that small, and most of the far water's cells cover a
    /// pixel or none, so that a look a corner would cost up to four times
    /// the looks a cell. `c` are the cell's corners `[tl, tr, bl, br]` at
    /// column `x` of `rows`, `faces` its faces, the farther first.
    fn fill_water_cell<'c>(
        &self,
        canvas: &mut Canvas,
        rows: &mut StripRows,
        x: usize,
        c: [&Corner; 4],
        faces: impl DoubleEndedIterator<Item = Face<'c>>,
    ) {
        let level = c[0].w;
        let blended = self.smooth() && !small(c.map(|k| k.p));
        let (Some(mirror), true) = (&self.mirror, blended) else {
            let mut colour = None;
            let mut once = || *colour.get_or_insert_with(|| self.water_colour(&c, level));
            return painter_order(canvas, faces, |canvas, f| {
                self.paint(canvas, [f[0].p, f[1].p, f[2].p], &mut once)
            });
        };
        let mut looks = None;
        let mut look = || {
            *looks.get_or_insert_with(|| {
                let kept = |v: &mut Vert, k: &Corner| {
                    *(v.water).get_or_insert_with(|| self.water_at(mirror, k, level))
                };
                let sides = [
                    kept(&mut rows.top[x], c[0]),
                    kept(&mut rows.top[x + 1], c[1]),
                    kept(&mut rows.bottom[x], c[2]),
                    kept(&mut rows.bottom[x + 1], c[3]),
                ];
                let (g, lit) = middle(&c);
                let near_sun = sides.iter().find_map(|w| w.near_sun);
                (sides, self.glitter(mirror, near_sun, g, lit))
            })
        };
        painter_order(canvas, faces, |canvas, f| {
            self.paint_mirrored(canvas, [f[0].p, f[1].p, f[2].p], || {
                let (sides, glint) = look();
                let of = |k: &Corner| {
                    let at = c.iter().position(|&ck| std::ptr::eq(ck, k));
                    sides[at.expect("a face's corner is one of its cell's")]
                };
                ([of(f[0]), of(f[1]), of(f[2])], glint)
            })
        });
    }

    /// The water at corner `k`, under a surface at `level`, with what it
    /// mirrors on each side of the mirrored outline.
    fn water_at(&self, mirror: &Mirror, k: &Corner, level: f32) -> Mirrored {
        let (water, streak) = self.water_own(&[k], level);
        self.mirrored_sides(mirror, water, (k.g, level), streak)
    }

    /// The colour of the water over corners `c` (a face's, or a cell's)
    /// under a surface at `level`: by their mean depth below it, with the
    /// wind's streak at their middle, and what it mirrors there.
    fn water_colour(&self, c: &[&Corner], level: f32) -> u32 {
        let (water, streak) = self.water_own(c, level);
        let Some(mirror) = &self.mirror else {
            return water;
        };
        let (g, lit) = middle(c);
        self.mirrored(mirror, water, (g, level), streak, lit)
    }

    /// The water's own colour over corners `c` under a surface at `level`
    /// (by their mean depth below it, hazed, with the wind's streak at
    /// their middle), and the streak.
    fn water_own(&self, c: &[&Corner], level: f32) -> (u32, Streak) {
        let n = c.len() as f32;
        let depth = -c.iter().map(|k| (k.h - level).min(0.0)).sum::<f32>() / n;
        let g = c.iter().map(|k| k.g).sum::<Vec2>() / n;
        let haze = c.iter().map(|k| k.haze).sum::<u32>() / c.len() as u32;
        let water = self.palette.water(depth);
        let (water, streak) = match &self.ripples {
            Some(r) => {
                let mirrored = self.mirror.is_some();
                let [fine, tilt] = self.streak_shares(g, level, r.finer_rows(), mirrored);
                let ripple = r.value_seen(g.x, g.y, fine);
                (r.with(water, ripple), Streak { ripple, tilt })
            }
            None => (
                water,
                Streak {
                    ripple: 0.0,
                    tilt: 1.0,
                },
            ),
        };
        (self.hazed(water, haze), streak)
    }

    /// The cut face below the edge from `a` to `b`, down to sea level, facing
    /// `normal` (palette frame). Wet parts of the edge have no face.
    fn fill_skirt(&self, canvas: &mut Canvas, a: Corner, b: Corner, normal: Vec3) {
        let foot = |k: Corner| Corner {
            p: self.project_sea(k.g),
            h: 0.0,
            ..k
        };
        let (a, b) = match (a.h > 0.0, b.h > 0.0) {
            (false, false) => return,
            (true, true) => (a, b),
            (true, false) => (a, self.shore(&a, &b, 0.0)),
            (false, true) => (self.shore(&a, &b, 0.0), b),
        };
        let (fa, fb) = (foot(a), foot(b));
        let colour = self.hazed_face(self.palette.skirt(normal), &[&a, &b, &fa]);
        let halves = [[a.p, b.p, fb.p], [a.p, fb.p, fa.p]];
        painter_order(canvas, halves.into_iter(), |canvas, v| {
            self.paint(canvas, v, || colour)
        });
    }

    /// `colour` faded by the air between the viewer and the face's corners.
    #[inline]
    fn hazed_face(&self, colour: u32, c: &Face) -> u32 {
        self.hazed(colour, (c[0].haze + c[1].haze + c[2].haze) / 3)
    }

    /// Fills one screen triangle with a colour (or its dither pattern in Mono).
    ///
    /// Most triangles of a fine grid cover no pixel centre at all, so the
    /// colour is only worked out once a first span turns up.
    fn paint(&self, canvas: &mut Canvas, v: [Fixed2; 3], colour: impl FnOnce() -> u32) {
        let make = || match self.style {
            Style::Mono => Paint::Dither(dither::lifted(
                dither::level(gray(colour())),
                self.mono_floor,
            )),
            _ => Paint::Solid(colour()),
        };
        paint_spans(canvas, v, make, |canvas, &mut paint, y, x0, x1| {
            Self::put(canvas, paint, y, x0, x1)
        });
    }

    /// Fills one screen triangle blending the colours of its corners across
    /// it (smooth shading); `colours` go with `v`'s corners.
    fn paint_blend(&self, canvas: &mut Canvas, v: [Fixed2; 3], colours: [u32; 3]) {
        let make = || Blend::new(v, colours);
        paint_spans(canvas, v, make, |canvas, b, y, x0, x1| {
            let row = b.row(y);
            canvas.fill_with(y, x0, x1, |x| b.at(&row, x));
        });
    }

    /// Fills one screen triangle of water under a mirror: `make()` gives
    /// its corners' water (see [`Mirrored`]) and the glitter over all of it
    /// (its colour and weight of 256), once a pixel is covered. Each side
    /// of the mirrored outline blends its corners' colours; the outline
    /// runs where the corners' margins cross 0, a pixel on it shared.
    fn paint_mirrored(
        &self,
        canvas: &mut Canvas,
        v: [Fixed2; 3],
        make: impl FnOnce() -> ([Mirrored; 3], Option<(u32, u32)>),
    ) {
        let make = || {
            let (sides, glint) = make();
            MirroredFace::new(v, sides, glint)
        };
        paint_spans(canvas, v, make, |canvas, face, y, x0, x1| {
            face.fill(canvas, y, x0, x1)
        });
    }

    /// Fills one screen triangle pixel by pixel with `make()`'s colour at
    /// each pixel (`make` runs once a first pixel is covered).
    fn paint_pixels<F: Fn(u32, u32) -> u32>(
        &self,
        canvas: &mut Canvas,
        v: [Fixed2; 3],
        make: impl FnOnce() -> F,
    ) {
        paint_spans(canvas, v, make, |canvas, f, y, x0, x1| {
            canvas.fill_with(y, x0, x1, |x| f(x, y))
        });
    }

    /// Sets one span of pixels.
    #[inline]
    fn put(canvas: &mut Canvas, paint: Paint, y: u32, x0: u32, x1: u32) {
        match paint {
            Paint::Solid(c) => canvas.fill(y, x0, x1, c),
            Paint::Dither(level) => canvas.fill_with(y, x0, x1, |x| {
                if dither::is_on(level, x, y) {
                    WHITE
                } else {
                    BLACK
                }
            }),
        }
    }
}

/// A triangle of water under a mirror, ready to fill (see
/// [`Scene::paint_mirrored`]).
struct MirroredFace {
    /// The land's side blended, and the sky's where the outline crosses
    /// the face.
    land: Blend,
    sky: Option<(Blend, Crossing)>,
    /// The glitter over it all: colour and weight of 256.
    glint: Option<(u32, u32)>,
}

impl MirroredFace {
    fn new(v: [Fixed2; 3], sides: [Mirrored; 3], glint: Option<(u32, u32)>) -> Self {
        let land = sides.map(|s| s.land);
        let sky = sides.map(|s| s.sky);
        if land == sky {
            return MirroredFace {
                land: Blend::new(v, land),
                sky: None,
                glint,
            };
        }
        let crossing = Crossing::new(v, sides.map(|s| s.margin));
        let (land, sky) = match crossing.whole(v) {
            Some(Whole::Above) => (Blend::new(v, sky), None),
            Some(Whole::Below) => (Blend::new(v, land), None),
            None => (Blend::new(v, land), Some((Blend::new(v, sky), crossing))),
        };
        MirroredFace { land, sky, glint }
    }

    /// Sets the pixels `x0..x1` of row `y`.
    #[inline]
    fn fill(&self, canvas: &mut Canvas, y: u32, x0: u32, x1: u32) {
        let land = &self.land;
        let row = land.row(y);
        let glint = |c: u32| match self.glint {
            Some((sun, w)) => blend_packed(c, sun, w),
            None => c,
        };
        match &self.sky {
            None => canvas.fill_with(y, x0, x1, |x| glint(land.at(&row, x))),
            Some((sky, crossing)) => {
                let (sky_row, at) = (sky.row(y), crossing.row(y));
                canvas.fill_with(y, x0, x1, |x| {
                    let c =
                        blend_packed(land.at(&row, x), sky.at(&sky_row, x), crossing.above(at, x));
                    glint(c)
                })
            }
        }
    }
}

/// How one side of a shore line is coloured at a pixel.
enum Side<'s> {
    /// One colour (water; land under flat shading).
    One(u32),
    /// The side's land under smooth shading (see [`Scene::land_fill`]);
    /// for a pixel across the line, the land's colour on the line itself.
    /// Boxed: its planes are many times a colour's size, and the faces
    /// crossing the shore are few.
    Land(Box<LandFill<'s>>),
}

impl Side<'_> {
    /// The colour at pixel (`x`, `y`), which lies on this side of `coast`
    /// or `across` it.
    #[inline]
    fn at(&self, x: u32, y: u32, coast: &ShoreLine, across: bool) -> u32 {
        match self {
            Side::One(c) => *c,
            Side::Land(_) if across => coast.land_at(x, y),
            Side::Land(f) => f.pixel(x, y),
        }
    }
}

/// How a land face is filled under smooth shading.
type LandFill<'s> = Fill<Sampler<'s>, &'s Relief>;

/// Calls `f` on each of `items` in the painter's order: as given, back to
/// front, on a canvas that keeps the last write; reversed on one that keeps
/// the first. Either way each pixel ends with the same colour.
pub(crate) fn painter_order<I: DoubleEndedIterator>(
    canvas: &mut Canvas,
    items: I,
    mut f: impl FnMut(&mut Canvas, I::Item),
) {
    if canvas.keeps_first() {
        items.rev().for_each(|i| f(canvas, i));
    } else {
        items.for_each(|i| f(canvas, i));
    }
}

/// A cell's two faces under smooth shading, the farther first: split along
/// the diagonal whose ends differ less in height, so that the split follows
/// the ridges and valleys rather than one direction of the grid (blended
/// colours show the split as a streak along it). Of two faces sharing an
/// edge, the one on the camera's side of it is the nearer. Corners
/// `[tl, tr, bl, br]`; each face's corners in `fill_cell`'s winding.
fn split_by_heights<'c>(eye: Vec2, c: [&'c Corner; 4]) -> [Face<'c>; 2] {
    let [tl, tr, bl, br] = c;
    // Each split: the diagonal's ends, the back face, the front face and
    // the front face's third corner.
    let (p, q, back, front, third) = if (tl.h - br.h).abs() < (tr.h - bl.h).abs() {
        (tl, br, [tl, tr, br], [tl, br, bl], bl)
    } else {
        (tr, bl, [tl, tr, bl], [tr, br, bl], br)
    };
    let side = |r: Vec2| (q.g - p.g).perp_dot(r - p.g);
    if side(eye) * side(third.g) > 0.0 {
        [back, front]
    } else {
        [front, back]
    }
}

/// Whether a grid triangle, its corners in `fill_cell`'s order, is seen
/// from behind: its screen winding is reversed (in y-down screen space the
/// corners of every face turned to the viewer run clockwise).
#[inline]
fn faces_away(p: [Fixed2; 3]) -> bool {
    // f64: the corners are not yet clamped, and only the sign matters.
    let d = |i: usize, k: usize| (p[i][k] - p[0][k]) as f64;
    d(1, 0) * d(2, 1) - d(1, 1) * d(2, 0) < 0.0
}

/// The land face `c` blended, with `strata` across it where they show
/// (smooth shading on steep rock): bands under half a level of colour at
/// their strongest are left out, as on far faces most of the rock's are.
/// With `relief`, the relief below the grid lights its pixels too.
#[inline]
fn banded<'s>(
    strata: &'s RockStrata,
    c: &Face,
    relief: Option<&'s Relief>,
) -> Fill<Sampler<'s>, &'s Relief> {
    Banded::or_plain(
        c.map(|k| k.p),
        c.map(|k| k.colour),
        c.map(|k| strata.bed_height(k.h, k.g)),
        c.map(|k| k.rock),
        |per_pixel, strongest| {
            let sampler = strata.sampler(per_pixel);
            (strongest * sampler.peak * 255.0 >= 0.5).then_some(sampler)
        },
        |gradient| relief.map(|r| fine(gradient, c, r)),
    )
}

/// The relief below the grid across the land face `c` of `gradient`.
#[inline]
fn fine<'r>(gradient: &Gradient, c: &Face, relief: &'r Relief) -> Fine<&'r Relief> {
    Fine::new(gradient, c.map(|k| k.fine.lanes(k.g, k.h)), relief)
}

/// Light on a face: the mean of its corners'.
fn lit_of(c: &Face) -> f32 {
    debug_assert!(
        c.iter().all(|k| k.lit_known),
        "a land face's corner is unlit"
    );
    (c[0].lit + c[1].lit + c[2].lit) / 3.0
}

/// Perceived brightness of a colour, 0-255.
fn gray(colour: u32) -> u32 {
    let (r, g, b) = ((colour >> 16) & 0xff, (colour >> 8) & 0xff, colour & 0xff);
    (r * 77 + g * 150 + b * 29) >> 8
}

/// The mean grid position of corners `c` and the mean share of the sun
/// that reaches them: where a cell's or a face's water looks from.
fn middle(c: &[&Corner]) -> (Vec2, f32) {
    let n = c.len() as f32;
    let g = c.iter().map(|k| k.g).sum::<Vec2>() / n;
    (g, c.iter().map(|k| k.lit).sum::<f32>() / n)
}

/// Calls `fill(canvas, state, y, x0, x1)` for each span of the screen
/// triangle `v` that can show (clipped to the canvas, not wholly behind
/// what is drawn), `state` made by `make()` once the first span turns up:
/// most triangles of a fine grid cover no pixel centre, and their colours
/// are never worked out.
#[inline(always)]
fn paint_spans<S>(
    canvas: &mut Canvas,
    v: [Fixed2; 3],
    make: impl FnOnce() -> S,
    fill: impl FnMut(&mut Canvas, &mut S, u32, u32, u32),
) {
    paint_spans_then(canvas, v, make, fill, |_, _| {});
}

/// [`paint_spans`], then `finish(canvas, state)` if the state was made
/// (to set what `fill` held back).
#[inline(always)]
fn paint_spans_then<S>(
    canvas: &mut Canvas,
    v: [Fixed2; 3],
    make: impl FnOnce() -> S,
    mut fill: impl FnMut(&mut Canvas, &mut S, u32, u32, u32),
    finish: impl FnOnce(&mut Canvas, &mut S),
) {
    let Some(t) = Triangle::new(v, canvas.clip()) else {
        return;
    };
    let [x0, x1, y0, _] = t.bounds();
    if canvas.hidden(x0, x1, y0) {
        return;
    }
    let mut make = Some(make);
    let mut state = None;
    t.spans(|y, x0, x1| {
        let s = state.get_or_insert_with(|| (make.take().expect("made once"))());
        fill(canvas, s, y, x0, x1);
    });
    if let Some(s) = &mut state {
        finish(canvas, s);
    }
}

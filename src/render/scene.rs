//! Everything fixed for one mountain in one frame size: the (turned) field,
//! the fitted view, colours, shadows and the drawing order within a strip.

use std::sync::Arc;

use glam::{Vec2, Vec3};

use super::base::colour::blend_packed;
use super::base::fixed::{Fixed2, to_fixed};
use super::base::size::Size;
use super::framing::easel;
use super::framing::tops::{RowTops, finite};
use super::framing::turn;
use super::framing::view::{Oblique, View, listing_relief};
use super::shade::clouds;
use super::shade::dither;
use super::shade::haze::Haze;
use super::shade::hour::SunAt;
use super::shade::mirror::{Mirror, Mirrored};
use super::shade::normals::Normals;
use super::shade::palette::Palette;
use super::shade::relief::{FinePoint, Relief};
use super::shade::ripples::Ripples;
use super::shade::shadow::{self, ShadowMap};
use super::shade::sky::Sky;
use super::shade::skylight::SkyLight;
use super::shade::stars::Stars;
use super::shade::strata::{self, RockStrata};
use super::shade::weather::Weather;
use crate::settings::{ColorMode, Look, Settings, Shading, ViewKind, worlds};
use crate::terrain::{Heightfield, Wetness};
use crate::threads::{both, both_if};

/// How faces are put on screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Style {
    /// Filled with the palette's shaded colours.
    Shaded,
    /// Filled with 1-bit ordered-dither patterns.
    Mono,
    /// Black faces with one-pixel white outlines.
    Sonar,
    /// Wire mesh only.
    Outline,
}

impl Style {
    /// Whether faces are filled (Shaded, Mono), not drawn as lines.
    pub(crate) fn is_filled(self) -> bool {
        matches!(self, Style::Shaded | Style::Mono)
    }

    /// The style a colour mode draws with (Ridges is handled elsewhere).
    pub(crate) fn of(mode: ColorMode) -> Self {
        match mode {
            // FL3's Filled mode: Sonar's filled and outlined cells in
            // its own colours (`Palette::fills`).
            ColorMode::Sonar | ColorMode::Filled => Style::Sonar,
            ColorMode::Outline => Style::Outline,
            ColorMode::Mono => Style::Mono,
            _ => Style::Shaded,
        }
    }
}

/// A grid point projected to the screen.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Vert {
    /// Screen position, drawn at sea level when the ground is below it.
    pub p: Fixed2,
    /// The ground's true height (finite).
    pub h: f32,
    /// The water surface over the point: sea level (0), or a lake's level
    /// where a lake is drawn over it.
    pub w: f32,
    /// Direct light reaching the point (0 until `lit_known`).
    pub lit: f32,
    /// Share of the sky the point sees (0 until `lit_known`).
    pub sky: f32,
    /// Where water runs at the point (`terrain::Wetness`; set with `sky`,
    /// where the palette follows it).
    pub wet: f32,
    /// How far the air has faded the point towards the horizon colour, in 1/256ths.
    pub haze: u32,
    /// Under smooth shading, the land's colour at the point (hazed).
    pub colour: u32,
    /// Under smooth shading, how strongly the rock's strata show at the
    /// point (0..=1 of `strata::DEPTH`: steep rock, less through haze).
    pub rock: f32,
    /// Under smooth shading with the finer relief, what the faces around
    /// the point need to light it (see [`Relief`]).
    pub fine: FinePoint,
    /// Whether `haze` is worked out (see [`Scene::shade`]).
    pub hazed: bool,
    /// Whether `lit` and `sky` are worked out (see [`Scene::shade`]).
    pub lit_known: bool,
    /// Whether `colour` is worked out (see [`Scene::shade`]).
    pub coloured: bool,
    /// Outside the land (the essay's turned square): cells touching it are
    /// cut along the square's side, and a cell of such points alone is not
    /// drawn.
    pub off: bool,
    /// Under a mirror and smooth shading, the water at the point, once a
    /// water cell drawn there needs it (see `fill_water_cell`).
    pub water: Option<Mirrored>,
}

/// How much of a colour faded `haze` (1/256ths) towards the horizon is
/// still its own.
#[inline]
fn clear(haze: u32) -> f32 {
    1.0 - haze.min(256) as f32 / 256.0
}

/// A field a scene draws: shared with a painter, or borrowed for one frame
/// (a full frame needs no copy of the caller's field).
pub(crate) enum FieldRef<'a> {
    Shared(Arc<Heightfield>),
    Borrowed(&'a Heightfield),
}

impl<'a> FieldRef<'a> {
    /// Another reference to the same field.
    fn again(&self) -> FieldRef<'a> {
        match self {
            FieldRef::Shared(f) => FieldRef::Shared(Arc::clone(f)),
            FieldRef::Borrowed(f) => FieldRef::Borrowed(f),
        }
    }
}

/// The essay's square as it was before the turn, the turn, and the scale
/// its heights are drawn at (see [`Heightfield::drawn`]).
pub(crate) struct Outline<'a> {
    pub square: FieldRef<'a>,
    pub turn: turn::Turn,
    pub scale: f32,
}

impl std::ops::Deref for FieldRef<'_> {
    type Target = Heightfield;

    fn deref(&self) -> &Heightfield {
        match self {
            FieldRef::Shared(f) => f,
            FieldRef::Borrowed(f) => f,
        }
    }
}

/// The fixed facts about drawing one mountain into one frame size.
pub(crate) struct Scene<'a> {
    pub field: FieldRef<'a>,
    pub view: View,
    pub palette: Palette,
    /// What is drawn behind the land.
    pub sky: Sky,
    /// Aerial haze, if the view has depth and the style has colours.
    pub haze: Option<Haze>,
    /// Wind on open water (the vista and perspective under a sun of the day).
    pub ripples: Option<Ripples>,
    shadow: Option<ShadowMap>,
    /// How much of the sky each point sees, if the look has sky light.
    skylight: Option<SkyLight>,
    /// Where water runs, if the world's cover follows it.
    wetness: Option<Wetness>,
    /// Each point's normal, when land is shaded smoothly (each point lit,
    /// the light blended across faces) or the water mirrors it.
    normals: Option<Normals>,
    /// Whether land faces blend their points' colours (else one colour a face).
    smooth: bool,
    /// Under smooth shading, the mountain's rock strata, drawn across its
    /// steep faces.
    pub(crate) strata: Option<RockStrata>,
    /// Under smooth shading in natural colours with a camera, the land's
    /// relief below the grid, lighting the pixels of near faces.
    pub(crate) relief: Option<Relief>,
    /// What the water mirrors: `None` without reflections (the key off,
    /// a look without ripples, a view without an eye).
    pub(crate) mirror: Option<Mirror>,
    /// Pixels a grid step would span were the grid as wide as the frame:
    /// the unit the mirror's streaks fade by (order/mirrored.rs), so that
    /// a frame and one drawn larger from the same grid (the quality
    /// figure's reference) fade the same water.
    pub(crate) frame_step: f32,
    /// Under smooth shading, where the camera stands over the ground (grid
    /// steps): each cell is split along the diagonal that suits its
    /// heights, and the camera's side of it says which face is nearer.
    pub eye: Option<Vec2>,
    pub style: Style,
    /// Whether the coast and the skyline are drawn anti-aliased (the
    /// shaded looks with depth; the classic looks keep their pixels).
    pub clean_edges: bool,
    /// Cells `0..split` of a row are drawn left to right, then the rest right
    /// to left, so faces nearer the camera's column overwrite farther ones.
    pub split: usize,
    /// Highest point of each row and of each block of it, at least sea level.
    pub(super) row_top: RowTops,
    /// The grid rows the mesh is drawn with (see `rows.rs`); strip `s` lies
    /// between rows `rows[s]` and `rows[s + 1]`.
    pub(super) rows: Vec<usize>,
    /// Whether the field's lakes are drawn (the filled looks; Sonar and
    /// Outline draw the ground's mesh).
    lakes: bool,
    /// The essay's square before it was turned, and the turn, when the
    /// field has points outside the land (NaN: the square turned): cells
    /// wholly outside are left undrawn, one on the land's edge is cut along
    /// the square's side (order/cut.rs).
    pub outline: Option<Outline<'a>>,
    /// Under the classic light, the shear of the parallelogram the oblique
    /// view draws (grid steps left per row forward; 0 otherwise): seed
    /// 000's listing lights the faces of its parallelogram, not of a square.
    pub normal_shear: f32,
    /// Whether cells are split on seed 000's diagonal, from the back left
    /// to the front right (the oblique view; its near-equilateral faces).
    pub listing_diagonal: bool,
    /// Whether a face crossing the water line is cut as seed 000's
    /// `DrawTriangle` cuts it (`look = "fractal-mountain-climbing"`): its
    /// land quadrilateral split from the crossing on the lone corner's
    /// edge to the next corner in the listing's winding, each part
    /// coloured by its own mean (order/strip.rs).
    pub listing_cuts: bool,
    /// Mono's darkest shade for a face (see [`dither::FACE_FLOOR`]): 0,
    /// the listing's solid black, only in seed 000's own look.
    pub mono_floor: u8,
    /// Whether the right and front cut faces (skirts) face the viewer.
    pub sees_right: bool,
    pub sees_front: bool,
}

impl<'a> Scene<'a> {
    /// Prepares `field` seen as `settings` ask, in a frame of `frame` size.
    pub(crate) fn new(field: FieldRef<'a>, settings: &Settings, frame: Size) -> Self {
        Self::at_hour(field, settings, frame, None)
    }

    /// [`Scene::new`] with the sun of `sun = "clock"` where `hour` puts it.
    pub(crate) fn at_hour(
        field: FieldRef<'a>,
        settings: &Settings,
        frame: Size,
        hour: Option<SunAt>,
    ) -> Self {
        // The world the mountain was made in: its keys and its colours.
        let settings = &worlds::drawn(settings, field.seed());
        let style = Style::of(settings.color);
        let (field, square, outline) = laid_out(field, settings, frame);
        let Start {
            row_top,
            view,
            rows,
            skylight,
            shadow,
            palette,
        } = Start::of(&field, settings, (style, square), frame, hour);
        let size = field.size();
        let wetness = palette.follows_water().then(|| Wetness::of(&field));
        let depth = Depth::of(settings, style, &palette, &field);
        let smooth = depth.smooth;
        let steep_ref = palette.steep_reference();
        let normals = (smooth || depth.reflections)
            .then(|| Normals::new(size, &rows, view.cell(), steep_ref));
        // The terraces' beds are level; others dip and fold.
        let strata = smooth.then(|| {
            let level = settings.cliffs > 0.0;
            RockStrata::new(field.seed().unwrap_or(0), field.extent(), size, level)
        });
        let relief = (smooth && settings.fine_relief && palette.coloured() && view.eye().is_some())
            .then(|| Relief::new(&field, field.identity(), palette.light(), view.cell()));
        let eye = view.camera_ground().filter(|_| smooth);
        let cells = size - 1;
        let sky = sky_of(&palette, &view, settings, &field, (style, &depth), frame);
        let mirror = view.eye().filter(|_| depth.reflections).and_then(|eye| {
            let light = palette.lighting();
            Mirror::new(&field, eye, view.cell(), light.sun, light.glints)
        });
        let lakes = style.is_filled() && field.lakes().is_some();
        let sides = Sides::of(settings, &view, &palette, cells);
        // A dry basin's sand and salt take no wind streaks (the weather
        // above was chosen with them).
        let ripples = depth.ripples.filter(|_| !palette.dry_basin());
        Scene {
            field,
            view,
            palette,
            sky,
            haze: depth.haze,
            ripples,
            shadow,
            skylight,
            wetness,
            normals,
            smooth,
            strata,
            relief,
            mirror,
            frame_step: frame.width as f32 / cells.max(1) as f32,
            eye,
            style,
            clean_edges: depth.clean_edges,
            split: sides.split,
            row_top,
            rows,
            lakes,
            outline,
            normal_shear: sides.normal_shear,
            listing_diagonal: sides.listing_diagonal,
            listing_cuts: sides.listing_cuts,
            mono_floor: sides.mono_floor,
            sees_right: sides.sees_right,
            sees_front: sides.sees_front,
        }
    }

    /// Lets go of what only the strips' faces read (the shadow and
    /// sky-light maps, wetness, normals, rock strata, the relief and the
    /// mirror) once every strip is drawn: the clean edges after them read
    /// the mesh's geometry and the sky. At 4K the mirror's profiles alone
    /// took 1.7 and 2.3 MB (seeds 1 and 5), held beside all the crests.
    pub(crate) fn let_go_of_faces(&mut self) {
        self.shadow = None;
        self.skylight = None;
        self.wetness = None;
        self.normals = None;
        self.strata = None;
        self.relief = None;
        self.mirror = None;
    }

    /// Whether the field has points outside the land (see
    /// [`Scene::outline`]).
    #[inline]
    pub(crate) fn holes(&self) -> bool {
        self.outline.is_some()
    }

    /// Cells per row.
    pub(crate) fn cells(&self) -> usize {
        self.field.size() - 1
    }

    /// Strips in the mesh: one between each two kept rows.
    pub(crate) fn strips(&self) -> usize {
        self.rows.len() - 1
    }

    /// The grid rows at the back and the front of strip `s`.
    #[inline]
    pub(crate) fn strip_grid_rows(&self, s: usize) -> (usize, usize) {
        (self.rows[s], self.rows[s + 1])
    }

    /// Projects points `xs` of grid row `y` into the same items of `out`
    /// (which holds a whole row); the rest of `out` is left as it was. Their
    /// light is left to [`Scene::shade`]: most points of hidden cells never
    /// need it.
    pub(crate) fn project_points(&self, y: usize, xs: std::ops::Range<usize>, out: &mut [Vert]) {
        let row = self.field.row(y);
        let line = self.view.along_row(y as f32);
        // Four points projected at once (RowView::project_few).
        let (mut xs_waiting, mut waiting) = ([0usize; 4], [[0.0f32; 2]; 4]);
        let mut n = 0;
        let project = |xs: &[usize], points: &[[f32; 2]], out: &mut [Vert]| {
            let [px, py] = line.project_few(points);
            for (k, &x) in xs.iter().enumerate() {
                out[x].p = to_fixed(px[k], py[k]);
            }
        };
        self.surfaces(y, xs, |x, w| {
            let h = finite(row[x]);
            out[x] = Vert {
                h,
                w,
                off: !row[x].is_finite(),
                ..Vert::default()
            };
            (xs_waiting[n], waiting[n]) = (x, [x as f32, h.max(w)]);
            n += 1;
            if n == 4 {
                project(&xs_waiting, &waiting, out);
                n = 0;
            }
        });
        project(&xs_waiting[..n], &waiting[..n], out);
    }

    /// Calls `f` with each point `x` of `xs` in grid row `y` and the water
    /// surface over it: a drawn lake's level, or the sea's 0. The drawn
    /// surface there is the higher of that and the ground.
    pub(crate) fn surfaces(
        &self,
        y: usize,
        xs: std::ops::Range<usize>,
        mut f: impl FnMut(usize, f32),
    ) {
        let lakes = self.field.lakes().filter(|_| self.lakes);
        let (Some(lakes), false) = (lakes, xs.is_empty()) else {
            xs.for_each(|x| f(x, 0.0));
            return;
        };
        // The runs are in order: find the first that ends past `xs`'s
        // start once, then walk them along with `x`.
        let runs = lakes.row(y);
        let mut i = runs.partition_point(|r| (r.end as usize) <= xs.start);
        for x in xs {
            while runs.get(i).is_some_and(|r| (r.end as usize) <= x) {
                i += 1;
            }
            let w = match runs.get(i) {
                Some(r) if r.start as usize <= x => lakes.level(r.lake),
                _ => 0.0,
            };
            f(x, w);
        }
    }

    /// Works out the haze of point `x` of grid row `y`, once; if `land`
    /// (a land face may touch the point) or the water mirrors, its light;
    /// and if `land`, its colour under smooth shading. Plain water takes
    /// neither light nor colour from its points: a point with plain water
    /// all round it is never lit or coloured (often much of the grid: the
    /// sea is wide).
    #[inline(always)]
    pub(crate) fn shade(&self, v: &mut Vert, x: usize, y: usize, land: bool) {
        if !v.hazed {
            self.haze_now(v, x, y);
        }
        if (land || self.mirror.is_some()) && !v.lit_known {
            self.light_now(v, x, y);
        }
        if land && self.smooth && !v.coloured {
            self.colour_now(v, x, y);
        }
    }

    /// [`Scene::shade`]'s haze, apart so that the check inlines.
    #[inline(never)]
    fn haze_now(&self, v: &mut Vert, x: usize, y: usize) {
        v.haze = self.haze_at(x as f32, y as f32, v.h.max(v.w));
        v.hazed = true;
    }

    /// [`Scene::shade`]'s light, apart so that the check inlines.
    #[inline(never)]
    fn light_now(&self, v: &mut Vert, x: usize, y: usize) {
        (v.lit, v.sky) = self.light_at(x, y);
        v.wet = self.wet_at(x, y);
        v.lit_known = true;
    }

    /// Where water runs at grid point (`x`, `y`), where the palette
    /// follows it.
    #[inline]
    fn wet_at(&self, x: usize, y: usize) -> f32 {
        (self.wetness.as_ref()).map_or(crate::terrain::wetness::ORDINARY, |w| w.at(x, y))
    }

    /// [`Scene::shade`]'s colour, once the point's light is worked out.
    #[inline(never)]
    fn colour_now(&self, v: &mut Vert, x: usize, y: usize) {
        let ground = v.h.max(v.w);
        // Smooth shading has its normals; without, a point is the air's colour.
        let Some(normals) = &self.normals else {
            v.colour = self.hazed(0, v.haze);
            v.coloured = true;
            return;
        };
        let n = normals.at(&self.field, x, y);
        let (land, rock) = (self.palette).land_and_rock_at_point(ground, n, v.lit, v.sky, v.wet);
        v.colour = self.hazed(land, v.haze);
        if let Some(relief) = &self.relief {
            v.fine = self.fine_point(relief, v, n, x, y);
        }
        if self.strata.is_some() && rock > 0.0 {
            // The haze veils the bands as it does the rock.
            v.rock = rock * strata::DEPTH * clear(v.haze);
        }
        v.coloured = true;
    }

    /// What the faces around grid point (`x`, `y`) need to light its
    /// finer relief: its light and haze are `v`'s, its normal `n`. A point
    /// whose cells span well under what the relief needs has no light for
    /// it (the faces around it are drawn plain, or fade their relief out
    /// towards it).
    fn fine_point(&self, relief: &Relief, v: &Vert, n: Vec3, x: usize, y: usize) -> FinePoint {
        let (gx, gy) = (x as f32, y as f32);
        let ground = v.h.max(v.w);
        // The palette's y runs to the back, the grid's to the front.
        let from_eye = (self.view.sight_to(gx, gy, ground)).map(|v| Vec3::new(v.x, -v.y, v.z));
        let cell_px = relief.cell_px_seen(self.view.cell_pixels(gx, gy, ground), n, from_eye);
        let slope = Vec2::new(n.x, n.y) / n.z.max(0.05);
        if !relief.needs(cell_px) {
            return FinePoint {
                slope,
                cell_px,
                ..FinePoint::default()
            };
        }
        FinePoint {
            slope,
            shares: self.palette.lighting().shares(n, v.lit, v.sky) * clear(v.haze),
            cell_px,
            rough: relief.rough_at(x, y),
        }
    }

    /// The direct light and the share of the sky reaching grid point (`x`, `y`).
    #[inline]
    fn light_at(&self, x: usize, y: usize) -> (f32, f32) {
        let lit = self.shadow.as_ref().map_or(1.0, |s| s.lit(x, y));
        let sky = (self.skylight.as_ref()).map_or(1.0, |s| s.blend(s.rows_at(y), x));
        (lit, sky)
    }

    /// How far the air fades a point at grid position (`gx`, `gy`),
    /// height `z`, in 1/256ths.
    #[inline]
    pub(crate) fn haze_at(&self, gx: f32, gy: f32, z: f32) -> u32 {
        (self.haze.as_ref()).map_or(0, |haze| haze.amount(self.view.distance(gx, gy, z)))
    }

    /// The land's colour at grid point (`x`, `y`) whose surface stands at
    /// `ground`, lit `lit`, seeing `sky` of the sky and wet `wet`, before
    /// haze, and how strongly its rock's strata show (the points of smooth
    /// shading; black and no strata where the scene has no normals).
    #[inline]
    fn land_at(&self, x: usize, y: usize, ground: f32, lit: f32, sky: f32, wet: f32) -> (u32, f32) {
        self.normals.as_ref().map_or((0, 0.0), |normals| {
            let n = normals.at(&self.field, x, y);
            self.palette
                .land_and_rock_at_point(ground, n, lit, sky, wet)
        })
    }

    /// The land's colour at grid point (`x`, `y`) as the points of smooth
    /// shading have it, before haze: what the water mirrors there.
    pub(crate) fn land_point(&self, x: usize, y: usize) -> u32 {
        let ground = finite(self.field.get(x, y)).max(0.0);
        let (lit, sky) = self.light_at(x, y);
        self.land_at(x, y, ground, lit, sky, self.wet_at(x, y)).0
    }

    /// Whether land faces are shaded smoothly (each point's colour blended
    /// across them) rather than one colour each.
    #[inline]
    pub(crate) fn smooth(&self) -> bool {
        self.smooth
    }

    /// `colour` faded `haze` (1/256ths) towards the horizon colour.
    #[inline]
    pub(crate) fn hazed(&self, colour: u32, haze: u32) -> u32 {
        match &self.haze {
            Some(h) => blend_packed(colour, h.colour, haze),
            None => colour,
        }
    }

    /// Fixed-point screen position of a point between grid points, at sea level.
    pub(crate) fn project_sea(&self, g: Vec2) -> Fixed2 {
        self.project_water(g, 0.0)
    }

    /// Fixed-point screen position of a point between grid points, on a
    /// water surface at height `level` (the sea's 0, or a lake's).
    pub(crate) fn project_water(&self, g: Vec2, level: f32) -> Fixed2 {
        let p = self.view.project(g.x, g.y, level);
        to_fixed(p.x, p.y)
    }

    /// Screen rows strip `s` (cells between grid rows `s` and `s + 1`, with
    /// their skirts) can touch, widened by a pixel each way.
    pub(crate) fn strip_rows(&self, s: usize) -> (i64, i64) {
        let (y0, y1) = self.strip_grid_rows(s);
        self.rows_reached([y0, y1], [self.row_top.row(y0), self.row_top.row(y1)])
    }

    /// The first screen row the cells `cells` of strip `s` can touch (the
    /// strip's faces lie wholly below it).
    pub(crate) fn strip_top(&self, s: usize, cells: &std::ops::Range<usize>) -> i64 {
        let (y0, y1) = self.strip_grid_rows(s);
        let points = cells.start..=cells.end;
        let tops = [y0, y1].map(|y| self.row_top.within(y, points.clone()));
        self.rows_reached([y0, y1], tops).0
    }

    /// [`Scene::strip_rows`] for a strip between grid rows `y0` and `y1`
    /// whose points reach heights `top0` and `top1`. Screen rows do not
    /// depend on the grid column in any view (the cameras do not roll).
    fn rows_reached(&self, [y0, y1]: [usize; 2], [top0, top1]: [f32; 2]) -> (i64, i64) {
        let top = self.view.project(0.0, y0 as f32, top0).y;
        let top2 = self.view.project(0.0, y1 as f32, top1).y;
        let bottom = self.view.project(0.0, y1 as f32, 0.0).y;
        let lo = top.min(top2).min(bottom);
        let hi = bottom.max(top).max(top2);
        if !(lo.is_finite() && hi.is_finite()) {
            return (i64::MIN, i64::MAX);
        }
        (lo.floor() as i64 - 1, hi.ceil() as i64 + 1)
    }
}

/// The frame's serial start: the view fitted and the rows kept, the
/// shadow swept, the sky light and the palette's tables, before any strip
/// is drawn.
struct Start {
    row_top: RowTops,
    view: View,
    rows: Vec<usize>,
    skylight: Option<SkyLight>,
    shadow: Option<ShadowMap>,
    palette: Palette,
}

impl Start {
    /// The start of drawing `field` under `settings` in `style` (the
    /// essay's `square`, if any) into a frame of `frame` size, lit at
    /// `hour`.
    fn of(
        field: &Heightfield,
        settings: &Settings,
        (style, square): (Style, Option<easel::Square>),
        frame: Size,
        hour: Option<SunAt>,
    ) -> Start {
        let lighting = Palette::lighting_at(settings, field, hour);
        let shaded = style.is_filled();
        let wants_sky = style == Style::Shaded && !lighting.classic;
        let light = lighting.sun;
        // Four parts, two to a thread, or each on its own with four cores,
        // paired so the two threads carry about the same; three threads on
        // two cores would only take turns.
        let wide = crate::cores::cores() >= 4;
        let (((row_top, view, rows), skylight), (shadow, palette)) = both(
            || {
                both_if(
                    wide,
                    || framed(field, settings, (shaded, square), frame),
                    || wants_sky.then(|| SkyLight::new(field)),
                )
            },
            || {
                both_if(
                    wide,
                    || (shaded && settings.shadows).then(|| shadow::cast(field, light)),
                    || Palette::lit_by(settings, field, lighting),
                )
            },
        );
        Start {
            row_top,
            view,
            rows,
            skylight,
            shadow,
            palette,
        }
    }
}

/// What the shaded looks with depth add to the picture (the seed
/// programs' looks, the oblique view and the classic light keep their
/// pixels): the air, the wind on the water, clean edges, smooth land and
/// the water's mirror.
struct Depth {
    haze: Option<Haze>,
    ripples: Option<Ripples>,
    clean_edges: bool,
    smooth: bool,
    reflections: bool,
}

impl Depth {
    /// What `settings` in `style` and the `palette` lit for `field` draw.
    fn of(settings: &Settings, style: Style, palette: &Palette, field: &Heightfield) -> Depth {
        let ours = style == Style::Shaded
            && settings.view != ViewKind::Oblique
            && settings.look == Look::Ours;
        let haze = ours.then(|| Haze::new(palette.sky().1, palette.haze()));
        let classic = palette.lighting().classic;
        let ripples = (ours && !classic).then(|| Ripples::new(palette.sky().1, field));
        let clean_edges = ours && !classic;
        Depth {
            smooth: clean_edges && settings.shading == Shading::Smooth,
            reflections: settings.reflections && ripples.is_some(),
            haze,
            ripples,
            clean_edges,
        }
    }
}

/// The sky behind the land: with the weather and the stars where the
/// water has its wind (the shaded views with depth).
fn sky_of(
    palette: &Palette,
    view: &View,
    settings: &Settings,
    field: &Heightfield,
    (style, depth): (Style, &Depth),
    frame: Size,
) -> Sky {
    let sky = backdrop(palette, view, style, frame.height);
    if depth.ripples.is_none() {
        return sky;
    }
    let w = weather(palette, view, settings, field, &sky, frame);
    let night = palette.lighting().night;
    let stars = Stars::new(frame.height, sky.horizon_row(), night, field.identity());
    sky.with_weather(w).with_stars(stars)
}

/// How the cells of a row are ordered and cut, and what the classic views
/// and the seed programs' looks keep of their own (see the [`Scene`]
/// fields of the same names).
struct Sides {
    split: usize,
    sees_right: bool,
    sees_front: bool,
    listing_diagonal: bool,
    listing_cuts: bool,
    mono_floor: u8,
    normal_shear: f32,
}

impl Sides {
    /// The sides of a grid `cells` wide seen in `view` under `settings`.
    fn of(settings: &Settings, view: &View, palette: &Palette, cells: usize) -> Sides {
        let listing = settings.look == Look::FractalMountainClimbing;
        let (split, sees_right, sees_front) = match view.camera_column() {
            Some(cx) => {
                let split = cx.floor().clamp(0.0, cells as f32) as usize;
                // The essay draws the surface alone.
                let sides = settings.look != Look::Essay;
                (split, sides && cx > cells as f32, sides)
            }
            // Seed 000's listing cuts no sides: below its front edge is
            // the black window.
            None if listing => (cells, false, false),
            None => (cells, true, true),
        };
        let listing_diagonal = view.camera_column().is_none();
        Sides {
            split,
            sees_right,
            sees_front,
            listing_diagonal,
            listing_cuts: listing_diagonal && listing,
            mono_floor: if listing { 0 } else { dither::FACE_FLOOR },
            normal_shear: match palette.lighting().classic {
                true => view.shear(),
                false => 0.0,
            },
        }
    }
}

/// The highest point of each row (at least sea level), the view fitted to
/// `field` in a frame of `frame` size, and the grid rows its mesh is
/// drawn with.
/// The essay's square (`square`, under `look = "essay"`) is seen in the
/// perspective view from the essay's own camera.
fn framed(
    field: &Heightfield,
    settings: &Settings,
    (shaded, square): (bool, Option<easel::Square>),
    frame: Size,
) -> (RowTops, View, Vec<usize>) {
    let size = field.size();
    let row_top = RowTops::of(field);
    // Framed on the lattice every detail shares, so a seed is framed alike
    // at every detail (the classic oblique view keeps its own fit).
    let shared = field
        .exponent()
        .saturating_sub(crate::terrain::SHARED_EXPONENT);
    let lattice = (shared > 0 && settings.view != ViewKind::Oblique)
        .then(|| RowTops::of(&field.coarsened(shared)));
    let tops = lattice.as_ref().unwrap_or(&row_top).rows();
    // Seed 000's look draws its parallelogram as its listing does: tipped
    // 80 degrees, heights at its own relief.
    let oblique = if settings.look == Look::FractalMountainClimbing {
        let height = crate::settings::handles::HEIGHT.clamp(settings.height);
        Oblique {
            listing_tilt: true,
            relief: listing_relief(height, field.extent(), field.max()),
        }
    } else {
        Oblique::OURS
    };
    let floor = super::framing::view::near_floor(field);
    let view = match square.filter(|_| settings.view == ViewKind::Perspective) {
        Some(square) => easel::view(square, size, field.extent(), frame),
        None => View::fitted_in(
            settings.view,
            (oblique, (settings.world, field.identity())),
            size,
            field.extent(),
            (tops, floor),
            frame,
        ),
    };
    // Sonar and Outline draw every line of their (already thinned) grid.
    let rows = if shaded {
        super::framing::rows::kept_rows(size, &view, |x, y| finite(field.get(x, y)).max(0.0))
    } else {
        (0..size).collect()
    };
    (row_top, view, rows)
}

/// The sky for this view: in a view with depth the horizon colour is
/// reached at the back edge, where the land begins; the oblique view's
/// gradient spans the frame.
fn backdrop(palette: &Palette, view: &View, style: Style, height: u32) -> Sky {
    let (top, horizon) = palette.sky();
    let row = match (style, view.camera_column()) {
        (Style::Shaded, Some(cx)) => view.project(cx, 0.0, 0.0).y,
        _ => height as f32,
    };
    Sky::new(top, horizon, row)
}

/// The sun's glow and the clouds of this slide (`settings.clouds`, drawn
/// from the field's identity under "varied") in a `frame` of that size.
fn weather(
    palette: &Palette,
    view: &View,
    settings: &Settings,
    field: &Heightfield,
    sky: &Sky,
    Size { width, height }: Size,
) -> Option<Weather> {
    let amount = clouds::amount_in(settings.clouds, settings.world, field.identity());
    Weather::new(
        view,
        palette.lighting(),
        |c| palette.filtered(c),
        (Vec2::new(width as f32, height as f32), sky.horizon_row()),
        amount,
        field.identity(),
    )
}

/// The field seen from another side: `rotation` degrees, in quarter turns
/// (other values are rounded to the nearest quarter).
/// Wire modes draw every edge: cells narrower than this many pixels merge
/// into a solid sheet of lines (a 257-point grid at 960 pixels is all white
/// in Sonar), so the mesh is thinned until its cells are at least this wide.
const MIN_WIRE_CELL_PX: f32 = 8.0;

/// The field on the coarsest nested grid whose cells, seen in this frame,
/// are at least `MIN_WIRE_CELL_PX` wide (the field itself if they already are).
fn legible<'a>(field: FieldRef<'a>, settings: &Settings, frame: Size) -> FieldRef<'a> {
    let cells = (field.size() - 1) as f32;
    let zmax = field.max().max(0.0);
    let view = View::new(
        settings.view,
        field.size(),
        field.extent(),
        finite(zmax),
        frame,
    );
    let mid = cells / 2.0;
    let span = (view.project(cells, mid, 0.0) - view.project(0.0, mid, 0.0)).length();
    let px = span / cells;
    // Low detail is what makes Sonar appealing (seed 003): larger faces,
    // so it doubles the legible size rather than being thinned away.
    let min_px = MIN_WIRE_CELL_PX * if settings.low_detail { 2.0 } else { 1.0 };
    if !(px.is_finite() && px > 0.0) || px >= min_px {
        return field;
    }
    let levels = (min_px / px).log2().ceil() as u32;
    FieldRef::Shared(Arc::new(field.coarsened(levels)))
}

/// `field` as `settings` lay it out in a frame of `frame` size: turned
/// by `rotation` and the essay's turn, a data set at its drawn scale,
/// Sonar's and Outline's grid coarsened to stay legible; with the essay's
/// square (before its turn, for its camera) and the outline its cells are
/// cut along.
pub(crate) fn laid_out<'a>(
    field: FieldRef<'a>,
    settings: &Settings,
    frame: Size,
) -> (FieldRef<'a>, Option<easel::Square>, Option<Outline<'a>>) {
    let mut field = turned(field, settings.quarter_turns());
    let mut square = None;
    let mut outline = None;
    if settings.look == Look::Essay {
        square = Some(easel::Square::of(&field));
        let degrees = turn::essay_degrees(field.identity());
        outline = Some(Outline {
            square: field.again(),
            turn: turn::Turn::new(field.size(), degrees),
            scale: 1.0,
        });
        field = FieldRef::Shared(Arc::new(turn::turned_by(&field, degrees)));
    }
    if let Some(drawn) = field.drawn() {
        let f = field.drawn_scale();
        square = square.map(|s| s.scaled(f));
        outline = outline.map(|o| Outline { scale: f, ..o });
        field = FieldRef::Shared(Arc::new(drawn));
    }
    if matches!(Style::of(settings.color), Style::Sonar | Style::Outline) {
        field = legible(field, settings, frame);
    }
    (field, square, outline)
}

fn turned(field: FieldRef<'_>, quarters: u32) -> FieldRef<'_> {
    if quarters == 0 {
        return field;
    }
    let n = field.size();
    let mut out = Heightfield::flat(field.exponent(), field.extent());
    out.set_seed(field.seed());
    // Each quarter turn brings the old right edge to the back.
    let source = |x: usize, y: usize| match quarters {
        1 => (n - 1 - y, x),
        2 => (n - 1 - x, n - 1 - y),
        _ => (y, n - 1 - x),
    };
    for y in 0..n {
        for x in 0..n {
            let (sx, sy) = source(x, y);
            out.set(x, y, field.get(sx, sy));
        }
    }
    out.set_lakes(field.lakes().map(|l| Arc::new(l.turned(source))));
    FieldRef::Shared(Arc::new(out))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::{Clouds, Detail, World};

    /// Point (`x`, `y`) of `scene`, projected and then shaded with `land`.
    fn shaded(scene: &Scene, x: usize, y: usize, land: bool) -> Vert {
        let mut row = vec![Vert::default(); scene.cells() + 1];
        scene.project_points(y, x..x + 1, &mut row);
        scene.shade(&mut row[x], x, y, land);
        row[x]
    }

    #[test]
    fn points_are_lit_only_where_land_or_a_mirror_needs_their_light() {
        let settings = |reflections| Settings {
            detail: Detail::Level(6),
            clouds: Clouds::Amount(0.0),
            reflections,
            // Seed 42's coast, its point (40, 50) as chosen (its varied
            // world is another).
            world: World::Temperate,
            ..Settings::default()
        };
        let field = crate::terrain::generate(&settings(false), 42);
        let (x, y) = (40, 50);
        let plain = Scene::new(
            FieldRef::Borrowed(&field),
            &settings(false),
            Size::new(320, 180),
        );
        assert!(plain.mirror.is_none() && plain.smooth);
        let water = shaded(&plain, x, y, false);
        assert!(water.hazed && !water.lit_known && !water.coloured);
        let land = shaded(&plain, x, y, true);
        assert!(land.hazed && land.lit_known && land.coloured);
        assert_eq!((land.lit, land.sky), plain.light_at(x, y));
        assert_eq!(land.haze, water.haze);
        // Water that mirrors takes its points' light.
        let mirroring = Scene::new(
            FieldRef::Borrowed(&field),
            &settings(true),
            Size::new(320, 180),
        );
        assert!(mirroring.mirror.is_some());
        let water = shaded(&mirroring, x, y, false);
        assert!(water.lit_known && !water.coloured);
        assert_eq!((water.lit, water.sky), mirroring.light_at(x, y));
    }
}

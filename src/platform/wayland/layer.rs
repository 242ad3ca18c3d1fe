//! `--layer`: the slide show on a wlr-layer-shell surface of every Wayland
//! output, as a desktop background or as swaylock-plugin's background under
//! its lock. Each surface is anchored on all four edges, overlaps panels
//! (exclusive zone -1), takes no keyboard, and is drawn at the output's real
//! pixels (its logical size times the output's scale, with that buffer
//! scale; at a fractional scale the output's mode, through a viewport).
//! The shows and the presenting are the winit windows' own
//! (`show`, `present`, through a raw handle: `target.rs`).
//!
//! It runs until SIGTERM or SIGINT, or until the compositor has closed every
//! surface; outputs that come and go while it runs gain and lose a surface.
//! How a buffer covers its output (buffer scale or viewport): `cover.rs`;
//! one landscape across the outputs (`monitors = "span"`): `layer/span.rs`.

mod span;

use std::time::{Duration, Instant};

use smithay_client_toolkit as sctk;

use sctk::compositor::{CompositorHandler, CompositorState};
use sctk::output::{OutputHandler, OutputState};
use sctk::reexports::calloop::{EventLoop, ping};
use sctk::reexports::calloop_wayland_source::WaylandSource;
use sctk::reexports::client::globals::{GlobalList, registry_queue_init};
use sctk::reexports::client::protocol::wl_output::{Transform, WlOutput};
use sctk::reexports::client::protocol::wl_surface::WlSurface;
use sctk::reexports::client::{Connection, Proxy, QueueHandle, delegate_noop};
use sctk::reexports::protocols::wp::viewporter::client::wp_viewport::WpViewport;
use sctk::reexports::protocols::wp::viewporter::client::wp_viewporter::WpViewporter;
use sctk::registry::{ProvidesRegistryState, RegistryState};
use sctk::shell::WaylandSurface;
use sctk::shell::wlr_layer::{
    Anchor, KeyboardInteractivity, Layer as ShellLayer, LayerShell, LayerShellHandler,
    LayerSurface, LayerSurfaceConfigure,
};
use sctk::{delegate_compositor, delegate_layer, delegate_output, delegate_registry};

use super::cover::{self, Cover};
use super::target::WaylandTarget;
use crate::cli::Layer;
use crate::mountain::Mountain;
use crate::render::{Damage, Size};
use crate::saver::error::SaverError;
use crate::saver::present::Presenter;
use crate::saver::show::Show;
use crate::saver::slideshow::Pacing;
use crate::saver::trace::Trace;
use crate::settings::Settings;

/// The protocol `--layer` needs, as a compositor lists it.
pub const LAYER_SHELL: &str = "zwlr_layer_shell_v1";

/// The layer surfaces' namespace: what compositors' rules match (Hyprland's
/// `layerrule`, for one).
const NAMESPACE: &str = "mountains";

/// Runs the slide show on `layer` of every output until it ends.
pub fn run(layer: Layer, settings: Settings, opened: Option<Mountain>) -> Result<(), SaverError> {
    crate::platform::libcheck::check_wayland_client()?;
    let conn = Connection::connect_to_env().map_err(not_connected)?;
    let (globals, queue) =
        registry_queue_init(&conn).map_err(|e| SaverError::NoCompositor(e.to_string()))?;
    let names: Vec<String> = globals
        .contents()
        .with_list(|list| list.iter().map(|g| g.interface.clone()).collect());
    check_globals(&names)?;
    let qh = queue.handle();
    let mut app = LayerApp::new(&conn, &globals, &qh, layer, settings, opened)?;
    let mut event_loop: EventLoop<LayerApp> =
        EventLoop::try_new().map_err(|e| other("cannot make an event loop", e))?;
    WaylandSource::new(conn.clone(), queue)
        .insert(event_loop.handle())
        .map_err(|e| other("cannot watch the compositor", e.error))?;
    let (ping, signalled) = ping::make_ping().map_err(|e| other("cannot make a ping", e))?;
    event_loop
        .handle()
        .insert_source(signalled, |(), _, app| app.end(&"SIGTERM or SIGINT"))
        .map_err(|e| other("cannot watch for SIGTERM", e.error))?;
    crate::platform::signals::on_terminate(move || ping.ping())
        .map_err(|e| other("cannot watch for SIGTERM", e))?;
    follow_power(&event_loop, &mut app)?;
    let mut timeout = Some(Duration::ZERO);
    while !app.ended {
        event_loop
            .dispatch(timeout, &mut app)
            .map_err(|e| SaverError::NoCompositor(format!("the connection failed: {e}")))?;
        timeout = app.step(Instant::now());
        // The signal handler's flag: strips being drawn stopped for it.
        if crate::platform::signals::ending() && !app.ended {
            app.end(&"SIGTERM or SIGINT");
        }
    }
    app.error.map_or(Ok(()), Err)
}

/// Makes every show follow the power and the outputs' power (`watch.rs`).
fn follow_power(event_loop: &EventLoop<LayerApp>, app: &mut LayerApp) -> Result<(), SaverError> {
    let (tx, rx) = sctk::reexports::calloop::channel::channel();
    event_loop
        .handle()
        .insert_source(rx, |event, _, app: &mut LayerApp| {
            if let sctk::reexports::calloop::channel::Event::Msg(seen) = event {
                app.follow_seen(seen);
            }
        })
        .map_err(|e| other("cannot watch the power", e.error))?;
    let watcher =
        crate::platform::watch_power_and_display(crate::platform::Backend::Wayland, move |seen| {
            let _ = tx.send(seen);
        });
    app.seen = watcher.seen();
    Ok(())
}

/// Refuses a compositor that lacks a global `--layer` needs, naming it;
/// `names` are the interfaces the compositor lists.
pub fn check_globals<S: AsRef<str>>(names: &[S]) -> Result<(), SaverError> {
    let lacks = |needed: &str| !names.iter().any(|n| n.as_ref() == needed);
    if lacks("wl_compositor") {
        return Err(SaverError::NoCompositor(
            "the compositor has no wl_compositor".into(),
        ));
    }
    if lacks(LAYER_SHELL) {
        return Err(no_layer_shell());
    }
    Ok(())
}

/// The compositor has no layer shell: what to use instead.
fn no_layer_shell() -> SaverError {
    SaverError::Unsupported(format!(
        "--layer: this Wayland compositor has no {LAYER_SHELL} (the wlr-layer-shell protocol): \
         use a compositor that offers it (sway, Hyprland, river, labwc, KDE Plasma; not GNOME), \
         or mountains /s"
    ))
}

/// Why there is no connection, naming the variable to set or the
/// compositor that did not answer.
fn not_connected(e: impl std::fmt::Display) -> SaverError {
    let var = |name: &str| std::env::var(name).ok().filter(|v| !v.is_empty());
    SaverError::NoCompositor(match (var("WAYLAND_DISPLAY"), var("WAYLAND_SOCKET")) {
        (Some(display), _) => format!("cannot connect to {display} (WAYLAND_DISPLAY): {e}"),
        (None, Some(_)) => format!("cannot use WAYLAND_SOCKET: {e}"),
        (None, None) => "--layer draws on Wayland; set WAYLAND_DISPLAY (it is not set)".into(),
    })
}

fn other(what: &str, e: impl std::fmt::Display) -> SaverError {
    SaverError::Other(format!("{what}: {e}"))
}

/// One output's layer surface and, once the compositor has sized it, the
/// show drawn on it.
struct Covered {
    /// Made at the first configure. Dropped before `surface`, whose
    /// `wl_surface` softbuffer holds by pointer.
    drawing: Option<Drawing>,
    surface: LayerSurface,
    output: WlOutput,
    /// The surface's viewport, where the compositor has viewports.
    viewport: Option<WpViewport>,
    /// The size the compositor gave, in its units (0: not configured yet).
    logical: Size,
    /// How the buffer covers the output now.
    cover: Cover,
    /// The cover last told to the compositor (with a frame of its size).
    applied: Option<Cover>,
}

impl Drop for Covered {
    fn drop(&mut self) {
        if let Some(viewport) = self.viewport.take() {
            viewport.destroy();
        }
    }
}

/// A show and what presents it.
struct Drawing {
    presenter: Presenter<WaylandTarget>,
    show: Show,
}

/// The layer-shell client: the compositor's globals, the surfaces, the shows.
struct LayerApp {
    registry: RegistryState,
    outputs: OutputState,
    compositor: CompositorState,
    shell: LayerShell,
    viewporter: Option<WpViewporter>,
    layer: ShellLayer,
    /// The `wl_display` pointer softbuffer's connection shares.
    display: *mut std::ffi::c_void,
    settings: Settings,
    opened: Option<Mountain>,
    covered: Vec<Covered>,
    /// `monitors = "span"`: the one show the surfaces show their parts of.
    span: Option<crate::saver::span::Span>,
    /// The power and the outputs' state, as last seen (`watch.rs`).
    seen: crate::saver::watch::Seen,
    ended: bool,
    error: Option<SaverError>,
    trace: Trace,
}

impl LayerApp {
    fn new(
        conn: &Connection,
        globals: &GlobalList,
        qh: &QueueHandle<Self>,
        layer: Layer,
        settings: Settings,
        opened: Option<Mountain>,
    ) -> Result<Self, SaverError> {
        let compositor = CompositorState::bind(globals, qh)
            .map_err(|e| SaverError::NoCompositor(e.to_string()))?;
        let shell = LayerShell::bind(globals, qh).map_err(|_| no_layer_shell())?;
        Ok(LayerApp {
            registry: RegistryState::new(globals),
            outputs: OutputState::new(globals, qh),
            compositor,
            shell,
            // Only for fractional scales: without it they are drawn at the
            // integer scale above and shrunk.
            viewporter: globals.bind(qh, 1..=1, ()).ok(),
            layer: shell_layer(layer),
            display: conn.backend().display_ptr().cast(),
            settings,
            opened,
            covered: Vec::new(),
            span: None,
            seen: crate::saver::watch::Seen {
                power: crate::platform::power::Power::default(),
                display_on: true,
            },
            ended: false,
            error: None,
            trace: Trace::from_env(),
        })
    }

    /// Ends the loop with status 0, tracing `why`.
    fn end(&mut self, why: &dyn std::fmt::Debug) {
        self.trace.ended_by(why);
        self.ended = true;
    }

    /// Ends the loop with `error` (the first one, if several come).
    fn fail(&mut self, error: SaverError) {
        self.error.get_or_insert(error);
        self.ended = true;
    }

    /// A layer surface on `output`, sized by the compositor's configure.
    fn cover(&mut self, qh: &QueueHandle<Self>, output: WlOutput) {
        if self.covered.iter().any(|c| c.output == output) {
            return;
        }
        let wl_surface = self.compositor.create_surface(qh);
        let surface = self.shell.create_layer_surface(
            qh,
            wl_surface,
            self.layer,
            Some(NAMESPACE),
            Some(&output),
        );
        surface.set_anchor(Anchor::all());
        surface.set_exclusive_zone(-1);
        surface.set_keyboard_interactivity(KeyboardInteractivity::None);
        surface.set_size(0, 0);
        // The first commit, without a buffer, asks for the first configure.
        surface.commit();
        let viewport = self
            .viewporter
            .as_ref()
            .map(|v| v.get_viewport(surface.wl_surface(), qh, ()));
        self.trace.note(&format!(
            "a layer surface on output {}",
            self.name_of(&output)
        ));
        self.covered.push(Covered {
            drawing: None,
            surface,
            output,
            viewport,
            logical: Size::default(),
            cover: Cover::Scaled {
                size: Size::default(),
                scale: 1,
            },
            applied: None,
        });
    }

    /// The output's name for traces (`HEADLESS-2`), or its global's number.
    fn name_of(&self, output: &WlOutput) -> String {
        let info = self.outputs.info(output);
        info.map_or_else(
            || "?".into(),
            |i| i.name.unwrap_or_else(|| format!("#{}", i.id)),
        )
    }

    /// How surface `i`'s buffer covers its output, from what the output
    /// says now.
    fn cover_of(&self, i: usize) -> Cover {
        let c = &self.covered[i];
        let info = self.outputs.info(&c.output);
        // A span is drawn in the compositor's units (`layer/span.rs`).
        let Some(info) = info.filter(|_| !self.spans()) else {
            return cover::cover(c.logical, 1, None, false);
        };
        let mode = info.modes.iter().find(|m| m.current);
        let mode = mode.map(|m| cover::turned(m.dimensions, quarter_turned(info.transform)));
        cover::cover(
            c.logical,
            info.scale_factor,
            mode,
            self.viewporter.is_some(),
        )
    }

    /// The compositor's units the output spans, for a configure of size 0.
    fn logical_size_of(&self, output: &WlOutput) -> Size {
        let Some(info) = self.outputs.info(output) else {
            return Size::default();
        };
        if let Some((w, h)) = info.logical_size {
            return Size::new(w.max(0) as u32, h.max(0) as u32);
        }
        let mode = info.modes.iter().find(|m| m.current);
        mode.map_or(Size::default(), |m| {
            let turned = cover::turned(m.dimensions, quarter_turned(info.transform));
            cover::logical_of(turned, info.scale_factor)
        })
    }

    /// Fits surface `i`'s show to its size in pixels, starting it at the
    /// first configure; presents what changed.
    fn fit(&mut self, i: usize) {
        let cover = self.cover_of(i);
        self.covered[i].cover = cover;
        let size = cover.size();
        if size.is_empty() {
            return;
        }
        let now = Instant::now();
        let told = self.covered[i].applied == Some(cover);
        let damage = match &mut self.covered[i].drawing {
            // Same pixels, told otherwise (scale 1 to 2 on one output):
            // the frame again, with the new cover.
            Some(d) if d.show.size() == size && told => return,
            Some(d) if d.show.size() == size => d
                .show
                .frame()
                .map(|f| f.bounds())
                .unwrap_or_default()
                .into(),
            Some(d) => d.show.resize(size, now).into(),
            None => match self.start_drawing(i, size, now) {
                Ok(bounds) => bounds,
                Err(e) => return self.fail(e),
            },
        };
        self.present(i, damage);
        if self.spans() {
            self.span_fitted(i, now);
        }
    }

    /// Makes surface `i`'s presenter and show; the whole frame to present.
    fn start_drawing(&mut self, i: usize, size: Size, now: Instant) -> Result<Damage, SaverError> {
        let surface = self.covered[i].surface.wl_surface();
        let target = WaylandTarget::new(self.display, surface.id().as_ptr().cast())
            .ok_or_else(|| SaverError::Other("the Wayland surface has no pointer".into()))?;
        let presenter = Presenter::new(target)
            .map_err(|e| SaverError::Other(format!("cannot draw on the layer surface: {e}")))?;
        let pacing = Pacing::from_seconds(
            self.settings.draw_seconds,
            self.settings.pause_seconds,
            true,
        );
        // A span's surface shows its part of the span's show (`layer/span.rs`).
        let mut show = if self.spans() {
            Show::blank(size, now)
        } else {
            crate::saver::options::new_show(
                self.settings.clone(),
                self.opened.clone(),
                pacing,
                size,
                now,
            )
        };
        crate::saver::watch::apply(self.seen, &mut show, now);
        let bounds = show.frame().map(|f| f.bounds()).unwrap_or_default();
        self.covered[i].drawing = Some(Drawing { presenter, show });
        Ok(bounds.into())
    }

    /// Puts the `damage` part of surface `i`'s frame on it, telling the
    /// compositor how the buffer covers the surface once the frame has the
    /// cover's size (a frame of the old size keeps the old cover until its
    /// redraw at the new one is done).
    fn present(&mut self, i: usize, damage: Damage) {
        let c = &mut self.covered[i];
        let Some(d) = c.drawing.as_mut() else {
            return;
        };
        let Some(frame) = d.show.frame().filter(|_| !damage.is_empty()) else {
            return;
        };
        let fits = c.cover.size() == frame.size();
        if fits && c.applied != Some(c.cover) {
            apply(&c.surface, c.viewport.as_ref(), c.cover);
            c.applied = Some(c.cover);
        }
        match d.presenter.present(frame, &damage) {
            Ok(()) => self.trace.presented(),
            Err(e) => self.fail(SaverError::Other(format!("cannot present: {e}"))),
        }
    }

    /// Every show follows the power and the outputs' state.
    fn follow_seen(&mut self, seen: crate::saver::watch::Seen) {
        self.seen = seen;
        let now = Instant::now();
        for i in 0..self.covered.len() {
            let damage = match self.covered[i].drawing.as_mut() {
                Some(d) => crate::saver::watch::apply(seen, &mut d.show, now),
                None => continue,
            };
            self.present(i, damage.into());
        }
        self.follow_span(seen, now);
    }

    /// Does what each show has due, presents it; how long to wait for the
    /// next thing due (`None`: until the compositor or a signal speaks).
    fn step(&mut self, now: Instant) -> Option<Duration> {
        for i in 0..self.covered.len() {
            let damage = match self.covered[i].drawing.as_mut() {
                Some(d) => d.show.tick(now),
                None => continue,
            };
            self.present(i, damage);
        }
        self.tick_span(now);
        let shows = self.covered.iter().filter_map(|c| c.drawing.as_ref());
        let wakes = shows.filter_map(|d| d.show.wake_at(now));
        let wake = wakes.chain(self.span_wake_at(now)).min()?;
        Some(wake.saturating_duration_since(Instant::now()))
    }
}

/// Tells the compositor how the next buffer covers `surface` (applied
/// with the buffer, at softbuffer's commit).
fn apply(surface: &LayerSurface, viewport: Option<&WpViewport>, cover: Cover) {
    let wl_surface = surface.wl_surface();
    match cover {
        Cover::Scaled { scale, .. } => {
            if let Some(v) = viewport {
                v.set_destination(-1, -1);
            }
            wl_surface.set_buffer_scale(scale);
        }
        Cover::Viewport { logical, .. } => {
            wl_surface.set_buffer_scale(1);
            if let Some(v) = viewport {
                let side = |n: u32| i32::try_from(n).unwrap_or(i32::MAX);
                v.set_destination(side(logical.width), side(logical.height));
            }
        }
    }
}

/// True when the output is turned a quarter (its mode's sides swap).
fn quarter_turned(transform: Transform) -> bool {
    matches!(
        transform,
        Transform::_90 | Transform::_270 | Transform::Flipped90 | Transform::Flipped270
    )
}

/// sctk's name for `layer`.
fn shell_layer(layer: Layer) -> ShellLayer {
    match layer {
        Layer::Background => ShellLayer::Background,
        Layer::Bottom => ShellLayer::Bottom,
        Layer::Top => ShellLayer::Top,
        Layer::Overlay => ShellLayer::Overlay,
    }
}

impl LayerShellHandler for LayerApp {
    fn closed(&mut self, _: &Connection, _: &QueueHandle<Self>, layer: &LayerSurface) {
        // One output's surface goes with its output; the compositor
        // closing the last one means the show is no longer wanted.
        let closed = self.covered.iter().find(|c| c.surface == *layer);
        if let Some(c) = closed {
            let name = self.name_of(&c.output);
            self.trace
                .note(&format!("the compositor closed the surface on {name}"));
        }
        self.covered.retain(|c| c.surface != *layer);
        if self.covered.is_empty() {
            self.end(&"the compositor closed the layer surface");
        }
    }

    fn configure(
        &mut self,
        _: &Connection,
        _: &QueueHandle<Self>,
        layer: &LayerSurface,
        configure: LayerSurfaceConfigure,
        _serial: u32,
    ) {
        let Some(i) = self.covered.iter().position(|c| c.surface == *layer) else {
            return;
        };
        let (w, h) = configure.new_size;
        let logical = if w == 0 || h == 0 {
            self.logical_size_of(&self.covered[i].output)
        } else {
            Size::new(w, h)
        };
        self.covered[i].logical = logical;
        self.fit(i);
    }
}

impl OutputHandler for LayerApp {
    fn output_state(&mut self) -> &mut OutputState {
        &mut self.outputs
    }

    fn new_output(&mut self, _: &Connection, qh: &QueueHandle<Self>, output: WlOutput) {
        self.cover(qh, output);
    }

    fn update_output(&mut self, _: &Connection, _: &QueueHandle<Self>, output: WlOutput) {
        // A new scale or mode: the compositor's configure may follow, or
        // not (the logical size can stay).
        if let Some(i) = self.covered.iter().position(|c| c.output == output)
            && self.cover_of(i) != self.covered[i].cover
        {
            self.fit(i);
        }
    }

    fn output_destroyed(&mut self, _: &Connection, _: &QueueHandle<Self>, output: WlOutput) {
        let name = self.name_of(&output);
        self.trace.note(&format!("output {name} is gone"));
        self.covered.retain(|c| c.output != output);
    }
}

impl CompositorHandler for LayerApp {
    fn scale_factor_changed(
        &mut self,
        _: &Connection,
        _: &QueueHandle<Self>,
        _: &WlSurface,
        _: i32,
    ) {
        // Followed through the output's own scale (`update_output`).
    }

    fn transform_changed(
        &mut self,
        _: &Connection,
        _: &QueueHandle<Self>,
        _: &WlSurface,
        _: Transform,
    ) {
    }

    fn frame(&mut self, _: &Connection, _: &QueueHandle<Self>, _: &WlSurface, _: u32) {}

    fn surface_enter(
        &mut self,
        _: &Connection,
        _: &QueueHandle<Self>,
        _: &WlSurface,
        _: &WlOutput,
    ) {
    }

    fn surface_leave(
        &mut self,
        _: &Connection,
        _: &QueueHandle<Self>,
        _: &WlSurface,
        _: &WlOutput,
    ) {
    }
}

impl ProvidesRegistryState for LayerApp {
    fn registry(&mut self) -> &mut RegistryState {
        &mut self.registry
    }
    sctk::registry_handlers![OutputState];
}

delegate_compositor!(LayerApp);
delegate_output!(LayerApp);
delegate_layer!(LayerApp);
delegate_registry!(LayerApp);
delegate_noop!(LayerApp: ignore WpViewporter);
delegate_noop!(LayerApp: ignore WpViewport);

#[cfg(test)]
mod tests {
    use super::*;

    /// What sway 1.7 lists (wayland-info), less or with the layer shell.
    const SWAY: [&str; 6] = [
        "wl_compositor",
        "wl_shm",
        "wl_output",
        "xdg_wm_base",
        "zwlr_layer_shell_v1",
        "wp_viewporter",
    ];

    #[test]
    fn a_compositor_without_the_layer_shell_is_refused_by_its_name() {
        assert_eq!(check_globals(&SWAY), Ok(()));
        let without: Vec<&str> = SWAY.iter().copied().filter(|n| *n != LAYER_SHELL).collect();
        let said = check_globals(&without).unwrap_err().to_string();
        assert!(said.contains("zwlr_layer_shell_v1"), "{said}");
        assert!(said.contains("--layer"), "{said}");
        let no_compositor: Vec<&str> = SWAY[1..].to_vec();
        let said = check_globals(&no_compositor).unwrap_err().to_string();
        assert!(said.contains("wl_compositor"), "{said}");
    }
}

//! Where full-screen windows go: the monitors to cover (the X server's
//! list, else winit's), and window attributes that cover one exactly.

use winit::event_loop::ActiveEventLoop;
use winit::monitor::MonitorHandle;
use winit::window::{WindowAttributes, WindowLevel};

use super::heads::{self, Head};

/// The monitors to cover, each with winit's handle where winit knows it.
/// The X server's own list (`server`) wins: winit lists CRTCs only. On
/// `wayland` the heads are in the compositor's logical pixels: there an
/// output's physical position is its logical one times its own scale, so
/// outputs of different scales would seem to overlap.
pub(super) fn find_heads(
    event_loop: &ActiveEventLoop,
    server: &[Head],
    wayland: bool,
) -> Vec<(Head, Option<MonitorHandle>)> {
    if !server.is_empty() {
        return server.iter().map(|h| (*h, None)).collect();
    }
    let primary = event_loop.primary_monitor();
    let monitors: Vec<(Head, MonitorHandle)> = event_loop
        .available_monitors()
        .map(|m| {
            let (mut position, mut size) = (m.position(), m.size());
            if wayland {
                let scale = m.scale_factor();
                position = position.to_logical::<i32>(scale).to_physical(1.0);
                size = size.to_logical::<u32>(scale).to_physical(1.0);
            }
            let head = Head {
                x: position.x,
                y: position.y,
                width: size.width,
                height: size.height,
                primary: Some(&m) == primary.as_ref(),
            };
            (head, m)
        })
        .collect();
    let heads: Vec<Head> = monitors.iter().map(|(h, _)| *h).collect();
    heads::clean(&heads)
        .into_iter()
        .map(|h| {
            let same = |(m, _): &&(Head, MonitorHandle)| {
                (m.x, m.y, m.width, m.height) == (h.x, h.y, h.width, h.height)
            };
            (h, monitors.iter().find(same).map(|(_, m)| m.clone()))
        })
        .collect()
}

/// Window attributes covering `head` exactly, above everything else. A
/// Wayland client cannot place its windows: it asks for full screen on
/// the monitor, and the compositor gives the window the output's size in
/// its real pixels.
pub(super) fn covering(
    base: WindowAttributes,
    head: &Head,
    monitor: Option<&MonitorHandle>,
    wayland: bool,
) -> WindowAttributes {
    let attrs = base
        .with_decorations(false)
        .with_window_level(WindowLevel::AlwaysOnTop);
    if wayland {
        let on = winit::window::Fullscreen::Borderless(monitor.cloned());
        return attrs.with_fullscreen(Some(on));
    }
    crate::platform::on_head(attrs, head, monitor)
}

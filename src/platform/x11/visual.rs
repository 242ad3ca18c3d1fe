//! A visual softbuffer can draw into, for the windows winit opens on X11
//! (the saver's and the settings screen's).
//! softbuffer takes 24- and 32-bit true colour with 8 bits a channel; a
//! window gets its screen's own visual unless asked otherwise, so on a
//! 30-bit or a 16-bit screen every window mode was refused, although such
//! servers also offer 32-bit (and often 24-bit) true-colour visuals.

use x11rb::connection::Connection;
use x11rb::protocol::xproto::{ConnectionExt as _, Screen, Setup, VisualClass, Visualtype};
use x11rb::rust_connection::RustConnection;

use super::bands::can_draw;

/// What every refusal says is needed, and how to get it.
const NEEDED: &str = "mountains draws in TrueColor of 15 to 32 bits";
const HOW: &str =
    "run the X server at depth 24 (Xvfb: -screen 0 1024x768x24; Xorg: DefaultDepth 24)";

/// The visual to ask winit for on `$DISPLAY`'s screen: `None` when the
/// screen's own will do (or none will: the window then says why).
pub fn drawable_visual() -> Option<u32> {
    let (conn, screen) = RustConnection::connect(None).ok()?;
    drawable_visual_on(&conn, screen)
}

/// [`screen_refusal`] for `$DISPLAY`'s screen; `None` when the server
/// cannot be reached (opening the window then says why).
pub fn refusal() -> Option<String> {
    let (conn, screen) = RustConnection::connect(None).ok()?;
    screen_refusal(conn.setup(), screen)
}

/// [`drawable_visual`] on screen `screen` of a connection already open.
pub fn drawable_visual_on(conn: &impl Connection, screen: usize) -> Option<u32> {
    choose(conn.setup().roots.get(screen)?)
}

/// Why no window can be drawn on screen `screen` (what it offers, what is
/// needed, what to do), as a sentence; `None` when one of its visuals will
/// do. A screen of 8-bit visuals only was refused with softbuffer's "Visual
/// 0x21 does not use softbuffer's pixel format".
pub fn screen_refusal(setup: &Setup, screen: usize) -> Option<String> {
    let offers = only_offers(setup, screen)?;
    Some(format!(
        "this X screen offers only {offers}; {NEEDED}: {HOW}"
    ))
}

/// What screen `screen` offers, when none of its visuals will do.
fn only_offers(setup: &Setup, screen: usize) -> Option<String> {
    let s = setup.roots.get(screen)?;
    let mut visuals = s
        .allowed_depths
        .iter()
        .flat_map(|d| d.visuals.iter().map(move |v| (d.depth, v)));
    let usable = visuals.any(|(depth, v)| can_draw(setup, depth, v.visual_id));
    (!usable).then(|| offered(s))
}

/// Why `window` (on screen `screen`) cannot be drawn into, as a sentence;
/// `None` when it can, or when the server does not say.
pub fn window_refusal(conn: &impl Connection, screen: usize, window: u32) -> Option<String> {
    let depth = conn.get_geometry(window).ok()?.reply().ok()?.depth;
    let visual = conn
        .get_window_attributes(window)
        .ok()?
        .reply()
        .ok()?
        .visual;
    let setup = conn.setup();
    if can_draw(setup, depth, visual) {
        return None;
    }
    let class = setup
        .roots
        .iter()
        .flat_map(|r| r.allowed_depths.iter().flat_map(|d| d.visuals.iter()))
        .find(|v| v.visual_id == visual)
        .map_or("unknown", |v| class_name(v.class));
    let window = format!("window 0x{window:x} is {depth}-bit {class}");
    Some(match only_offers(setup, screen) {
        Some(offers) => format!("{window} and this X screen offers only {offers}; {NEEDED}: {HOW}"),
        None => format!(
            "{window}; {NEEDED}: the program that made the window must give it such a visual"
        ),
    })
}

/// What a screen offers, by depth: "8-bit visuals (PseudoColor, TrueColor)".
fn offered(screen: &Screen) -> String {
    let mut parts = Vec::new();
    for depth in screen
        .allowed_depths
        .iter()
        .filter(|d| !d.visuals.is_empty())
    {
        let mut classes: Vec<&str> = Vec::new();
        for name in depth.visuals.iter().map(|v| class_name(v.class)) {
            if !classes.contains(&name) {
                classes.push(name);
            }
        }
        parts.push(format!(
            "{}-bit visuals ({})",
            depth.depth,
            classes.join(", ")
        ));
    }
    match parts.is_empty() {
        true => "no visuals".into(),
        false => parts.join(" and "),
    }
}

/// A visual class as X names it.
fn class_name(class: VisualClass) -> &'static str {
    match class {
        VisualClass::STATIC_GRAY => "StaticGray",
        VisualClass::GRAY_SCALE => "GrayScale",
        VisualClass::STATIC_COLOR => "StaticColor",
        VisualClass::PSEUDO_COLOR => "PseudoColor",
        VisualClass::TRUE_COLOR => "TrueColor",
        VisualClass::DIRECT_COLOR => "DirectColor",
        _ => "unknown",
    }
}

/// `screen`'s own visual if softbuffer can draw into it (then `None`), else
/// its first such visual, 24-bit before 32-bit.
fn choose(screen: &Screen) -> Option<u32> {
    let visuals = || {
        screen
            .allowed_depths
            .iter()
            .flat_map(|d| d.visuals.iter().map(move |v| (d.depth, v)))
    };
    let own = visuals().find(|(_, v)| v.visual_id == screen.root_visual);
    if own.is_some_and(|(depth, v)| drawable(depth, v)) {
        return None;
    }
    [24, 32].into_iter().find_map(|want| {
        visuals()
            .find(|&(depth, v)| depth == want && drawable(depth, v))
            .map(|(_, v)| v.visual_id)
    })
}

/// Whether a visual of `depth` bits is one softbuffer draws into.
fn drawable(depth: u8, v: &Visualtype) -> bool {
    (depth == 24 || depth == 32)
        && v.class == VisualClass::TRUE_COLOR
        && (v.red_mask, v.green_mask, v.blue_mask) == (0xff_0000, 0xff00, 0xff)
}

#[cfg(test)]
mod tests {
    use super::*;
    use x11rb::protocol::xproto::{Depth, Format};

    fn visual(id: u32, class: VisualClass, masks: (u32, u32, u32)) -> Visualtype {
        Visualtype {
            visual_id: id,
            class,
            bits_per_rgb_value: 8,
            colormap_entries: 256,
            red_mask: masks.0,
            green_mask: masks.1,
            blue_mask: masks.2,
        }
    }

    fn screen(root_visual: u32, depths: Vec<Depth>) -> Screen {
        Screen {
            root: 1,
            default_colormap: 2,
            white_pixel: 0,
            black_pixel: 0,
            current_input_masks: Default::default(),
            width_in_pixels: 640,
            height_in_pixels: 480,
            width_in_millimeters: 0,
            height_in_millimeters: 0,
            min_installed_maps: 1,
            max_installed_maps: 1,
            root_visual,
            backing_stores: Default::default(),
            save_unders: false,
            root_depth: 30,
            allowed_depths: depths,
        }
    }

    const RGB888: (u32, u32, u32) = (0xff_0000, 0xff00, 0xff);
    const RGB101010: (u32, u32, u32) = (0x3ff0_0000, 0xffc00, 0x3ff);

    #[test]
    fn a_30_bit_screen_gets_its_32_bit_true_colour_visual() {
        let depths = vec![
            Depth {
                depth: 30,
                visuals: vec![visual(0x21, VisualClass::TRUE_COLOR, RGB101010)],
            },
            Depth {
                depth: 32,
                visuals: vec![
                    visual(0x40, VisualClass::DIRECT_COLOR, RGB888),
                    visual(0x41, VisualClass::TRUE_COLOR, RGB888),
                ],
            },
        ];
        assert_eq!(choose(&screen(0x21, depths)), Some(0x41));
    }

    #[test]
    fn a_24_bit_screen_keeps_its_own_and_24_bits_come_before_32() {
        let ok = |id| visual(id, VisualClass::TRUE_COLOR, RGB888);
        let depths = || {
            vec![
                Depth {
                    depth: 32,
                    visuals: vec![ok(0x50)],
                },
                Depth {
                    depth: 24,
                    visuals: vec![ok(0x21), ok(0x22)],
                },
                Depth {
                    depth: 16,
                    visuals: vec![visual(0x60, VisualClass::TRUE_COLOR, (0xf800, 0x7e0, 0x1f))],
                },
            ]
        };
        assert_eq!(choose(&screen(0x21, depths())), None);
        assert_eq!(choose(&screen(0x60, depths())), Some(0x21));
    }

    /// A server set up with `screen` and the usual pixmap formats.
    fn setup_with(screen: Screen) -> Setup {
        let format = |depth, bits_per_pixel| Format {
            depth,
            bits_per_pixel,
            scanline_pad: 32,
        };
        Setup {
            pixmap_formats: vec![format(1, 1), format(8, 8), format(16, 16), format(24, 32)],
            roots: vec![screen],
            ..Setup::default()
        }
    }

    #[test]
    fn an_8_bit_screen_is_refused_in_words() {
        let depths = vec![Depth {
            depth: 8,
            visuals: vec![
                visual(0x21, VisualClass::PSEUDO_COLOR, (0, 0, 0)),
                visual(0x22, VisualClass::GRAY_SCALE, (0, 0, 0)),
                visual(0x24, VisualClass::TRUE_COLOR, (0xe0, 0x1c, 0x3)),
                visual(0x25, VisualClass::PSEUDO_COLOR, (0, 0, 0)),
            ],
        }];
        let said = screen_refusal(&setup_with(screen(0x21, depths)), 0);
        assert_eq!(
            said.as_deref(),
            Some(
                "this X screen offers only 8-bit visuals (PseudoColor, GrayScale, TrueColor); \
                 mountains draws in TrueColor of 15 to 32 bits: run the X server at depth 24 \
                 (Xvfb: -screen 0 1024x768x24; Xorg: DefaultDepth 24)"
            )
        );
    }

    #[test]
    fn a_screen_with_a_16_or_24_bit_true_colour_visual_is_not_refused() {
        for (depth, masks) in [(16, (0xf800, 0x7e0, 0x1f)), (24, RGB888)] {
            let depths = vec![
                Depth {
                    depth: 8,
                    visuals: vec![visual(0x21, VisualClass::PSEUDO_COLOR, (0, 0, 0))],
                },
                Depth {
                    depth,
                    visuals: vec![visual(0x30, VisualClass::TRUE_COLOR, masks)],
                },
            ];
            assert_eq!(screen_refusal(&setup_with(screen(0x21, depths)), 0), None);
        }
    }

    #[test]
    fn a_screen_with_nothing_to_draw_into_gets_no_visual() {
        let depths = vec![Depth {
            depth: 8,
            visuals: vec![visual(0x21, VisualClass::PSEUDO_COLOR, (0, 0, 0))],
        }];
        assert_eq!(choose(&screen(0x21, depths)), None);
    }
}

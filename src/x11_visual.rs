//! A visual softbuffer can draw into, for the windows winit opens on X11
//! (the saver's and the settings screen's).
//! softbuffer takes 24- and 32-bit true colour with 8 bits a channel; a
//! window gets its screen's own visual unless asked otherwise, so on a
//! 30-bit or a 16-bit screen every window mode was refused, although such
//! servers also offer 32-bit (and often 24-bit) true-colour visuals.

use x11rb::connection::Connection;
use x11rb::protocol::xproto::{Screen, VisualClass, Visualtype};
use x11rb::rust_connection::RustConnection;

/// The visual to ask winit for on `$DISPLAY`'s screen: `None` when the
/// screen's own will do (or none will: the window then says why).
pub fn drawable_visual() -> Option<u32> {
    let (conn, screen) = RustConnection::connect(None).ok()?;
    drawable_visual_on(&conn, screen)
}

/// [`drawable_visual`] on screen `screen` of a connection already open.
pub fn drawable_visual_on(conn: &impl Connection, screen: usize) -> Option<u32> {
    choose(conn.setup().roots.get(screen)?)
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
    use x11rb::protocol::xproto::Depth;

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

    #[test]
    fn a_screen_with_nothing_to_draw_into_gets_no_visual() {
        let depths = vec![Depth {
            depth: 8,
            visuals: vec![visual(0x21, VisualClass::PSEUDO_COLOR, (0, 0, 0))],
        }];
        assert_eq!(choose(&screen(0x21, depths)), None);
    }
}

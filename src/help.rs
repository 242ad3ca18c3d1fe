//! The `--help` text, built from the key table so it can never fall behind.

use crate::saver::input::WINDOW_KEYS;
use crate::settings::keys::{self, KEYS};
use crate::settings::{Settings, paths};

/// Everything a user can type: modes, flags and every preference key.
pub fn text() -> String {
    let mut t = String::from(USAGE);
    t.push_str("\nPreference keys (TOML file, --set key=value, settings screen):\n");
    let defaults = Settings::default();
    for key in KEYS {
        t.push_str(&format!("  {:<15} {}\n", key.name, key.doc));
        t.push_str(&format!(
            "  {:<15}   {}; default {}\n",
            "",
            key.kind.allowed(),
            keys::get(&defaults, key)
        ));
    }
    t.push_str("\nKeys in a window (H or F1 shows them there too):\n");
    for k in WINDOW_KEYS {
        t.push_str(&format!("  {:<15} {}\n", k.label, k.doc));
    }
    let config =
        paths::config_file().map_or("(no home directory)".into(), |p| p.display().to_string());
    let data = paths::data_dir().map_or("(no home directory)".into(), |p| p.display().to_string());
    t.push_str(&format!(
        "\nPreferences file: {config}\nData sets, screenshots and the log: {data}\n"
    ));
    t
}

/// How each mode is started: the top of `--help`.
pub const USAGE: &str = "\
mountains: fractal mountains, drawn strip by strip, as a slide show.

Usage:
  mountains [OPTIONS]                  a window (Linux, macOS); the settings (Windows)
  mountains --window [OPTIONS]         a normal resizable window
  mountains /s                         full screen on every monitor; any input ends it
  mountains /p [HWND]                  preview inside a window, or a small window
  mountains /c[:HWND] | --settings     the settings
  mountains --root                     xscreensaver: draw on $XSCREENSAVER_WINDOW or the root
  mountains --window-id ID             xscreensaver preview: draw into window ID (0x.. or decimal)
  mountains --layer LAYER              Wayland: every output's background, bottom, top or overlay layer
  mountains render -o OUT.png [--size WxH] [OPTIONS]   one mountain to a PNG (.jpg: JPEG);
                                                       WxH also 720p, 1080p, 1440p, 4k (2160p), 5k, 8k
  mountains heightmap -o OUT.png [OPTIONS]             generate and save a data set (.r16: raw)
  mountains --check-config [FILE]      check a preferences file; exit 0 if good, 1 if not (2: a bad --set or flag)
  mountains --help | --version
  mountains --xscreensaver-xml | --man-page   print contrib/mountains.xml or mountains.6

Options (every mode but those that only print: --xscreensaver-xml, --man-page, /a):
  --config FILE      preferences file instead of the usual one
  --set KEY=VALUE    override one preference (repeatable), e.g. --set color=sonar
  --open FILE        show a saved data set (the modes that show a mountain): a
                     grayscale PNG heightmap, ours or a terrain tool's, or raw
                     16-bit samples (.r16, .raw); - reads standard input
                     (heightmap -o - | mountains --open -)
  -KEY VALUE         every preference key is a flag too (dashes for underscores):
                     -cragginess 40, --color sonar; booleans -shadows / -no-shadows

xscreensaver's options (the slide show's modes; --settings takes -display alone,
and --layer every one but -display):
  -fps               draw the frame rate and load in a corner
  -delay USECS       microseconds between frames while a mountain is drawn
                     (a frame at least every second, however long a delay)
  -display NAME      the X display instead of $DISPLAY
  -install, -visual V   accepted; a true-colour framebuffer needs neither

Exit status: 0 done; 1 the work failed (a file that cannot be read or written,
a broken data set, no display); 2 a mistake in what was typed, said before any work.

Windows flags take / or -, any case: /s -S /p:1234 /c:1234.
xscreensaver flags take one or two dashes: -root --root -window-id --window-id;
-root with -window-id (either order) draws into the window, as the settings
dialog's preview asks.
--layer needs a compositor with wlr-layer-shell (sway, Hyprland, river, labwc,
KDE Plasma; not GNOME): `--layer background` is a wallpaper, and the background
under swaylock-plugin's lock (swaylock-plugin --command 'mountains --layer
background'); it ends on SIGTERM or SIGINT, not on input.
";

//! `mountains.6`, the man page every xscreensaver hack has, in the plain
//! man(7) macros: the modes, the options, xscreensaver's common options and
//! every key.

use std::fmt::Write;

use super::default_text;
use crate::cli::key_flags::flag_name;
use crate::settings::keys::{KEYS, Kind};

/// The whole man page.
pub fn man_page() -> String {
    let mut m = String::from(HEAD);
    for k in KEYS {
        let flag = flag_name(k);
        let synopsis = if k.kind == Kind::Bool {
            format!(
                "\\-{flag} | \\-no\\-{flag}",
                flag = flag.replace('-', "\\-")
            )
        } else {
            format!("\\-{} \\fIvalue\\fP", flag.replace('-', "\\-"))
        };
        let _ = writeln!(m, ".TP\n.B {synopsis}");
        let _ = writeln!(
            m,
            "{}. Allowed: {}; default {}. In the preferences file: \\fB{}\\fP.",
            escape(k.doc),
            escape(&k.kind.allowed()),
            escape(&match default_text(k) {
                t if t.is_empty() => "\"\"".to_string(),
                t => t,
            }),
            k.name.replace('_', "\\_")
        );
    }
    m.push_str(TAIL);
    m
}

/// Text safe in a man page line: backslashes doubled, a leading dot or quote guarded.
fn escape(s: &str) -> String {
    let s = s.replace('\\', "\\e").replace('-', "\\-");
    if s.starts_with('.') || s.starts_with('\'') {
        format!("\\&{s}")
    } else {
        s
    }
}

const HEAD: &str = r#".TH MOUNTAINS 6 "2026" "mountains" "XScreenSaver"
.SH NAME
mountains \- fractal mountains drawn strip by strip, as a slide show
.SH SYNOPSIS
.B mountains
[\-root | \-window\-id \fIid\fP | \-\-window | \-\-layer \fIlayer\fP | /s | /p [\fIhwnd\fP] | \-\-settings]
[\-\-config \fIfile\fP] [\-\-set \fIkey\fP=\fIvalue\fP] [\-\fIkey\fP \fIvalue\fP]
[\-\-open \fIfile\fP] [\-fps] [\-delay \fIusecs\fP] [\-display \fIhost:display.screen\fP]
.br
.B mountains render \-o
.I out.png
[\-\-size \fIW\fPx\fIH\fP] [options]
.br
.B mountains heightmap \-o
.I out.png
[options]
.SH DESCRIPTION
A fractal mountain made by recursive subdivision (cragginess halved at every
level), drawn from the back to the front as shaded triangles, held, and
followed by a new one. It keeps the modes of Mountain Terrain 3.0 and Fractal
Mountain Climbing: colour filters, Sonar, Outline, Mono, water coloured by its
depth, low detail and saved data sets.
.SH MODES
.TP
.B \-root
Draw on the window in $XSCREENSAVER_WINDOW, else the root window.
.TP
.B \-window\-id \fIid\fP
Draw into the window \fIid\fP (hex with 0x, or decimal); with \-root too, as
xscreensaver's settings dialog runs its preview.
.TP
.B \-\-window
A normal resizable window (the default outside Windows).
.TP
.B /s
Full screen, a mountain on every monitor (\fBmonitors = "span"\fP: one
landscape across them); any key, click or mouse movement ends it. What an
idle daemon starts on Wayland (swayidle, hypridle); a second \fB/s\fP on the
same display ends at once.
.TP
.B /p [\fIhwnd\fP]
The preview inside the window \fIhwnd\fP (on X11 a window id, as for
\-window\-id), or a small window.
.TP
.B \-\-layer \fIlayer\fP
On Wayland, a wlr\-layer\-shell surface covering every output, drawn at the
output's real pixels: \fIlayer\fP is background, bottom, top or overlay.
\fB\-\-layer background\fP is a wallpaper, or the background under
swaylock\-plugin's lock (\fBswaylock\-plugin \-\-command 'mountains \-\-layer background'\fP).
With \fBmonitors = "span"\fP one landscape goes across the outputs, each
showing its part where the compositor's layout puts it.
Outputs that come and go are followed; it ends on SIGTERM or SIGINT, or
when the compositor closes its last surface, not on input. A compositor
without zwlr_layer_shell_v1 (GNOME) is refused with a message.
.TP
.B \-\-settings, /c[:\fIhwnd\fP]
The settings screen, a live preview beside every preference; OK saves them
into the preferences file, keeping its comments and unknown keys.
.TP
.B render \-o \fIout.png\fP [\-\-size \fIW\fPx\fIH\fP]
One complete mountain to a PNG (\fIout.jpg\fP: a JPEG), without a display;
prints its seed.
.TP
.B heightmap \-o \fIout.png\fP
Generate a data set and save it as a 16\-bit grayscale PNG heightmap
(\fIout.r16\fP: raw 16\-bit little\-endian samples).
.TP
.B \-\-check\-config [\fIfile\fP]
Check a preferences file: exit 0 if good, 1 if not, 2 for a bad flag or \-\-set.
.TP
.B \-\-xscreensaver\-xml, \-\-man\-page
Print xscreensaver's settings file for this hack, or this page.
.TP
.B \-\-help
Every mode, flag and preference key with its range.
.SH OPTIONS
Every mode but those that only print (\fB\-\-xscreensaver\-xml\fP,
\fB\-\-man\-page\fP) takes these.
.TP
.B \-\-config \fIfile\fP
The preferences file instead of the usual one (see FILES).
.TP
.B \-\-set \fIkey\fP=\fIvalue\fP
One preference for this run (repeatable); see PREFERENCE KEYS.
.TP
.B \-\-open \fIfile\fP
Show a saved data set (the modes that show a mountain): a grayscale PNG
heightmap, or raw 16\-bit samples (\fI.r16\fP, \fI.raw\fP); \fB\-\fP reads
standard input.
.SH COMMON OPTIONS
xscreensaver's options, taken by the slide show's modes (\fB\-\-settings\fP takes
\fB\-display\fP too, \fB\-\-layer\fP all but \fB\-display\fP); beside another
mode they are refused.
.TP
.B \-fps
Draw the frame rate and load in a corner.
.TP
.B \-delay \fIusecs\fP
Microseconds between frames while a mountain is drawn (a frame at least
every second, however long a delay).
.TP
.B \-display \fIhost:display.screen\fP
The X display to use.
.TP
.B \-install, \-visual \fIvisual\fP
Accepted for xscreensaver; a true-colour framebuffer needs neither.
.TP
.B \-\-version, \-V
Print the version.
.SH PREFERENCE KEYS
Every key is read from the preferences file, from \fB\-\-set\fP \fIkey\fP=\fIvalue\fP,
and from a flag of its own (one or two dashes; underscores written as dashes;
the value after a space or =: \fB\-seed 5\fP, \fB\-seed=5\fP).
"#;

const TAIL: &str = r#".SH FILES
.TP
.I ~/.config/mountains/mountains.toml
The preferences (\fBmountains \-\-settings\fP edits it).
.TP
.I ~/.local/share/mountains/mountains.log
Problems met while running as a screensaver, whose output nobody sees.
.SH ENVIRONMENT
.TP
.B XSCREENSAVER_WINDOW
The window \-root draws on.
.TP
.B DISPLAY
The X display, unless \-display is given.
.TP
.B WAYLAND_DISPLAY
The Wayland compositor (/s, \-\-window and \-\-layer use it before DISPLAY).
.SH EXIT STATUS
.TP
.B 0
Done.
.TP
.B 1
The work failed: a file that cannot be read or written, a data set that
is broken, no display, too little memory; \-\-check\-config: the file has
problems.
.TP
.B 2
A mistake in what was typed (a flag, a value, flags that conflict),
said before any work.
.SH SEE ALSO
.BR xscreensaver (1),
.BR xscreensaver\-settings (1)
.SH AUTHOR
Written by the mountains authors; 2026.
"#;

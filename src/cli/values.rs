//! The values of the flags that are not files or keys: a layer's name,
//! a window's handle, a frame's size.

use super::{Layer, UsageError};
use crate::quote::clipped;
use crate::render::Size;

/// `--layer NAME`, typed as `typed`: one of [`Layer::NAMES`], or a
/// message listing them.
pub(super) fn layer_named(typed: &str, name: &str) -> Result<Layer, UsageError> {
    Layer::named(name).ok_or_else(|| {
        let names: Vec<&str> = Layer::NAMES.iter().map(|(n, _)| *n).collect();
        UsageError(format!("{typed}: expected one of {}", names.join(", ")))
    })
}

/// An X window id `text` for `flag`, typed with it as `typed`: a handle
/// that fits X's 32 bits.
pub(super) fn x_window_id(flag: &str, typed: &str, text: &str) -> Result<u64, UsageError> {
    let id = handle_for(flag, text)?;
    if id > u64::from(u32::MAX) {
        return Err(UsageError(format!(
            "{typed}: X window ids have 32 bits (at most 0xffffffff)"
        )));
    }
    Ok(id)
}

/// The window handle `text` given to `flag`, or a message naming both.
pub(super) fn handle_for(flag: &str, text: &str) -> Result<u64, UsageError> {
    parse_handle(text).map_err(|e| UsageError(format!("{flag}: {e}")))
}

/// A window handle: decimal, or hex with `0x` (xscreensaver writes both).
pub fn parse_handle(text: &str) -> Result<u64, UsageError> {
    let t = text.trim();
    let parsed = match t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        Some(hex) => u64::from_str_radix(hex, 16),
        None => t.parse::<u64>(),
    };
    match parsed {
        Ok(h) if h != 0 => Ok(h),
        _ => Err(UsageError(format!(
            "`{}` is not a window handle (a decimal number, or hex with 0x)",
            clipped(text)
        ))),
    }
}

/// The longest side `--size` takes, in pixels. No screen or picture needs
/// more, and a frame one pixel high and 2^28 wide (inside the frame's
/// pixel count) took 97 s and 3.5 GB: the work of a frame grows with each
/// side, not only with its pixels.
pub const MAX_SIDE: u32 = 32768;

/// The screens' sizes `--size` also takes by name (any case), as people
/// call them.
pub(super) const NAMED_SIZES: &[(&str, u32, u32)] = &[
    ("720p", 1280, 720),
    ("1080p", 1920, 1080),
    ("1440p", 2560, 1440),
    ("4k", 3840, 2160),
    ("2160p", 3840, 2160),
    ("5k", 5120, 2880),
    ("8k", 7680, 4320),
];

/// `--size WIDTHxHEIGHT` (or one of [`NAMED_SIZES`]): both sides from 1
/// to [`MAX_SIDE`].
pub(super) fn parse_size(text: &str) -> Result<Size, UsageError> {
    let text = text.trim();
    if let Some(&(_, w, h)) = NAMED_SIZES
        .iter()
        .find(|(n, ..)| n.eq_ignore_ascii_case(text))
    {
        return Ok(Size::new(w, h));
    }
    // The size as a message echoes it: a flood typed is no flood said.
    let shown = clipped(text);
    let bad = || {
        let names: Vec<&str> = NAMED_SIZES.iter().map(|(n, ..)| *n).collect();
        UsageError(format!(
            "--size {shown}: expected WIDTHxHEIGHT, e.g. 1920x1080, or one of {}",
            names.join(", ")
        ))
    };
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let too_large = || {
        UsageError(format!(
            "--size {shown}: too large (each side at most {MAX_SIDE} pixels)"
        ))
    };
    // A side of digits past what a number holds is a size too large, not
    // a misspelling (`4294967296x1` was "expected WIDTHxHEIGHT").
    let side = |s: &str| -> Result<u32, UsageError> {
        let s = s.trim();
        match s.parse::<u32>() {
            Ok(n) => Ok(n),
            Err(_) if !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()) => Err(too_large()),
            Err(_) => Err(bad()),
        }
    };
    let size = Size::new(side(w)?, side(h)?);
    if size.is_empty() {
        return Err(UsageError(format!(
            "--size {shown}: too small (each side at least 1 pixel)"
        )));
    }
    if size.width.max(size.height) > MAX_SIDE {
        return Err(too_large());
    }
    // Said here with the other bounds, before any other check or warning:
    // `render` found it only once its output was asked about.
    let most = crate::render::frame::MAX_PIXELS;
    if size.pixels() > most {
        return Err(UsageError(format!(
            "--size {shown}: too large (at most {most} pixels in all)"
        )));
    }
    Ok(size)
}

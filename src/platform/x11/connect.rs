//! Why the X display cannot be reached, in words: a connection of our own
//! says what winit's "Failed to open connection to X server" does not.

use x11rb::errors::{ConnectError, DisplayParsingError};

use crate::saver::error::{SaverError, display_as_named, without_source_place};

/// The display named by `DISPLAY` could not be reached.
pub fn connect_failed(e: ConnectError) -> SaverError {
    match (e, std::env::var("DISPLAY")) {
        (ConnectError::DisplayParsingError(DisplayParsingError::MalformedValue(_)), Ok(d)) => {
            SaverError::NoDisplay(format!(
                "{} is not a display name (such as :0, :1 or host:0)",
                display_as_named(&d)
            ))
        }
        (e, _) => SaverError::no_display(&e.to_string()),
    }
}

/// winit could not open the X display: its words say only "Failed to
/// open connection to X server", after a place in its source. A
/// connection of our own says why (nobody answers, an unknown host, a
/// malformed name), in the same words as the embedded modes.
pub fn x_unreachable(winit_detail: &str) -> SaverError {
    match x11rb::rust_connection::RustConnection::connect(None) {
        Err(e) => connect_failed(e),
        Ok(_) => SaverError::no_display(&without_source_place(winit_detail)),
    }
}

//! Pointer moves the X server makes itself: when the screen shrinks, or a
//! monitor goes, the server puts the pointer back onto what is left of the
//! screen, and the input grab reports that as a motion like any other. A
//! mode change (a docking laptop, a game, a projector) then ended the
//! full-screen saver with nobody there.
//!
//! The server tells of the screen's change (RandR events, the root's
//! ConfigureNotify) before the motion it queues for the pointer it moved.
//! So on each such event the grab's connection asks where the pointer is
//! now: that place is the new origin, and a motion the server sent before
//! it answered was its own move, not a person's. A motion after the answer
//! is measured from the new origin as usual.

use x11rb::connection::{Connection, SequenceNumber};
use x11rb::protocol::Event;
use x11rb::protocol::randr::{ConnectionExt as _, NotifyMask};
use x11rb::protocol::xproto::{ChangeWindowAttributesAux, ConnectionExt as _, EventMask};

/// Asks the server, on the grab's connection, to tell when the screen
/// changes; false when it cannot (no RandR: the root's ConfigureNotify
/// still tells of a new size).
pub fn watch_screen(conn: &impl Connection, root: u32) -> bool {
    let structure = ChangeWindowAttributesAux::new().event_mask(EventMask::STRUCTURE_NOTIFY);
    let root_watched = conn
        .change_window_attributes(root, &structure)
        .is_ok_and(|c| c.check().is_ok());
    let mask = NotifyMask::SCREEN_CHANGE | NotifyMask::CRTC_CHANGE | NotifyMask::OUTPUT_CHANGE;
    let randr_watched = conn
        .randr_query_version(1, 2)
        .ok()
        .and_then(|c| c.reply().ok())
        .is_some()
        && conn
            .randr_select_input(root, mask)
            .is_ok_and(|c| c.check().is_ok());
    root_watched || randr_watched
}

/// True for the events that tell the screen or its monitors changed.
pub fn is_screen_change(event: &Event, root: u32) -> bool {
    match event {
        Event::ConfigureNotify(e) => e.window == root,
        Event::RandrScreenChangeNotify(_) | Event::RandrNotify(_) => true,
        _ => false,
    }
}

/// Which motions are the server's own: those it sent before answering the
/// last question asked after a screen change.
#[derive(Debug, Default, Clone, Copy)]
pub struct ServerMoves {
    /// The sequence number of that question.
    answered_at: Option<SequenceNumber>,
}

impl ServerMoves {
    /// After a screen change: where the server has put the pointer (root
    /// coordinates), the origin to measure from now. `None` if it does not
    /// answer.
    pub fn look(&mut self, conn: &impl Connection, root: u32) -> Option<(i16, i16)> {
        let cookie = conn.query_pointer(root).ok()?;
        self.answered_at = Some(cookie.sequence_number());
        let reply = cookie.reply().ok()?;
        Some((reply.root_x, reply.root_y))
    }

    /// True if an event with sequence number `sequence` (the last request
    /// the server had read from us when it sent the event) came before the
    /// answer to `look`: a motion that the answer's place already counts.
    pub fn before_the_answer(&self, sequence: SequenceNumber) -> bool {
        self.answered_at.is_some_and(|q| sequence < q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_motion_sent_before_the_answer_is_the_servers() {
        let mut moves = ServerMoves::default();
        assert!(!moves.before_the_answer(0), "no screen change yet");
        moves.answered_at = Some(40);
        assert!(moves.before_the_answer(39));
        assert!(!moves.before_the_answer(40));
        assert!(!moves.before_the_answer(41));
    }
}

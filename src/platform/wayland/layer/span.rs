//! `--layer` with `monitors = "span"`: one landscape across every output,
//! as full screen spans its monitors (`saver/span.rs`). Each output's
//! surface keeps a black show that the span's show copies its part into,
//! where the compositor's layout puts the output (its logical position).
//! The span is drawn in the compositor's units: on an output of scale 2
//! the compositor enlarges its part (the parts of outputs of different
//! scales would not otherwise meet).
//!
//! It is laid once every output's surface has its size; an output that
//! comes, goes or moves later shows what it can of the slide on screen,
//! and the next slide is laid over the outputs there are then.

use std::time::Instant;

use super::LayerApp;
use crate::render::Damage;
use crate::saver::heads::Head;
use crate::saver::span::Span;
use crate::settings::Monitors;

impl LayerApp {
    /// True when the outputs show one landscape across them.
    pub(super) fn spans(&self) -> bool {
        self.settings.monitors == Monitors::Span
    }

    /// Where surface `i` lies in the compositor's layout, as large as its
    /// show; `None` before the compositor has sized it.
    fn head_of(&self, i: usize) -> Option<Head> {
        let c = &self.covered[i];
        let size = c.drawing.as_ref()?.show.size();
        let info = self.outputs.info(&c.output);
        let (x, y) = info.and_then(|o| o.logical_position).unwrap_or((0, 0));
        Some(Head {
            x,
            y,
            width: size.width,
            height: size.height,
            primary: false,
        })
    }

    /// The places of the surfaces drawn, in the order of `covered`
    /// (`None` for one not sized yet).
    fn span_heads(&self) -> Vec<Option<Head>> {
        (0..self.covered.len()).map(|i| self.head_of(i)).collect()
    }

    /// Surface `i` was sized (first, or again): the span is laid once
    /// every surface has its size; later the surface shows its part of the
    /// slide on screen.
    pub(super) fn span_fitted(&mut self, i: usize, now: Instant) {
        let heads = self.span_heads();
        if self.span.is_none() {
            if heads.iter().all(Option::is_some) {
                self.lay_span(now);
            }
            return;
        }
        self.paint_span(i, &heads, None);
    }

    /// One show over the bounding rectangle of the surfaces' places, each
    /// surface showing its part.
    fn lay_span(&mut self, now: Instant) {
        let heads = self.span_heads();
        let placed: Vec<Head> = heads.iter().flatten().copied().collect();
        let (settings, opened, seen) = (&self.settings, &self.opened, self.seen);
        let pacing = crate::saver::slideshow::Pacing::from_seconds(
            settings.draw_seconds,
            settings.pause_seconds,
            true,
        );
        self.span = Span::new(&placed, |size| {
            let mut show = crate::saver::options::new_show(
                settings.clone(),
                opened.clone(),
                pacing,
                size,
                now,
            );
            crate::saver::watch::apply(seen, &mut show, now);
            show
        });
        for i in 0..self.covered.len() {
            self.paint_span(i, &heads, None);
        }
    }

    /// Copies the span's new pixels (`damage`, or all of them) into
    /// surface `i` (placed at `heads[i]`) and presents them.
    fn paint_span(&mut self, i: usize, heads: &[Option<Head>], damage: Option<&Damage>) {
        let (Some(span), Some(Some(head))) = (&self.span, heads.get(i)) else {
            return;
        };
        let Some(drawing) = self.covered[i].drawing.as_mut() else {
            return;
        };
        let changed = match damage {
            Some(d) => span.paint_to(head, &mut drawing.show, d),
            None => span.paint_to(head, &mut drawing.show, &span.everything()),
        };
        self.present(i, changed);
    }

    /// Moves the span's show on and copies what changed to every surface;
    /// a new slide after the outputs changed is laid over them as they
    /// are now.
    pub(super) fn tick_span(&mut self, now: Instant) {
        let heads = self.span_heads();
        let Some(span) = self.span.as_mut() else {
            return;
        };
        let slide = span.slide();
        let damage = span.tick(now);
        let placed: Vec<Head> = heads.iter().flatten().copied().collect();
        if span.slide() != slide && !span.laid_for(&placed) {
            return self.lay_span(now);
        }
        for i in 0..self.covered.len() {
            self.paint_span(i, &heads, Some(&damage));
        }
    }

    /// The span's show follows the power and the outputs' state.
    pub(super) fn follow_span(&mut self, seen: crate::saver::watch::Seen, now: Instant) {
        let changed = self.span.as_mut().map(|s| s.follow(seen, now));
        if changed.is_some_and(|c| !c.is_empty()) {
            let heads = self.span_heads();
            for i in 0..self.covered.len() {
                self.paint_span(i, &heads, None);
            }
        }
    }

    /// When the span's show wants to be woken.
    pub(super) fn span_wake_at(&self, now: Instant) -> Option<Instant> {
        self.span.as_ref().and_then(|s| s.wake_at(now))
    }
}

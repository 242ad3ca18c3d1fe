//! The mountain a show has on screen, whose heights a held slide lets go
//! while the next mountain is made.
//!
//! At 4K the auto grid has 2049 points a side: 16.8 MB of heights. Holding
//! the shown mountain's heights while the next one is generated put two
//! fields beside the frame and the window's image, past what a screensaver
//! should hold. A generated mountain is its seed and the generator's
//! settings ("one seed, one mountain"), so its heights are let go during the
//! hold and made again, bit for bit, in the rare case something wants them
//! before the slide leaves the screen (a redraw after a resize or a colour
//! change, saving the data set).

use std::sync::Arc;

use crate::mountain::Mountain;
use crate::settings::Settings;
use crate::terrain::heightmap::GeneratorParams;
use crate::terrain::{self, Heightfield};

/// The mountain on screen: its heights, or how to make them again.
pub(super) struct OnScreen {
    seed: Option<u64>,
    generated: bool,
    /// What a data set's file recorded (see `Mountain::recorded`).
    recorded: Option<GeneratorParams>,
    heights: Heights,
}

/// Where a shown mountain's heights are.
enum Heights {
    /// In memory; with the generator's settings (detail fitted) when the
    /// seed makes them again.
    Kept(Arc<Heightfield>, Option<Settings>),
    /// Let go: the generator makes them again from the seed under these
    /// settings.
    Parked(u64, Settings),
}

impl OnScreen {
    /// `mountain`, which the generator made under `made` (the detail
    /// fitted) if it is a generated one; `None` for a data set read from a
    /// file, whose heights are always kept.
    pub(super) fn new(mountain: Mountain, made: Option<Settings>) -> Self {
        let remakes = mountain.generated && mountain.seed.is_some();
        OnScreen {
            seed: mountain.seed,
            generated: mountain.generated,
            recorded: mountain.recorded,
            heights: Heights::Kept(mountain.field, made.filter(|_| remakes)),
        }
    }

    /// The seed that made the mountain, if one did.
    pub(super) fn seed(&self) -> Option<u64> {
        self.seed
    }

    /// Whether the generator made it (a remake from the seed gives it again).
    pub(super) fn generated(&self) -> bool {
        self.generated
    }

    /// The heights, made again from the seed if they were let go.
    pub(super) fn field(&self) -> Arc<Heightfield> {
        match &self.heights {
            Heights::Kept(field, _) => field.clone(),
            Heights::Parked(seed, made) => Arc::new(terrain::generate(made, *seed)),
        }
    }

    /// The whole mountain (see [`OnScreen::field`]).
    pub(super) fn mountain(&self) -> Mountain {
        Mountain {
            field: self.field(),
            seed: self.seed,
            generated: self.generated,
            recorded: self.recorded.clone(),
        }
    }

    /// The settings it is drawn with under the preferences `prefs` (see
    /// `Mountain::drawn_with`).
    pub(super) fn drawn_with(&self, prefs: &Settings) -> Settings {
        Mountain::drawn_under(self.recorded.as_ref(), prefs)
    }

    /// The seed and the generator's settings, while the heights are let go.
    pub(super) fn parked(&self) -> Option<(u64, &Settings)> {
        match &self.heights {
            Heights::Parked(seed, made) => Some((*seed, made)),
            Heights::Kept(..) => None,
        }
    }

    /// Lets the heights go if the seed makes them again; they are freed
    /// once no painter or redraw holds them any more.
    pub(super) fn park(&mut self) {
        if let (Heights::Kept(_, Some(made)), Some(seed)) = (&self.heights, self.seed) {
            self.heights = Heights::Parked(seed, made.clone());
        }
    }

    /// Keeps `field`, a redraw's heights: the same ones, or those of a
    /// remake under `made`.
    pub(super) fn redrawn(&mut self, field: Arc<Heightfield>, made: Option<Settings>) {
        let made = made.or_else(|| match &mut self.heights {
            Heights::Kept(_, made) => made.take(),
            Heights::Parked(_, made) => Some(made.clone()),
        });
        let remakes = self.generated && self.seed.is_some();
        self.heights = Heights::Kept(field, made.filter(|_| remakes));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::Detail;

    fn made() -> Settings {
        Settings {
            detail: Detail::Level(5),
            ..Settings::default()
        }
    }

    #[test]
    fn parked_heights_come_back_bit_for_bit() {
        let mountain = Mountain::from_seed(&made(), 23);
        let kept = mountain.field.clone();
        let mut shown = OnScreen::new(mountain, Some(made()));
        shown.park();
        assert_eq!(shown.parked().map(|(seed, _)| seed), Some(23));
        assert_eq!(
            Arc::strong_count(&kept),
            1,
            "the show still holds the heights"
        );
        assert_eq!(*shown.field(), *kept);
        let back = shown.mountain();
        assert_eq!((back.seed, back.generated), (Some(23), true));
        shown.redrawn(back.field, None);
        assert!(shown.parked().is_none());
        shown.park();
        assert!(shown.parked().is_some(), "the remake's settings were lost");
    }

    #[test]
    fn a_data_set_read_from_a_file_is_never_let_go() {
        let mut read = Mountain::from_seed(&made(), 5);
        read.generated = false;
        let mut shown = OnScreen::new(read, Some(made()));
        shown.park();
        assert!(shown.parked().is_none());
        let unknown = OnScreen::new(Mountain::from_seed(&made(), 5), None);
        let mut unknown = unknown;
        unknown.park();
        assert!(unknown.parked().is_none(), "parked without its settings");
    }
}

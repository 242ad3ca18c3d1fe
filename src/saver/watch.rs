//! Whether anyone can see the show, and at what cost: the power supply
//! (every three seconds, `crate::platform::power`) and whether the display is powered
//! on (X11: DPMS, asked every second, `x11/dpms.rs`; Wayland: the
//! compositor's output power events, `wayland/power.rs`; Windows: the
//! console display state, `win32/display.rs`). A change is written to the
//! log file and handed to the event loop, which applies it to every show
//! (`apply`): a hold on battery, longer pauses, or no work at all while the
//! display is off.
//!
//! The looks are a few file reads every three seconds and one X request a
//! second, on a thread that sleeps in between: the event loop itself is not
//! woken unless something changed.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use super::show::Show;
use super::slideshow::Economy;
use crate::platform::power::Power;
use crate::render::Rect;
use crate::settings::OnBattery;

/// Time between two looks at a polled display: a display turned off is
/// followed within it (no work within two seconds of the switch).
const LOOK_EVERY: Duration = Duration::from_secs(1);

/// Looks at the display per look at the power supply: a change of power is
/// followed within three seconds, and a minute of holding costs a few
/// milliseconds of reading files.
const LOOKS_PER_POWER_LOOK: u32 = 3;

/// What the watcher sees.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Seen {
    /// The power supply.
    pub power: Power,
    /// The display is powered on (or nobody can tell).
    pub display_on: bool,
}

/// Asks the display whether it is on; `None` when it cannot tell.
pub type Probe = Box<dyn FnMut() -> Option<bool> + Send>;

/// Hands a change to the event loop.
type Notify = Box<dyn Fn(Seen) + Send>;

/// The watcher's state, shared by its threads.
#[derive(Clone)]
pub struct Watcher {
    inner: Arc<(Mutex<Seen>, Mutex<Notify>)>,
}

impl Watcher {
    /// Looks at the power now (logging it) and every three seconds from
    /// now on, and at the display every second with `probe` if given;
    /// `notify` is called on every change.
    pub fn start(probe: Option<Probe>, notify: impl Fn(Seen) + Send + 'static) -> Self {
        let seen = Seen {
            power: crate::platform::power::read(),
            display_on: true,
        };
        crate::log::record(&format!("power: {}", seen.power.describe()));
        let watcher = Watcher {
            inner: Arc::new((Mutex::new(seen), Mutex::new(Box::new(notify)))),
        };
        let looking = watcher.clone();
        let spawned = std::thread::Builder::new()
            .name("power".into())
            .spawn(move || looking.look_forever(probe));
        if let Err(e) = spawned {
            crate::log::warn(&format!(
                "power and display changes will not be followed: {e}"
            ));
        }
        watcher
    }

    /// What was seen last.
    pub fn seen(&self) -> Seen {
        *self.inner.0.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The display is on or off now (from a display's own events).
    pub fn set_display(&self, on: bool) {
        self.update(|seen| seen.display_on = on);
    }

    fn look_forever(&self, mut probe: Option<Probe>) {
        // Without a display to ask, the thread wakes only for the power.
        let (pause, power_every) = match probe {
            Some(_) => (LOOK_EVERY, LOOKS_PER_POWER_LOOK),
            None => (LOOK_EVERY * LOOKS_PER_POWER_LOOK, 1),
        };
        let mut look: u32 = 0;
        loop {
            if look.is_multiple_of(power_every) {
                let power = crate::platform::power::read();
                self.update(|seen| seen.power = power);
            }
            if let Some(on) = probe.as_mut().and_then(|p| p()) {
                self.update(|seen| seen.display_on = on);
            }
            look = look.wrapping_add(1);
            std::thread::sleep(pause);
        }
    }

    /// Changes what is seen; a change is logged and notified.
    fn update(&self, change: impl FnOnce(&mut Seen)) {
        let (seen, notify) = &*self.inner;
        let (old, new) = {
            let mut seen = seen.lock().unwrap_or_else(|e| e.into_inner());
            let old = *seen;
            change(&mut seen);
            (old, *seen)
        };
        if old == new {
            return;
        }
        if old.power != new.power {
            crate::log::record(&format!("power: {}", new.power.describe()));
        }
        if old.display_on != new.display_on {
            let state = if new.display_on { "on" } else { "off" };
            crate::log::record(&format!("display: {state}"));
        }
        let notify = notify.lock().unwrap_or_else(|e| e.into_inner());
        notify(new);
    }
}

/// The slide show's behaviour for `power` under the `on_battery` key.
pub fn economy(power: Power, on_battery: OnBattery) -> Economy {
    match (power.economy(), on_battery) {
        (false, _) | (true, OnBattery::Same) => Economy::None,
        (true, OnBattery::Hold) => Economy::Hold,
        (true, OnBattery::Slow) => Economy::Slow,
    }
}

/// Makes `show` follow `seen`: the pixels that changed (a fresh slide
/// when the display came back).
pub fn apply(seen: Seen, show: &mut Show, now: Instant) -> Rect {
    show.set_economy(economy(seen.power, show.settings().on_battery));
    show.set_display(seen.display_on, now)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A display that a probe finds off is told within a look or two, once;
    /// a display event says it is on again.
    #[test]
    fn a_probe_that_finds_the_display_off_is_told_once() {
        let (tx, rx) = std::sync::mpsc::channel();
        let probe: Probe = Box::new(|| Some(false));
        let watcher = Watcher::start(Some(probe), move |seen| {
            let _ = tx.send(seen);
        });
        let told = rx.recv_timeout(Duration::from_secs(10)).expect("told");
        assert!(!told.display_on);
        assert!(
            rx.recv_timeout(LOOK_EVERY * 4).is_err(),
            "told again without a change"
        );
        watcher.set_display(true);
        assert!(rx.recv_timeout(Duration::from_secs(10)).unwrap().display_on);
    }

    #[test]
    fn the_key_decides_only_on_battery_or_power_saver() {
        let mains = Power::default();
        let battery = Power {
            on_battery: true,
            saver: false,
        };
        let saver = Power {
            on_battery: false,
            saver: true,
        };
        assert_eq!(economy(mains, OnBattery::Hold), Economy::None);
        assert_eq!(economy(battery, OnBattery::Hold), Economy::Hold);
        assert_eq!(economy(saver, OnBattery::Hold), Economy::Hold);
        assert_eq!(economy(battery, OnBattery::Slow), Economy::Slow);
        assert_eq!(economy(battery, OnBattery::Same), Economy::None);
    }
}

//! How far the X pointer's devices moved, from XInput 2 raw motion, counting
//! only the axes a device reports relative to its last place.
//!
//! winit passes every raw motion on as a delta, but an absolute device (XTEST
//! as VNC servers drive it, a virtual machine's tablet) reports where it
//! is: absolute motion to where the pointer already is came out as a jump
//! of (300, 200) and ended the full-screen saver. An
//! absolute device's motion that moves the pointer is seen where the pointer
//! goes (the input grab's motion events); its raw values count nothing here.
//! Nor do those of the XTEST devices, whose absolute fake motion passes for
//! relative.

use std::collections::HashMap;

use x11rb::connection::Connection;
use x11rb::protocol::xinput::{
    ConnectionExt as _, Device, DeviceClassData, DeviceId, EventMask, Fp3232, RawMotionEvent,
    ValuatorMode, XIEventMask,
};

/// For each device, whether its x and y axes (valuators 0 and 1) are relative.
pub struct Devices {
    relative: HashMap<DeviceId, [bool; 2]>,
}

impl Devices {
    /// Asks for raw motion and device changes on `root`, and reads the
    /// devices; `None` when the server has no XInput 2.2 (or refuses).
    pub fn watch(conn: &impl Connection, root: u32) -> Option<Devices> {
        let version = conn.xinput_xi_query_version(2, 2).ok()?.reply().ok()?;
        if (version.major_version, version.minor_version) < (2, 2) {
            return None;
        }
        // Hierarchy changes can only be asked of all devices together.
        let masks = [
            EventMask {
                deviceid: DeviceId::from(bool::from(Device::ALL_MASTER)),
                mask: vec![XIEventMask::RAW_MOTION],
            },
            EventMask {
                deviceid: DeviceId::from(bool::from(Device::ALL)),
                mask: vec![XIEventMask::HIERARCHY],
            },
        ];
        conn.xinput_xi_select_events(root, &masks)
            .ok()?
            .check()
            .ok()?;
        Devices::query(conn)
    }

    /// The devices as they are now (after a device came or went).
    pub fn query(conn: &impl Connection) -> Option<Devices> {
        let all = DeviceId::from(bool::from(Device::ALL));
        let reply = conn.xinput_xi_query_device(all).ok()?.reply().ok()?;
        let mut relative = HashMap::new();
        for info in reply.infos.iter().filter(|i| !is_xtest(&i.name)) {
            let mut axes = [false; 2];
            for class in &info.classes {
                if let DeviceClassData::Valuator(v) = &class.data
                    && let Some(axis) = axes.get_mut(usize::from(v.number))
                {
                    *axis = v.mode == ValuatorMode::RELATIVE;
                }
            }
            relative.insert(info.deviceid, axes);
        }
        Some(Devices { relative })
    }

    /// How far `event` moved its device along x and y; an absolute axis,
    /// or a device not known, counts nothing.
    pub fn travel(&self, event: &RawMotionEvent) -> (f64, f64) {
        let axes = self.relative.get(&event.sourceid).copied();
        travel(
            axes.unwrap_or_default(),
            &event.valuator_mask,
            &event.axisvalues_raw,
        )
    }
}

/// True for the server's XTEST devices ("Virtual core XTEST pointer"): they
/// claim relative axes, but an absolute fake motion (as VNC servers send)
/// comes out with the place as its raw values. Their moves show where the
/// pointer goes instead.
fn is_xtest(name: &[u8]) -> bool {
    name.windows(5).any(|w| w == b"XTEST")
}

/// The relative part of one raw motion: `values` holds one number for each
/// bit set in `mask`, in order of the bits.
fn travel(relative: [bool; 2], mask: &[u32], values: &[Fp3232]) -> (f64, f64) {
    let mut moved = [0.0; 2];
    let set = (0..mask.len() * 32).filter(|&bit| mask[bit / 32] & (1 << (bit % 32)) != 0);
    for (bit, value) in set.zip(values) {
        if bit < 2 && relative[bit] {
            moved[bit] = f64::from(value.integral) + f64::from(value.frac) / 4_294_967_296.0;
        }
    }
    (moved[0], moved[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fp(x: f64) -> Fp3232 {
        let integral = x.floor();
        Fp3232 {
            integral: integral as i32,
            frac: ((x - integral) * 4_294_967_296.0) as u32,
        }
    }

    #[test]
    fn xtest_devices_are_known_by_name() {
        assert!(is_xtest(b"Virtual core XTEST pointer"));
        assert!(!is_xtest(b"Logitech USB Optical Mouse"));
    }

    #[test]
    fn relative_axes_move_and_absolute_ones_do_not() {
        let values = [fp(3.5), fp(-2.0)];
        assert_eq!(travel([true, true], &[0b11], &values), (3.5, -2.0));
        assert_eq!(travel([false, false], &[0b11], &values), (0.0, 0.0));
        // Only y in the mask: its value is the first.
        assert_eq!(travel([true, true], &[0b10], &[fp(7.0)]), (0.0, 7.0));
        // A wheel's valuator (bit 3) is not motion.
        assert_eq!(travel([true, true], &[0b1001], &values), (3.5, 0.0));
    }
}

//! Whether Windows has turned the display off: the console display state
//! (`GUID_CONSOLE_DISPLAY_STATE`), delivered to a callback of ours by
//! `PowerSettingRegisterNotification`, with no window and no polling.
//! Windows sends the state at once on registering, then each change.

use windows_sys::Win32::System::Power::{
    DEVICE_NOTIFY_SUBSCRIBE_PARAMETERS, POWERBROADCAST_SETTING, PowerSettingRegisterNotification,
};
use windows_sys::Win32::UI::WindowsAndMessaging::{DEVICE_NOTIFY_CALLBACK, PBT_POWERSETTINGCHANGE};
use windows_sys::core::GUID;

/// What the callback tells.
type Changed = Box<dyn Fn(bool) + Send + Sync>;

/// `GUID_CONSOLE_DISPLAY_STATE`: its data is 0 off, 1 on, 2 dimmed.
const CONSOLE_DISPLAY_STATE: GUID = GUID::from_u128(0x6fe69556_704a_47a0_8f24_c28d936fda47);

/// The display's state as the notification's data says: off only at 0.
pub fn display_on(data: u32) -> bool {
    data != 0
}

/// Follows the console display state from now on, telling `changed`
/// (true: on).
pub fn watch(changed: impl Fn(bool) + Send + Sync + 'static) {
    // Lives as long as the process: the registration is never undone.
    let context = Box::into_raw(Box::new(Box::new(changed) as Changed));
    let mut params = DEVICE_NOTIFY_SUBSCRIBE_PARAMETERS {
        Callback: Some(on_notification),
        Context: context.cast(),
    };
    let mut handle = std::ptr::null_mut();
    // SAFETY: the parameters are read during the call; the context they
    // carry is leaked above, so it outlives every callback.
    let err = unsafe {
        PowerSettingRegisterNotification(
            &CONSOLE_DISPLAY_STATE,
            DEVICE_NOTIFY_CALLBACK,
            (&mut params as *mut DEVICE_NOTIFY_SUBSCRIBE_PARAMETERS).cast(),
            &mut handle,
        )
    };
    if err != 0 {
        crate::log::record(&format!(
            "the display's power is not followed (PowerSettingRegisterNotification: error {err})"
        ));
    }
}

/// The notification callback, on a thread of Windows'.
unsafe extern "system" fn on_notification(
    context: *const std::ffi::c_void,
    kind: u32,
    setting: *const std::ffi::c_void,
) -> u32 {
    if kind != PBT_POWERSETTINGCHANGE || setting.is_null() || context.is_null() {
        return 0;
    }
    // SAFETY: Windows passes a POWERBROADCAST_SETTING for this kind, and
    // the context is the callback leaked by `watch`.
    let (setting, changed) = unsafe {
        (
            &*setting.cast::<POWERBROADCAST_SETTING>(),
            &*context.cast::<Changed>(),
        )
    };
    if !same_guid(&setting.PowerSetting, &CONSOLE_DISPLAY_STATE) || setting.DataLength < 4 {
        return 0;
    }
    // SAFETY: DataLength says four bytes follow the header.
    let data = unsafe { std::ptr::read_unaligned(setting.Data.as_ptr().cast::<u32>()) };
    changed(display_on(data));
    0
}

/// windows-sys's GUID has no `==`.
fn same_guid(a: &GUID, b: &GUID) -> bool {
    (a.data1, a.data2, a.data3, a.data4) == (b.data1, b.data2, b.data3, b.data4)
}

//! Whether the compositor has powered its outputs off, from
//! wlr-output-power-management (`zwlr_output_power_v1.mode` events, sent
//! on every change: no polling), on a connection and thread of our own.
//! The display counts as off when every output is off; a compositor
//! without the protocol cannot say, and the display counts as on.

use smithay_client_toolkit as sctk;

use sctk::reexports::client::globals::{GlobalListContents, registry_queue_init};
use sctk::reexports::client::protocol::wl_output::WlOutput;
use sctk::reexports::client::protocol::wl_registry::{self, WlRegistry};
use sctk::reexports::client::{Connection, Dispatch, QueueHandle, WEnum, delegate_noop};
use sctk::reexports::protocols_wlr::output_power_management::v1::client::{
    zwlr_output_power_manager_v1::ZwlrOutputPowerManagerV1,
    zwlr_output_power_v1::{self, Mode, ZwlrOutputPowerV1},
};

/// Follows the outputs' power on a thread of its own, telling `changed`
/// (true: on) whenever it may have changed.
pub fn watch(changed: impl Fn(bool) + Send + 'static) {
    let spawned = std::thread::Builder::new()
        .name("output-power".into())
        .spawn(move || {
            if let Err(e) = follow(Box::new(changed)) {
                crate::log::record(&format!("the outputs' power is not followed: {e}"));
            }
        });
    if let Err(e) = spawned {
        crate::log::record(&format!("the outputs' power is not followed: {e}"));
    }
}

/// One output and its power, once the compositor said it.
struct Output {
    name: u32,
    output: WlOutput,
    power: ZwlrOutputPowerV1,
    on: Option<bool>,
}

struct State {
    manager: ZwlrOutputPowerManagerV1,
    outputs: Vec<Output>,
    changed: Box<dyn Fn(bool) + Send>,
}

fn follow(changed: Box<dyn Fn(bool) + Send>) -> Result<(), String> {
    let conn = Connection::connect_to_env().map_err(|e| e.to_string())?;
    let (globals, mut queue) = registry_queue_init::<State>(&conn).map_err(|e| e.to_string())?;
    let qh = queue.handle();
    let manager: ZwlrOutputPowerManagerV1 = globals
        .bind(&qh, 1..=1, ())
        .map_err(|_| "the compositor has no zwlr_output_power_manager_v1".to_string())?;
    let mut state = State {
        manager,
        outputs: Vec::new(),
        changed,
    };
    let outputs: Vec<u32> = globals.contents().with_list(|list| {
        list.iter()
            .filter(|g| g.interface == "wl_output")
            .map(|g| g.name)
            .collect()
    });
    for name in outputs {
        state.add(globals.registry(), name, &qh);
    }
    loop {
        queue
            .blocking_dispatch(&mut state)
            .map_err(|e| e.to_string())?;
    }
}

impl State {
    fn add(&mut self, registry: &WlRegistry, name: u32, qh: &QueueHandle<Self>) {
        let output: WlOutput = registry.bind(name, 1, qh, ());
        let power = self.manager.get_output_power(&output, qh, name);
        self.outputs.push(Output {
            name,
            output,
            power,
            on: None,
        });
    }

    fn remove(&mut self, name: u32) {
        self.outputs.retain(|o| {
            if o.name == name {
                o.power.destroy();
                o.output.release_if_possible();
            }
            o.name != name
        });
        self.report();
    }

    /// Off only when every output said it is off.
    fn report(&self) {
        let off = !self.outputs.is_empty() && self.outputs.iter().all(|o| o.on == Some(false));
        (self.changed)(!off);
    }
}

/// `WlOutput::release` exists from version 3 on; bound at 1, nothing to do.
trait ReleaseIfPossible {
    fn release_if_possible(&self);
}

impl ReleaseIfPossible for WlOutput {
    fn release_if_possible(&self) {
        if sctk::reexports::client::Proxy::version(self) >= 3 {
            self.release();
        }
    }
}

impl Dispatch<WlRegistry, GlobalListContents> for State {
    fn event(
        state: &mut Self,
        registry: &WlRegistry,
        event: wl_registry::Event,
        _: &GlobalListContents,
        _: &Connection,
        qh: &QueueHandle<Self>,
    ) {
        match event {
            wl_registry::Event::Global {
                name, interface, ..
            } if interface == "wl_output" => state.add(registry, name, qh),
            wl_registry::Event::GlobalRemove { name } => state.remove(name),
            _ => {}
        }
    }
}

impl Dispatch<ZwlrOutputPowerV1, u32> for State {
    fn event(
        state: &mut Self,
        _: &ZwlrOutputPowerV1,
        event: zwlr_output_power_v1::Event,
        name: &u32,
        _: &Connection,
        _: &QueueHandle<Self>,
    ) {
        match event {
            zwlr_output_power_v1::Event::Mode { mode } => {
                let on = !matches!(mode, WEnum::Value(Mode::Off));
                if let Some(o) = state.outputs.iter_mut().find(|o| o.name == *name) {
                    o.on = Some(on);
                }
                state.report();
            }
            // The output went, or another client manages its power.
            zwlr_output_power_v1::Event::Failed => state.remove(*name),
            _ => {}
        }
    }
}

delegate_noop!(State: ignore WlOutput);
delegate_noop!(State: ZwlrOutputPowerManagerV1);

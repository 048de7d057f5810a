//! haply-probe PORT N: connects to an Inverse Service (Tactus's emulator) on localhost:PORT with the `haply`
//! crate, lists the devices from the service's snapshot, then N times sends a force to the first Inverse3 and
//! prints the force it sent and the position it read next. Output lines, one fact each:
//!   DEVICE <id> <type>
//!   VERSION <project_name> <git_tag>          (GET /version, the crate's HTTP client)
//!   HTTPDEVICE <id> <type>                    (GET /devices)
//!   SESSION <id> <profile>                    (GET /sessions)
//!   SENT <k> <fx> <fy> <fz>
//!   POS <k> <x> <y> <z>
//!   DONE
//!   CRATE-ERROR <target>: <message>           (and CRATE-WARN: whatever the crate logs at those levels)
use haply::device_model::*;
use haply::HaplyDevice;
use std::time::{Duration, Instant};

/// Prints every warning and error the crate logs as a line "CRATE-<LEVEL> <target>: <message>", so that the test
/// sees the parse errors the crate would otherwise hide behind its fallback parsing.
struct Loud;

impl log::Log for Loud {
    fn enabled(&self, m: &log::Metadata) -> bool {
        m.level() <= log::Level::Warn
    }

    fn log(&self, r: &log::Record) {
        if self.enabled(r.metadata()) {
            println!("CRATE-{} {}: {}", r.level(), r.target(), r.args());
        }
    }

    fn flush(&self) {}
}

static LOUD: Loud = Loud;

fn fail(msg: &str) -> ! {
    eprintln!("haply-probe: {}", msg);
    std::process::exit(1);
}

#[tokio::main]
async fn main() {
    if log::set_logger(&LOUD).is_ok() {
        log::set_max_level(log::LevelFilter::Warn);
    }
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 3 {
        fail("usage: haply-probe PORT N");
    }
    let port: u16 = args[1].parse().unwrap_or_else(|_| fail("PORT must be a number"));
    let n: usize = args[2].parse().unwrap_or_else(|_| fail("N must be a number"));
    let http = format!("http://127.0.0.1:{}", port);
    let ws = format!("ws://127.0.0.1:{}/", port);
    let mut device = HaplyDevice::new(&http, &ws)
        .await
        .unwrap_or_else(|e| fail(&format!("connect: {}", e)));

    let session = SessionConfigure {
        profile: Some(ProfileConfig { name: "haply-probe".to_string(), required_version: None }),
        basis: None,
        serialization: None,
        sdf: None,
    };
    device.configure_session(session, Some(true)).await.unwrap_or_else(|e| fail(&format!("session: {}", e)));

    // the devices, as the crate reads them from the service's snapshot
    let start = Instant::now();
    let configs = loop {
        if let Ok(c) = device.get_devices().await {
            if !c.is_empty() {
                break c;
            }
        }
        if start.elapsed() > Duration::from_secs(10) {
            fail("no device in the service's snapshot");
        }
        tokio::time::sleep(Duration::from_millis(5)).await;
    };
    let mut id = String::new();
    for c in &configs {
        match c {
            Config::DeviceConfig(d) => {
                println!("DEVICE {} {:?}", d.device_info.id, d.type_);
                if id.is_empty() {
                    id = d.device_info.id.clone();
                }
            }
            Config::VGConfig(v) => println!("DEVICE {} {:?}", v.id, v.type_),
            Config::WVGConfig(v) => println!("DEVICE {} {:?}", v.id, v.type_),
        }
    }
    if id.is_empty() {
        fail("no Inverse3 in the service's snapshot");
    }

    // the service's HTTP routes on the same port, as the crate reads them
    let version = device.get_service_version().await.unwrap_or_else(|e| fail(&format!("GET /version: {}", e)));
    println!("VERSION {} {}", version.project_name, version.git_tag);
    let listed = device.list_devices().await.unwrap_or_else(|e| fail(&format!("GET /devices: {}", e)));
    for c in &listed {
        match c {
            Config::DeviceConfig(d) => println!("HTTPDEVICE {} {:?}", d.device_info.id, d.type_),
            Config::VGConfig(v) => println!("HTTPDEVICE {} {:?}", v.id, v.type_),
            Config::WVGConfig(v) => println!("HTTPDEVICE {} {:?}", v.id, v.type_),
        }
    }
    let sessions = haply::http::InverseHttpClient::new(&http)
        .get_sessions()
        .await
        .unwrap_or_else(|e| fail(&format!("GET /sessions: {}", e)));
    for s in &sessions.sessions {
        let profile = s.config.as_ref().and_then(|c| c.profile_name.clone()).unwrap_or_default();
        println!("SESSION {} {}", s.session_id, profile);
    }

    for k in 0..n {
        let kf = k as f32;
        let force = Force { x: 0.5 + 0.01 * kf, y: -0.25, z: 0.001 * kf };
        let before = device.state.lock().await.timestamp;
        device
            .update_force(vec![ForceInput { device_id: id.clone(), forces: force }], Some(true), Some(true))
            .await
            .unwrap_or_else(|e| fail(&format!("send: {}", e)));
        println!("SENT {} {} {} {}", k, force.x, force.y, force.z);
        let t0 = Instant::now();
        loop {
            if device.state.lock().await.timestamp > before {
                break;
            }
            if t0.elapsed() > Duration::from_secs(5) {
                fail("no state frame answered a force");
            }
            tokio::time::sleep(Duration::from_micros(200)).await;
        }
        let state = device.read_state().await.unwrap_or_else(|e| fail(&format!("read: {}", e)));
        let p = state
            .inverse3
            .iter()
            .find(|d| d.device_id == id)
            .and_then(|d| d.state.cursor_position)
            .unwrap_or_else(|| fail("the state has no cursor_position"));
        println!("POS {} {} {} {}", k, p.x, p.y, p.z);
    }
    let _ = device.shutdown().await;
    println!("DONE");
}

//! Support for the hardening tests: run the real `fieldbal serve` binary,
//! read its peak memory, and build sessions of a given size.
#![allow(dead_code)] // each test binary uses a different part of this module

use std::path::Path;
use std::process::Child;
use std::time::Duration;

use serde_json::{json, Value};

/// A running `fieldbal serve`; killed (SIGKILL) when dropped.
pub struct Binary {
    pub child: Child,
    pub addr: String,
}

impl Binary {
    /// Start `fieldbal serve --listen 127.0.0.1:0 --database DB ARGS…` and wait for its address.
    pub fn start(db: &Path, args: &[&str]) -> Binary {
        let mut all = vec!["--listen", "127.0.0.1:0", "--database"];
        let db = db.to_str().expect("utf-8 path");
        all.push(db);
        all.extend_from_slice(args);
        let (child, addr) = crate::common::binary::start(None, &all, &[]);
        Binary { child, addr }
    }

    pub fn url(&self, path: &str) -> String {
        format!("http://{}{path}", self.addr)
    }

    /// Peak resident memory of the process so far (VmHWM), bytes.
    pub fn peak_rss_bytes(&self) -> u64 {
        let status = std::fs::read_to_string(format!("/proc/{}/status", self.child.id()))
            .expect("/proc/<pid>/status is readable");
        let line = status
            .lines()
            .find(|l| l.starts_with("VmHWM:"))
            .expect("VmHWM in /proc/<pid>/status");
        let kb: u64 = line
            .split_whitespace()
            .nth(1)
            .and_then(|n| n.parse().ok())
            .expect("VmHWM in kB");
        kb * 1024
    }

    /// SIGKILL and reap.
    pub fn kill(mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Drop for Binary {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A client that waits long enough for the largest solves.
pub fn client() -> reqwest::Client {
    reqwest::Client::builder()
        .timeout(Duration::from_secs(120))
        .build()
        .unwrap()
}

/// A solvable session: `planes` planes, one trial run per plane (a weight in
/// that plane alone), `sensors` sensors read at `speeds` speeds in every run.
/// Readings follow a made-up linear rotor so the solve is well posed.
pub fn session(planes: usize, sensors: usize, speeds: usize) -> Value {
    // 2 % apart: every speed is its own speed point (1 % tolerance).
    let speed = |p: usize| (1000.0 * 1.02f64.powi(p as i32)).round();
    let reading = |run: usize, s: usize, p: usize| {
        let base = 20.0 + ((s * 7 + p * 3) % 17) as f64;
        let effect = if run == 0 {
            0.0
        } else {
            5.0 + ((run + s + p) % 5) as f64
        };
        json!({
            "speed_rpm": speed(p),
            "sensor": format!("S{s}"),
            "amplitude": base + effect,
            "phase_deg": ((s * 13 + p * 29 + run * 71) % 360) as f64,
        })
    };
    let runs: Vec<Value> = (0..=planes)
        .map(|run| {
            let weights = if run == 0 {
                vec![]
            } else {
                vec![json!({"plane": format!("P{}", run - 1), "mass_g": 10.0, "angle_deg": 0.0})]
            };
            let readings: Vec<Value> = (0..sensors)
                .flat_map(|s| (0..speeds).map(move |p| (s, p)))
                .map(|(s, p)| reading(run, s, p))
                .collect();
            json!({"id": format!("R{run}"), "weights": weights, "readings": readings})
        })
        .collect();
    json!({
        "name": "large",
        "planes": (0..planes).map(|i| json!({"id": format!("P{i}"), "radius_mm": 100})).collect::<Vec<_>>(),
        "sensors": (0..sensors).map(|i| json!({"id": format!("S{i}"), "unit": "um_pp"})).collect::<Vec<_>>(),
        "runs": runs,
    })
}

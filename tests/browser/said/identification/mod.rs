//! What the identification answers say on the page: a damping the readings
//! cannot resolve, a critical speed outside the speeds read and with its
//! half-width, and a free decay pasted on its page.

pub(super) mod critical;
pub(super) mod damping;
pub(super) mod decay;

/// Jeffcott rotors for the identification scenes (`damping`, `critical`).
#[path = "../../../identification/support.rs"]
mod jeffcott;

use crate::harness::stand::{post, Stand};

/// A 150 kg Jeffcott rotor critical at 2450 rpm with damping ratio `zeta`,
/// read in µm pk-pk at `speeds` with `noise` (relative, drawn with `seed`):
/// its session, and what `POST /api/v1/identify/rotor` says of it, to
/// compare the page with.
async fn identified(
    stand: &Stand,
    zeta: f64,
    speeds: &[f64],
    noise: f64,
    seed: u64,
) -> (serde_json::Value, serde_json::Value) {
    use fieldbal::balancing::model::Unit;
    let rotor = jeffcott::Jeffcott::with(150.0, 2450.0, zeta);
    let session = jeffcott::session(&[rotor], speeds, Unit::UmPp, noise, seed);
    let session = serde_json::to_value(session).unwrap();
    let body = serde_json::json!({ "session": session });
    let said = post(stand, "/api/v1/identify/rotor", body).await;
    (session, said)
}

//! Crash safety: writers post sessions while the real binary is killed with
//! SIGKILL; after a restart every write that was answered 201 is there, whole.
//! Bounded: three cycles, each ended after a bounded number of writes.

use crate::common;
use crate::support;

use std::sync::{Arc, Mutex};

use common::{example, post, send};
use serde_json::{json, Value};
use support::{client, Binary};

const CYCLES: usize = 3;
const WRITERS: usize = 4;
/// Acknowledged writes per cycle before the kill.
const WRITES_BEFORE_KILL: usize = 40;

#[tokio::test]
async fn every_acknowledged_write_survives_kill_9() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("crash.db");
    let client = client();
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let acked: Arc<Mutex<Vec<(String, String)>>> = Arc::default();

    for cycle in 0..CYCLES {
        let server = Binary::start(&db, &[]);
        let url = server.url("/api/v1/sessions");
        let start = acked.lock().unwrap().len();
        let writers: Vec<_> = (0..WRITERS)
            .map(|w| {
                let (client, url, acked) = (client.clone(), url.clone(), acked.clone());
                let mut body = session.clone();
                tokio::spawn(async move {
                    // Bounded: each writer stops at the first failure (the kill)
                    // or after its share and a margin.
                    for n in 0..WRITES_BEFORE_KILL {
                        let name = format!("cycle {cycle} writer {w} write {n}");
                        body["name"] = json!(name);
                        let Ok(res) = client.post(&url).json(&body).send().await else {
                            return;
                        };
                        if res.status() != 201 {
                            return;
                        }
                        let Ok(created) = res.json::<Value>().await else {
                            return;
                        };
                        let id = created["id"].as_str().unwrap().to_string();
                        acked.lock().unwrap().push((id, name));
                    }
                })
            })
            .collect();
        // Kill while the writers run: once a bounded number has been answered.
        for _ in 0..400 {
            if acked.lock().unwrap().len() >= start + WRITES_BEFORE_KILL {
                break;
            }
            tokio::time::sleep(std::time::Duration::from_millis(5)).await;
        }
        server.kill();
        for w in writers {
            w.await.unwrap();
        }
    }

    let server = Binary::start(&db, &[]);
    let acked = acked.lock().unwrap().clone();
    assert!(
        acked.len() >= CYCLES * WRITES_BEFORE_KILL / 2,
        "{} writes",
        acked.len()
    );
    for (id, name) in &acked {
        let (status, _, back) =
            send(client.get(server.url(&format!("/api/v1/sessions/{id}")))).await;
        assert_eq!(status, 200, "acknowledged session {id} ({name}) lost");
        assert_eq!(back["name"], json!(name));
        let runs = |v: &Value| -> Vec<fieldbal::balancing::model::Run> {
            serde_json::from_value(v["runs"].clone()).unwrap()
        };
        assert_eq!(runs(&back), runs(&session), "{name} is whole");
    }
    let (_, _, body) = post(&client, &server.url("/api/v1/sessions"), &session).await;
    assert!(
        body["id"].is_string(),
        "the database still takes writes: {body}"
    );
}

//! Storage faults: a full disk gives a clean 507 JSON error and `/healthz`
//! 503, and writes recover by themselves once space is freed; a read-only
//! database keeps the service from starting, with a message that says so.
//!
//! The full disk is simulated with SQLite's `PRAGMA max_page_count` on a pool
//! of one connection (the limit is per connection), which needs no root or
//! tmpfs: SQLite then fails page allocation with SQLITE_FULL, the error a
//! full disk gives. A full tmpfs would fail the commit's write to the WAL
//! instead; both end in the same rollback path (`db::WriteTx`).

use crate::common;

use std::sync::atomic::{AtomicI64, Ordering};

use common::{example, post, send};
use fieldbal::http::{self, AppState};
use serde_json::Value;

/// The page limit, applied to the pool's connection now and to any
/// connection the pool opens later (the service closes one whose rollback
/// failed, which SQLite's own rollback on SQLITE_FULL makes happen).
static MAX_PAGES: AtomicI64 = AtomicI64::new(1_000_000);

async fn page_count(pool: &sqlx::AnyPool) -> i64 {
    sqlx::query_scalar("PRAGMA page_count")
        .fetch_one(pool)
        .await
        .unwrap()
}

fn set_max_pages_for_new_connections(pages: i64) {
    MAX_PAGES.store(pages, Ordering::SeqCst);
}

async fn set_max_pages(pool: &sqlx::AnyPool, pages: i64) {
    set_max_pages_for_new_connections(pages);
    sqlx::query(&format!("PRAGMA max_page_count = {pages}"))
        .execute(pool)
        .await
        .unwrap();
}

/// Each new connection's set-up: the current page limit.
fn limit_pages(
    conn: &mut sqlx::AnyConnection,
) -> std::pin::Pin<Box<dyn std::future::Future<Output = sqlx::Result<()>> + Send + '_>> {
    Box::pin(async move {
        let pages = MAX_PAGES.load(Ordering::SeqCst);
        sqlx::query(&format!("PRAGMA max_page_count = {pages}"))
            .execute(&mut *conn)
            .await?;
        Ok(())
    })
}

/// A service on its own SQLite file whose disk can be filled
/// ([`set_max_pages`]). One at a time: the page limit is process-wide (a
/// connection the pool reopens takes the current one), so two such tests in
/// parallel would fill each other's disk.
struct FullDisk {
    pool: sqlx::AnyPool,
    addr: std::net::SocketAddr,
    stop: tokio::sync::oneshot::Sender<()>,
    server: tokio::task::JoinHandle<std::io::Result<()>>,
    _dir: tempfile::TempDir,
    _one_at_a_time: tokio::sync::MutexGuard<'static, ()>,
}

static ONE_FULL_DISK: tokio::sync::Mutex<()> = tokio::sync::Mutex::const_new(());

impl FullDisk {
    async fn start() -> FullDisk {
        let one_at_a_time = ONE_FULL_DISK.lock().await;
        set_max_pages_for_new_connections(1_000_000);
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("full.db");
        // One connection: the page limit applies to it, and a connection left
        // inside a transaction would block every later request.
        let pool = fieldbal::db::connect_pool(path.to_str().unwrap(), Some(1), Some(limit_pages))
            .await
            .unwrap();
        let state = AppState::new(pool.clone());
        let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
        let addr = listener.local_addr().unwrap();
        let (stop, stopped) = tokio::sync::oneshot::channel::<()>();
        let server = tokio::spawn(http::serve(listener, state, async {
            let _ = stopped.await;
        }));
        FullDisk {
            pool,
            addr,
            stop,
            server,
            _dir: dir,
            _one_at_a_time: one_at_a_time,
        }
    }

    fn url(&self, path: &str) -> String {
        format!("http://{}{path}", self.addr)
    }

    async fn stop(self) {
        let _ = self.stop.send(());
        self.server.await.unwrap().unwrap();
    }
}

#[tokio::test]
async fn writes_fail_cleanly_on_a_full_disk_and_recover_once_space_is_freed() {
    let disk = FullDisk::start().await;
    let (pool, client) = (&disk.pool, reqwest::Client::new());
    let url = |p: &str| disk.url(p);
    let session: Value = example("compressor-multispeed-noisy.json")["session"].clone();

    let (status, _, _) = send(client.get(url("/healthz"))).await;
    assert_eq!(status, 200);
    set_max_pages(pool, page_count(pool).await + 2).await;

    // Fill the allowed pages; a bounded number of sessions does it.
    let mut refused = None;
    for _ in 0..200 {
        let (status, _, body) = post(&client, &url("/api/v1/sessions"), &session).await;
        if status != 201 {
            refused = Some((status, body));
            break;
        }
    }
    let (status, body) = refused.expect("the page limit is reached within 200 sessions");
    assert_eq!(status, 507, "{body}");
    assert_eq!(body["error"]["code"], "storage_full");
    assert!(body["error"]["message"]
        .as_str()
        .unwrap()
        .contains("nothing was stored"));
    let (status, _, body) = send(client.get(url("/healthz"))).await;
    assert_eq!(status, 503, "{body}");
    assert_eq!(body["error"]["code"], "not_ready");
    // Reads still work on a full disk.
    let (status, _, _) = send(client.get(url("/api/v1/sessions"))).await;
    assert_eq!(status, 200);

    set_max_pages(pool, 1_000_000).await;
    for _ in 0..3 {
        let (status, _, body) = post(&client, &url("/api/v1/sessions"), &session).await;
        assert_eq!(status, 201, "writes recover once space is freed: {body}");
    }
    let (status, _, _) = send(client.get(url("/healthz"))).await;
    assert_eq!(status, 200);
    disk.stop().await;
}

/// `fieldbal serve` on `database`, which must refuse to start: its log.
fn serve_refused(database: &str) -> String {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(["serve", "--listen", "127.0.0.1:0", "--database", database])
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    assert!(!out.status.success(), "serve started on {database}");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[tokio::test]
async fn serve_refuses_to_start_on_a_read_only_database() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("ro.db");
    // Create it, then open it read-only (file permissions do not stop root).
    drop(fieldbal::db::connect(path.to_str().unwrap()).await.unwrap());
    let url = format!("sqlite://{}?mode=ro", path.display());
    let log = serve_refused(&url);
    assert!(log.contains("read-only"), "{log}");
}

/// A database the service cannot switch to WAL (here an SQLite file in the
/// default rollback-journal mode opened read-only; in the field, a new file in
/// a directory the service may not write, where SQLite answers
/// SQLITE_READONLY_DIRECTORY) must be refused at once with the read-only
/// message. It used to fail each new connection's set-up, which the pool
/// retried for its 30 s acquire time, and then say only "pool timed out while
/// waiting for an open connection".
#[tokio::test]
async fn serve_names_a_database_it_cannot_set_up_as_read_only() {
    use sqlx::Connection;
    sqlx::any::install_default_drivers();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("journal.db");
    let mut conn = sqlx::AnyConnection::connect(&format!("sqlite://{}?mode=rwc", path.display()))
        .await
        .unwrap();
    sqlx::query("CREATE TABLE t (x INTEGER)")
        .execute(&mut conn)
        .await
        .unwrap();
    conn.close().await.unwrap();
    let url = format!("sqlite://{}?mode=ro", path.display());
    let log = serve_refused(&url);
    assert!(log.contains("is read-only"), "{log}");
    assert!(!log.contains("timed out"), "{log}");
}

/// A PostgreSQL server that refuses the connection is named as such at
/// start, not hidden behind the pool's "timed out" ten seconds later.
#[tokio::test]
async fn serve_says_why_it_cannot_reach_postgres() {
    // Port 1 on loopback: nothing listens there, the connection is refused.
    let log = serve_refused("postgres://fieldbal:secret@127.0.0.1:1/fieldbal");
    assert!(log.contains("refused"), "{log}");
    assert!(!log.contains("timed out"), "{log}");
    assert!(!log.contains("secret"), "the password is not logged: {log}");
}

/// Every write answers 507 `storage_full` on a full disk, so the served
/// OpenAPI document must declare it for each of them (it did for storing a
/// session only): a client generated from the document would otherwise meet
/// an undeclared status on the run it appends or the solution it stores.
#[tokio::test]
async fn every_write_declares_the_full_disk_answer_it_gives() {
    let disk = FullDisk::start().await;
    let (pool, client) = (&disk.pool, reqwest::Client::new());
    let url = |p: &str| disk.url(p);
    let (status, _, doc) = send(client.get(url("/api/v1/openapi.json"))).await;
    assert_eq!(status, 200);
    let mut session: Value = example("compressor-multispeed-noisy.json")["session"].clone();
    session["machine"] = "M-FULL".into();
    let (status, _, body) = post(
        &client,
        &url("/api/v1/machines"),
        &serde_json::json!({"id": "M-FULL"}),
    )
    .await;
    assert_eq!(status, 201, "{body}");
    let (status, _, stored) = post(&client, &url("/api/v1/sessions"), &session).await;
    assert_eq!(status, 201, "{stored}");
    let id = stored["id"].as_str().unwrap().to_string();

    set_max_pages(pool, page_count(pool).await + 2).await;
    let mut full = false;
    for _ in 0..200 {
        let (status, _, _) = post(&client, &url("/api/v1/sessions"), &session).await;
        if status == 507 {
            full = true;
            break;
        }
    }
    assert!(full, "the page limit is reached within 200 sessions");

    let mut run = session["runs"][1].clone();
    run["id"] = "t1-again".into();
    let writes: Vec<(&str, &str, String, Value)> = vec![
        (
            "post",
            "/api/v1/sessions/{id}/runs",
            format!("/api/v1/sessions/{id}/runs"),
            run,
        ),
        (
            "put",
            "/api/v1/sessions/{id}/runs/{run_id}",
            format!("/api/v1/sessions/{id}/runs/t1"),
            session["runs"][1].clone(),
        ),
        (
            "post",
            "/api/v1/sessions/{id}/solutions",
            format!("/api/v1/sessions/{id}/solutions"),
            serde_json::json!({}),
        ),
        (
            "post",
            "/api/v1/machines",
            "/api/v1/machines".into(),
            serde_json::json!({"id": "M-NEW"}),
        ),
        (
            "post",
            "/api/v1/machines/{id}/coefficients",
            "/api/v1/machines/M-FULL/coefficients".into(),
            serde_json::json!({"sessions": [id]}),
        ),
    ];
    let mut refused = 0;
    let mut undeclared = Vec::new();
    for (method, template, path, body) in writes {
        let req = match method {
            "post" => client.post(url(&path)),
            _ => client.put(url(&path)),
        };
        let (status, _, answer) = send(req.json(&body)).await;
        let declared = &doc["paths"][template][method]["responses"];
        if declared.get(status.to_string()).is_none() {
            undeclared.push(format!(
                "{} {template} {status} {answer}",
                method.to_uppercase()
            ));
        }
        if status == 507 {
            refused += 1;
        }
    }
    assert!(
        undeclared.is_empty(),
        "answers the OpenAPI document does not declare: {undeclared:#?}"
    );
    assert!(refused > 0, "the full disk refused none of the writes");
    disk.stop().await;
}

/// Started with the default database (`sqlite://fieldbal.db`, relative), the
/// service says which file that is: a service started from another directory
/// opens another, empty store, and the log said only `sqlite://fieldbal.db`.
#[test]
fn serve_names_the_database_file_it_opened() {
    use std::io::BufRead;
    let dir = tempfile::tempdir().unwrap();
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(["serve", "--listen", "127.0.0.1:0"])
        .current_dir(dir.path())
        .env_remove("DATABASE_URL")
        .env_remove("FIELDBAL_TOKENS")
        .env("NO_COLOR", "1")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let lines = std::io::BufReader::new(child.stderr.take().unwrap()).lines();
    let mut listening = None;
    for line in lines {
        let line = line.unwrap();
        if line.contains("listening") {
            listening = Some(line);
            break;
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    let line = listening.expect("the service says it listens");
    let file = std::fs::canonicalize(dir.path())
        .unwrap()
        .join("fieldbal.db");
    assert!(
        line.contains(&format!("file={}", file.display())),
        "{line} (the file is {})",
        file.display()
    );
}

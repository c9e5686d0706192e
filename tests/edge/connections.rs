//! Connections: a header that never ends is cut off, an idle kept-alive
//! connection is closed, a client that stops reading its answers is
//! disconnected, connections beyond the cap are refused while the others are
//! served, and SIGTERM is not held up by a half-open connection.

use crate::common;
use crate::support;

use std::time::Duration;

use fieldbal::http::edge::connections::Limits;
use fieldbal::http::edge::EdgeConfig;
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::{TcpSocket, TcpStream};

use common::{send, start_server_configured};
use support::{closed_without_answer, read_answer, start_binary, terminate};

fn limits(header_read_secs: u64, max_connections: usize) -> EdgeConfig {
    EdgeConfig {
        connections: Limits {
            header_read_timeout: Duration::from_secs(header_read_secs),
            max_connections,
            ..Limits::default()
        },
        ..EdgeConfig::default()
    }
}

/// Open a connection and send the start of a request that never ends.
async fn half_sent(addr: std::net::SocketAddr) -> TcpStream {
    let mut stream = TcpStream::connect(addr).await.expect("connect");
    let start = format!("GET /api/v1/sessions HTTP/1.1\r\nHost: {addr}\r\nX-Slow: ");
    stream.write_all(start.as_bytes()).await.expect("sent");
    stream
}

#[tokio::test]
async fn half_sent_headers_are_cut_off_while_other_clients_are_answered() {
    let dir = tempfile::tempdir().unwrap();
    let (addr, server) =
        start_server_configured(&dir.path().join("t.db"), |s| s.with_edge(limits(2, 64))).await;
    let mut slow = Vec::new();
    for _ in 0..20 {
        slow.push(half_sent(addr).await);
    }
    let client = reqwest::Client::new();
    let (status, _, _) = send(client.get(server.url("/api/v1/sessions"))).await;
    assert_eq!(status, 200, "answered beside 20 half-sent headers");
    for stream in &mut slow {
        assert!(closed_without_answer(stream).await);
    }
    server.shutdown().await;
}

#[tokio::test]
async fn an_idle_kept_alive_connection_is_closed_after_the_header_timeout() {
    let dir = tempfile::tempdir().unwrap();
    let (addr, server) =
        start_server_configured(&dir.path().join("t.db"), |s| s.with_edge(limits(1, 64))).await;
    let mut stream = TcpStream::connect(addr).await.unwrap();
    let request = format!("GET /healthz HTTP/1.1\r\nHost: {addr}\r\n\r\n");
    stream.write_all(request.as_bytes()).await.unwrap();
    let answer = read_answer(&mut stream).await.expect("an answer");
    assert_eq!(answer.status, 200);
    assert_ne!(answer.header("connection"), Some("close"), "kept alive");
    assert!(closed_without_answer(&mut stream).await);
    server.shutdown().await;
}

#[tokio::test]
async fn a_client_that_stops_reading_its_answers_is_disconnected_after_the_write_timeout() {
    let dir = tempfile::tempdir().unwrap();
    let mut edge = limits(30, 64);
    edge.connections.write_timeout = Duration::from_secs(1);
    let (addr, server) =
        start_server_configured(&dir.path().join("t.db"), |s| s.with_edge(edge)).await;
    let client = reqwest::Client::new();
    let (status, _, document) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    assert_eq!(status, 200);
    let one = document.to_string().len();
    // Pipeline far more answer bytes than the two socket buffers hold, read none.
    let requests = (64 * 1024 * 1024 / one).max(64);
    let socket = TcpSocket::new_v4().unwrap();
    socket.set_recv_buffer_size(4096).unwrap();
    let mut stream = socket.connect(addr).await.expect("connect");
    let request = format!("GET /api/v1/openapi.json HTTP/1.1\r\nHost: {addr}\r\n\r\n");
    let all = request.repeat(requests);
    // The server stops reading requests once its answers are stuck: send what it takes.
    let _ = tokio::time::timeout(Duration::from_secs(3), stream.write_all(all.as_bytes())).await;
    tokio::time::sleep(Duration::from_secs(3)).await;
    // Now read: a disconnected stream ends (EOF or reset) well before all the answers.
    let mut received = 0usize;
    let mut buf = vec![0u8; 1 << 16];
    let ended = tokio::time::timeout(Duration::from_secs(20), async {
        loop {
            match stream.read(&mut buf).await {
                Ok(0) | Err(_) => break,
                Ok(n) => received += n,
            }
        }
    })
    .await
    .is_ok();
    assert!(ended, "the connection was closed by the server");
    assert!(
        received < requests * one,
        "only part of the {requests} answers arrived ({received} bytes of {})",
        requests * one
    );
    let (status, _, _) = send(client.get(server.url("/healthz"))).await;
    assert_eq!(status, 200, "the service still answers");
    server.shutdown().await;
}

#[tokio::test]
async fn connections_beyond_the_cap_get_503_and_the_service_recovers_when_they_go() {
    let dir = tempfile::tempdir().unwrap();
    let (addr, server) =
        start_server_configured(&dir.path().join("t.db"), |s| s.with_edge(limits(5, 8))).await;
    let mut held = Vec::new();
    for _ in 0..8 {
        held.push(half_sent(addr).await);
    }
    // Accepted after the eight (the kernel queues connections in order): over the cap.
    let mut extra = TcpStream::connect(addr).await.unwrap();
    let answer = read_answer(&mut extra).await.expect("an answer");
    assert_eq!(answer.status, 503);
    assert_eq!(answer.json()["error"]["code"], "too_many_connections");
    assert!(answer.header("retry-after").is_some());
    // Once the header timeout has cut the eight off, a client is served again.
    for stream in &mut held {
        assert!(closed_without_answer(stream).await);
    }
    let client = reqwest::Client::new();
    let (status, _, _) = send(client.get(server.url("/healthz"))).await;
    assert_eq!(status, 200);
    server.shutdown().await;
}

#[tokio::test]
async fn sigterm_with_a_half_sent_header_open_still_exits_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    // A header timeout far beyond the test: only the bounded grace period can end it.
    let (child, addr) = start_binary(
        dir.path(),
        &[
            "--header-read-timeout-secs",
            "3600",
            "--shutdown-grace-secs",
            "1",
        ],
    );
    let mut stuck = half_sent(addr).await;
    // Answered after the half-sent connection was accepted (accepts are in order).
    let client = reqwest::Client::new();
    let (status, _, _) = send(client.get(format!("http://{addr}/healthz"))).await;
    assert_eq!(status, 200);
    let status = tokio::task::spawn_blocking(move || terminate(child))
        .await
        .unwrap();
    assert!(status.success(), "{status:?}");
    assert!(closed_without_answer(&mut stuck).await);
}

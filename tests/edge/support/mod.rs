//! Raw HTTP/1.1 over TCP for the edge tests: what reqwest will not send
//! (half-sent headers, lying `Content-Length`, garbage request lines).
#![allow(dead_code)] // each edge test binary uses a different part of this module

use std::net::SocketAddr;
use std::time::Duration;

use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::TcpStream;

/// Longest wait for an answer; a bound on the loop, not a claim about speed.
pub const PATIENCE: Duration = Duration::from_secs(60);

/// A parsed answer: status, lower-cased headers, body.
#[derive(Debug)]
pub struct Answer {
    pub status: u16,
    pub headers: Vec<(String, String)>,
    pub body: Vec<u8>,
}

impl Answer {
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }

    pub fn json(&self) -> serde_json::Value {
        serde_json::from_slice(&self.body).unwrap_or_else(|e| {
            panic!(
                "status {}: body is not JSON ({e}): {:?}",
                self.status,
                String::from_utf8_lossy(&self.body)
            )
        })
    }
}

/// Send `request` as it is and read one answer (or `None` if the server
/// closes without answering).
/// The answer to a request whose head only is sent (`head` given the
/// server's address), from a fresh service with a 3 s request time limit:
/// were the body awaited, the answer would be 408, so a 4xx other than that
/// was given before the body was read.
pub async fn answer_to_head(head: impl FnOnce(SocketAddr) -> String) -> Answer {
    let dir = tempfile::tempdir().unwrap();
    let (addr, server) = crate::common::start_server_configured(&dir.path().join("t.db"), |s| {
        s.with_request_timeout(Duration::from_secs(3))
    })
    .await;
    let answer = exchange(addr, head(addr).as_bytes())
        .await
        .expect("an answer");
    server.shutdown().await;
    answer
}

pub async fn exchange(addr: SocketAddr, request: &[u8]) -> Option<Answer> {
    let mut stream = TcpStream::connect(addr).await.expect("connect");
    stream.write_all(request).await.expect("request sent");
    read_answer(&mut stream).await
}

/// Read one answer from `stream`: `None` if it is closed first.
pub async fn read_answer(stream: &mut TcpStream) -> Option<Answer> {
    let mut buf = Vec::new();
    let read = async {
        let mut chunk = [0u8; 8192];
        loop {
            if let Some(answer) = parse(&buf) {
                return Some(answer);
            }
            match stream.read(&mut chunk).await {
                Ok(0) | Err(_) => return parse(&buf),
                Ok(n) => buf.extend_from_slice(&chunk[..n]),
            }
        }
    };
    tokio::time::timeout(PATIENCE, read)
        .await
        .expect("the server neither answered nor closed")
}

/// Whether the server closes `stream` (EOF or reset) without sending anything more.
pub async fn closed_without_answer(stream: &mut TcpStream) -> bool {
    let mut chunk = [0u8; 1024];
    match tokio::time::timeout(PATIENCE, stream.read(&mut chunk)).await {
        Ok(Ok(0)) | Ok(Err(_)) => true,
        Ok(Ok(_)) => false,
        Err(_) => panic!("the connection stayed open"),
    }
}

fn parse(buf: &[u8]) -> Option<Answer> {
    let end = buf.windows(4).position(|w| w == b"\r\n\r\n")?;
    let head = String::from_utf8_lossy(&buf[..end]).to_string();
    let mut lines = head.split("\r\n");
    let status = lines.next()?.split(' ').nth(1)?.parse().ok()?;
    let headers: Vec<(String, String)> = lines
        .filter_map(|l| l.split_once(':'))
        .map(|(n, v)| (n.trim().to_ascii_lowercase(), v.trim().to_string()))
        .collect();
    let length: usize = headers
        .iter()
        .find(|(n, _)| n == "content-length")
        .and_then(|(_, v)| v.parse().ok())
        .unwrap_or(0);
    let body = &buf[end + 4..];
    (body.len() >= length).then(|| Answer {
        status,
        headers,
        body: body[..length].to_vec(),
    })
}

/// Start `fieldbal serve` on 127.0.0.1:0 in `dir` with `args`; returns it and its address.
pub fn start_binary(dir: &std::path::Path, args: &[&str]) -> (std::process::Child, SocketAddr) {
    let mut all = vec!["--listen", "127.0.0.1:0"];
    all.extend_from_slice(args);
    let (child, addr) = crate::common::binary::start(Some(dir), &all, &[]);
    (child, addr.parse().unwrap())
}

/// SIGTERM, then wait (bounded: 30 s) for the exit status.
pub fn terminate(child: std::process::Child) -> std::process::ExitStatus {
    crate::common::binary::terminate(child, 30)
}
pub mod numbers;
pub mod schema;

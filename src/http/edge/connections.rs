//! The accept loop: HTTP/1.1 connections served by hyper with a header-read
//! timeout, a write timeout, a cap on open connections and a bounded graceful
//! shutdown, so neither half-sent headers nor a client that stops reading its
//! answers can exhaust the service or hold SIGTERM forever.
//! (`axum::serve` offers none of these settings.)

use std::future::Future;
use std::sync::Arc;
use std::time::Duration;

use axum::Router;
use hyper_util::rt::{TokioIo, TokioTimer};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::{watch, Semaphore};
use tokio::task::JoinSet;
use tower::ServiceExt;

pub const DEFAULT_HEADER_READ_TIMEOUT_SECS: u64 = 10;
/// Longest a write to a client may make no progress: the largest answer (a
/// solution of a big session, some MiB) reaches a live client on a slow
/// network within it.
pub const DEFAULT_WRITE_TIMEOUT_SECS: u64 = 30;
/// Below the unit's `LimitNOFILE=4096`, leaving room for the database and logs.
pub const DEFAULT_MAX_CONNECTIONS: usize = 1024;
/// Below the unit's `TimeoutStopSec=30`.
pub const DEFAULT_SHUTDOWN_GRACE_SECS: u64 = 20;

/// Connection limits.
#[derive(Debug, Clone)]
pub struct Limits {
    /// Longest wait for a complete request header; hyper starts this clock
    /// whenever it waits for a request, so it also ends idle kept-alive connections.
    pub header_read_timeout: Duration,
    /// Longest time a write to the client may stay blocked (a client that
    /// stops reading with a full socket buffer); then the connection is closed.
    pub write_timeout: Duration,
    /// Most connections served at once; beyond it a connection gets a 503 and is closed.
    pub max_connections: usize,
    /// After the shutdown signal, longest wait for open connections.
    pub shutdown_grace: Duration,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            header_read_timeout: Duration::from_secs(DEFAULT_HEADER_READ_TIMEOUT_SECS),
            write_timeout: Duration::from_secs(DEFAULT_WRITE_TIMEOUT_SECS),
            max_connections: DEFAULT_MAX_CONNECTIONS,
            shutdown_grace: Duration::from_secs(DEFAULT_SHUTDOWN_GRACE_SECS),
        }
    }
}

/// Serve `app` on `listener` until `shutdown` completes; then stop accepting,
/// let each connection finish its request in flight, and close what is still
/// open after the grace period.
pub async fn serve(
    listener: TcpListener,
    app: Router,
    limits: Limits,
    shutdown: impl Future<Output = ()> + Send + 'static,
) -> std::io::Result<()> {
    let permits = Arc::new(Semaphore::new(limits.max_connections));
    let (stop_tx, stop_rx) = watch::channel(false);
    let mut open = JoinSet::new();
    let mut shutdown = std::pin::pin!(shutdown);
    let mut full = false;
    loop {
        tokio::select! {
            () = &mut shutdown => break,
            Some(_) = open.join_next(), if !open.is_empty() => {}
            accepted = listener.accept() => {
                let stream = match accepted {
                    Ok((stream, _)) => stream,
                    Err(e) => {
                        // Out of descriptors, say: wait rather than spin.
                        tracing::warn!(error = %e, "accept failed");
                        tokio::time::sleep(Duration::from_millis(100)).await;
                        continue;
                    }
                };
                let Ok(permit) = permits.clone().try_acquire_owned() else {
                    if !full {
                        tracing::warn!(max = limits.max_connections, "connection cap reached; refusing new connections");
                    }
                    full = true;
                    refuse_busy(stream);
                    continue;
                };
                full = false;
                let (app, stop, limits) = (app.clone(), stop_rx.clone(), limits.clone());
                open.spawn(async move {
                    serve_one(stream, app, &limits, stop).await;
                    drop(permit);
                });
            }
        }
    }
    drop(listener);
    let _ = stop_tx.send(true);
    let grace = tokio::time::sleep(limits.shutdown_grace);
    tokio::pin!(grace);
    loop {
        tokio::select! {
            () = &mut grace => {
                tracing::warn!(open = open.len(), "closing connections still open after the grace period");
                open.abort_all();
                break;
            }
            next = open.join_next() => if next.is_none() { break },
        }
    }
    Ok(())
}

/// One connection, until the client closes it, a timeout, or shutdown.
async fn serve_one(
    stream: TcpStream,
    app: Router,
    limits: &Limits,
    mut stop: watch::Receiver<bool>,
) {
    let _ = stream.set_nodelay(true);
    let service = hyper::service::service_fn(move |req| app.clone().oneshot(req));
    let mut builder = hyper::server::conn::http1::Builder::new();
    builder
        .timer(TokioTimer::new())
        .header_read_timeout(limits.header_read_timeout)
        // Above the limit the edge answers with the JSON 431 (protocol.rs).
        .max_headers(2 * super::protocol::MAX_HEADERS);
    // hyper has no write timeout: the stream enforces one, so a client that
    // never reads cannot hold its connection (and a slot of the cap) forever.
    let mut io = tokio_io_timeout::TimeoutStream::new(stream);
    io.set_write_timeout(Some(limits.write_timeout));
    // hyper's own bare 400/414/431 get the contract's JSON body (unparsed.rs).
    let io = super::unparsed::ErrorBodies::new(Box::pin(io));
    let conn = builder.serve_connection(TokioIo::new(io), service);
    tokio::pin!(conn);
    // The guard `wait_for` returns is not `Send`: drop it inside.
    let stopping = async move {
        let _ = stop.wait_for(|stopping| *stopping).await;
    };
    tokio::select! {
        done = conn.as_mut() => {
            if let Err(e) = done {
                tracing::debug!(error = %e, "connection ended");
            }
        }
        () = stopping => {
            // Finish the request in flight, take no new one; the caller bounds the wait.
            conn.as_mut().graceful_shutdown();
            let _ = conn.await;
        }
    }
}

/// Over the cap: answer 503 with the JSON error if the socket takes it at
/// once (never wait on this client), then close.
fn refuse_busy(stream: TcpStream) {
    let body = r#"{"error":{"code":"too_many_connections","message":"the service has too many open connections; try again shortly"}}"#;
    let response = format!(
        "HTTP/1.1 503 Service Unavailable\r\ncontent-type: application/json\r\n\
         retry-after: 1\r\ncache-control: no-store\r\nconnection: close\r\n\
         content-length: {}\r\n\r\n{body}",
        body.len()
    );
    let _ = stream.try_write(response.as_bytes());
}

//! The JSON error body for requests hyper itself refuses before the service
//! sees them: a request it cannot parse (400), a target over its 64 KiB limit
//! (414), more header fields or bytes than its buffer holds (431).
//!
//! hyper answers those with a bare head (`content-length: 0`,
//! `connection: close`) and has no hook to change it, so the connection's
//! writer recognises that head and writes the contract's answer in its place.
//! The service's own 400/414/431 always carry the JSON body (`protocol.rs`),
//! so a bodiless head with one of these statuses can only be hyper's.

use std::io;
use std::pin::Pin;
use std::task::{Context, Poll};

use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};

/// A connection whose bodiless protocol errors get the JSON body.
pub struct ErrorBodies<T> {
    inner: T,
    /// The answer being written in place of hyper's head, how much of it is
    /// written, and the length of hyper's head to report once it all is.
    pending: Option<(Vec<u8>, usize, usize)>,
}

impl<T> ErrorBodies<T> {
    pub fn new(inner: T) -> Self {
        ErrorBodies {
            inner,
            pending: None,
        }
    }
}

/// The contract's answer for hyper's bare `head`, or `None` for any other write.
fn replacement(head: &[u8]) -> Option<Vec<u8>> {
    const BARE: &[u8] = b"\r\ncontent-length: 0\r\n";
    let status = head.strip_prefix(b"HTTP/1.1 ")?.get(..3)?;
    let (code, message) = match status {
        b"400" => (
            "bad_request",
            "the request could not be read as HTTP/1.1 (a malformed request line or header field)",
        ),
        b"414" => (
            "uri_too_long",
            "the request target is longer than the server reads (64 KiB)",
        ),
        b"431" => (
            "headers_too_large",
            "the request's header section is larger than the server reads",
        ),
        _ => return None,
    };
    if !head.ends_with(b"\r\n\r\n") {
        return None;
    }
    let at = head.windows(BARE.len()).position(|w| w == BARE)?;
    let body = serde_json::json!({ "error": { "code": code, "message": message } }).to_string();
    let mut out = Vec::with_capacity(head.len() + body.len() + 128);
    out.extend_from_slice(&head[..at + 2]);
    out.extend_from_slice(b"content-type: application/json\r\n");
    out.extend_from_slice(b"x-content-type-options: nosniff\r\n");
    out.extend_from_slice(b"cache-control: no-store\r\n");
    out.extend_from_slice(format!("content-length: {}\r\n", body.len()).as_bytes());
    out.extend_from_slice(&head[at + BARE.len()..]);
    out.extend_from_slice(body.as_bytes());
    Some(out)
}

impl<T: AsyncWrite + Unpin> ErrorBodies<T> {
    /// Write the pending answer; ready with hyper's head length once all is out.
    fn poll_pending(&mut self, cx: &mut Context<'_>) -> Poll<io::Result<usize>> {
        while let Some((bytes, written, reported)) = self.pending.as_mut() {
            if *written == bytes.len() {
                let n = *reported;
                self.pending = None;
                return Poll::Ready(Ok(n));
            }
            match Pin::new(&mut self.inner).poll_write(cx, &bytes[*written..]) {
                Poll::Ready(Ok(0)) => return Poll::Ready(Err(io::ErrorKind::WriteZero.into())),
                Poll::Ready(Ok(n)) => *written += n,
                other => return other,
            }
        }
        Poll::Ready(Ok(0))
    }
}

impl<T: AsyncWrite + Unpin> AsyncWrite for ErrorBodies<T> {
    fn poll_write(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &[u8],
    ) -> Poll<io::Result<usize>> {
        let this = &mut *self;
        if this.pending.is_none() {
            match replacement(buf) {
                Some(bytes) => this.pending = Some((bytes, 0, buf.len())),
                None => return Pin::new(&mut this.inner).poll_write(cx, buf),
            }
        }
        this.poll_pending(cx)
    }

    fn poll_write_vectored(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[io::IoSlice<'_>],
    ) -> Poll<io::Result<usize>> {
        let this = &mut *self;
        if this.pending.is_none() {
            // hyper's bare head goes out as one slice; replace only that.
            let first = bufs.iter().find(|b| !b.is_empty());
            match first.and_then(|b| replacement(b).map(|r| (r, b.len()))) {
                Some((bytes, len)) => this.pending = Some((bytes, 0, len)),
                None => return Pin::new(&mut this.inner).poll_write_vectored(cx, bufs),
            }
        }
        this.poll_pending(cx)
    }

    fn is_write_vectored(&self) -> bool {
        self.inner.is_write_vectored()
    }

    fn poll_flush(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        if self.pending.is_some() {
            if let Err(e) = std::task::ready!(self.poll_pending(cx)) {
                return Poll::Ready(Err(e));
            }
        }
        Pin::new(&mut self.inner).poll_flush(cx)
    }

    fn poll_shutdown(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.inner).poll_shutdown(cx)
    }
}

impl<T: AsyncRead + Unpin> AsyncRead for ErrorBodies<T> {
    fn poll_read(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &mut ReadBuf<'_>,
    ) -> Poll<io::Result<()>> {
        Pin::new(&mut self.inner).poll_read(cx, buf)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const HEAD: &[u8] = b"HTTP/1.1 431 Request Header Fields Too Large\r\nconnection: close\r\ncontent-length: 0\r\ndate: Sun, 22 Nov 2026 11:58:19 GMT\r\n\r\n";

    fn split(answer: &[u8]) -> (String, serde_json::Value) {
        let text = String::from_utf8(answer.to_vec()).unwrap();
        let (head, body) = text.split_once("\r\n\r\n").unwrap();
        (head.to_string(), serde_json::from_str(body).unwrap())
    }

    #[test]
    fn hypers_bare_431_head_becomes_the_contract_error_with_a_matching_length() {
        let answer = replacement(HEAD).expect("a bare 431 is replaced");
        let (head, body) = split(&answer);
        assert!(head.starts_with("HTTP/1.1 431 "), "{head}");
        assert!(head.contains("connection: close\r\n"), "{head}");
        assert!(head.contains("content-type: application/json"), "{head}");
        let length = serde_json::to_string(&body).unwrap().len();
        assert!(
            head.contains(&format!("content-length: {length}")),
            "{head}"
        );
        assert!(!head.contains("content-length: 0"), "{head}");
        assert_eq!(body["error"]["code"], "headers_too_large");
    }

    #[test]
    fn other_heads_and_answers_with_a_body_pass_unchanged() {
        let cases: [&[u8]; 4] = [
            b"HTTP/1.1 200 OK\r\ncontent-length: 0\r\n\r\n",
            b"HTTP/1.1 400 Bad Request\r\ncontent-type: application/json\r\ncontent-length: 52\r\n\r\n",
            b"HTTP/1.1 204 No Content\r\ndate: x\r\n\r\n",
            b"{\"error\":{\"code\":\"bad_request\"}}",
        ];
        for case in cases {
            assert!(
                replacement(case).is_none(),
                "{}",
                String::from_utf8_lossy(case)
            );
        }
    }

    #[tokio::test]
    async fn the_replacement_is_written_whole_and_hyper_is_told_its_own_length() {
        use tokio::io::AsyncWriteExt;
        let mut out = ErrorBodies::new(Vec::new());
        let n = out.write(HEAD).await.unwrap();
        assert_eq!(n, HEAD.len());
        out.write_all(b"next").await.unwrap();
        let written = out.inner;
        assert!(written.ends_with(b"}next"));
        assert_eq!(
            split(&written[..written.len() - 4]).1["error"]["code"],
            "headers_too_large"
        );
    }
}

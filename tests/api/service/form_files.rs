//! The web form's files on the wire: gzip-compressed for a browser that
//! accepts it (the same bytes once inflated), as they are for a client that
//! does not ask, and a reload that names the file's tag answered 304 with
//! nothing sent again (they were sent whole, uncompressed, on every load:
//! about 250 kB over a plant's network each time).

use crate::common;

use std::io::Read;

use common::fresh_server;

#[tokio::test]
async fn the_forms_files_are_compressed_and_a_current_copy_is_not_sent_again() {
    let (_dir, server, client) = fresh_server().await;
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("static");
    for (url, file) in [
        ("/", "index.html"),
        ("/static/js/app.js", "js/app.js"),
        ("/static/style.css", "style.css"),
        ("/static/js/steps/runs.js", "js/steps/runs.js"),
    ] {
        let on_disk = std::fs::read(root.join(file)).unwrap();
        // Asked without Accept-Encoding: the file as it is.
        let plain = client.get(server.url(url)).send().await.unwrap();
        assert_eq!(plain.status(), 200, "{url}");
        assert!(plain.headers().get("content-encoding").is_none(), "{url}");
        let tag = plain.headers()["etag"].to_str().unwrap().to_string();
        assert!(tag.starts_with("W/\""), "{url}: a weak tag: {tag}");
        assert_eq!(
            plain.bytes().await.unwrap().as_ref(),
            on_disk.as_slice(),
            "{url}"
        );
        // Asked as a browser asks: gzip, fewer bytes, the same file inflated.
        let zipped = client
            .get(server.url(url))
            .header("accept-encoding", "gzip, deflate, br")
            .send()
            .await
            .unwrap();
        assert_eq!(zipped.status(), 200, "{url}");
        assert_eq!(zipped.headers()["content-encoding"], "gzip", "{url}");
        assert_eq!(zipped.headers()["etag"].to_str().unwrap(), tag, "{url}");
        let sent = zipped.bytes().await.unwrap();
        assert!(
            sent.len() * 2 < on_disk.len(),
            "{url}: {} bytes sent for {}",
            sent.len(),
            on_disk.len()
        );
        let mut inflated = Vec::new();
        flate2::read::GzDecoder::new(sent.as_ref())
            .read_to_end(&mut inflated)
            .unwrap();
        assert_eq!(inflated, on_disk, "{url}");
        // A reload with the tag: 304, no body; with another tag, the file.
        for (asked, status) in [
            (tag.clone(), 304),
            (tag.trim_start_matches("W/").to_string(), 304),
            (format!("\"other\", {tag}"), 304),
            ("*".to_string(), 304),
            ("W/\"0000000000000000\"".to_string(), 200),
        ] {
            let again = client
                .get(server.url(url))
                .header("if-none-match", &asked)
                .send()
                .await
                .unwrap();
            assert_eq!(again.status(), status, "{url} If-None-Match {asked}");
            assert_eq!(again.headers()["etag"].to_str().unwrap(), tag, "{url}");
            let body = again.bytes().await.unwrap();
            if status == 304 {
                assert!(body.is_empty(), "{url}: a 304 has no body");
            } else {
                assert_eq!(body.as_ref(), on_disk.as_slice(), "{url}");
            }
        }
    }
    server.shutdown().await;
}

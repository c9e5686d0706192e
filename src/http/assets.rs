//! The web form's files, embedded in the binary so `fieldbal serve` shows it from any directory.

use std::hash::{Hash, Hasher};
use std::sync::OnceLock;

use axum::{
    extract::Path,
    http::{header, HeaderMap, HeaderValue, StatusCode},
    response::{IntoResponse, Response},
    routing::get,
    Router,
};
use tower_http::compression::CompressionLayer;

/// One embedded file: its path under `/static/`, content type and bytes.
struct Asset {
    path: &'static str,
    content_type: &'static str,
    body: &'static str,
}

macro_rules! asset {
    ($path:literal, $type:expr) => {
        Asset {
            path: $path,
            content_type: $type,
            body: include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/static/", $path)),
        }
    };
}

const JS: &str = "text/javascript; charset=utf-8";

/// Every file of `static/`; the test below fails when one is missing here.
static ASSETS: &[Asset] = &[
    asset!("index.html", "text/html; charset=utf-8"),
    asset!("style.css", "text/css; charset=utf-8"),
    asset!("js/app.js", JS),
    asset!("js/answer/answer.js", JS),
    asset!("js/answer/planes.js", JS),
    asset!("js/answer/words.js", JS),
    asset!("js/job/api.js", JS),
    asset!("js/job/keep.js", JS),
    asset!("js/job/state.js", JS),
    asset!("js/job/token.js", JS),
    asset!("js/page/dom.js", JS),
    asset!("js/page/fields.js", JS),
    asset!("js/page/num.js", JS),
    asset!("js/page/paged.js", JS),
    asset!("js/plots/bode.js", JS),
    asset!("js/plots/plots.js", JS),
    asset!("js/plots/polar.js", JS),
    asset!("js/steps/csv.js", JS),
    asset!("js/steps/decay.js", JS),
    asset!("js/steps/machines.js", JS),
    asset!("js/steps/options.js", JS),
    asset!("js/steps/picture.js", JS),
    asset!("js/steps/report.js", JS),
    asset!("js/steps/residual.js", JS),
    asset!("js/steps/runs.js", JS),
    asset!("js/steps/sessions.js", JS),
    asset!("js/steps/setup.js", JS),
    asset!("js/steps/solve.js", JS),
    asset!("js/steps/trial.js", JS),
];

/// Scripts and styles from this origin only: even if user text ever reached
/// the page as HTML, an inline handler such as `onerror=` would not run.
const CSP: &str = "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; \
                   connect-src 'self'; object-src 'none'; base-uri 'none'; frame-ancestors 'none'; form-action 'none'";

fn find(path: &str) -> Option<&'static Asset> {
    ASSETS.iter().find(|a| a.path == path)
}

/// Each file's entity-tag, in the order of `ASSETS`: a hash of its bytes,
/// weak because the bytes sent may be gzip-compressed (RFC 9110 §8.8.1: a
/// weak tag holds for every encoding of the same content).
fn tag(asset: &'static Asset) -> &'static HeaderValue {
    static TAGS: OnceLock<Vec<HeaderValue>> = OnceLock::new();
    let tags = TAGS.get_or_init(|| {
        ASSETS
            .iter()
            .map(|a| {
                let mut h = std::collections::hash_map::DefaultHasher::new();
                a.body.hash(&mut h);
                HeaderValue::from_str(&format!("W/\"{:016x}\"", h.finish()))
                    .expect("a hex tag is a header value")
            })
            .collect()
    });
    let i = ASSETS
        .iter()
        .position(|a| std::ptr::eq(a, asset))
        .expect("an embedded asset");
    &tags[i]
}

/// Whether `If-None-Match` names `tag` (or is `*`): the browser's copy is
/// current. Tags compare weakly (RFC 9110 §13.1.2).
fn not_modified(headers: &HeaderMap, tag: &HeaderValue) -> bool {
    let bare = |t: &str| t.trim().trim_start_matches("W/").to_string();
    let ours = bare(tag.to_str().unwrap_or_default());
    headers
        .get_all(header::IF_NONE_MATCH)
        .iter()
        .filter_map(|v| v.to_str().ok())
        .flat_map(|v| v.split(','))
        .any(|t| t.trim() == "*" || bare(t) == ours)
}

fn respond(asset: &'static Asset, request: &HeaderMap) -> Response {
    let tag = tag(asset);
    let mut resp = if not_modified(request, tag) {
        StatusCode::NOT_MODIFIED.into_response()
    } else {
        asset.body.into_response()
    };
    let headers = resp.headers_mut();
    headers.insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static(asset.content_type),
    );
    // The files change with the binary; revalidate rather than keep a stale
    // form: a reload asks with the tag and gets 304, nothing sent again.
    headers.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-cache"));
    headers.insert(header::ETAG, tag.clone());
    headers.insert(
        header::X_CONTENT_TYPE_OPTIONS,
        HeaderValue::from_static("nosniff"),
    );
    headers.insert(
        header::CONTENT_SECURITY_POLICY,
        HeaderValue::from_static(CSP),
    );
    resp
}

async fn index(request: HeaderMap) -> Response {
    respond(
        find("index.html").expect("index.html is embedded"),
        &request,
    )
}

async fn file(Path(path): Path<String>, request: HeaderMap) -> Response {
    match find(&path) {
        Some(asset) => respond(asset, &request),
        None => (
            StatusCode::NOT_FOUND,
            [(header::CONTENT_TYPE, "application/json")],
            r#"{"error":{"code":"not_found","message":"no such file of the web form"}}"#,
        )
            .into_response(),
    }
}

/// Routes for `/` and the form's static files, gzip-compressed for a
/// browser that accepts it (about a quarter of the bytes on a stand's
/// network; the API's answers are left as they are).
pub fn router<S: Clone + Send + Sync + 'static>() -> Router<S> {
    Router::new()
        .route("/", get(index))
        .route("/static/{*path}", get(file))
        .layer(CompressionLayer::new().gzip(true))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn files_under(dir: &std::path::Path, prefix: &str, out: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).expect("static/ is readable") {
            let entry = entry.expect("directory entry");
            let name = format!("{prefix}{}", entry.file_name().to_string_lossy());
            if entry.file_type().expect("file type").is_dir() {
                files_under(&entry.path(), &format!("{name}/"), out);
            } else {
                out.push(name);
            }
        }
    }

    #[test]
    fn every_file_of_static_is_embedded() {
        let mut on_disk = Vec::new();
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("static");
        files_under(&root, "", &mut on_disk);
        for path in &on_disk {
            assert!(find(path).is_some(), "static/{path} is not in ASSETS");
        }
        assert_eq!(on_disk.len(), ASSETS.len(), "ASSETS lists a file twice");
    }

    /// The path under `static/` of `module` (`./x.js` or `../dir/x.js`) imported
    /// by the file at `from`, as the browser resolves it; None for any other form.
    fn resolve(from: &str, module: &str) -> Option<String> {
        let mut parts: Vec<&str> = from.split('/').collect();
        parts.pop(); // the importing file itself
        let mut rest = module;
        if let Some(r) = rest.strip_prefix("./") {
            rest = r;
        } else if !rest.starts_with("../") {
            return None;
        }
        while let Some(r) = rest.strip_prefix("../") {
            parts.pop()?;
            rest = r;
        }
        parts.push(rest);
        Some(parts.join("/"))
    }

    #[test]
    fn relative_imports_resolve_as_the_browser_does() {
        assert_eq!(
            resolve("js/app.js", "./page/dom.js").as_deref(),
            Some("js/page/dom.js")
        );
        assert_eq!(
            resolve("js/steps/runs.js", "./csv.js").as_deref(),
            Some("js/steps/csv.js")
        );
        assert_eq!(
            resolve("js/steps/runs.js", "../job/api.js").as_deref(),
            Some("js/job/api.js")
        );
        assert_eq!(resolve("js/app.js", "../../x.js"), None);
        assert_eq!(resolve("js/app.js", "/static/js/x.js"), None);
    }

    #[test]
    fn every_imported_module_is_embedded() {
        for asset in ASSETS.iter().filter(|a| a.path.ends_with(".js")) {
            for line in asset.body.lines().filter(|l| l.starts_with("import ")) {
                let path = line
                    .split('"')
                    .nth(1)
                    .and_then(|m| resolve(asset.path, m))
                    .unwrap_or_else(|| panic!("{}: unexpected import {line}", asset.path));
                assert!(
                    find(&path).is_some(),
                    "{} imports {path}, which is not embedded",
                    asset.path
                );
            }
        }
    }

    #[test]
    fn content_types_follow_the_extension() {
        for asset in ASSETS {
            let ext = asset.path.rsplit('.').next().unwrap_or_default();
            let expected = match ext {
                "html" => "text/html",
                "css" => "text/css",
                "js" => "text/javascript",
                other => panic!("no content type for .{other}"),
            };
            assert!(asset.content_type.starts_with(expected), "{}", asset.path);
        }
    }
}

//! Which engine a database URL names (SQLite or PostgreSQL), opening a pool on
//! it with the service's settings and embedded migrations, and the few
//! statements whose SQL differs between the engines (row and key locks).

use std::future::Future;
use std::path::Path;
use std::pin::Pin;
use std::time::Duration;

use sqlx::any::AnyPoolOptions;
use sqlx::{AnyConnection, AnyPool, Database};

/// The database engine behind a pool or connection.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Engine {
    Sqlite,
    Postgres,
}

impl Engine {
    /// `postgres://…` or `postgresql://…` is PostgreSQL; anything else
    /// (`sqlite://…`, `sqlite::memory:`, a file path) is SQLite.
    pub fn of_url(url: &str) -> Engine {
        if url.starts_with("postgres://") || url.starts_with("postgresql://") {
            Engine::Postgres
        } else {
            Engine::Sqlite
        }
    }

    pub fn of_pool(pool: &AnyPool) -> Engine {
        Engine::of_url(pool.connect_options().database_url.as_str())
    }

    pub fn of_conn(conn: &AnyConnection) -> Engine {
        if conn.backend_name() == sqlx::Postgres::NAME {
            Engine::Postgres
        } else {
            Engine::Sqlite
        }
    }
}

/// `url` for logs and messages: a URL without its password (a PostgreSQL
/// URL's, or one of an engine fieldbal refuses).
pub fn redacted(url: &str) -> String {
    match url::Url::parse(url) {
        Ok(mut u) if u.password().is_some() => {
            let _ = u.set_password(Some("***"));
            u.to_string()
        }
        _ => url.to_string(),
    }
}

/// The scheme of a URL that names neither SQLite nor PostgreSQL
/// (`mysql://…`, `file://…`): such a URL is refused, not opened as an SQLite
/// file of that name. A path with `://` inside has no scheme.
fn unsupported_scheme(url: &str) -> Option<&str> {
    let (scheme, _) = url.split_once("://")?;
    let mut chars = scheme.chars();
    let is_scheme = chars.next().is_some_and(|c| c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || "+-.".contains(c));
    (is_scheme && !["sqlite", "postgres", "postgresql"].contains(&scheme)).then_some(scheme)
}

/// The file an SQLite `url` (`sqlite://fieldbal.db`, `sqlite:///var/…`, a plain
/// path) opens, made absolute against the working directory; `None` for
/// PostgreSQL and in-memory databases. Said at start, since a relative
/// default lands in whatever directory the service was started from. A URL's
/// path is percent-decoded, as sqlx decodes it to open the file
/// (`sqlite:///tmp/a%20b/f.db` opens `/tmp/a b/f.db`); a plain path is the
/// name as given.
pub fn sqlite_file(url: &str) -> Option<std::path::PathBuf> {
    if Engine::of_url(url) != Engine::Sqlite
        || url.contains(":memory:")
        || unsupported_scheme(url).is_some()
    {
        return None;
    }
    let path = match url
        .strip_prefix("sqlite://")
        .or_else(|| url.strip_prefix("sqlite:"))
    {
        Some(rest) => {
            let (path, query) = rest.split_once('?').unwrap_or((rest, ""));
            if query.split('&').any(|p| p == "mode=memory") {
                return None;
            }
            percent_decoded(path)?
        }
        None => url.into(),
    };
    std::path::absolute(Path::new(&path)).ok()
}

/// `text` with each `%XX` replaced by its byte (the `percent-encoding`
/// crate `url` is built on); `None` when the bytes are not UTF-8 (sqlx
/// refuses such a URL).
fn percent_decoded(text: &str) -> Option<String> {
    percent_encoding::percent_decode_str(text)
        .decode_utf8()
        .ok()
        .map(|s| s.into_owned())
}

/// How long an SQLite connection waits for another process's writer.
const BUSY_TIMEOUT_MS: u64 = 10_000;
/// Connections per process. SQLite has one writer anyway; a PostgreSQL
/// replica's writers wait on row locks, not on the pool, so it gets more.
const SQLITE_CONNECTIONS: u32 = 8;
const POSTGRES_CONNECTIONS: u32 = 16;

/// Extra set-up of each new connection (tests use it to limit SQLite's pages).
pub type Setup = for<'c> fn(
    &'c mut AnyConnection,
) -> Pin<Box<dyn Future<Output = sqlx::Result<()>> + Send + 'c>>;

/// Open (creating if missing) the database at `url` and apply the embedded
/// migrations of its engine.
///
/// `url` is `postgres://…`, an SQLite URL (`sqlite://fieldbal.db`,
/// `sqlite::memory:`) or a plain file path (SQLite).
pub async fn connect(url: &str) -> Result<AnyPool, sqlx::Error> {
    connect_pool(url, None, None).await
}

/// [`connect`] with `connections` instead of the default pool size and
/// `setup` run on each new connection after the service's own settings.
pub async fn connect_pool(
    url: &str,
    connections: Option<u32>,
    setup: Option<Setup>,
) -> Result<AnyPool, sqlx::Error> {
    sqlx::any::install_default_drivers();
    if let Some(scheme) = unsupported_scheme(url) {
        return Err(sqlx::Error::Configuration(
            format!(
                "'{scheme}://' is not a database fieldbal can use: give sqlite://FILE (or a file path) or postgres://USER:PASSWORD@HOST/DB"
            )
            .into(),
        ));
    }
    match Engine::of_url(url) {
        Engine::Sqlite => {
            let url = sqlite_url(url)?;
            first_connection(&url, true).await?;
            let pool = AnyPoolOptions::new()
                .max_connections(connections.unwrap_or(SQLITE_CONNECTIONS))
                .after_connect(move |conn, _| {
                    Box::pin(async move {
                        sqlite_settings(conn).await?;
                        match setup {
                            Some(setup) => setup(conn).await,
                            None => Ok(()),
                        }
                    })
                })
                .connect(&url)
                .await?;
            sqlx::migrate!().run(&pool).await?;
            Ok(pool)
        }
        Engine::Postgres => {
            first_connection(url, false).await?;
            let pool = AnyPoolOptions::new()
                .max_connections(connections.unwrap_or(POSTGRES_CONNECTIONS))
                // A database that is down answers 503 within this, not after sqlx's 30 s.
                .acquire_timeout(FIRST_CONNECTION)
                .after_connect(move |conn, _| {
                    Box::pin(async move {
                        match setup {
                            Some(setup) => setup(conn).await,
                            None => Ok(()),
                        }
                    })
                })
                .connect(url)
                .await?;
            // sqlx takes an advisory lock around PostgreSQL migrations, so
            // replicas starting together apply each one once.
            sqlx::migrate!("migrations/postgres").run(&pool).await?;
            Ok(pool)
        }
    }
}

/// How long the first connection at start may take (a PostgreSQL host that
/// does not answer), the pool's own acquire time.
const FIRST_CONNECTION: Duration = Duration::from_secs(10);

/// Open one connection to `url` outside any pool (with the SQLite settings when
/// `sqlite`) and close it, so that start-up fails at once with the real cause.
/// A pool retries a connection whose set-up fails until its acquire time is up
/// and then says only "pool timed out": an SQLite file in a directory the
/// service may not write failed its `journal_mode = WAL` for 30 s that way,
/// and a refused PostgreSQL connection for 10 s.
async fn first_connection(url: &str, sqlite: bool) -> Result<(), sqlx::Error> {
    use sqlx::Connection;
    let open = async {
        let mut conn = AnyConnection::connect(url).await?;
        if sqlite {
            sqlite_settings(&mut conn).await?;
        }
        conn.close().await
    };
    tokio::time::timeout(FIRST_CONNECTION, open)
        .await
        .unwrap_or_else(|_| {
            Err(sqlx::Error::Io(std::io::Error::new(
                std::io::ErrorKind::TimedOut,
                format!(
                    "no connection within {} s (is the database server up and reachable?)",
                    FIRST_CONNECTION.as_secs()
                ),
            )))
        })
}

/// The SQLite URL for `url`: a plain path becomes an absolute, percent-encoded
/// `sqlite://` URL; either is opened read-write-create unless it says a mode.
fn sqlite_url(url: &str) -> Result<String, sqlx::Error> {
    let mut out = if url.starts_with("sqlite:") {
        url.to_string()
    } else {
        let path = std::path::absolute(Path::new(url)).map_err(sqlx::Error::Io)?;
        let file = url::Url::from_file_path(&path)
            .map_err(|()| sqlx::Error::Configuration(format!("bad path {url}").into()))?;
        format!("sqlite://{}", file.path())
    };
    if !out.contains("mode=") && !out.contains(":memory:") {
        out.push(if out.contains('?') { '&' } else { '?' });
        out.push_str("mode=rwc");
    }
    Ok(out)
}

/// The service's SQLite settings, per connection.
async fn sqlite_settings(conn: &mut AnyConnection) -> sqlx::Result<()> {
    for pragma in [
        format!("PRAGMA busy_timeout = {BUSY_TIMEOUT_MS}"),
        "PRAGMA journal_mode = WAL".to_string(),
        // FULL fsyncs the WAL on every commit, so a session answered 201 survives
        // a power cut of the stand PC, not only a crash of the process (NORMAL's
        // guarantee). It costs about a quarter of the store rate, which stays
        // above 1,000 sessions/s (BENCHMARKS.md).
        "PRAGMA synchronous = FULL".to_string(),
        "PRAGMA foreign_keys = ON".to_string(),
    ] {
        sqlx::query(&pragma).execute(&mut *conn).await?;
    }
    Ok(())
}

/// `sql` (a `SELECT` of one table's rows) locking the rows it reads until the
/// transaction ends, on PostgreSQL; on SQLite the write transaction already
/// holds the database's only write lock.
pub(crate) fn for_update(
    conn: &AnyConnection,
    sql: &'static str,
) -> std::borrow::Cow<'static, str> {
    match Engine::of_conn(conn) {
        Engine::Sqlite => sql.into(),
        Engine::Postgres => format!("{sql} FOR UPDATE").into(),
    }
}

/// Serialise the transactions using `key` (an `Idempotency-Key`) until this
/// one ends, on PostgreSQL: the second then finds what the first stored.
/// On SQLite writers are serialised already.
pub(crate) async fn lock_key(conn: &mut AnyConnection, key: &str) -> sqlx::Result<()> {
    if Engine::of_conn(conn) == Engine::Postgres {
        sqlx::query(
            "SELECT COUNT(*) FROM (SELECT pg_advisory_xact_lock(hashtextextended($1, 0))) l",
        )
        .bind(key)
        .execute(&mut *conn)
        .await?;
    }
    Ok(())
}

#[cfg(test)]
mod file_tests {
    use super::sqlite_file;
    use std::path::Path;

    /// The start log names the file SQLite opens: sqlx percent-decodes the
    /// URL's path, so `%20` is a space in the file's name.
    #[test]
    fn an_sqlite_url_names_the_decoded_file() {
        assert_eq!(
            sqlite_file("sqlite:///tmp/a%20b/f%23.db?mode=rwc").as_deref(),
            Some(Path::new("/tmp/a b/f#.db"))
        );
        assert_eq!(
            sqlite_file("sqlite:/tmp/a b/f.db").as_deref(),
            Some(Path::new("/tmp/a b/f.db"))
        );
        // A plain path is the file's name as it is, `%` included.
        assert_eq!(
            sqlite_file("/tmp/a%20b.db").as_deref(),
            Some(Path::new("/tmp/a%20b.db"))
        );
        // No file at all.
        assert_eq!(sqlite_file("sqlite://a.db?mode=memory"), None);
        assert_eq!(sqlite_file("sqlite::memory:"), None);
        assert_eq!(sqlite_file("postgres://u@h/db"), None);
    }

    /// A URL of an engine fieldbal does not speak is refused naming its
    /// scheme; it was taken for an SQLite path (`mysql://x/y` tried to open
    /// the file `./mysql:/x/y`, "unable to open database file").
    #[tokio::test]
    async fn an_unsupported_database_url_is_refused_naming_its_scheme() {
        for url in [
            "mysql://u:secret@h/db",
            "MariaDB://h/db",
            "file:///tmp/x.db",
        ] {
            let scheme = &url[..url.find("://").unwrap()];
            assert_eq!(sqlite_file(url), None, "{url}");
            let e = super::connect(url).await.expect_err(url).to_string();
            assert!(
                e.contains(&format!("'{scheme}://'"))
                    && e.contains("sqlite://")
                    && e.contains("postgres://"),
                "{url}: {e}"
            );
            assert!(!e.contains("secret"), "{url}: {e}");
        }
        // A path with `://` inside is still a path.
        assert!(sqlite_file("/tmp/a://b.db").is_some());
    }

    /// A password in any URL is left out of logs and messages.
    #[test]
    fn a_password_is_redacted_whatever_the_scheme() {
        for url in ["postgres://u:secret@h/db", "mysql://u:secret@h/db"] {
            let shown = super::redacted(url);
            assert!(
                !shown.contains("secret") && shown.contains("u:***@h"),
                "{shown}"
            );
        }
        assert_eq!(super::redacted("sqlite://a.db"), "sqlite://a.db");
    }
}

//! The database engine the tests run on, and a database of its own per test server.

use std::hash::{Hash, Hasher};
use std::path::Path;

use sqlx::Connection;

/// The variable naming the engine (`sqlite`, the default, or `postgres`).
pub const ENGINE_VAR: &str = "FIELDBAL_TEST_ENGINE";
/// The variable `scripts/test.sh` sets to its throw-away cluster's URL.
pub const POSTGRES_VAR: &str = "FIELDBAL_TEST_POSTGRES_URL";

/// Whether the tests run on PostgreSQL.
pub fn postgres() -> bool {
    std::env::var(ENGINE_VAR).is_ok_and(|e| e == "postgres")
}

/// The test cluster's URL; a test that needs PostgreSQL fails without it,
/// saying how to get one (never passes silently).
pub fn cluster_url() -> String {
    std::env::var(POSTGRES_VAR).unwrap_or_else(|_| {
        panic!(
            "{POSTGRES_VAR} is not set: the PostgreSQL tests need a server. Run them through \\
             scripts/test.sh (all tests) or scripts/with-postgres.sh cargo test --test NAME, \\
             which start a throw-away cluster and set it"
        )
    })
}

/// A new, empty PostgreSQL database `name` on the test cluster (kept if it
/// exists); returns its URL.
pub async fn postgres_database(name: &str) -> String {
    let cluster = cluster_url();
    let mut admin = sqlx::PgConnection::connect(&cluster)
        .await
        .unwrap_or_else(|e| panic!("the test cluster {cluster} answers: {e}"));
    let exists = sqlx::query("SELECT 1 FROM pg_database WHERE datname = $1")
        .bind(name)
        .fetch_optional(&mut admin)
        .await
        .expect("pg_database readable")
        .is_some();
    if !exists {
        sqlx::query(&format!("CREATE DATABASE \"{name}\""))
            .execute(&mut admin)
            .await
            .expect("CREATE DATABASE");
    }
    let _ = admin.close().await;
    let mut url = url::Url::parse(&cluster).expect("a URL");
    url.set_path(name);
    url.to_string()
}

/// The database for a test server on the SQLite file `db_path`: that file,
/// or on PostgreSQL a database named after it.
pub async fn database_url(db_path: &Path) -> String {
    if !postgres() {
        return db_path.to_str().expect("utf-8 path").to_string();
    }
    let mut hash = std::collections::hash_map::DefaultHasher::new();
    db_path.hash(&mut hash);
    postgres_database(&format!("fieldbal_test_{:016x}", hash.finish())).await
}

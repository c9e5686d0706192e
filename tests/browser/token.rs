//! End-to-end test of the form on a service with bearer tokens: it asks once
//! when the service answers 401, keeps the token for the tab (a reload does
//! not ask again), shows a read token's 403 without asking, and asks again
//! when the kept token is no longer accepted.

use crate::common;

use crate::harness::Browser;
use fieldbal::http::edge::access::Tokens;
use fieldbal::http::edge::EdgeConfig;
use serde_json::Value;

const WRITE: &str = "write-token-for-the-stand-pc";
const READ: &str = "read-token-for-the-office";

async fn stored_token(b: &Browser) -> Value {
    b.client
        .execute("return sessionStorage.getItem('fieldbal.token')", vec![])
        .await
        .expect("script runs")
}

async fn sessions_total(server: &common::Server) -> Value {
    let list: Value = reqwest::Client::new()
        .get(server.url("/api/v1/sessions"))
        .bearer_auth(READ)
        .send()
        .await
        .unwrap()
        .json()
        .await
        .unwrap();
    list["total"].clone()
}

async fn answer_prompt(b: &Browser, token: &str) {
    let input = b.wait_for("#token-dialog[open] #token-input").await;
    input.send_keys(token).await.expect("typed");
    b.click("#token-ok").await;
    b.wait_until(
        "the token dialog closes",
        "return !document.querySelector('#token-dialog')",
    )
    .await;
}

/// Delete the listed session, accepting the form's confirmation.
async fn delete_listed(b: &Browser) {
    b.click("button.delete").await;
    for _ in 0..crate::harness::WAIT_POLLS {
        if b.client.accept_alert().await.is_ok() {
            return;
        }
        tokio::time::sleep(std::time::Duration::from_millis(100)).await;
    }
    panic!("no confirmation was asked within 30 s");
}

async fn open_sessions(b: &Browser, server: &common::Server) {
    b.client
        .goto(&server.url("/"))
        .await
        .expect("the form loads");
    b.wait_for("[data-field=\"name\"]").await;
    b.click("nav [data-step=\"sessions\"]").await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_form_asks_for_a_token_once_and_keeps_it_for_the_tab() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let tokens = Tokens::parse(&format!("write {WRITE}\nread {READ}"), "test").unwrap();
    let edge = EdgeConfig {
        tokens,
        ..EdgeConfig::default()
    };
    let (_, server) =
        common::start_server_configured(&dir.path().join("token.db"), |s| s.with_edge(edge)).await;
    let session = common::example("pump-two-plane-exact.json")["session"].clone();
    let created = reqwest::Client::new()
        .post(server.url("/api/v1/sessions"))
        .bearer_auth(WRITE)
        .json(&session)
        .send()
        .await
        .unwrap();
    assert_eq!(created.status(), 201);

    let b = Browser::start().await;
    open_sessions(&b, &server).await;
    b.wait_for("#token-dialog[open]").await;
    b.screenshot("token-dialog").await;
    answer_prompt(&b, READ).await;
    b.wait_for("button.open-session").await;
    assert_eq!(stored_token(&b).await, READ);

    // A read token may not delete: the 403 is shown, nothing is asked, nothing deleted.
    delete_listed(&b).await;
    let banner = b.text("#step-sessions .banner.error").await;
    assert!(banner.contains("may read but not change"), "{banner}");
    assert!(b
        .client
        .find(fantoccini::Locator::Css("dialog"))
        .await
        .is_err());
    assert_eq!(sessions_total(&server).await, 1);

    // The token lasts for the tab: a reload lists the sessions without asking.
    open_sessions(&b, &server).await;
    b.wait_for("button.open-session").await;
    assert!(b
        .client
        .find(fantoccini::Locator::Css("dialog"))
        .await
        .is_err());

    // A kept token the service no longer accepts: asked again, the new one used.
    b.client
        .execute(
            "sessionStorage.setItem('fieldbal.token', 'revoked-token-0123456789')",
            vec![],
        )
        .await
        .unwrap();
    open_sessions(&b, &server).await;
    answer_prompt(&b, WRITE).await;
    b.wait_for("button.open-session").await;
    assert_eq!(stored_token(&b).await, WRITE);
    delete_listed(&b).await;
    b.wait_until(
        "the deleted session leaves the list",
        "return !document.querySelector('button.open-session')",
    )
    .await;
    assert_eq!(sessions_total(&server).await, 0);
    b.close().await;
    server.shutdown().await;
}

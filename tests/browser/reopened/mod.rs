//! A job reopened in another browser (loaded from the server by id, nothing
//! of it in local storage) is the job it was: a trim job not yet solved
//! needs no trial runs (`trim`); a check run renamed "trial…" stays a check
//! run (`check`); one solved more than 20 times shows its last solution
//! (`solved`). A machine stored without a name has none (`machine`). And
//! a whole job at a narrow window with the keyboard alone (`keyboard`).

mod check;
mod keyboard;
mod keys;
mod machine;
mod solved;
mod trim;

use crate::harness::stand::Stand;
use crate::harness::steps::js;

/// One browser for every scene (CI time); each scene gets a new server and
/// database and a freshly loaded form (`Stand::renew`).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_reopened_job_is_what_it_was_and_a_job_runs_from_the_keyboard() {
    let mut stand = Stand::start().await;
    trim::an_unsolved_trim_job_reopened_elsewhere_asks_for_no_trial_runs(&stand).await;
    stand.renew().await;
    trim::a_job_with_supplied_coefficients_reopened_elsewhere_is_a_trim_job(&stand).await;
    stand.renew().await;
    check::a_check_run_named_trial_stays_a_check_run_when_reopened(&stand).await;
    stand.renew().await;
    solved::a_job_solved_often_reopens_with_its_last_solution(&stand).await;
    stand.renew().await;
    machine::a_machine_without_a_name_is_stored_without_one(&stand).await;
    stand.renew().await;
    keyboard::a_whole_job_at_1024_by_768_with_the_keyboard_alone(&stand).await;
    stand.stop().await;
}

/// Open the stored session `id` at `step` as another browser would: nothing
/// of the job kept in this one's local storage.
pub async fn reopen_elsewhere(stand: &Stand, id: &str, step: &str) {
    let b = &stand.browser;
    // Off the form first (leaving it keeps the job in local storage), then
    // clear the origin's storage from a page that writes none.
    b.client.goto(&stand.server.url("/healthz")).await.unwrap();
    let left = js(b, "localStorage.clear(); return localStorage.length").await;
    assert_eq!(left, serde_json::json!(0));
    b.client
        .goto(&stand.server.url(&format!("/#session={id}&step={step}")))
        .await
        .unwrap();
}

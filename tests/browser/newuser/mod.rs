//! What an outside review found a new user meeting in the form (session 18),
//! one scene each: readings in in/s shown rounded away and answers without
//! their unit (`typed`); rotor data lost without a word — a rotor mass
//! checked as a "radius in mm", a rotor without its grade refused by the
//! service, a machine's rotor that could never be stored (`rotor`); a typed
//! run dropped when another job was opened from a list, and a spreadsheet row
//! pasted whole into one cell (`typed`); sessions
//! beyond the 50 newest and machines beyond 100 that the lists never showed
//! (`lists`); a trim job from stored coefficients that could not be solved
//! again when reopened in another browser (`trim`).

mod lists;
mod rotor;
mod trim;
mod typed;

use crate::harness::stand::Stand;
use crate::harness::Browser;

pub const ENTER: &str = "\u{e007}";

/// One browser for every scene of this binary (CI time); each scene gets a
/// new server and database and a freshly loaded form (`Stand::renew`).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_new_user_loses_nothing_typed_and_reads_each_number_with_its_unit() {
    let mut stand = Stand::start().await;
    typed::small_readings_are_shown_as_typed_and_answers_carry_their_unit(&stand).await;
    stand.renew().await;
    typed::a_pasted_spreadsheet_block_fills_the_cells_in_tab_order(&stand).await;
    stand.renew().await;
    rotor::a_rotor_given_in_part_is_marked_not_dropped(&stand).await;
    stand.renew().await;
    rotor::a_machine_is_stored_with_its_rotor(&stand).await;
    stand.renew().await;
    lists::every_stored_session_can_be_reached_from_the_list(&stand).await;
    stand.renew().await;
    typed::a_typed_run_is_not_dropped_by_opening_another_job(&stand).await;
    stand.renew().await;
    trim::a_trim_job_reopened_elsewhere_still_uses_the_stored_coefficients(&stand).await;
    stand.stop().await;
}

pub async fn texts(b: &Browser, css: &str) -> Vec<String> {
    b.wait_for(css).await;
    let script = format!(
        "return [...document.querySelectorAll({})].map((e) => e.textContent.trim())",
        serde_json::to_string(css).unwrap()
    );
    serde_json::from_value(b.client.execute(&script, vec![]).await.unwrap()).unwrap()
}

/// The message shown at `css` (empty when the field is not marked).
pub async fn message_at(b: &Browser, css: &str) -> String {
    let script = format!(
        "const f = document.querySelector({}).closest('.field'); return f.classList.contains('bad') ? f.querySelector('.msg').textContent : ''",
        serde_json::to_string(css).unwrap()
    );
    b.client
        .execute(&script, vec![])
        .await
        .unwrap()
        .as_str()
        .unwrap()
        .to_string()
}

/// The text of the confirmation the page asks (waited for, bounded).
pub async fn confirmation(b: &Browser) -> String {
    for _ in 0..crate::harness::WAIT_POLLS {
        if let Ok(text) = b.client.get_alert_text().await {
            return text;
        }
        tokio::time::sleep(std::time::Duration::from_millis(100)).await;
    }
    panic!("no confirmation was asked within 30 s");
}

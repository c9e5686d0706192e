//! The name the form proposes for a new trial run once check runs are stored.

use crate::harness::form::{field, value_of};
use crate::harness::Browser;

/// After the trials in both planes and two check runs ("check", "check 2"),
/// "+ Add trial run" proposes "trial 3": trials are counted, check runs not.
/// Every run with weights was counted, and it proposed "trial 5". Fails
/// without the fix (static/js/steps/options.js, trialCount).
pub async fn a_trial_after_check_runs_is_numbered_by_trials(b: &Browser) {
    b.click("#step-runs button.add-trial").await;
    assert_eq!(value_of(b, &field("runs[5].id")).await, "trial 3");
    b.click("#step-runs button.cancel").await;
}

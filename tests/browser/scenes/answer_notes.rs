//! What the answer page says where its figures could read as a contradiction
//! (issue 12, session 18): the job-level `regions_unreliable` by its cause,
//! a 95 % bound below the predicted figure, and a check run that agrees with
//! a row above its bound. Each is the page's own module rendered in the
//! browser; imported jobs (tests/browser/import.rs) run them in turn.

use crate::harness::stand::Stand;
use crate::harness::steps::js_async;

/// `regions_unreliable` has two causes (uncertainty/hidden.rs): planes alike
/// to the sensors, or a small trial beside planes without a warning (session
/// 18). The page's own words module tells them apart by the service's
/// message, and says what to do for each.
pub async fn the_job_level_warning_says_whether_a_small_trial_or_alike_planes_spoil_the_figures(
    stand: &Stand,
) {
    let b = &stand.browser;
    let script = r#"
        const [done] = arguments;
        import('/static/js/answer/words.js').then((m) => {
          const weak = { code: 'regions_unreliable', message: 'the trial in plane(s) P0 changed the vibration too little for its figures to be trusted (trial_effect_small), and the planes are solved together' };
          const alike = { code: 'regions_unreliable', message: 'plane(s) P1 act on the sensors almost like a combination of the other planes (ill_conditioned): a vibration ...' };
          const p1 = { plane: 'P1', mass_g: 3, angle_deg: 10, uncertainty: { mass_g: [2.9, 3.1], angle_deg: [9, 11] } };
          done([m.plainWarning(weak), m.plainWarning(alike),
                m.doubt({ warnings: [weak] }, p1), m.doubt({ warnings: [alike] }, p1)]);
        });
    "#;
    let got = js_async(b, script).await;
    let text = |v: &serde_json::Value| v.to_string();
    assert!(
        text(&got[0]).contains("A trial weight was too small")
            && text(&got[0]).contains("Repeat the small trial with a bigger weight")
            && !text(&got[0]).contains("almost the same"),
        "{got}"
    );
    assert!(
        text(&got[1]).contains("look almost the same") && !text(&got[1]).contains("too small"),
        "{got}"
    );
    assert!(
        text(&got[2]).contains("another plane's trial weight was too small"),
        "{got}"
    );
    assert!(text(&got[3]).contains("look almost the same"), "{got}");
}

/// A row whose 95 % bound is below its predicted figure, and a check run
/// that agrees with a row above its bound (helper qa18's review): the page
/// says why each is so, and says nothing where neither happens.
pub async fn a_bound_below_the_prediction_and_an_agreeing_row_above_its_bound_are_explained(
    stand: &Stand,
) {
    let b = &stand.browser;
    let script = r#"
        const [done] = arguments;
        Promise.all([import('/static/js/steps/solve.js'), import('/static/js/answer/answer.js')]).then(([s, a]) => {
          const row = (amplitude, amplitude_95) => ({ speed_rpm: 7200, sensor: 'B2Y', unit: 'um_pp', amplitude_before: 80, amplitude, phase_deg: 10, amplitude_95, used: true });
          const words = (x) => (x && x.textContent) || '';
          const check = (measured, consistent) => ({ conventions: { phase: 'lag' }, run_checks: [{ run: 'check', consistent, rms_measured: 9, rms_predicted: 7,
            rows: [{ speed_rpm: 7200, sensor: 'B2Y', measured, measured_phase_deg: 10, predicted: 7, predicted_phase_deg: 12, amplitude_95: 8 }] }] });
          const agrees = a.runChecks(check(9.5, true));
          done([words(s.residualNote({ predicted_residual: [row(31.2, 22.1), row(4, 9)] })),
                words(s.residualNote({ predicted_residual: [row(4, 9)] })),
                words(agrees.querySelector('.check-note')), agrees.querySelector('tr.above95') !== null,
                words(a.runChecks(check(7.5, true)).querySelector('.check-note')),
                words(a.runChecks(check(9.5, false)).querySelector('.check-note'))]);
        });
    "#;
    let got = js_async(b, script).await;
    let said = |i: usize| got[i].as_str().unwrap_or_default().to_string();
    assert!(
        said(0).starts_with("One row's 95 % bound is below the predicted figure")
            && said(0).contains("scatter of that row's own readings"),
        "{got}"
    );
    assert_eq!(said(1), "", "{got}");
    assert!(
        said(2).starts_with("One row lies above its 95 % bound, yet the run agrees"),
        "{got}"
    );
    assert_eq!(got[3], serde_json::json!(true), "the row is marked: {got}");
    assert_eq!(said(4), "", "no row above its bound: {got}");
    assert_eq!(said(5), "", "a run that differs needs no such note: {got}");
}

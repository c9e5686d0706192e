//! What the form says matches what the service means: a damping the readings
//! cannot resolve is shown as the bound it is, with the service's warning
//! (`damping`), a critical outside the speeds measured as extrapolated,
//! and each critical and damping ratio with its 95 % half-width
//! (`critical`), a solution's date in the one format of every other stored
//! time (`dates`), and a trim job's set-up says it is one and with which
//! coefficients, its run checks what they predict from, its results CSV
//! what run it adds to (`trim`); every warning of a solve with the service's
//! message, beside the plane it names (`warnings`); every angle of the
//! answer and the report with its convention (`conventions`), every
//! amplitude with its unit, on the machine page too (`units`); coefficients
//! pooled from jobs that disagree say so (`pooled`); a run typed while the
//! service is away is kept and stored later (`unreachable`); readings with
//! repeated samples say so in the grid (`samples`); a mass limit that a twin
//! plane makes up for is not called costly (`bound`); a store whose answer
//! was lost is not taken for another tab's, nor stored twice (`retry`); what
//! a technician read walking a job through the form (`walk`); a free decay
//! pasted on its page is answered as the service answers it (`decay`), and
//! so is a residual-unbalance check (`residual`).

mod answer;
mod identification;
mod job;
mod residual;

use crate::harness::stand::Stand;

/// One browser for every scene (CI time); each scene gets a new server and
/// database and a freshly loaded form (`Stand::renew`).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_form_says_what_the_service_means() {
    let mut stand = Stand::start().await;
    identification::decay::a_pasted_free_decay_is_answered_as_the_service_says(&stand).await;
    stand.renew().await;
    residual::a_residual_check_is_answered_as_the_service_says(&stand).await;
    stand.renew().await;
    identification::damping::an_unresolved_damping_is_shown_as_a_bound(&stand).await;
    stand.renew().await;
    identification::critical::a_critical_outside_the_speeds_measured_is_shown_as_extrapolated(
        &stand,
    )
    .await;
    stand.renew().await;
    identification::critical::a_critical_speed_is_shown_with_its_half_width(&stand).await;
    stand.renew().await;
    answer::dates::a_solution_date_is_in_the_format_of_the_lists(&stand).await;
    stand.renew().await;
    job::trim::a_trim_job_from_a_machine_says_so_at_its_set_up(&stand).await;
    stand.renew().await;
    job::trim::a_trim_job_with_supplied_coefficients_says_so_at_its_set_up(&stand).await;
    stand.renew().await;
    job::trim::a_trim_jobs_run_check_names_its_coefficients(&stand).await;
    stand.renew().await;
    job::trim::a_trims_results_csv_says_from_run_and_total(&stand).await;
    stand.renew().await;
    answer::warnings::every_solve_warning_is_shown_with_its_message_beside_its_plane(&stand).await;
    stand.renew().await;
    answer::conventions::every_angle_of_the_answer_and_report_says_its_convention(&stand).await;
    stand.renew().await;
    answer::units::every_amplitude_of_the_answer_says_its_unit(&stand).await;
    stand.renew().await;
    answer::units::the_machine_pages_jobs_say_their_unit(&stand).await;
    stand.renew().await;
    answer::units::figures_over_mixed_units_say_so(&stand).await;
    stand.renew().await;
    answer::units::a_limit_per_unit_when_sensors_mix_units(&stand).await;
    stand.renew().await;
    job::pooled::coefficients_from_jobs_that_disagree_say_so(&stand).await;
    stand.renew().await;
    job::unreachable::a_run_typed_while_the_service_is_away_is_kept_and_stored_later(&stand).await;
    stand.renew().await;
    answer::samples::readings_with_samples_say_so_in_the_grid(&stand).await;
    stand.renew().await;
    answer::bound::a_limit_a_twin_plane_makes_up_for_is_not_called_costly(&stand).await;
    stand.renew().await;
    job::retry::a_store_that_half_succeeded_is_not_taken_for_another_tab(&stand).await;
    stand.renew().await;
    job::walk::what_a_technician_reads_walking_a_job(&stand).await;
    stand.stop().await;
}

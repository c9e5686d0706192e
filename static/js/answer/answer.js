// The answer of a solve, as the corrections step shows it (the report reuses
// the parts): the verdict, what to bolt on, doubts, check runs, pictures.

import { h } from "../page/dom.js";
import { fmt, fmtAngle, unitOrMix, unitLabel } from "../page/num.js";
import { state, readingFor } from "../job/state.js";
import { sensorUnits } from "../steps/options.js";
import { correctionsTable, summaryBox, residualTable, residualNote, warningsBox, phaseWords, angleWords } from "../steps/solve.js";
import { doubt } from "./words.js";
import { planePicture } from "./planes.js";
import { plotsSection } from "../plots/plots.js";

/** The run a solution's "as found" describes: its from_run, else the zero run. */
function baseRun(sol) {
  const id = sol.from_run;
  return state.runs.find((r) => (id ? r.id === id : r.weights.length === 0)) || null;
}

/** Within tolerance: the largest reading of the base run against the limit the technician set. */
export function verdict(sol) {
  const run = baseRun(sol);
  if (!run) return "";
  if (sensorUnits().length > 1) return verdictByUnit(sol, run);
  const limit = state.options.limit;
  const max = sol.summary ? sol.summary.max_before : null;
  if (!limit || max === null) return "";
  const ok = max <= limit;
  const unit = unitOrMix(sol.predicted_residual);
  const u = unit ? ` ${unit}` : "";
  return h("div", { class: `verdict ${ok ? "ok" : "not-yet"}`, role: "status" },
    ok ? `Within tolerance: the largest vibration in run “${run.id}” is ${fmt(max)}${u}, at or below the limit of ${fmt(limit)}${u}. No more weights are needed.`
      : `Not yet within tolerance: the largest vibration in run “${run.id}” is ${fmt(max)}${u}, above the limit of ${fmt(limit)}${u}. Fit the weights below and do a check run.`);
}

/**
 * Sensors in several units: each unit's largest reading of the run (over the
 * rows the solve used) against that unit's limit; within tolerance when every
 * unit with a limit is. The summary's largest is over all the units at once,
 * a figure in no unit, so it is not used here.
 */
function verdictByUnit(sol, run) {
  const limits = state.options.limits || {};
  const used = sol.predicted_residual || [];
  const parts = [];
  for (const unit of sensorUnits()) {
    const limit = limits[unit];
    if (!limit) continue;
    const sensors = new Set(state.setup.sensors.filter((x) => x.unit === unit).map((x) => x.id));
    const rows = used.filter((row) => sensors.has(row.sensor));
    const amps = rows.map((row) => readingFor(run, { sensor: row.sensor, speed: row.speed_rpm })).filter(Boolean).map((r) => Math.abs(r.amplitude));
    if (!amps.length) continue;
    parts.push({ unit: unitLabel(unit), max: Math.max(...amps), limit });
  }
  if (!parts.length) return "";
  const ok = parts.every((p) => p.max <= p.limit);
  const each = parts.map((p) => `${fmt(p.max)} ${p.unit} ${p.max <= p.limit ? "at or below" : "above"} the limit of ${fmt(p.limit)} ${p.unit}`).join("; ");
  return h("div", { class: `verdict ${ok ? "ok" : "not-yet"}`, role: "status" },
    ok ? `Within tolerance: the largest vibration in run “${run.id}” is ${each}. No more weights are needed.`
      : `Not yet within tolerance: the largest vibration in run “${run.id}” is ${each}. Fit the weights below and do a check run.`);
}

/** "Add 4.2 g at 250° to what is on now, or replace the weights in this plane by …" */
export function trimWords(sol) {
  if (!sol.from_run) return "";
  const run = state.runs.find((r) => r.id === sol.from_run);
  return h("div", { class: "trim" },
    h("h3", {}, `Trim: the rotor as it is in run “${sol.from_run}”${run ? ` (${run.weights.length} weight${run.weights.length === 1 ? "" : "s"} on)` : ""}; angles ${angleWords(sol.conventions || state.setup.conventions)} from the mark`),
    h("ul", {}, sol.corrections.map((c) => h("li", { dataset: { plane: c.plane } },
      // A doubtful trim is said, not shouted: no bold for a weight that may be far off.
      c.mass_g < 0.05 ? h("strong", {}, `Plane ${c.plane}: nothing to add`) : h(doubt(sol, c) ? "span" : "strong", { class: doubt(sol, c) ? "doubtful" : null }, `Plane ${c.plane}: add ${fmt(c.mass_g)} g at ${fmtAngle(c.angle_deg)} to what is on now`),
      c.total ? `, or replace the weights in this plane by one weight of ${fmt(c.total.mass_g)} g at ${fmtAngle(c.total.angle_deg)}.` : "."))));
}

/** The unit of a sensor of the set-up, in words. */
function unitOf(sensor) {
  const x = state.setup.sensors.find((s) => s.id === sensor);
  return x ? unitLabel(x.unit) : "";
}

function checkRow(r) {
  return h("tr", { class: r.measured > r.amplitude_95 ? "above95" : "" },
    h("td", {}, fmt(r.speed_rpm, 0)), h("td", {}, r.sensor),
    h("td", { class: "measured" }, `${fmt(r.measured)} at ${fmtAngle(r.measured_phase_deg)}`),
    h("td", { class: "predicted" }, `${fmt(r.predicted)} at ${fmtAngle(r.predicted_phase_deg)}`),
    h("td", {}, `≤ ${fmt(r.amplitude_95)}`),
    h("td", { class: "unit" }, unitOf(r.sensor)));
}

/** " µm pk-pk" when every row of `rows` (with a `sensor`) reads in that unit; " (mixed units: …)" when they mix units. */
function rowsUnit(rows) {
  const u = unitOrMix((rows || []).map((r) => ({ unit: (state.setup.sensors.find((s) => s.id === r.sensor) || {}).unit })));
  return u ? ` ${u.startsWith("mixed") ? `(${u})` : u}` : "";
}

/**
 * What a run check's prediction comes from: the other runs of the job, or,
 * in a trim job, the coefficients it is solved with (the service checks each
 * run against those then, and no run against the others).
 */
function predictedFrom(sol) {
  const from = sol.coefficients_from;
  if (from) return { what: `the stored coefficients of machine ${from.machine} (version ${from.version ?? "latest"})`, given: true, verb: "predict" };
  const trim = state.setup.trim;
  const n = trim && Array.isArray(trim.influence_coefficients) ? trim.influence_coefficients.length : 0;
  if (n) return { what: `the ${n} supplied influence coefficient${n === 1 ? "" : "s"}`, given: true, verb: n === 1 ? "predicts" : "predict" };
  return { what: "the other runs", given: false, verb: "predict" };
}

/** Each check run (any run the others, or a trim job's coefficients, predict) beside its prediction. */
export function runChecks(sol) {
  if (!sol.run_checks || !sol.run_checks.length) return "";
  const from = predictedFrom(sol);
  const scatter = from.given ? "the scatter of the readings and of the coefficients" : "the readings' scatter";
  const then = from.given ? "Check its weights and readings; else the rotor or its mounting may have changed since the coefficients were measured." : "Check its weights and readings.";
  return h("div", { class: "run-checks" },
    h("h3", {}, "Runs beside their predictions"),
    sol.run_checks.map((c) => h("div", { class: `run-check ${c.consistent ? "agrees" : "differs"}`, dataset: { run: c.run } },
      h("p", {}, h("strong", {}, `Run “${c.run}”: `), c.consistent
        ? `agrees with what ${from.what} ${from.verb} for its weights (RMS ${fmt(c.rms_measured)}${rowsUnit(c.rows)} measured, ${fmt(c.rms_predicted)}${rowsUnit(c.rows)} predicted).`
        : `differs from what ${from.what} ${from.verb} for its weights by more than ${scatter} explains (RMS ${fmt(c.rms_measured)}${rowsUnit(c.rows)} measured, ${fmt(c.rms_predicted)}${rowsUnit(c.rows)} predicted). ${then}`),
      h("div", { class: "scroll" }, h("table", { class: "check-table" },
        h("thead", {}, h("tr", {}, h("th", {}, "Speed, rpm"), h("th", {}, "Sensor"), h("th", {}, `Measured, at phase ${phaseWords(sol)}`), h("th", {}, `Predicted, at phase ${phaseWords(sol)}`), h("th", {}, "95 % bound"), h("th", {}, "Unit"))),
        h("tbody", {}, c.rows.map(checkRow)))),
      checkNote(c))));
}

/**
 * Why a run can agree while a row lies above its 95 % bound: the verdict
 * weighs all the run's rows together at 99 %, the check readings' own
 * scatter included, and the bound is each row's own at 95 %.
 */
function checkNote(c) {
  const above = c.rows.filter((r) => r.measured > r.amplitude_95).length;
  if (!c.consistent || !above) return "";
  return h("p", { class: "note check-note" },
    `${above === 1 ? "One row lies" : `${above} rows lie`} above ${above === 1 ? "its" : "their"} 95 % bound, yet the run agrees: the verdict weighs all its rows together (at 99 %, counting the scatter of the check readings themselves), while each bound is that row's alone, and about one row in twenty is expected above it.`);
}

/** Where the influence coefficients came from, when not from this job's trial runs. */
function coefficientsWords(sol) {
  const from = sol.coefficients_from;
  const supplied = state.setup.trim && state.setup.trim.influence_coefficients;
  if (!from && supplied) return h("p", { class: "coefficients-from" }, `Influence coefficients: the ${supplied.length} supplied with the job (no trial runs in this job).`);
  if (!from) return "";
  return h("p", { class: "coefficients-from" }, `Influence coefficients: the stored ones of machine ${from.machine}, version ${from.version ?? "latest"} (no trial runs in this job).`);
}

/** Greyed corrections explained: why, and what to do. */
export function doubts(sol) {
  const list = sol.corrections.map((c) => doubt(sol, c)).filter(Boolean);
  if (!list.length) return "";
  return h("div", { class: "doubts", role: "note" }, h("h4", {}, "Not to be trusted as it stands (greyed above)"), h("ul", {}, list.map((t) => h("li", {}, t))));
}

/** Per plane, the picture of where the weights go. */
export function planePictures(sol) {
  const direction = (sol.conventions || state.setup.conventions).angle_direction;
  return h("div", { class: "plane-pics" }, sol.corrections.map((c) => {
    const plane = state.setup.planes.find((p) => p.id === c.plane) || { id: c.plane };
    const fig = planePicture(plane, sol, c, direction);
    // A weight not to be trusted as it stands is greyed here too, not drawn as sure.
    if (doubt(sol, c)) fig.classList.add("doubtful");
    return fig;
  }));
}

/** What the kit weights leave, beside what the exact corrections would. */
function fitSummary(sol) {
  const f = sol.fit_summary;
  if (!sol.fit || !f) return "";
  const unit = unitOrMix(sol.predicted_residual);
  const u = unit ? ` ${unit.startsWith("mixed") ? `(${unit})` : unit}` : "";
  return h("p", { class: "fit-summary" },
    `With the kit weights shown: RMS ${fmt(f.rms_after)}${u}, largest ${fmt(f.max_after)}${u} predicted after (the exact corrections above: RMS ${fmt(sol.summary.rms_after)}${u}). `,
    f.optimal ? "The best choice the kits allow." : "The best choice found in the time allowed, not proven the best.");
}

/** The weights on the rotor for the next check run: the base run's, plus the corrections (added). */
function checkWeights(sol, replaceInPlane) {
  const base = baseRun(sol);
  const on = base ? base.weights.map((w) => ({ ...w })) : [];
  const fit = (c) => {
    const f = sol.fit && sol.fit.find((x) => x.plane === c.plane);
    return f ? f.weights.map((w) => ({ plane: c.plane, mass_g: Number(w.mass_g.toFixed(1)), angle_deg: Number(w.angle_deg.toFixed(1)) }))
      : [{ plane: c.plane, mass_g: Number(c.mass_g.toFixed(1)), angle_deg: Number(c.angle_deg.toFixed(1)) }];
  };
  if (replaceInPlane && sol.from_run) {
    return sol.corrections.flatMap((c) => (c.total ? [{ plane: c.plane, mass_g: Number(c.total.mass_g.toFixed(1)), angle_deg: Number(c.total.angle_deg.toFixed(1)) }] : on.filter((w) => w.plane === c.plane)));
  }
  // A correction that rounds to 0.0 g is nothing to fit (the service refuses a weight of 0 g).
  return [...(sol.from_run ? on : []), ...sol.corrections.filter((c) => c.mass_g >= 0.05).flatMap(fit)].filter((w) => w.mass_g > 0);
}

/**
 * What the corrections are fitted to when they add to no run: the rotor as
 * found. A trim job has had no trial weights: it was told to fit them with
 * "all trial weights removed".
 */
function fitWords(sol) {
  if (!predictedFrom(sol).given) return "Fit these weights (all trial weights removed)";
  return state.runs.some((r) => r.weights.length) ? "Fit these weights to the rotor as found (the check runs' weights removed)" : "Fit these weights to the rotor as found";
}

export function answerParts(sol, checkRun) {
  return [
    verdict(sol),
    warningsBox(sol),
    coefficientsWords(sol),
    trimWords(sol),
    h("h3", {}, sol.from_run ? `Add these weights to what is on in run “${sol.from_run}”` : fitWords(sol)),
    h("div", { class: "scroll" }, correctionsTable(sol)),
    doubts(sol),
    planePictures(sol),
    fitSummary(sol),
    summaryBox(sol),
    runChecks(sol),
    h("h3", {}, "Predicted vibration after correction"),
    h("div", { class: "scroll" }, residualTable(sol)),
    residualNote(sol),
    plotsSection(sol),
    h("div", { class: "actions" },
      h("button", { type: "button", class: "primary check-run", onclick: () => checkRun(checkWeights(sol, false), sol.from_run || null) },
        sol.from_run ? "Weights added: record a check run →" : "Fit the weights, then record a check run →"),
      sol.from_run ? h("button", { type: "button", class: "check-run-replaced", onclick: () => checkRun(checkWeights(sol, true), sol.from_run) }, "Weights replaced by one per plane: record a check run →") : ""),
  ];
}

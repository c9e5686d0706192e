// The plots of a solution: for a job at several speeds, a Bode plot per sensor
// and a polar plot across speeds, with the identification of a critical speed
// when the job spans one; then the polar plot per sensor and speed, with a
// filter so that forty plots do not bury the one wanted.

import { h, replace } from "../page/dom.js";
import { fmt } from "../page/num.js";
import { api } from "../job/api.js";
import { state, rows, readingFor, referenceRun, sessionJson } from "../job/state.js";
import { polarPlot } from "./polar.js";
import { bodePlot, nyquistPlot, SERIES, CHECK_COLOURS } from "./bode.js";
import { checkRuns } from "../steps/options.js";

const near = (a, b) => Math.abs(a - b) <= 0.01 * Math.max(a, b);

/** Bode series of one sensor: as found, predicted after, each check run. */
function bodeSeries(sol, sensor) {
  const reference = referenceRun();
  const speeds = state.setup.speeds;
  const pick = (run) => speeds.map((speed) => readingFor(run, { speed, sensor })).filter(Boolean).map((r) => ({ speed: r.speed_rpm, amplitude: r.amplitude, phase: r.phase_deg }));
  const out = [{ ...SERIES[0], points: reference ? pick(reference) : [] }];
  out.push({ ...SERIES[1], points: sol.predicted_residual.filter((r) => r.sensor === sensor).map((r) => ({ speed: r.speed_rpm, amplitude: r.amplitude, phase: r.phase_deg })) });
  const checks = checkRuns();
  checks.forEach((run, i) => out.push({ text: `check run “${run.id}”`, colour: CHECK_COLOURS[i % CHECK_COLOURS.length], points: pick(run) }));
  return out;
}

/** Two significant digits, for a damping ratio that may be far below 0.001. */
const sig = (x) => (Number.isFinite(x) ? String(Number(x.toPrecision(2))) : "–");

/**
 * A damping ratio or amplification factor as the service gives it: a number,
 * or, when the readings do not resolve the damping (`*_bound`), the bound
 * they allow: "≤ ζ" (`upper`), "≥ AF" (`lower`), not a figure as if measured.
 */
function bounded(x, bound, digits) {
  if (bound === "upper") return `≤ ${x > 0 && x < 0.01 ? sig(x) : fmt(x, digits)}`;
  if (bound === "lower") return `≥ ${fmt(x, digits)}`;
  return fmt(x, digits);
}

/**
 * A fitted figure with its 95 % half-width `hw` (the identify answer's
 * `*_resolution*`), both to the half-width's second significant digit:
 * "2452 ± 23", "0.0512 ± 0.0087". A half-width below what `digits`
 * shows (exact readings) leaves the figure as it was.
 */
function withHalfWidth(x, hw, digits) {
  if (!Number.isFinite(x) || !Number.isFinite(hw) || hw < 0.5 * 10 ** -digits) return fmt(x, digits);
  const d = Math.max(0, 1 - Math.floor(Math.log10(hw)));
  return `${x.toFixed(d)} ± ${hw.toFixed(d)}`;
}

/**
 * The identify answer's warnings that concern one result: the service names
 * the plane (`plane`) and starts its message with "sensor 'S', plane 'P':".
 */
const aboutRow = (w, r) => w.plane === r.plane && String(w.message || "").startsWith(`sensor '${r.sensor}', plane '${r.plane}'`);

/** A warning of the identify answer, in the service's words. */
const identWarning = (w, tag) => h(tag, { class: `ident-warning ${w.code === "damping_unresolved" ? "damping-unresolved" : ""}`, dataset: { code: w.code, plane: w.plane || "" } },
  tag === "tr" ? h("td", { colspan: 6 }, `⚠ ${w.message}`) : `⚠ ${w.message}`);

/**
 * Identification of the rotor from the coefficients over the speeds (3 or
 * more): every critical speed the service finds, one outside the speeds
 * measured marked as extrapolated, and every warning the answer carries in
 * the service's words, under the result it concerns.
 */
function identification(sol) {
  const box = h("div", { class: "identification" }, h("p", { class: "hint" }, "Looking for a critical speed in the range…"));
  // Asked again whenever the job sent differs (a corrected run, a new speed).
  const session = sessionJson();
  const key = JSON.stringify(session);
  const draw = (res) => {
    const lo = Math.min(...state.setup.speeds);
    const hi = Math.max(...state.setup.speeds);
    const results = res.results || [];
    const warnings = res.warnings || [];
    const outside = (r) => r.critical_speed_rpm < lo || r.critical_speed_rpm > hi || warnings.some((w) => w.code === "critical_outside_range" && aboutRow(w, r));
    const loose = warnings.filter((w) => !results.some((r) => aboutRow(w, r)));
    const range = `${fmt(lo, 0)}–${fmt(hi, 0)} rpm`;
    replace(box,
      h("h4", {}, `Critical speeds from the readings at ${range}`),
      results.length ? h("table", { class: "ident-table" },
        h("thead", {}, h("tr", {}, h("th", {}, "Sensor"), h("th", {}, "Plane"), h("th", {}, "Critical speed, rpm"), h("th", {}, "Damping ratio"), h("th", {}, "Amplification"), h("th", {}, "Margin to service speed"))),
        h("tbody", {}, results.map((r) => [h("tr", { class: outside(r) ? "ident-result outside" : "ident-result", dataset: { sensor: r.sensor, plane: r.plane } },
          h("td", {}, r.sensor), h("td", {}, r.plane),
          h("td", { class: "critical" }, withHalfWidth(r.critical_speed_rpm, r.critical_speed_resolution_rpm, 0), outside(r) ? h("span", { class: "outside-note" }, ` outside the ${range} measured: extrapolated`) : ""),
          h("td", { class: r.damping_ratio_bound ? "damping bound" : "damping" }, r.damping_ratio_bound ? bounded(r.damping_ratio, r.damping_ratio_bound, 3) : withHalfWidth(r.damping_ratio, r.damping_ratio_resolution, 3)),
          h("td", { class: r.amplification_factor_bound ? "amplification bound" : "amplification" }, bounded(r.amplification_factor, r.amplification_factor_bound, 1)),
          h("td", {}, r.separation_margin_pct === undefined || r.separation_margin_pct === null ? "no service speed in this job's rotor data"
            : `${fmt(r.separation_margin_pct, 0)} %${r.required_margin_pct !== undefined && r.required_margin_pct !== null ? ` (API 684 asks ${fmt(r.required_margin_pct, 0)} %)` : ""}`)),
        warnings.filter((w) => aboutRow(w, r)).map((w) => identWarning(w, "tr"))]))) : h("p", { class: "hint" }, "No critical speed found."),
      loose.length ? h("ul", { class: "ident-warnings" }, loose.map((w) => identWarning(w, "li"))) : "");
  };
  if (identification.cache && identification.cache.key === key) draw(identification.cache.res);
  else {
    api.identifyRotor(session).then((res) => {
      identification.cache = { key, res };
      draw(res);
    }, (err) => replace(box, h("p", { class: "hint ident-error" }, `The rotor could not be identified from these speeds: ${err.message}`)));
  }
  return box;
}

function polarFor(sol, row) {
  const reference = referenceRun();
  const ref = reference && readingFor(reference, row);
  if (!ref) return "";
  const trials = state.runs.filter((r) => r.stored && r.weights.length > 0);
  const sensors = new Map(state.setup.sensors.map((x) => [x.id, x]));
  const residual = sol.predicted_residual.find((p) => p.sensor === row.sensor && near(p.speed_rpm, row.speed));
  return polarPlot({
    sensor: row.sensor,
    unit: (sensors.get(row.sensor) || {}).unit,
    speed: row.speed,
    phase: (sol.conventions || state.setup.conventions).phase,
    reference: ref,
    trials: trials.map((t) => ({ id: t.id, ...readingFor(t, row) })).filter((t) => t.amplitude !== undefined),
    residual,
  });
}

/** The polar plots per sensor and speed, behind a filter when there are many. */
function polarSection(sol) {
  const all = rows();
  const filter = state.polarFilter || (state.polarFilter = { sensor: "", speed: all.length > 8 ? String(state.setup.speeds[0]) : "" });
  const grid = h("div", { class: "plots" });
  const draw = () => replace(grid, all.filter((r) => (!filter.sensor || r.sensor === filter.sensor) && (!filter.speed || String(r.speed) === filter.speed)).map((r) => polarFor(sol, r)));
  draw();
  const select = (label, cls, key, choices) => h("label", {}, `${label} `, h("select", { class: cls, onchange: (e) => { filter[key] = e.target.value; draw(); } },
    h("option", { value: "", selected: !filter[key] }, "all"),
    choices.map(([v, t]) => h("option", { value: v, selected: filter[key] === v }, t))));
  return [
    h("h3", {}, "Polar plots"),
    all.length > 1 ? h("div", { class: "polar-filter" },
      select("Sensor", "filter-sensor", "sensor", state.setup.sensors.map((x) => [x.id, x.id])),
      state.setup.speeds.length > 1 ? select("Speed", "filter-speed", "speed", state.setup.speeds.map((x) => [String(x), `${fmt(x, 0)} rpm`])) : "") : "",
    grid,
  ];
}

export function plotsSection(sol) {
  const multi = state.setup.speeds.length > 1;
  const sensors = new Map(state.setup.sensors.map((x) => [x.id, x]));
  const phase = (sol.conventions || state.setup.conventions).phase;
  return h("div", { class: "all-plots" },
    multi ? [
      h("h3", {}, "Across the speeds"),
      h("div", { class: "bode-plots" }, state.setup.sensors.map((x) => [
        bodePlot({ sensor: x.id, unit: x.unit, phase, series: bodeSeries(sol, x.id) }),
        nyquistPlot({ sensor: x.id, unit: (sensors.get(x.id) || {}).unit, phase, points: bodeSeries(sol, x.id)[0].points }),
      ])),
      state.setup.speeds.length >= 3 ? identification(sol) : "",
    ] : "",
    polarSection(sol));
}

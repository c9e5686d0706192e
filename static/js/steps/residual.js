// Residual-unbalance check (API 617 / API 684 test-stand acceptance) by
// `POST /api/v1/residual-unbalance`: a line per trial position pasted ("angle
// amplitude phase", the phase optional); the service's answer, 95 % interval,
// API worksheet figure and warnings.

import { h, replace, $ } from "../page/dom.js";
import { numberInput, selectInput, textInput, mark, clearMarks, banner, sendAndShow, keptForm } from "../page/fields.js";
import { parseNumber, fmt, fmtAngle, isHeading } from "../page/num.js";
import { api } from "../job/api.js";
import { keptPage } from "../job/keep.js";

const PHASES = [["lag", "lag (the analyser's default)"], ["lead", "lead"]];
const DIRECTIONS = [["against_rotation", "against rotation"], ["with_rotation", "with rotation"]];

const EMPTY = {
  plane: "", speed_rpm: null, journal_load_kg: null, mass_g: null, radius_mm: null,
  phase: "lag", angle_direction: "against_rotation", readings: "", answer: null, stale: false,
};

// What was typed and its answer, kept across steps and reloads until "Start over".
const typed = keptPage("residual", EMPTY);
if (!PHASES.some(([v]) => v === typed.phase)) typed.phase = EMPTY.phase;
if (!DIRECTIONS.some(([v]) => v === typed.angle_direction)) typed.angle_direction = EMPTY.angle_direction;

/**
 * The positions of pasted text, a line each: trial angle, amplitude and
 * optionally phase, separated by tabs, spaces or ";" (decimal commas as in
 * the runs grid), or by ", " between numbers; a heading and degree signs
 * passed over. `{ readings, lines }` (each one's line) or `{ error }`.
 */
export function parsePositions(text) {
  const lines = String(text || "").split(/\r?\n/).map((l, k) => ({ k: k + 1, line: l.trim() })).filter((l) => l.line !== "");
  if (lines.length && isHeading(lines[0].line)) lines.shift();
  if (!lines.length) return { error: "paste a line per trial position: angle, amplitude and (optionally) phase" };
  const readings = [];
  const at = [];
  for (const { k, line } of lines) {
    const tokens = line.split(/[\s;]+|,\s+/).filter((x) => x !== "");
    if (tokens.length < 2 || tokens.length > 3) {
      return { error: `line ${k} (${line}): angle and amplitude, then the phase if measured` };
    }
    const values = [];
    for (const [i, token] of tokens.entries()) {
      const r = parseNumber(i === 1 ? token : token.replace(/\s*°$/, ""));
      if (r.error) return { error: `line ${k} (${token}): ${r.error}` };
      values.push(r.value);
    }
    const reading = { angle_deg: values[0], amplitude: values[1] };
    if (values.length === 3) reading.phase_deg = values[2];
    readings.push(reading);
    at.push(k);
  }
  const phased = readings.map((r) => r.phase_deg !== undefined);
  const odd = phased.findIndex((p) => p !== phased[0]);
  if (odd > 0) {
    return { error: `line ${at[odd]} ${phased[0] ? "has no phase, line " + at[0] + " has one" : "has a phase, line " + at[0] + " has none"}: a phase on every line or none` };
  }
  return { readings, lines: at };
}

/** The service's "readings[3]" as the line it was pasted on. */
export function inLines(text, lines) {
  return String(text ?? "").replace(/readings\[(\d+)\]/g, (m, i) => (lines[Number(i)] ? `line ${lines[Number(i)]}` : m));
}

function answerTable(a) {
  const dir = (a.conventions && a.conventions.angle_direction) === "with_rotation" ? "with rotation" : "against rotation";
  const u = a.uncertainty || {};
  const interval = (pair, f) => (Array.isArray(pair) ? `${f(pair[0])} to ${f(pair[1])}` : "–");
  const gmm = (x) => `${fmt(x, 0)} g·mm`;
  const angleUndetermined = Array.isArray(u.residual_angle_deg) && u.residual_angle_deg[0] === 0 && u.residual_angle_deg[1] === 360;
  const rows = [
    ["verdict", "Verdict", a.pass ? `Pass: residual ${fmt(100 * a.ratio, 0)} % of the allowable` : `Fail: residual ${fmt(100 * a.ratio, 0)} % of the allowable`],
    ["residual", "Residual unbalance", `${gmm(a.residual_unbalance_gmm)} (95 %: ${interval(u.residual_unbalance_gmm, (x) => fmt(x, 0))} g·mm)`],
    ["angle", `Where it is (heavy spot), ° ${dir} from the trial's 0°`, angleUndetermined
      ? `${fmtAngle(a.residual_angle_deg)} (undetermined)`
      : `${fmtAngle(a.residual_angle_deg)} (95 %: ${interval(u.residual_angle_deg, (x) => fmtAngle(x))})`],
    ["allowable", "Allowable, API 6350·W/N", gmm(a.allowable_gmm)],
    ["trial", "Trial unbalance", `${gmm(a.trial_unbalance_gmm)} (${fmt(a.trial_ratio)} × allowable; API asks 1 to 2)`],
    ["method", "Fit", a.method === "circle_fit"
      ? `circle through ${a.positions} positions (amplitudes and phases)`
      : `amplitudes of ${a.positions} positions (no phases)`],
  ];
  if (a.alternative_residual_gmm !== undefined && a.alternative_residual_gmm !== null) {
    rows.push(["alternative", "The other residual the amplitudes allow", gmm(a.alternative_residual_gmm)]);
  }
  if (a.worksheet) {
    rows.push(["worksheet", "API worksheet (trial · Y/Z)", `${gmm(a.worksheet.residual_unbalance_gmm)}, ${a.worksheet.pass ? "pass" : "fail"}`]);
  }
  return h("table", { class: "residual-answer" },
    h("tbody", {}, rows.map(([cls, label, value]) => h("tr", { class: cls }, h("th", { scope: "row" }, label), h("td", {}, value)))));
}

function answerView(a) {
  const warnings = Array.isArray(a.warnings) ? a.warnings : [];
  return h("div", { class: `residual-result ${a.pass ? "pass" : "fail"}`, role: "status" },
    h("h3", {}, a.plane ? `Answer, plane ${a.plane}` : "Answer"),
    answerTable(a),
    warnings.length
      ? h("div", { class: "warnings residual-warnings", role: "alert" },
        h("ul", {}, warnings.map((w) => h("li", { dataset: { code: w.code || "" } }, `⚠ ${w.message || w.code}`))))
      : null);
}

/** Draw the residual-unbalance page in `root`. */
export function renderResidual(root) {
  const readings = h("textarea", {
    rows: 13, cols: 28, spellcheck: "false", autocomplete: "off",
    dataset: { field: "readings" }, "aria-label": "Readings, a line per trial position",
    placeholder: "0 2.45 335.7\n30 2.59 356.3\n60 2.62 15.5\n…",
    oninput: () => { typed.readings = readings.value; mark(readings, ""); },
  });
  readings.value = typed.readings;
  const kept = keptForm("residual", typed, EMPTY, answerView, "Empty this page: the readings, the plane, speed, load and trial weight, and the answer? Cancel to keep them.", () => {
    renderResidual(root);
    $('[data-field="readings"]', root).focus();
  });
  const result = h("div", { class: "residual-out" }, kept.shown);
  const run = h("button", { type: "submit", class: "primary check-residual" }, "Check");
  const num = (field, kind, label, placeholder, key) => h("label", {}, h("span", {}, label),
    numberInput({ field, kind, value: typed[key], label, placeholder, size: 9, onValue: (v) => { typed[key] = v; } }));
  const form = kept.watch(h("form", { class: "decay-form residual-form", novalidate: true, onsubmit: (e) => { e.preventDefault(); check(); } },
    h("div", { class: "decay-fields" },
      h("label", {}, h("span", {}, "Readings: a line per trial position — the trial weight's angle, the 1X amplitude (any one unit), and its phase if measured; pasted from a spreadsheet or separated by spaces"),
        h("span", { class: "field readings-field" }, readings, h("span", { class: "msg", role: "alert" }))),
      h("div", { class: "decay-side" },
        h("label", {}, h("span", {}, "Plane (optional)"),
          textInput({ field: "plane", value: typed.plane, label: "Plane", size: 9, maxlength: 64, onValue: (v) => { typed.plane = v; } })),
        num("speed_rpm", "speed", "Speed, rpm (API's N)", "9000", "speed_rpm"),
        num("journal_load_kg", "load", "Static load on the nearest journal, kg (API's W)", "530.7", "journal_load_kg"),
        num("trial.mass_g", "mass", "Trial weight, g", "3", "mass_g"),
        num("trial.radius_mm", "radius", "Trial weight radius, mm", "150", "radius_mm"),
        h("label", {}, h("span", {}, "Phase convention"),
          selectInput({ field: "conventions.phase", value: typed.phase, choices: PHASES, label: "Phase convention", onValue: (v) => { typed.phase = v; } })),
        h("label", {}, h("span", {}, "Trial angles counted"),
          selectInput({ field: "conventions.angle_direction", value: typed.angle_direction, choices: DIRECTIONS, label: "Trial angle direction", onValue: (v) => { typed.angle_direction = v; } })),
        h("div", { class: "actions decay-actions" }, run, kept.again))),
  ), result);

  async function check() {
    clearMarks(root);
    mark(readings, "");
    banner(root, "error", "");
    for (const f of ["speed_rpm", "journal_load_kg", "trial.mass_g", "trial.radius_mm"]) {
      const input = $(`[data-field="${f}"]`, root);
      if (!input.validateNow()) return input.focus();
    }
    const parsed = parsePositions(readings.value);
    if (parsed.error) {
      mark(readings, parsed.error);
      return readings.focus();
    }
    const body = {
      speed_rpm: typed.speed_rpm,
      trial: { mass_g: typed.mass_g, radius_mm: typed.radius_mm },
      journal_load_kg: typed.journal_load_kg,
      readings: parsed.readings,
      conventions: { phase: typed.phase, angle_direction: typed.angle_direction },
    };
    if (typed.plane) body.plane = typed.plane;
    const said = (w) => ({ ...w, message: inLines(w.message, parsed.lines) });
    const send = () => api.residualUnbalance(body).then(
      (a) => (Array.isArray(a.warnings) ? { ...a, warnings: a.warnings.map(said) } : a),
      (err) => {
        err.message = inLines(err.message, parsed.lines);
        throw err;
      });
    await sendAndShow({ root, run, result, typed, send, view: answerView });
    kept.save();
  }

  replace(root,
    h("h2", {}, "Residual-unbalance check (API 617 / API 684)"),
    h("p", { class: "note" }, "The test-stand acceptance test: a known trial weight placed in turn at 4 or more equally spaced angles (API asks 6 or 12; the first may be repeated at the end), the 1X reading at each. The service fits all positions exactly and compares the residual with API's allowable 6350·W/N g·mm (4W/N oz·in). Nothing is stored on the service."),
    form,
    result);
}

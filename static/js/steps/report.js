// Step 4, the printable report with what ISO 21940-13 asks of an in-situ
// balancing report, the answer first. Print CSS shows only this section.

import { h, replace, $ } from "../page/dom.js";
import { fmt, fmtAngle, unitLabel, unitOrMix, storedAt } from "../page/num.js";
import { state, rows, readingFor } from "../job/state.js";
import { weightsText } from "./runs.js";
import { correctionsTable, residualTable, residualNote, summaryBox, warningsBox, angleWords } from "./solve.js";
import { verdict, trimWords, runChecks, planePictures, doubts } from "../answer/answer.js";
import { plotsSection } from "../plots/plots.js";

// The kit weights to fit, when the solution has a discrete fit (`fit`), in g
// to 0.1 g as every other table of weights.
function fitTable(sol) {
  if (!sol.fit) return "";
  const optimal = sol.fit_summary && sol.fit_summary.optimal;
  const unit = unitOrMix(sol.predicted_residual);
  const u = unit ? ` ${unit.startsWith("mixed") ? `(${unit})` : unit}` : "";
  return h("div", { class: "report-fit" },
    h("h4", {}, "Weights to fit"),
    h("table", {}, h("thead", {}, h("tr", {}, h("th", {}, "Plane"), h("th", {}, "Place"), h("th", {}, `Angle, ° (${angleWords(sol.conventions || state.setup.conventions)})`), h("th", {}, "Mass, g"))),
      h("tbody", {}, sol.fit.map((p) => (p.weights.length ? p.weights : [null]).map((w, i) =>
        h("tr", {}, h("td", {}, i === 0 ? p.plane : ""),
          h("td", {}, w ? String(w.place) : "none"), h("td", {}, w ? fmt(w.angle_deg) : "–"), h("td", {}, w ? fmt(w.mass_g) : "–")))))),
    sol.fit_summary ? h("p", {}, `With these weights: RMS ${fmt(sol.fit_summary.rms_after)}${u}, max ${fmt(sol.fit_summary.max_after)}${u}${optimal ? " (proven best for the kits)" : " (best found within the time bound, not proven best)"}.`) : "");
}

/** "(lag)" or "(lead)", for a column of phases. */
const phaseOf = (c) => (c.phase === "lead" ? "(lead)" : "(lag)");

function conventionWords(c) {
  return `phase ${c.phase}, weight angles ${c.angle_direction === "with_rotation" ? "with rotation" : "against rotation"}`;
}

// The ISO 21940-11 verdict per plane (issue 17), when the solution carries one.
function isoVerdict(sol) {
  const iso = sol.iso_21940;
  if (!iso || !iso.planes) return "";
  const word = (ok) => (ok === undefined || ok === null ? "–" : ok ? "pass" : "fail");
  return h("div", { class: "iso-verdict" },
    h("h4", {}, `ISO 21940-11 ${iso.balance_grade}: ${word(iso.pass)} as measured, ${word(iso.after_correction_pass)} once corrected (95 %)`),
    h("table", {}, h("thead", {}, h("tr", {}, h("th", {}, "Plane"), h("th", {}, "Residual, g·mm"), h("th", {}, "Permissible, g·mm"), h("th", {}, "As measured"), h("th", {}, "After correction ≤, g·mm"), h("th", {}, "Once corrected"))),
      h("tbody", {}, iso.planes.map((v) => h("tr", { dataset: { plane: v.plane } },
        h("td", {}, v.plane), h("td", {}, fmt(v.residual_unbalance_gmm, 0)), h("td", {}, fmt(v.permissible_gmm, 0)),
        h("td", { class: "verdict" }, word(v.pass)),
        h("td", {}, v.after_correction_95_gmm === undefined ? "–" : fmt(v.after_correction_95_gmm, 0)),
        h("td", {}, word(v.after_correction_pass)))))));
}

/**
 * The fixed place a weight sits at, from its angle: the plane's equally
 * spaced places (place 0 at the mark) or its listed angles; "–" off a place.
 */
export function placeOf(plane, angle) {
  const near = (a, b) => Math.abs(((a - b + 540) % 360) - 180) < 0.05;
  const at = plane && plane.places_deg ? plane.places_deg : plane && plane.positions ? [...Array(plane.positions).keys()].map((k) => (360 * k) / plane.positions) : [];
  const k = at.findIndex((a) => near(a, angle));
  return k < 0 ? "–" : String(k);
}

/** A weight as the report lists it: plane, mass, radius, angle, place. */
function weightRows(run) {
  const planes = new Map(state.setup.planes.map((p) => [p.id, p]));
  return run.weights.map((w, i) => h("tr", {},
    h("td", {}, i === 0 ? run.id : ""), h("td", {}, w.plane), h("td", {}, `${fmt(w.mass_g)} g`),
    h("td", {}, planes.get(w.plane) && planes.get(w.plane).radius_mm ? `${fmt(planes.get(w.plane).radius_mm, 0)} mm` : "–"),
    h("td", {}, fmtAngle(w.angle_deg)), h("td", { class: "place" }, placeOf(planes.get(w.plane), w.angle_deg))));
}

/** Where the coefficients came from: a trim job with supplied ones did not estimate them from its runs. */
function coefficientsSource(sol) {
  if (sol.coefficients_from) return `Stored coefficients of machine ${sol.coefficients_from.machine}, version ${sol.coefficients_from.version ?? "latest"}.`;
  const supplied = state.setup.trim && state.setup.trim.influence_coefficients;
  if (supplied) return `Supplied with the job (${supplied.length} coefficient${supplied.length === 1 ? "" : "s"}), not estimated from its runs.`;
  return "Estimated from this job's runs by least squares.";
}

function coefficientsTable(sol) {
  const units = new Map(state.setup.sensors.map((x) => [x.id, x.unit]));
  return [
    h("p", { class: "coefficients-source" }, coefficientsSource(sol)),
    h("table", { class: "report-coefficients" },
      h("thead", {}, h("tr", {}, h("th", {}, "Speed, rpm"), h("th", {}, "Sensor"), h("th", {}, "Plane"), h("th", {}, "Amplitude per gram"), h("th", {}, `Phase, ° ${phaseOf(sol.conventions || state.setup.conventions)}`))),
      h("tbody", {}, (sol.influence_coefficients || []).map((c) => h("tr", {},
        h("td", {}, fmt(c.speed_rpm, 0)), h("td", {}, c.sensor), h("td", {}, c.plane),
        h("td", {}, `${fmt(c.amplitude_per_g, 3)} ${unitLabel(units.get(c.sensor))}/g`), h("td", {}, fmt(c.phase_deg)))))),
  ];
}

/** The part the customer reads first: the verdict and what was (to be) fitted. */
function answerSection(sol) {
  if (!sol) return h("section", { class: "report-answer" }, h("h3", {}, "Result"), h("p", {}, "Not solved yet."));
  return h("section", { class: "report-answer" },
    h("h3", {}, "Result"),
    verdict(sol),
    trimWords(sol),
    correctionsTable(sol),
    doubts(sol),
    fitTable(sol),
    summaryBox(sol),
    isoVerdict(sol),
    warningsBox(sol));
}

export function renderReport(root) {
  const setup = state.setup;
  const runs = state.runs.filter((r) => r.stored);
  const sol = state.solution;
  const now = new Date();
  const info = state.report;
  const units = new Map(setup.sensors.map((x) => [x.id, x.unit]));
  replace(root,
    h("div", { class: "no-print report-fields" },
      h("label", {}, h("span", {}, "Reason for balancing"), h("input", { type: "text", class: "report-reason", value: info.reason, size: 40, placeholder: "e.g. vibration alarm after blade repair", oninput: (e) => { info.reason = e.target.value; $(".reason-text", root).textContent = info.reason || "–"; } })),
      h("label", {}, h("span", {}, "Balanced by"), h("input", { type: "text", class: "report-by", value: info.by, size: 24, oninput: (e) => { info.by = e.target.value; $(".by-text", root).textContent = info.by || ""; } })),
      h("button", { type: "button", class: "primary print", onclick: () => window.print() }, "Print report")),
    h("article", { class: "report" },
      h("header", {},
        h("h2", { class: "report-title" }, `Balancing report — ${setup.name || "unnamed"}`),
        h("p", {}, `Machine: ${setup.machine || "–"} · printed ${storedAt(now.toISOString())}${state.id ? ` · Session ${state.id}` : ""}`),
        h("p", {}, "Reason: ", h("span", { class: "reason-text" }, info.reason || "–"))),
      answerSection(sol),
      h("section", { class: "report-setup" },
        h("h3", {}, "Machine, instrumentation and conventions"),
        setup.rotor && setup.rotor.mass_kg ? h("p", {}, `Rotor: ${fmt(setup.rotor.mass_kg, 0)} kg, service speed ${fmt(setup.rotor.service_speed_rpm, 0)} rpm${setup.rotor.balance_grade ? `, balance grade ${setup.rotor.balance_grade} (ISO 21940-11)` : ""}.`) : "",
        h("p", {}, `Phase reference: the once-per-revolution mark, angle 0°. Conventions: ${conventionWords(setup.conventions)}. Speeds: ${setup.speeds.map((x) => fmt(x, 0)).join(", ")} rpm. 1X readings (amplitude and phase at running speed).`),
        h("table", {}, h("thead", {}, h("tr", {}, h("th", {}, "Plane"), h("th", {}, "Radius, mm"), h("th", {}, "Fixed places"), h("th", {}, "Kit, g"))),
          h("tbody", {}, setup.planes.map((p) => h("tr", {}, h("td", {}, p.id), h("td", {}, p.radius_mm ?? "–"),
            h("td", {}, p.places_deg ? p.places_deg.join(", ") + "°" : p.positions ?? "–"), h("td", {}, p.kit ? p.kit.masses_g.join(", ") : "–"))))),
        h("table", {}, h("thead", {}, h("tr", {}, h("th", {}, "Sensor"), h("th", {}, "Unit"), h("th", {}, "Where"))),
          h("tbody", {}, setup.sensors.map((x) => h("tr", {}, h("td", {}, x.id), h("td", {}, unitLabel(x.unit)), h("td", {}, x.label || "–")))))),
      h("section", { class: "report-weights" },
        h("h3", {}, "Trial and correction weights"),
        h("table", {}, h("thead", {}, h("tr", {}, h("th", {}, "Run"), h("th", {}, "Plane"), h("th", {}, "Mass"), h("th", {}, "Radius"), h("th", {}, `Angle (${angleWords(setup.conventions)})`), h("th", {}, "Place"))),
          h("tbody", {}, runs.filter((r) => r.weights.length).map(weightRows)))),
      h("section", { class: "report-runs-section" },
        h("h3", {}, "Runs"),
        h("table", { class: "report-runs" },
          h("thead", {}, h("tr", {}, h("th", {}, "Run"), h("th", {}, `Weights (angles ${angleWords(setup.conventions)})`), h("th", {}, "Speed, rpm"), h("th", {}, "Sensor"), h("th", {}, "Amplitude"), h("th", {}, "Unit"), h("th", {}, `Phase, ° ${phaseOf(setup.conventions)}`))),
          h("tbody", {}, runs.map((run) => rows().map((row, i) => {
            const r = readingFor(run, row);
            // The run's name on every row: a page break may fall anywhere in it.
            return h("tr", { class: i === 0 ? "first" : "cont" },
              h("td", { class: "run-name" }, run.id), h("td", {}, i === 0 ? weightsText(run.weights) : ""),
              h("td", {}, fmt(row.speed, 0)), h("td", {}, row.sensor),
              h("td", {}, r ? fmt(r.amplitude, 2) : "–"), h("td", {}, unitLabel(units.get(row.sensor))), h("td", {}, r ? fmt(r.phase_deg) : "–"));
          }))))),
      sol ? h("section", { class: "report-coeffs" }, h("h3", {}, "Influence coefficients used"), coefficientsTable(sol)) : "",
      sol ? h("section", { class: "report-residual" }, h("h3", {}, "Predicted vibration after correction"), residualTable(sol), residualNote(sol), runChecks(sol)) : "",
      sol ? h("section", { class: "report-plots" }, h("h3", {}, "Plots"), planePictures(sol), plotsSection(sol)) : "",
      h("footer", { class: "signature" },
        h("p", {}, `Date: ${now.toISOString().slice(0, 10)}`),
        h("div", { class: "sign-lines" },
          h("div", {}, h("span", { class: "line" }), h("span", {}, "Balanced by: ", h("span", { class: "by-text" }, info.by || ""))),
          h("div", {}, h("span", { class: "line" }), h("span", {}, "Accepted for the customer: name and signature")))),
    ),
  );
}

// Step 4, the printable report: set-up, all runs, the solution and the date.
// Print CSS shows only this section on paper.

import { h, replace } from "./dom.js";
import { fmt, unitLabel } from "./num.js";
import { state, rows, readingFor } from "./state.js";
import { weightsText } from "./runs.js";
import { correctionsTable, residualTable, summaryBox, warningsBox } from "./solve.js";

// The kit weights to fit, when the solution has a discrete fit (`fit`).
function fitTable(sol) {
  if (!sol.fit) return "";
  const optimal = sol.fit_summary && sol.fit_summary.optimal;
  return h("div", { class: "report-fit" },
    h("h4", {}, "Weights to fit"),
    h("table", {}, h("thead", {}, h("tr", {}, h("th", {}, "Plane"), h("th", {}, "Place"), h("th", {}, "Angle, °"), h("th", {}, "Mass, g"))),
      h("tbody", {}, sol.fit.map((p) => (p.weights.length ? p.weights : [null]).map((w, i) =>
        h("tr", {}, h("td", {}, i === 0 ? p.plane : ""),
          h("td", {}, w ? String(w.place) : "none"), h("td", {}, w ? fmt(w.angle_deg, 1) : "–"), h("td", {}, w ? fmt(w.mass_g, 2) : "–")))))),
    sol.fit_summary ? h("p", {}, `With these weights: RMS ${fmt(sol.fit_summary.rms_after, 2)}, max ${fmt(sol.fit_summary.max_after, 2)}${optimal ? " (proven best for the kits)" : " (best found within the time bound, not proven best)"}.`) : "");
}

function conventionWords(c) {
  return `phase ${c.phase}, weight angles ${c.angle_direction === "with_rotation" ? "with rotation" : "against rotation"}`;
}

export function renderReport(root) {
  const setup = state.setup;
  const runs = state.runs.filter((r) => r.stored);
  const sol = state.solution;
  const now = new Date();
  replace(root,
    h("div", { class: "no-print actions" }, h("button", { type: "button", class: "primary print", onclick: () => window.print() }, "Print report")),
    h("article", { class: "report" },
      h("header", {},
        h("h2", { class: "report-title" }, `Balancing report — ${setup.name || "unnamed"}`),
        h("p", {}, `Machine: ${setup.machine || "–"} · Printed ${now.toLocaleString()} (${now.toISOString().slice(0, 10)})${state.id ? ` · Session ${state.id}` : ""}`)),
      h("section", {},
        h("h3", {}, "Set-up"),
        h("p", {}, `Conventions: ${conventionWords(setup.conventions)}. Speeds: ${setup.speeds.map((x) => fmt(x, 0)).join(", ")} rpm.`),
        h("table", {}, h("thead", {}, h("tr", {}, h("th", {}, "Plane"), h("th", {}, "Radius, mm"), h("th", {}, "Fixed places"))),
          h("tbody", {}, setup.planes.map((p) => h("tr", {}, h("td", {}, p.id), h("td", {}, p.radius_mm ?? "–"), h("td", {}, p.positions ?? "–"))))),
        h("table", {}, h("thead", {}, h("tr", {}, h("th", {}, "Sensor"), h("th", {}, "Unit"), h("th", {}, "Where"))),
          h("tbody", {}, setup.sensors.map((x) => h("tr", {}, h("td", {}, x.id), h("td", {}, unitLabel(x.unit)), h("td", {}, x.label || "–")))))),
      h("section", {},
        h("h3", {}, "Runs"),
        h("table", { class: "report-runs" },
          h("thead", {}, h("tr", {}, h("th", {}, "Run"), h("th", {}, "Weights"), h("th", {}, "Speed, rpm"), h("th", {}, "Sensor"), h("th", {}, "Amplitude"), h("th", {}, "Phase, °"))),
          h("tbody", {}, runs.map((run) => rows().map((row, i) => {
            const r = readingFor(run, row);
            return h("tr", { class: i === 0 ? "first" : "" },
              h("td", {}, i === 0 ? run.id : ""), h("td", {}, i === 0 ? weightsText(run.weights) : ""),
              h("td", {}, fmt(row.speed, 0)), h("td", {}, row.sensor),
              h("td", {}, r ? fmt(r.amplitude, 2) : "–"), h("td", {}, r ? fmt(r.phase_deg, 1) : "–"));
          }))))),
      sol ? h("section", {},
        h("h3", {}, "Solution"),
        warningsBox(sol),
        correctionsTable(sol),
        fitTable(sol),
        summaryBox(sol),
        residualTable(sol)) : h("p", {}, "Not solved yet."),
    ),
  );
}

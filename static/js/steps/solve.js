// Step 3, the solution: warnings first and in plain words, then the corrections
// (mass, angle, unbalance, split over fixed places, uncertainty), the predicted
// residual per sensor and speed, the before/after summary and the polar plots.

import { h, replace } from "../page/dom.js";
import { banner, markServerError } from "../page/fields.js";
import { fmt, fmtAngle, angleDiff, unitLabel, unitOrMix, storedAt } from "../page/num.js";
import { api } from "../job/api.js";
import { state, changed } from "../job/state.js";
import { plainWarning, doubt, UNBIASED_WORDS } from "../answer/words.js";
import { optionsPanel, solveOptions } from "./options.js";
import { answerParts } from "../answer/answer.js";

/** "52 g ± 4 g, 141° ± 5°": the 95 % intervals as a half-width around the value. */
export function uncertaintyText(c) {
  return uncertaintyParts(c).join(", ");
}

/** The mass part and the angle part of `uncertaintyText`. */
function uncertaintyParts(c) {
  const u = c.uncertainty;
  if (!u) return [];
  // No mass interval: the readings cannot determine this plane (plane_undetermined).
  if (!u.mass_g) return [`${fmt(c.mass_g)} g (undetermined)`, "angle undetermined"];
  // A 95 % region around zero (the service gives the angle as [0, 360]): the
  // noise could account for the whole correction, so no angle can be trusted.
  if (u.angle_deg[1] - u.angle_deg[0] >= 359.999) {
    return [`${fmt(c.mass_g)} g (0 to ${fmt(u.mass_g[1])} g)`, "angle undetermined"];
  }
  const dm = Math.max(Math.abs(u.mass_g[1] - c.mass_g), Math.abs(c.mass_g - u.mass_g[0]));
  const da = Math.max(angleDiff(u.angle_deg[1], c.angle_deg), angleDiff(c.angle_deg, u.angle_deg[0]));
  return [`${fmt(c.mass_g)} g ± ${fmt(dm)} g`, `${fmtAngle(c.angle_deg)} ± ${fmt(da)}°`];
}

/**
 * The correction without the pull towards zero that noisy coefficients give
 * least squares (`uncertainty.bias_corrected`, C* of method.md 8.11), as one
 * short line under the 95 % figures; nothing when the service gives none
 * (the noise neither stated nor measured, min-max, a mass limit reached).
 */
function unbiasedLine(c) {
  const b = c.uncertainty && c.uncertainty.bias_corrected;
  if (!b) return "";
  return h("div", { class: "corr-unbiased", title: UNBIASED_WORDS }, `without the noise's pull: ${fmt(b.mass_g)} g at ${fmtAngle(b.angle_deg)}`);
}

/** "with rotation" or "against rotation": how the weight angles are counted from the mark. */
export function angleWords(conventions) {
  return conventions.angle_direction === "with_rotation" ? "with rotation" : "against rotation";
}

/**
 * The warnings that name a plane, in a row under that plane's correction, so
 * that the weight read off the table (a mass held at its limit, a split that
 * cannot be exact) comes with them.
 */
function planeWarnings(solution, plane) {
  return (solution.warnings || []).filter((w) => w.plane === plane).map((w) => h("tr", { class: "plane-warning", dataset: { code: w.code, plane } },
    h("td", { colspan: 6 }, `⚠ Plane ${plane}: ${plainWarning(w).what}`)));
}

export function correctionsTable(solution) {
  const words = angleWords(solution.conventions || state.setup.conventions);
  return h("table", { class: "corrections" },
    h("thead", {}, h("tr", {}, h("th", {}, "Plane"), h("th", {}, "Mass"), h("th", {}, `Angle (${words})`), h("th", {}, "95 % uncertainty"), h("th", {}, "Unbalance"), h("th", {}, "On fixed places"))),
    h("tbody", {}, solution.corrections.map((c) => {
      // A trim that leaves a plane as it is: no weight, so no angle to read (the trim words say so).
      const nothing = solution.from_run && c.mass_g < 0.05;
      return [h("tr", { dataset: { plane: c.plane }, class: doubt(solution, c) ? "doubtful" : nothing ? "nothing" : null, title: doubt(solution, c) || null },
      h("th", { class: "corr-plane" }, c.plane),
      h("td", { class: "corr-mass" }, nothing ? "nothing to add" : `${fmt(c.mass_g)} g`),
      h("td", { class: "corr-angle" }, nothing ? "–" : fmtAngle(c.angle_deg)),
      h("td", { class: "corr-uncertainty" }, c.uncertainty ? [uncertaintyParts(c).map((part, i) => [i ? ", " : "", h("span", { class: "nw" }, part)]), nothing ? null : unbiasedLine(c)] : "–"),
      h("td", { class: "corr-unbalance" }, c.unbalance_gmm !== undefined && c.unbalance_gmm !== null ? `${fmt(c.unbalance_gmm, 0)} g·mm` : "–"),
      h("td", { class: "corr-split" }, c.split && !nothing ? c.split.map((p) => `${fmt(p.mass_g)} g at place ${p.position} (${fmtAngle(p.angle_deg)})`).join(" + ") : "–"),
      ), planeWarnings(solution, c.plane)];
    })),
  );
}

/** A residual so small beside the reading as found that its phase means nothing. */
function negligible(r) {
  return r.amplitude <= 1e-9 * Math.max(r.amplitude_before || 0, 1e-300);
}

/** "(lag)" or "(lead)": the phase convention the answer's phases are in. */
export function phaseWords(solution) {
  return ((solution.conventions || state.setup.conventions).phase === "lead") ? "(lead)" : "(lag)";
}

export function residualTable(solution) {
  return h("table", { class: unsure(solution) ? "residual unsure" : "residual" },
    h("thead", {}, h("tr", {}, h("th", {}, "Speed, rpm"), h("th", {}, "Sensor"), h("th", {}, solution.from_run ? `In run “${solution.from_run}”` : "As found"), h("th", {}, "Predicted after"), h("th", {}, "95 % bound"), h("th", {}, `Phase, ° ${phaseWords(solution)}`), h("th", {}, "Unit"))),
    h("tbody", {}, solution.predicted_residual.map((r) => h("tr", { class: r.used === false ? "unused" : "" },
      h("td", {}, fmt(r.speed_rpm, 0)),
      h("td", {}, r.sensor),
      h("td", { class: "before" }, fmt(r.amplitude_before)),
      h("td", { class: "after" }, fmt(r.amplitude)),
      h("td", { class: "after95" }, r.amplitude_95 !== undefined && r.amplitude_95 !== null ? `≤ ${fmt(r.amplitude_95)}` : "–"),
      h("td", {}, negligible(r) ? "–" : fmtAngle(r.phase_deg)),
      h("td", {}, unitLabel(r.unit)),
    ))),
  );
}

/** Why a row's 95 % bound may be below its predicted figure (method.md 8.6–8.8). */
export function residualNote(solution) {
  const below = (solution.predicted_residual || []).filter((r) => r.amplitude_95 !== undefined && r.amplitude_95 !== null && r.amplitude_95 < r.amplitude);
  if (!below.length) return "";
  return h("p", { class: "note residual-note" },
    `${below.length === 1 ? "One row's" : `${below.length} rows'`} 95 % bound is below the predicted figure. That is not a mistake: the predicted figure also carries the scatter of that row's own readings, which will not be on the rotor once the weights are fitted, while the bound is for the vibration that will really remain, judged from all the rows together.`);
}

/** Whether any correction of the answer is not to be trusted as it stands (words.js). */
export function unsure(solution) {
  return (solution.corrections || []).some((c) => doubt(solution, c));
}

/**
 * Before → after. The "after" figures assume the corrections are right: when
 * one is greyed they are greyed too, said to be a guess, and point to what to do.
 */
export function summaryBox(solution) {
  const sm = solution.summary;
  const cut = sm.rms_before > 0 ? 100 * (1 - sm.rms_after / sm.rms_before) : 0;
  const doubtful = unsure(solution);
  // The unit the figures are in, or the units they mix (the RMS of mixed units has none).
  const unit = unitOrMix(solution.predicted_residual);
  const inUnit = unit ? `, ${unit}` : "";
  return h("div", { class: doubtful ? "summary unsure" : "summary" },
    doubtful ? h("p", { class: "unsure-note" }, "Not to be trusted: the vibration after and the reduction below assume the corrections above are right, and the greyed ones may be far off. Do what is said under them first (a bigger trial weight, or a check run and a trim).") : "",
    h("div", { class: "big" }, h("span", { class: "label" }, `RMS over sensors${inUnit}`), h("span", { class: "value" }, `${fmt(sm.rms_before)} → ${doubtful ? "about " : ""}${fmt(sm.rms_after)}`)),
    h("div", { class: "big" }, h("span", { class: "label" }, `Largest${inUnit}`), h("span", { class: "value" }, `${fmt(sm.max_before)} → ${doubtful ? "about " : ""}${fmt(sm.max_after)}`)),
    h("div", { class: "big" }, h("span", { class: "label" }, doubtful ? "Reduction, if the corrections were right" : "Reduction"), h("span", { class: "value" }, `${fmt(cut, 0)} %`)),
    h("div", { class: "small" }, `Condition number ${fmt(solution.condition_number)}`),
    solution.iso_21940 ? h("div", { class: "small" }, `ISO 21940-11 ${solution.iso_21940.balance_grade}: permissible ${fmt(solution.iso_21940.permissible_per_plane_gmm, 0)} g·mm per plane`) : "",
  );
}

export function warningsBox(solution) {
  if (!solution.warnings.length) {
    // A trim job, from stored or supplied coefficients, has no trial runs to speak of.
    return h("div", { class: "warnings none" }, solution.coefficients_from || state.setup.trim ? "No warnings." : "No warnings: the trial runs were clear and the planes independent.");
  }
  return h("div", { class: "warnings", role: "alert" },
    h("h3", {}, solution.warnings.length === 1 ? "1 warning — read before fitting weights" : `${solution.warnings.length} warnings — read before fitting weights`),
    h("ul", {}, solution.warnings.map((w) => {
      const { what, todo, said } = plainWarning(w);
      return h("li", { dataset: { code: w.code, plane: w.plane || "" } },
        what,
        todo ? h("div", { class: "advice" }, `What to do: ${todo}`) : "",
        // The service's own message, a click away: its figures and names.
        said ? h("details", { class: "said" }, h("summary", {}, "The service's own words"), h("p", { class: "said-text" }, said)) : "");
    })),
  );
}

// Solves asked (`data-solves`) and the last come back (`data-settled`); while
// one is out the step is busy and its button off (no second solution stored).
async function solve(root, rerender) {
  const mine = Number(root.dataset.solves || 0) + 1;
  root.dataset.solves = String(mine);
  root.setAttribute("aria-busy", "true");
  const button = root.querySelector("button.solve");
  if (button) button.disabled = true;
  const settled = () => {
    root.dataset.settled = String(mine);
    root.removeAttribute("aria-busy");
  };
  banner(root, "error", "");
  const id = state.id;
  try {
    const stored = await api.solve(id, solveOptions());
    // Not if another job was opened meanwhile: the answer is stored with its own.
    if (state.id === id) {
      state.solution = stored && stored.solution ? stored.solution : stored;
      state.solutionDate = (stored && stored.created_at) || null;
    }
  } catch (err) {
    settled();
    // Nor its refusal: drawn afresh for the job now open.
    if (state.id !== id) return rerender();
    if (button) {
      button.disabled = false;
      button.focus();
    }
    if (!markServerError(err)) banner(root, "error", err.message);
    return;
  }
  changed();
  settled();
  rerender();
  // Drawn afresh: keep the technician's place; Tab goes on into the answer.
  root.querySelector("button.solve")?.focus();
}

/** Render the solve step; `checkRun(weights, fromRun)` starts a check run with those weights on. */
export function renderSolve(root, checkRun) {
  const rerender = () => renderSolve(root, checkRun);
  const sol = state.solution;
  replace(root,
    h("h2", {}, "3 · Corrections"),
    optionsPanel(),
    h("div", { class: "actions solve-actions" },
      h("button", { type: "button", class: "primary solve", disabled: state.id === null || root.getAttribute("aria-busy") === "true", onclick: () => solve(root, rerender) }, sol ? "Solve again" : "Solve")),
    sol ? [
      state.solutionDate ? h("p", { class: "hint solved-at" }, `Solved ${storedAt(state.solutionDate)}`) : "",
      answerParts(sol, checkRun, rerender),
    ] : h("p", { class: "lead" }, state.id === null ? "Store the zero run and the trial runs first." : "Press Solve to compute the corrections."),
  );
}

// Before a trial run is stored: the suggested trial weight (POST
// /trial-weights on the zero run), and the question when a trial weight goes
// into a plane an earlier run already tried (a plane picked wrong?).

import { h, $ } from "../page/dom.js";
import { fmt, fmtAngle } from "../page/num.js";
import { api } from "../job/api.js";
import { state, sessionJson, triedPlanes } from "../job/state.js";

/** The last stored run with weights: the one whose weights may still be on the rotor. */
function previousTrial() {
  const trials = state.runs.filter((r) => r.stored && r.weights.length > 0);
  return trials.length ? trials[trials.length - 1] : null;
}

/** A trial weight in a plane an earlier run already tried: ask before storing (a plane typed wrong?). */
export function retrialQuestion(run, d) {
  if (d.zero || d.check || d.index !== null || d.confirmedRetrial) return null;
  const tried = triedPlanes();
  const carried = new Set(d.carry && previousTrial() ? previousTrial().weights.map((w) => w.plane) : []);
  const again = [...new Set(d.weights.map((w) => w.plane))].filter((p) => tried.has(p) && !carried.has(p));
  if (!again.length) return null;
  const untried = state.setup.planes.map((p) => p.id).filter((p) => !tried.has(p));
  const plane = again[0];
  return `Plane ${plane} already had a trial weight (run “${tried.get(plane)}”).` +
    (untried.length ? ` Plane${untried.length > 1 ? "s" : ""} ${untried.join(", ")} ${untried.length > 1 ? "have" : "has"} none yet. Is the plane right?` : " A second trial in it only repeats the first one. Is that what you want?");
}

export function ask(root, text, yes, no) {
  const box = h("div", { class: "question", role: "alertdialog" },
    h("p", {}, text),
    h("div", { class: "actions" },
      h("button", { type: "button", class: "primary yes", onclick: () => { box.remove(); yes(); } }, "Yes, store it"),
      h("button", { type: "button", class: "no", onclick: () => { box.remove(); no(); } }, "No, let me change it")));
  $(".question", root)?.remove();
  $(".draft", root).prepend(box);
  $(".question .no", root).focus();
}

/**
 * The trial-weight suggestion before the first trial (POST /trial-weights on
 * the zero run): a weight per plane that should move the vibration by about 30 %.
 */
export function suggestionBox(d, k, rerender) {
  if (d.zero || d.check || d.index !== null || triedPlanes().size > 0 || !state.id) return "";
  if (!d.suggest) {
    d.suggest = { loading: true };
    api.trialWeights(sessionJson()).then(
      (r) => { d.suggest = { items: r.suggestions || [] }; if (state.draft === d) rerender(); },
      (err) => { d.suggest = { none: err.code === "no_basis" ? "give the rotor's mass and service speed, and each plane's radius, in the set-up" : err.message }; if (state.draft === d) rerender(); },
    );
  }
  const s = d.suggest;
  if (s.loading) return h("div", { class: "suggestion" }, "Sizing a trial weight…");
  if (s.none) return h("div", { class: "suggestion none" }, `No trial weight can be suggested: ${s.none}. A trial weight should change the vibration by about 30 % (or its phase by 30°).`);
  return h("div", { class: "suggestion" },
    h("h4", {}, `Suggested trial weights (about 30 % change in vibration; angles ${state.setup.conventions.angle_direction === "with_rotation" ? "with" : "against"} rotation from the mark)`),
    h("ul", {}, s.items.map((x) => h("li", { dataset: { plane: x.plane } },
      `Plane ${x.plane}: ${fmt(x.mass_g)} g at ${fmtAngle(x.angle_deg)}`,
      x.weights ? ` — kit weights ${x.weights.map((m) => `${fmt(m)} g`).join(" + ")} stacked at place ${x.place}` : "",
      x.basis === "rotor" ? " (from the rotor's mass and speed: a centrifugal force of a tenth of its weight on the plane)" : x.expected_change_pct ? ` (expected change ${fmt(x.expected_change_pct, 0)} %)` : "",
      " ",
      h("button", { type: "button", class: "small use-suggestion", onclick: () => {
        // What the fitter bolts on: each kit weight of a stack is a weight of
        // its own, all at the place's angle (not one weight of their sum).
        const angle = Number(fmtAngle(x.angle_deg).replace("°", ""));
        const masses = x.weights && x.weights.length ? x.weights : [x.mass_g];
        d.weights = d.weights.filter((w) => w.plane !== x.plane && w.mass_g !== null && w.mass_g !== undefined);
        d.weights.push(...masses.map((m) => ({ plane: x.plane, mass_g: Number(fmt(m)), angle_deg: angle })));
        rerender();
      } }, "Use it")))));
}


// The service's warnings in the technician's words: what happened and what to
// do, never an option name, a field path or a code; and the rule for an answer
// not to be trusted as it stands, shown greyed with the reason.

import { fmt, angleDiff } from "../page/num.js";

const quoted = (message, fallback) => {
  const m = /'([^']+)'/.exec(message || "");
  return m ? `“${m[1]}”` : fallback;
};

/** Every run the message names ('T1', 'T2'), as “T1”, “T2”; "" when none. */
const quotedAll = (message) => [...String(message || "").matchAll(/'([^']+)'/g)].map((m) => `“${m[1]}”`).join(", ");

/** Per warning code: `[what happened, what to do]`. */
const PLAIN = {
  trial_effect_small: (w) => [`The trial weight${w.plane ? ` in plane ${w.plane}` : ""} moved the vibration too little to measure its effect.`, "Repeat that trial run with a bigger trial weight (aim for at least 30 % change in amplitude or 30° in phase)."],
  ill_conditioned: (w) => [`${w.plane ? `Plane ${w.plane} looks` : "Two planes look"} to the sensors almost the same as the other planes together, so the corrections may be large and cancel each other.`, "Use planes further apart, add a sensor at the other bearing, or solve with fewer planes (tick “leave out planes the sensors cannot tell apart” in the options)."],
  regions_unreliable: (w) => {
    const [alike, weak] = unreliableWhy(w);
    const what = [];
    if (alike) what.push("Some planes look almost the same to the sensors, so vibration that no plane can correct can hide in the answer.");
    if (weak) what.push("A trial weight was too small, and the planes are solved together, so the other planes share its error.");
    const todo = [];
    if (weak) todo.push("Repeat the small trial with a bigger weight.");
    if (alike) todo.push("Fit the weights, then do a check run and trim; better, add a sensor or speed that tells the planes apart, or solve with fewer planes.");
    return [`${what.join(" ")} The 95 % figures of every plane may be far off.`, todo.join(" ")];
  },
  mass_limit_active: (w) => /the same as without the bound/.test(w.message || "")
    ? [`A correction${w.plane ? ` in plane ${w.plane}` : ""} reached the mass limit you set, but a plane with the same effect on the sensors takes the rest.`, "The vibration left is the same as without the limit; nothing to do."]
    : [`A correction${w.plane ? ` in plane ${w.plane}` : ""} reached the mass limit you set.`, "The vibration left will be larger than without the limit; raise the limit if the plane can take more."],
  mixed_units: () => ["The sensors use different units, so the sum over them mixes units.", "Leave out the sensors of one unit, or accept that the larger numbers count more."],
  plane_undetermined: (w) => [`The readings cannot tell what plane ${w.plane || ""} needs: its trial weight changed nothing that the sensors see on their own.`, `Repeat the trial in plane ${w.plane || "that plane"} with a heavier weight or at a larger radius, add a sensor that sees it, or leave the plane out.`],
  uncertainty_approximate: () => ["With this objective or a mass limit that is reached, the 95 % figures are an estimate.", "Read them as the scatter to expect, not as exact bounds."],
  run_inconsistent: (w) => [`Run ${quoted(w.message, "")} does not agree with what the other runs predict for its weights, by more than the readings' scatter explains.`, "Check that run's weights (mass, angle, plane; a weight that fell off or was left on) and its readings; correct the run if one was typed wrong. A rotor that is not linear does this too."],
  coefficients_disagree: (w) => [`${quotedAll(w.message) ? `Run ${quotedAll(w.message)} does` : "The runs of this job do"} not agree with the coefficients this job is solved with (the machine's stored ones, or those supplied).`, "The rotor or its mounting may have changed since they were measured, or a weight was typed wrong: check the weights, or do trial runs for this job."],
  split_approximate: (w) => [`The correction${w.plane ? ` in plane ${w.plane}` : ""} cannot be split exactly over two neighbouring places.`, "Use the places shown and check with a run, or fit the weight at its free angle if the plane allows it."],
  fit_not_proven: () => ["The choice of kit weights is the best found in the time allowed, not proven the best.", "It is usually good enough; check with a run."],
};

/**
 * The title of the "without the noise's pull" line under a correction's 95 %
 * figures: `uncertainty.bias_corrected`, the errors-in-variables estimate C*
 * (method.md 8.11, session 13), beside the least-squares weight that is fitted.
 */
export const UNBIASED_WORDS = "Noisy readings pull the computed weight towards zero; this is the estimate with that pull removed. Fit the weight in the Mass and Angle columns, which leaves less vibration; a large difference between the two means the trial weight was small against the noise.";

/**
 * Why the service said `regions_unreliable`, from its message: `[alike, weak]`,
 * planes that look alike to the sensors, and one plane's trial too small
 * beside the others (uncertainty/hidden.rs). A message naming neither counts
 * as the first, the older and more general reason.
 */
function unreliableWhy(w) {
  const m = String(w.message || "");
  const weak = m.includes("trial_effect_small");
  const alike = !weak || m.includes("ill_conditioned") || m.includes("own share") || m.includes("only this much of each plane's effect");
  return [alike, weak];
}

/** `{what, todo, said}` for a warning: `said`, the service's own message (its figures), null when `what` is made of it. */
export function plainWarning(w) {
  const f = PLAIN[w.code];
  if (f) {
    const [what, todo] = f(w);
    return { what, todo, said: w.message ? String(w.message) : null };
  }
  // An unknown code: the service's own sentence, without option names or code words.
  const text = String(w.message || "").replace(/`[^`]*`/g, "").replace(/\(?\b[a-z]+(?:[._][a-z0-9_]+)+\b\)?/g, "").replace(/\s+/g, " ").trim();
  return { what: text ? text[0].toUpperCase() + text.slice(1) : "The service warned about this answer.", todo: "", said: null };
}

/**
 * Why a correction should not be trusted as it stands, in words, with what to
 * do; null when it can be. Wide means a 95 % mass interval wider than ±25 % of
 * the mass or an angle interval wider than ±20°.
 */
export function doubt(solution, c) {
  // Nothing to add (a trim that leaves a plane as it is): nothing to doubt either.
  if (solution.from_run && c.mass_g < 0.05) return null;
  const small = solution.warnings.some((w) => (w.code === "trial_effect_small" || w.code === "plane_undetermined") && (!w.plane || w.plane === c.plane));
  if (small) return `The trial weight in plane ${c.plane} was too small to measure its effect, so this correction may be far off. Repeat the trial run in plane ${c.plane} with a bigger weight before fitting it.`;
  const unreliable = solution.warnings.find((w) => w.code === "regions_unreliable");
  if (unreliable) {
    const [alike, weak] = unreliableWhy(unreliable);
    if (weak && !alike) {
      return `The 95 % figures for plane ${c.plane} may be far off: another plane's trial weight was too small, and the planes are solved together. Repeat that trial with a bigger weight before fitting.`;
    }
    return `The 95 % figures for plane ${c.plane} may be far off: planes that look almost the same to the sensors can hide vibration that no plane corrects. Fit the weight, then do a check run and trim.`;
  }
  const u = c.uncertainty;
  if (!u) return null;
  if (!u.mass_g || u.angle_deg[1] - u.angle_deg[0] >= 359.999) {
    return `The scatter of the readings could account for the whole correction in plane ${c.plane}: its angle is not known. Repeat the trial run with a bigger weight, or take the readings again, before fitting it.`;
  }
  const dm = Math.max(Math.abs(u.mass_g[1] - c.mass_g), Math.abs(c.mass_g - u.mass_g[0]));
  const da = Math.max(angleDiff(u.angle_deg[1], c.angle_deg), angleDiff(c.angle_deg, u.angle_deg[0]));
  if (dm > 0.25 * c.mass_g || da > 20) {
    return `The 95 % figures for plane ${c.plane} are wide (± ${fmt(dm)} g, ± ${fmt(da, 0)}°): the weight may be well off. Fit it, then do a check run and trim; or repeat the trial run with a bigger weight first.`;
  }
  return null;
}

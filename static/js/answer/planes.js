// Where to bolt the weights on: each plane drawn as the fitter sees it, with
// the reference mark at the top, the rotation arrow, the fixed places
// (numbered) and the weights to fit — the kit fit, else the split over two
// places, else the correction at its free angle. The rotor turns clockwise in
// the picture, as in the conventions picture.

import { h, s } from "../page/dom.js";
import { fmt, fmtAngle } from "../page/num.js";

const SIZE = 240;
const C = SIZE / 2;
const R = 78;
// Room at the sides for the labels of weights at 90° and 270°.
const PAD = 34;

/** Screen point of a weight angle in the session's direction. */
function at(angle, direction, r) {
  const a = ((direction === "with_rotation" ? angle : -angle) * Math.PI) / 180;
  return [C + r * Math.sin(a), C - r * Math.cos(a)];
}

/** Angles of a plane's fixed places, if it has any. */
export function placesOf(plane) {
  if (Array.isArray(plane.places_deg) && plane.places_deg.length) return plane.places_deg;
  if (plane.positions) return Array.from({ length: plane.positions }, (_, k) => (360 * k) / plane.positions);
  return [];
}

/** The weights to fit in a plane: `[{angle, mass, place?}]` and what they are. */
export function weightsToFit(solution, correction) {
  const fit = solution.fit && solution.fit.find((f) => f.plane === correction.plane);
  if (fit) return { kind: "kit weights", weights: fit.weights.map((w) => ({ angle: w.angle_deg, mass: w.mass_g, place: w.place })) };
  if (correction.split && correction.split.length) return { kind: "split over two places", weights: correction.split.map((p) => ({ angle: p.angle_deg, mass: p.mass_g, place: p.position })) };
  return { kind: "at a free angle", weights: [{ angle: correction.angle_deg, mass: correction.mass_g }] };
}

/** Weights at one angle (stacked at a place) drawn and said once: `[{angle, place?, masses}]`. */
export function stacks(weights) {
  const out = [];
  for (const w of weights) {
    const same = out.find((x) => Math.abs(((x.angle - w.angle + 540) % 360) - 180) < 0.05 && x.place === w.place);
    if (same) same.masses.push(w.mass);
    else out.push({ angle: w.angle, place: w.place, masses: [w.mass] });
  }
  return out;
}

/** A stack in words: "10.0 g + 5.0 g at 240.0° (place 8)". */
export function stackWords(x) {
  return `${x.masses.map((m) => `${fmt(m)} g`).join(" + ")} at ${fmtAngle(x.angle)}${x.place !== undefined ? ` (place ${x.place})` : ""}`;
}

/** Screen angle (clockwise from the top) of a weight angle in the session's direction. */
const screen = (angle, direction) => (((direction === "with_rotation" ? angle : -angle) % 360) + 360) % 360;

/** Start of 60° of the rim far from every weight (screen angles): where the rotation arrow goes. */
function freeArc(angles) {
  const gapAt = (a) => Math.min(360, ...angles.map((x) => Math.abs(((((x - (a + 30)) % 360) + 540) % 360) - 180)));
  if (gapAt(50) >= 50) return 50;
  let best = 50;
  // Not over the top, where the mark and its label are.
  for (let a = 30; a <= 270; a += 10) if (gapAt(a) > gapAt(best)) best = a;
  return best;
}

/** The picture of one plane with its weights to fit. */
export function planePicture(plane, solution, correction, direction) {
  const places = placesOf(plane);
  const found = weightsToFit(solution, correction);
  const weights = stacks(found.weights.filter((w) => w.mass >= 0.05));
  const kind = weights.length ? found.kind : "nothing to add";
  const svg = s("svg", { viewBox: `${-PAD} 0 ${SIZE + 2 * PAD} ${SIZE}`, class: "plane-pic", role: "img", "aria-label": `Plane ${plane.id} seen from the drive end` });
  svg.append(s("circle", { cx: C, cy: C, r: R, class: "disc" }), s("circle", { cx: C, cy: C, r: 6, class: "shaft" }));
  svg.append(s("path", { d: `M${C},${C - R - 14} l-6,-10 h12 z`, class: "mark" }));
  svg.append(s("text", { x: C + 10, y: C - R - 16, class: "label" }, "mark (0°)"));
  // Rotation: clockwise, an arc outside the disc where no weight is labelled.
  const a0 = freeArc(weights.map((w) => screen(w.angle, direction)));
  const [ax1, ay1] = at(a0, "with_rotation", R + 16);
  const [ax2, ay2] = at(a0 + 60, "with_rotation", R + 16);
  const t = ((a0 + 60 + 90) * Math.PI) / 180; // along the arc at its end
  const [dx, dy] = [Math.sin(t), -Math.cos(t)];
  svg.append(s("path", { d: `M${ax1.toFixed(1)},${ay1.toFixed(1)} A${R + 16},${R + 16} 0 0 1 ${ax2.toFixed(1)},${ay2.toFixed(1)}`, class: "rotation" }));
  svg.append(s("polygon", { points: [[ax2 + dx * 8, ay2 + dy * 8], [ax2 - dy * 5, ay2 + dx * 5], [ax2 + dy * 5, ay2 - dx * 5]].map((p) => p.map((v) => v.toFixed(1)).join(",")).join(" "), class: "rotation-head" }));
  // Its word at the picture's edge on the arc's side, below the arc's lower end.
  const right = a0 + 30 < 180;
  svg.append(s("text", { x: right ? SIZE + PAD - 2 : 2 - PAD, y: Math.min(Math.max(ay1, ay2) + 16, SIZE - 4), class: "label", "text-anchor": right ? "end" : "start" }, "rotation"));
  places.forEach((angle, k) => {
    const [px, py] = at(angle, direction, R - 10);
    const [lx, ly] = at(angle, direction, R - 24);
    svg.append(s("circle", { cx: px, cy: py, r: 4, class: "place" }));
    if (places.length <= 24 || k % Math.ceil(places.length / 24) === 0) svg.append(s("text", { x: lx, y: ly + 3, class: "place-label", "text-anchor": "middle" }, String(k)));
  });
  for (const w of weights) {
    const [wx, wy] = at(w.angle, direction, R - 10);
    // Near the top the mark's label is outside the rim: label the weight inside it.
    const nearMark = Math.abs(((screen(w.angle, direction) + 180) % 360) - 180) < 30;
    const [lx, ly] = at(w.angle, direction, nearMark ? R - 34 : R + 30);
    const total = w.masses.reduce((a, b) => a + b, 0);
    svg.append(s("circle", { cx: wx, cy: wy, r: 9, class: "weight" }));
    svg.append(s("text", { x: lx, y: ly + 4, class: "label weight-label", "text-anchor": "middle" }, `${fmt(total)} g`));
  }
  return h("figure", { class: "plane-fig", dataset: { plane: plane.id } },
    h("figcaption", {}, `Plane ${plane.id}: ${kind}`),
    svg,
    weights.length ? h("ul", { class: "fit-words" }, weights.map((w) => h("li", {}, stackWords(w)))) : h("p", { class: "fit-words" }, "Nothing to fit in this plane."),
    h("p", { class: "hint" }, `Seen from the drive end, rotor turning clockwise; angles counted ${direction === "with_rotation" ? "with" : "against"} rotation from the mark.`));
}

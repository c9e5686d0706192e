// Polar plot of one sensor at one speed, drawn as SVG by the page: the
// reference vector, each trial run's effect (from the reference tip to the
// trial reading) and the predicted residual. Vectors are placed in one physical
// frame (method 1.1: lag φ is drawn at -φ, lead φ at +φ) and the angle labels
// are written in the session's own phase convention.

import { s, h } from "../page/dom.js";
import { fmt, unitLabel, wrap360 } from "../page/num.js";

const SIZE = 300;
const C = SIZE / 2;
const R = 110;
const COLOURS = ["#c2410c", "#7c3aed", "#0e7490", "#a16207", "#be185d", "#4d7c0f"];

/** Reading → complex number in the drawing frame (counter-clockwise angles). */
function phasor(amplitude, phaseDeg, phase) {
  const a = ((phase === "lead" ? phaseDeg : -phaseDeg) * Math.PI) / 180;
  return [amplitude * Math.cos(a), amplitude * Math.sin(a)];
}

/** Drawing frame → SVG coordinates, with 0° at the top. */
function toScreen([x, y], scale) {
  return [C - y * scale, C - x * scale];
}

function arrow(from, to, scale, cls, colour, dashed) {
  const [x1, y1] = toScreen(from, scale);
  const [x2, y2] = toScreen(to, scale);
  const len = Math.hypot(x2 - x1, y2 - y1);
  const parts = [s("line", { x1, y1, x2, y2, class: cls, stroke: colour, "stroke-dasharray": dashed ? "5 3" : null })];
  if (len > 6) {
    const ux = (x2 - x1) / len;
    const uy = (y2 - y1) / len;
    const pts = [[x2, y2], [x2 - 9 * ux + 4 * uy, y2 - 9 * uy - 4 * ux], [x2 - 9 * ux - 4 * uy, y2 - 9 * uy + 4 * ux]];
    parts.push(s("polygon", { points: pts.map((p) => p.map((v) => v.toFixed(1)).join(",")).join(" "), fill: colour }));
  }
  return parts;
}

function ringLabel(x) {
  return Number.isInteger(x) ? String(x) : String(Number(x.toPrecision(3)));
}

function niceStep(max) {
  const raw = max / 4;
  const p = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 2.5, 5, 10].map((m) => m * p).find((v) => v >= raw);
}

/**
 * One plot. `reference` and `trials` are readings (`{amplitude, phase_deg}`,
 * trials with `id`), `residual` the predicted one or null.
 */
export function polarPlot({ sensor, unit, speed, phase, reference, trials, residual }) {
  const ref = phasor(reference.amplitude, reference.phase_deg, phase);
  const tips = trials.map((t) => phasor(t.amplitude, t.phase_deg, phase));
  const res = residual ? phasor(residual.amplitude, residual.phase_deg, phase) : null;
  const maxAmp = Math.max(...[ref, ...tips, ...(res ? [res] : [])].map(([x, y]) => Math.hypot(x, y)), 1e-9);
  const step = niceStep(maxAmp);
  const rings = Math.ceil(maxAmp / step);
  const scale = R / (rings * step);
  const svg = s("svg", { viewBox: `0 0 ${SIZE} ${SIZE}`, class: "polar", role: "img", "aria-label": `Polar plot, ${sensor} at ${speed} rpm` });
  for (let i = 1; i <= rings; i++) {
    svg.append(s("circle", { cx: C, cy: C, r: i * step * scale, class: "ring" }));
    svg.append(s("text", { x: C + 3, y: C - i * step * scale - 2, class: "ring-label" }, ringLabel(i * step)));
  }
  for (let deg = 0; deg < 360; deg += 30) {
    // `deg` is counter-clockwise in the drawing frame; label it in the session's convention.
    const [x, y] = toScreen([Math.cos((deg * Math.PI) / 180), Math.sin((deg * Math.PI) / 180)], R + 14);
    const [xi, yi] = toScreen([Math.cos((deg * Math.PI) / 180), Math.sin((deg * Math.PI) / 180)], R);
    svg.append(s("line", { x1: C, y1: C, x2: xi, y2: yi, class: "spoke" }));
    const label = phase === "lead" ? deg : wrap360(-deg);
    svg.append(s("text", { x, y: y + 4, class: "angle-label", "text-anchor": "middle" }, `${label}°`));
  }
  svg.append(...arrow([0, 0], ref, scale, "vec ref", "#1d4ed8", false));
  tips.forEach((tip, i) => svg.append(...arrow(ref, tip, scale, "vec trial", COLOURS[i % COLOURS.length], true)));
  if (res) svg.append(...arrow([0, 0], res, scale, "vec residual", "#15803d", false));
  const legend = h(
    "ul",
    { class: "legend" },
    h("li", {}, h("span", { class: "swatch", dataset: { colour: "ref" } }), `as found: ${fmt(reference.amplitude)} at ${fmt(reference.phase_deg, 0)}°`),
    trials.map((t, i) => h("li", {}, h("span", { class: "swatch dashed", dataset: { colour: String(i % COLOURS.length) } }), `effect of “${t.id}”`)),
    res ? h("li", {}, h("span", { class: "swatch", dataset: { colour: "residual" } }), `predicted after correction: ${fmt(residual.amplitude)} at ${fmt(residual.phase_deg, 0)}°`) : "",
  );
  return h(
    "figure",
    { class: "polar-fig" },
    h("figcaption", {}, `${sensor} at ${fmt(speed, 0)} rpm`, h("small", {}, `, ${unitLabel(unit)}, phase ${phase}`)),
    svg,
    legend,
  );
}

// Multi-speed pictures, drawn as inline SVG by the page: a Bode plot per sensor
// (amplitude and phase against speed: as found, predicted after correction,
// each check run) and a polar (Nyquist) plot of the as-found vibration across
// the speeds. Phases are shown in the session's own convention.

import { h, s } from "../page/dom.js";
import { fmt, unitLabel, wrap360 } from "../page/num.js";

const W = 520;
const PAD_L = 52;
const PAD_R = 12;
const AMP_H = 150;
const PH_H = 90;
const GAP = 34;
const SERIES = [
  { key: "found", colour: "#1d4ed8", text: "as found" },
  { key: "after", colour: "#15803d", text: "predicted after correction", dash: "6 3" },
];
const CHECK_COLOURS = ["#c2410c", "#7c3aed", "#be185d", "#a16207"];

function niceMax(x) {
  if (!(x > 0)) return 1;
  const p = 10 ** Math.floor(Math.log10(x));
  return [1, 2, 2.5, 5, 10].map((m) => m * p).find((v) => v >= x);
}

function path(points) {
  return points.map(([x, y], i) => `${i ? "L" : "M"}${x.toFixed(1)},${y.toFixed(1)}`).join(" ");
}

/** A short line in the series' colour (no inline styles: the page's CSP forbids them). */
function swatch(line) {
  return s("svg", { width: 26, height: 8, class: "swatch-svg", "aria-hidden": "true" },
    s("line", { x1: 1, y1: 4, x2: 25, y2: 4, stroke: line.colour, "stroke-width": 3, "stroke-dasharray": line.dash || null }));
}

/**
 * One Bode plot. `series` is `[{ text, colour, dash?, points: [{speed, amplitude, phase}] }]`.
 */
export function bodePlot({ sensor, unit, phase, series }) {
  const all = series.flatMap((x) => x.points);
  const speeds = all.map((p) => p.speed);
  const lo = Math.min(...speeds);
  const hi = Math.max(...speeds);
  const span = hi > lo ? hi - lo : 1;
  const top = niceMax(Math.max(...all.map((p) => p.amplitude)));
  const x = (v) => PAD_L + ((v - lo) / span) * (W - PAD_L - PAD_R);
  const ya = (v) => 10 + AMP_H - (v / top) * AMP_H;
  const y0 = 10 + AMP_H + GAP;
  const yp = (v) => y0 + (wrap360(v) / 360) * PH_H;
  const H = y0 + PH_H + 28;
  const svg = s("svg", { viewBox: `0 0 ${W} ${H}`, class: "bode", role: "img", "aria-label": `Bode plot, ${sensor}` });
  for (let i = 0; i <= 4; i++) {
    const v = (top * i) / 4;
    svg.append(s("line", { x1: PAD_L, x2: W - PAD_R, y1: ya(v), y2: ya(v), class: "grid" }));
    svg.append(s("text", { x: PAD_L - 4, y: ya(v) + 3, class: "tick", "text-anchor": "end" }, fmt(v)));
  }
  for (const v of [0, 90, 180, 270, 360]) {
    svg.append(s("line", { x1: PAD_L, x2: W - PAD_R, y1: yp(v === 360 ? 359.999 : v), y2: yp(v === 360 ? 359.999 : v), class: "grid" }));
    svg.append(s("text", { x: PAD_L - 4, y: yp(v === 360 ? 359.999 : v) + 3, class: "tick", "text-anchor": "end" }, `${v}°`));
  }
  for (const v of [...new Set(speeds)].sort((a, b) => a - b)) {
    svg.append(s("line", { x1: x(v), x2: x(v), y1: 10, y2: y0 + PH_H, class: "grid v" }));
  }
  svg.append(s("text", { x: PAD_L, y: H - 4, class: "tick" }, `${fmt(lo, 0)} rpm`));
  svg.append(s("text", { x: W - PAD_R, y: H - 4, class: "tick", "text-anchor": "end" }, `${fmt(hi, 0)} rpm`));
  svg.append(s("text", { x: PAD_L + 4, y: 20, class: "axis-title" }, `amplitude, ${unitLabel(unit)}`));
  svg.append(s("text", { x: PAD_L + 4, y: y0 - 6, class: "axis-title" }, "phase"));
  for (const line of series) {
    const pts = [...line.points].sort((a, b) => a.speed - b.speed);
    if (!pts.length) continue;
    svg.append(s("path", { d: path(pts.map((p) => [x(p.speed), ya(p.amplitude)])), class: `series ${line.cls || ""}`, stroke: line.colour, "stroke-dasharray": line.dash || null }));
    for (const p of pts) {
      svg.append(s("circle", { cx: x(p.speed), cy: ya(p.amplitude), r: 3, fill: line.colour }));
      if (Number.isFinite(p.phase)) svg.append(s("circle", { cx: x(p.speed), cy: yp(p.phase), r: 3, fill: line.colour }));
    }
  }
  return h("figure", { class: "bode-fig", dataset: { sensor } },
    h("figcaption", {}, `${sensor}: amplitude and phase against speed`, h("small", {}, `, ${unitLabel(unit)}, phase ${phase}`)),
    svg,
    h("ul", { class: "legend" }, series.map((line) => h("li", {}, swatch(line), line.text))));
}

/** A polar (Nyquist) plot of one sensor's as-found vibration across the speeds. */
export function nyquistPlot({ sensor, unit, phase, points }) {
  const size = 300;
  const c = size / 2;
  const r = 118;
  const max = niceMax(Math.max(...points.map((p) => p.amplitude), 1e-9));
  const scale = r / max;
  // Same frame as the per-speed polar plots: 0° at the top, lag clockwise.
  const at = (p) => {
    const a = ((phase === "lead" ? p.phase : -p.phase) * Math.PI) / 180;
    return [c - p.amplitude * Math.sin(a) * scale, c - p.amplitude * Math.cos(a) * scale];
  };
  const svg = s("svg", { viewBox: `0 0 ${size} ${size}`, class: "nyquist", role: "img", "aria-label": `Polar plot across speeds, ${sensor}` });
  for (let i = 1; i <= 4; i++) svg.append(s("circle", { cx: c, cy: c, r: (r * i) / 4, class: "ring" }));
  svg.append(s("text", { x: c + 3, y: c - r - 2, class: "tick" }, fmt(max)));
  svg.append(s("text", { x: c, y: 12, class: "tick", "text-anchor": "middle" }, "0°"));
  const sorted = [...points].sort((a, b) => a.speed - b.speed);
  svg.append(s("path", { d: path(sorted.map(at)), class: "series", stroke: "#1d4ed8" }));
  sorted.forEach((p, i) => {
    const [px, py] = at(p);
    svg.append(s("circle", { cx: px, cy: py, r: 3, fill: "#1d4ed8" }));
    if (i === 0 || i === sorted.length - 1 || sorted.length <= 6) svg.append(s("text", { x: px + 5, y: py - 4, class: "tick" }, fmt(p.speed, 0)));
  });
  return h("figure", { class: "nyquist-fig", dataset: { sensor } },
    h("figcaption", {}, `${sensor}: as found across speeds (rpm marked)`, h("small", {}, `, ${unitLabel(unit)}, phase ${phase}`)),
    svg);
}

export { SERIES, CHECK_COLOURS };

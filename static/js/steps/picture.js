// The small picture that explains the two conventions, redrawn when they change:
// where a weight "at 90°" sits, and what "phase lag/lead" means on the signal.

import { h, s } from "../page/dom.js";

const R = 58;
const CX = 100;
const CY = 100;

/** Point at `deg` measured clockwise from the top (screen coordinates). */
function at(deg, r = R) {
  const a = (deg * Math.PI) / 180;
  return [CX + r * Math.sin(a), CY - r * Math.cos(a)];
}

function arc(from, to, r, clockwise) {
  const [x1, y1] = at(from, r);
  const [x2, y2] = at(to, r);
  const large = Math.abs(to - from) > 180 ? 1 : 0;
  return `M${x1.toFixed(1)},${y1.toFixed(1)} A${r},${r} 0 ${large} ${clockwise ? 1 : 0} ${x2.toFixed(1)},${y2.toFixed(1)}`;
}

function arrowHead(deg, r, clockwise) {
  // A small triangle at the end of an arc, pointing along it.
  const [x, y] = at(deg, r);
  const t = ((deg + (clockwise ? 90 : -90)) * Math.PI) / 180;
  const dx = Math.sin(t);
  const dy = -Math.cos(t);
  const nx = -dy;
  const ny = dx;
  const pts = [
    [x + dx * 7, y + dy * 7],
    [x + nx * 4, y + ny * 4],
    [x - nx * 4, y - ny * 4],
  ];
  return pts.map((p) => p.map((v) => v.toFixed(1)).join(",")).join(" ");
}

/** The rotor as seen by the technician, rotation clockwise, a weight at 90°. */
function rotor(direction) {
  const withRotation = direction === "with_rotation";
  const weightAt = withRotation ? 90 : 270;
  const [wx, wy] = at(weightAt, R - 12);
  const [lx, ly] = at(weightAt, R + 20);
  const [mx, my] = at(0, R + 4);
  return s(
    "svg",
    { viewBox: "0 0 200 225", class: "picture-rotor", role: "img", "aria-label": "Where a weight at 90 degrees sits" },
    s("circle", { cx: CX, cy: CY, r: R, class: "disc" }),
    s("circle", { cx: CX, cy: CY, r: 5, class: "shaft" }),
    s("path", { d: `M${CX},${CY - R - 10} L${mx - 5},${my - 12} L${mx + 5},${my - 12} Z`, class: "mark" }),
    s("text", { x: CX, y: 12, class: "label", "text-anchor": "middle" }, "0° = reference mark"),
    s("path", { d: arc(130, 230, R + 12, true), class: "rotation" }),
    s("polygon", { points: arrowHead(230, R + 12, true), class: "rotation-head" }),
    s("text", { x: CX, y: CY + R + 30, class: "label rot", "text-anchor": "middle" }, "rotation"),
    s("path", { d: arc(0, withRotation ? 90 : 270, R - 24, withRotation), class: "count" }),
    s("polygon", { points: arrowHead(withRotation ? 90 : 270, R - 24, withRotation), class: "count-head" }),
    s("circle", { cx: wx, cy: wy, r: 8, class: "weight" }),
    s("text", { x: lx, y: ly + 4, class: "label", "text-anchor": "middle" }, "90°"),
    s("text", { x: CX, y: 220, class: "label", "text-anchor": "middle" }, withRotation ? "counted with rotation" : "counted against rotation"),
  );
}

/** The once-per-revolution pulse and the 1X signal, with the phase the analyser reports. */
function signal(phase) {
  const W = 220;
  const phi = 90; // the peak comes a quarter turn after the mark
  const x0 = 20;
  const scale = (W - 40) / 360;
  let d = "";
  for (let t = -20; t <= 360; t += 5) {
    const y = 60 - 26 * Math.cos(((t - phi) * Math.PI) / 180);
    d += `${d ? "L" : "M"}${(x0 + t * scale + 20 * scale).toFixed(1)},${y.toFixed(1)}`;
  }
  const xm = x0 + 20 * scale;
  const xp = xm + phi * scale;
  return s(
    "svg",
    { viewBox: `0 0 ${W} 120`, class: "picture-signal", role: "img", "aria-label": "Phase of the 1X signal" },
    s("line", { x1: 10, y1: 60, x2: W - 5, y2: 60, class: "axis" }),
    s("path", { d, class: "wave" }),
    s("line", { x1: xm, y1: 20, x2: xm, y2: 100, class: "pulse" }),
    s("text", { x: xm, y: 14, class: "label", "text-anchor": "middle" }, "mark"),
    s("line", { x1: xp, y1: 30, x2: xp, y2: 100, class: "peak" }),
    s("text", { x: xp, y: 24, class: "label", "text-anchor": "middle" }, "peak"),
    s("line", { x1: xm, y1: 92, x2: xp, y2: 92, class: "span" }),
    s("text", { x: (xm + xp) / 2, y: 112, class: "label", "text-anchor": "middle" }, phase === "lag" ? "shown as 90°" : "shown as 270°"),
  );
}

/** The whole explanation, for the current conventions. */
export function conventionsPicture(conventions) {
  const lag = conventions.phase === "lag";
  const withRotation = conventions.angle_direction === "with_rotation";
  return h(
    "div",
    { class: "picture" },
    h(
      "figure",
      {},
      rotor(conventions.angle_direction),
      h(
        "figcaption",
        {},
        withRotation
          ? "Weight angles are counted from the mark in the direction the rotor turns."
          : "Weight angles are counted from the mark against the direction the rotor turns.",
      ),
    ),
    h(
      "figure",
      {},
      signal(conventions.phase),
      h(
        "figcaption",
        {},
        lag
          ? "Phase lag: the analyser shows how far the vibration peak comes after the mark (most analysers)."
          : "Phase lead: the analyser shows how far the peak comes before the next mark — a peak 90° after the mark shows as 270°.",
      ),
    ),
    h(
      "p",
      { class: "hint" },
      "Check both in the analyser's manual before the zero run. A wrong choice does not show as an error: it puts the correction weight at the mirror-image angle.",
    ),
  );
}

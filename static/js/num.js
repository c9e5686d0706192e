// Numbers as a technician types them: checked on every keystroke, with the
// message shown next to the cell before anything is sent to the server.

const NUMBER = /^[+-]?(\d+([.,]\d*)?|[.,]\d+)([eE][+-]?\d+)?$/;

/**
 * Parse typed text. A decimal comma is accepted (many analysers and keyboards
 * use it). Returns `{ value }` or `{ error }`; empty text gives `{ empty: true }`.
 */
export function parseNumber(text) {
  const t = String(text ?? "").trim();
  if (t === "") return { empty: true };
  if (!NUMBER.test(t)) return { error: "not a number" };
  const value = Number(t.replace(",", "."));
  if (!Number.isFinite(value)) return { error: "number too large" };
  return { value };
}

/** Rules for each kind of numeric field: the check and its message. */
export const RULES = {
  amplitude: { test: (x) => x >= 0 && x < 1e6, message: "amplitude must be 0 or more" },
  phase: { test: (x) => x > -360 && x < 720, message: "phase in degrees, 0 to 360" },
  angle: { test: (x) => x > -360 && x < 720, message: "angle in degrees, 0 to 360" },
  mass: { test: (x) => x > 0 && x < 1e6, message: "mass in grams, more than 0" },
  radius: { test: (x) => x > 0 && x < 1e5, message: "radius in mm, more than 0" },
  positions: {
    test: (x) => Number.isInteger(x) && x >= 2 && x <= 360,
    message: "a whole number of places, 2 or more",
  },
  speed: { test: (x) => x > 0 && x < 1e6, message: "speed in rpm, more than 0" },
};

/** Check typed text against a rule; `{ value }`, `{ empty }` or `{ error }`. */
export function check(text, kind, required = true) {
  const parsed = parseNumber(text);
  if (parsed.empty) return required ? { error: "required", empty: true } : { empty: true };
  if (parsed.error) return parsed;
  const rule = RULES[kind];
  if (rule && !rule.test(parsed.value)) return { error: rule.message };
  return parsed;
}

/** Speeds typed as one list: "1480" or "1480 2950" or "1480; 2950". */
export function parseSpeeds(text) {
  const parts = String(text ?? "").split(/[\s;]+/).filter((p) => p !== "");
  if (parts.length === 0) return { error: "at least one speed, rpm" };
  const speeds = [];
  for (const part of parts) {
    const r = check(part, "speed");
    if (r.error) return { error: `${part}: ${r.error}` };
    if (speeds.some((x) => Math.abs(x - r.value) <= 0.01 * Math.max(x, r.value))) {
      return { error: `${part}: within 1 % of another speed (the same point)` };
    }
    speeds.push(r.value);
  }
  return { value: speeds };
}

/** Angle in [0, 360). */
export function wrap360(deg) {
  const a = deg % 360;
  return a < 0 ? a + 360 : a;
}

/** Smallest absolute difference of two angles, degrees. */
export function angleDiff(a, b) {
  const d = wrap360(a - b);
  return d > 180 ? 360 - d : d;
}

/** A number for people: `digits` decimals, or fewer significant ones for big values. */
export function fmt(x, digits = 1) {
  if (x === null || x === undefined || !Number.isFinite(x)) return "–";
  const abs = Math.abs(x);
  const d = abs >= 1000 ? 0 : abs >= 100 ? Math.min(digits, 1) : abs > 0 && abs < 1 ? digits + 1 : digits;
  return x.toFixed(d);
}

/** An angle for people, 0 to 360 with one decimal. */
export function fmtAngle(deg) {
  if (!Number.isFinite(deg)) return "–";
  let a = wrap360(deg);
  if (a.toFixed(1) === "360.0") a = 0;
  return `${a.toFixed(1)}°`;
}

/** Sensor unit codes in technician words. */
export const UNITS = {
  um_pp: "µm pk-pk",
  mils_pp: "mils pk-pk",
  mm_s_rms: "mm/s RMS",
  mm_s_pk: "mm/s peak",
  in_s_pk: "in/s peak",
  g_pk: "g peak",
};

export function unitLabel(unit) {
  return UNITS[unit] || unit || "";
}

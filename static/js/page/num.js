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
  // "1,234" reads as a thousand and more to some and as 1.234 to others: ask.
  if (/^[+-]?[1-9]\d{0,2},\d{3}$/.test(t)) {
    return { error: `${t} could mean ${t.replace(",", "")} or ${t.replace(",", ".")}: type it without the comma, or with a point` };
  }
  const value = Number(t.replace(",", "."));
  if (!Number.isFinite(value)) return { error: "number too large" };
  return { value };
}

/** A heading copied over pasted columns: a line starting with a letter or quote. */
export function isHeading(line) {
  return /^["'A-Za-z\u00C0-\u024F]/.test(String(line).trim());
}

/** Rules for each kind of numeric field: the check and its message. */
export const RULES = {
  amplitude: { test: (x) => x >= 0 && x < 1e6, message: (x) => (x < 0 ? "amplitude must be 0 or more" : "amplitude must be less than 1000000 (check the unit)") },
  phase: { test: (x) => x >= 0 && x <= 360, message: (x) => `phase in degrees, 0 to 360: ${turnWords(x)}` },
  angle: { test: (x) => x >= 0 && x <= 360, message: (x) => `angle in degrees, 0 to 360: ${turnWords(x)}` },
  mass: { test: (x) => x > 0 && x < 1e6, message: (x) => (x <= 0 ? "mass in grams, more than 0" : "mass in grams, less than 1000000") },
  radius: { test: (x) => x > 0 && x < 1e5, message: (x) => (x <= 0 ? "radius in mm, more than 0" : "radius in mm, less than 100000") },
  // The rotor's mass is in kilograms (the service takes up to 10^7 kg).
  // API's W, the static load on the journal nearest the plane.
  load: { test: (x) => x > 0 && x < 1e7, message: (x) => (x <= 0 ? "journal load in kg, more than 0" : "journal load in kg, less than 10000000") },
  rotor_mass: { test: (x) => x > 0 && x < 1e7, message: (x) => (x <= 0 ? "rotor mass in kg, more than 0" : "rotor mass in kg, less than 10000000") },
  positions: {
    test: (x) => Number.isInteger(x) && x >= 2 && x <= 360,
    message: "a whole number of places, 2 to 360",
  },
  speed: { test: (x) => x > 0 && x < 1e6, message: (x) => (x <= 0 ? "speed in rpm, more than 0" : "speed in rpm, less than 1000000") },
  noise: { test: (x) => x > 0 && x < 100, message: "more than 0 and less than 100" },
  limit: { test: (x) => x > 0 && x < 1e6, message: (x) => (x <= 0 ? "a vibration level, more than 0" : "a vibration level, less than 1000000") },
};

/** Check typed text against a rule; `{ value }`, `{ empty }` or `{ error }`. */
export function check(text, kind, required = true) {
  const parsed = parseNumber(text);
  if (parsed.empty) return required ? { error: "required", empty: true } : { empty: true };
  if (parsed.error) return parsed;
  const rule = RULES[kind];
  if (rule && !rule.test(parsed.value)) {
    return { error: typeof rule.message === "function" ? rule.message(parsed.value) : rule.message };
  }
  return parsed;
}

/** Why an angle outside one turn is refused, and what it probably meant. */
function turnWords(x) {
  const meant = Number(wrap360(x).toFixed(6));
  return x < 0
    ? `${x}° is below 0, the same place as ${meant}°; type ${meant}`
    : `${x}° is more than a turn, the same place as ${meant}°; type ${meant}`;
}

/** The one decimal rule, said where numbers are typed. */
export const DECIMAL_RULE = "Decimals with a point or a comma (2.5 or 2,5); no thousands separators (1,234 is refused: type 1234 or 1.234).";
export const SPEEDS_RULE = "Several speeds: separate them with a space or “;” (1480; 2950), decimals with a point.";

/**
 * Speeds typed as one list: "1480", "1480 2950", "1480; 2950" or "1480, 2950".
 * A comma between two digits ("1480,2950") could be a decimal comma: refused.
 */
export function parseSpeeds(text) {
  const t = String(text ?? "");
  const glued = /\d+,\d+/.exec(t);
  if (glued) {
    return { error: `“${glued[0]}” is ambiguous: one speed with a decimal comma, or two speeds? Separate speeds with a space or “;” (e.g. 1480; 2950) and write decimals with a point` };
  }
  const parts = t.split(/[\s;,]+/).filter((p) => p !== "");
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

/**
 * A number for people: `digits` decimals, or fewer significant ones for big
 * values; below 0.1 (readings in in/s or g) two significant digits, up to
 * three decimals more, so that 0.085 is not shown as 0.09 nor 0.004 as 0.00.
 * A value that rounds to zero even so keeps `digits` + 1 decimals.
 */
export function fmt(x, digits = 1) {
  if (!Number.isFinite(x)) return "–";
  const abs = Math.abs(x);
  const d = abs >= 1000 ? 0 : abs >= 100 ? Math.min(digits, 1) : abs > 0 && abs < 1 ? digits + 1 : digits;
  if (abs > 0 && abs < 0.1) {
    const small = Math.min(digits + 3, Math.max(d, 1 - Math.floor(Math.log10(abs))));
    if (Number(x.toFixed(small)) !== 0) return x.toFixed(small);
  }
  return x.toFixed(d);
}

/**
 * A stored reading as it was typed: the number itself, shortest form, up to
 * six significant digits (more than any analyser shows): 212.45 reads 212.45,
 * 21,25 reads 21.25 (the service keeps the number, not the text).
 */
export function fmtReading(x) {
  return sig(x, 6);
}

/** `x` to `digits` significant digits, shortest form ("–" for no number). */
export function sig(x, digits = 4) {
  if (!Number.isFinite(x)) return "–";
  return String(Number(x.toPrecision(digits)));
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

/** The one unit all these rows share, in words; "" when they mix units (or there are none). */
export function commonUnit(rows) {
  const units = new Set((rows || []).map((r) => r.unit).filter(Boolean));
  return units.size === 1 ? unitLabel([...units][0]) : "";
}

/**
 * The unit of a figure taken over these rows, in words: their one unit, or,
 * when they mix units (µm pk-pk beside mils pk-pk), "mixed units: µm pk-pk,
 * mils pk-pk", so that an RMS or a largest over them is not read as µm.
 */
export function unitOrMix(rows) {
  const units = [...new Set((rows || []).map((r) => r.unit).filter(Boolean))];
  if (units.length <= 1) return commonUnit(rows);
  return `mixed units: ${units.map(unitLabel).join(", ")}`;
}

/**
 * When something was stored, as one text on every page: "2026-11-24 06:25
 * UTC" (the service's RFC 3339 UTC time), as the trend's axis and the
 * report's date; a text that is no time as it is.
 */
export function storedAt(t) {
  const d = t ? new Date(t) : null;
  if (!d || Number.isNaN(d.getTime())) return t ? String(t) : "";
  return `${d.toISOString().slice(0, 16).replace("T", " ")} UTC`;
}

// The stored-session REST API. Errors carry the server's
// `{"error":{"code","message","field"}}` so the form can show them at the field.

import { askToken, storedToken, storeToken } from "./token.js";

const BASE = "/api/v1";

export class ApiError extends Error {
  constructor(status, code, message, field) {
    super(message);
    this.status = status;
    this.code = code;
    this.field = field || null;
  }
}

async function call(method, path, body, retried, extra) {
  const init = { method, headers: { Accept: "application/json", ...((extra && extra.headers) || {}) } };
  // Every write says JSON, body or not: the service refuses writes without it,
  // so that no page elsewhere can change the store through this browser.
  if (method !== "GET") init.headers["Content-Type"] = "application/json";
  if (body !== undefined) init.body = JSON.stringify(body);
  const token = storedToken();
  if (token) init.headers.Authorization = `Bearer ${token}`;
  let resp;
  try {
    resp = await fetch(BASE + path, init);
  } catch (e) {
    // Plain words on the stand PC: the command, not a code span with backticks.
    throw new ApiError(0, "network", "The fieldbal service does not answer: is it running on this PC (the command fieldbal serve)?");
  }
  const text = await resp.text();
  let data = null;
  if (text) {
    try {
      data = JSON.parse(text);
    } catch (e) {
      data = null;
    }
  }
  if (resp.status === 401 && !retried) {
    // Ask once; a token that is refused again is forgotten and the error shown.
    storeToken(null);
    const entered = await askToken(token ? "The service did not accept that access token. Enter another:" : "This fieldbal service needs an access token.");
    if (entered) {
      storeToken(entered);
      return call(method, path, body, true, extra);
    }
  }
  if (resp.status === 401) storeToken(null);
  if (!resp.ok) {
    const err = (data && data.error) || {};
    throw new ApiError(resp.status, err.code || `http_${resp.status}`, err.message || `The service answered ${resp.status}.`, err.field);
  }
  // With `full`, the caller also gets the entity tag (two tabs on one session).
  if (extra && extra.full) return { data, etag: resp.headers.get("ETag") };
  return data;
}

/** Pull the session out of whatever wrapper the service puts around it. */
export function unwrapSession(data) {
  if (data && data.session && typeof data.session === "object") return data.session;
  return data;
}

export const api = {
  listSessions: (limit = 50, offset = 0) => call("GET", `/sessions?limit=${limit}&offset=${offset}`),
  getSession: (id) => call("GET", `/sessions/${encodeURIComponent(id)}`),
  createSession: (session) => call("POST", "/sessions", session),
  deleteSession: (id) => call("DELETE", `/sessions/${encodeURIComponent(id)}`),
  addRun: (id, run) => call("POST", `/sessions/${encodeURIComponent(id)}/runs`, run),
  putRun: (id, runId, run) => call("PUT", `/sessions/${encodeURIComponent(id)}/runs/${encodeURIComponent(runId)}`, run),
  solutions: (id, limit = 100, offset = 0) => call("GET", `/sessions/${encodeURIComponent(id)}/solutions?limit=${limit}&offset=${offset}`),
  getSessionTagged: (id) => call("GET", `/sessions/${encodeURIComponent(id)}`, undefined, false, { full: true }),
  getRunTagged: (id, runId) => call("GET", `/sessions/${encodeURIComponent(id)}/runs/${encodeURIComponent(runId)}`, undefined, false, { full: true }),
  putRunIfMatch: (id, runId, run, etag) => call("PUT", `/sessions/${encodeURIComponent(id)}/runs/${encodeURIComponent(runId)}`, run, false, { headers: etag ? { "If-Match": etag } : {} }),
  solveOnce: (session, options) => call("POST", "/solve", { session, options: options || {} }),
  trialWeights: (session, options) => call("POST", "/trial-weights", { session, options: options || {} }),
  identifyRotor: (session, options) => call("POST", "/identify/rotor", { session, options: options || {} }),
  identifyFreeDecay: (body) => call("POST", "/identify/free-decay", body),
  residualUnbalance: (body) => call("POST", "/residual-unbalance", body),
  listMachines: (limit = 100, offset = 0) => call("GET", `/machines?limit=${limit}&offset=${offset}`),
  getMachine: (id) => call("GET", `/machines/${encodeURIComponent(id)}`),
  createMachine: (machine) => call("POST", "/machines", machine),
  getCoefficients: (id) => call("GET", `/machines/${encodeURIComponent(id)}/coefficients`),
  poolCoefficients: (id, sessions) => call("POST", `/machines/${encodeURIComponent(id)}/coefficients`, { sessions }),
  solve: (id, options) => call("POST", `/sessions/${encodeURIComponent(id)}/solutions`, options || {}),
};

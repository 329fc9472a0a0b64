// friction-rig virtual lab: the page only draws what the server (rig.lab.app) sends; every number
// comes from rig.stands and sensors on the server. Plain JS, no library, no other host.
"use strict";

const $ = (id) => document.getElementById(id);
const lab = { spec: null, session: null, series: null, source: null, drift: null, answers: {}, shownTwin: {}, busy: 0, dropped: {},
              token: sessionStorage.getItem("rig-lab-token") || "" };
const SYNC_MS = 2000;  // how often the page asks whether another tab changed the session
const RPM = 60 / (2 * Math.PI), DEG = 180 / Math.PI;
// a reading without the binary rounding noise of its decimal steps (0.4018, not 0.40180000000000005)
const tidy = (x) => +x.toPrecision(12);

// What differs between the stands on the page: the controls (page unit <-> SI), the live traces,
// the readings table, the lab sheet's columns. Everything else is shared.
const STANDS = {
  yoke: {
    section: "stand-a", apply: "apply", readings: "readings-a", strobe: true, label: "stand A",
    controls: [
      { name: "normal_force_N", id: "normal_force_N", toSI: (v) => v, fromSI: (v) => v },
      { name: "delta_h_m", id: "delta_h_mm", toSI: (v) => v / 1000, fromSI: (v) => +(v * 1000).toPrecision(6) },
      { name: "brake_setpoint_N_m", id: "brake_setpoint_N_m", toSI: (v) => v, fromSI: (v) => v },
      { name: "omega_1_set_rad_s", id: "speed_rpm", toSI: (v) => v / RPM, fromSI: (v) => +(v * RPM).toPrecision(6) },
    ],
    traces: [{ name: "omega_1", label: "ω1", axis: "speed", color: "#1565c0" }, { name: "omega_2", label: "ω2", axis: "speed", color: "#c62828" },
             { name: "brake_moment", label: "brake moment [N m]", axis: "load", color: "#2e7d32" }],
    columns: [["F<sub>N</sub> [N]", (r) => r.settings.normal_force], ["Δh [mm]", (r) => (r.settings.delta_h * 1000).toFixed(3)],
              ["T<sub>set</sub> [N m]", (r) => r.settings.brake_setpoint], ["N<sub>1</sub>", (r) => r.counts.wheel_1],
              ["N<sub>2</sub>", (r) => r.counts.wheel_2], ["gate [s]", (r) => r.gate_time_s],
              ["dyn. [V]", (r) => r.dynamometer_V.mean.toPrecision(6)], ["T<sub>2</sub> [N m]", (r) => tidy(r.balance_N_m.T2)]],
    schematic(s) {
      $("sch-force").textContent = `F_N = ${s.normal_force_N} N`;
      $("sch-dh").textContent = `Δh = ${(s.delta_h_m * 1000).toFixed(2)} mm`;
      $("sch-brake").textContent = `T_set = ${s.brake_setpoint_N_m} N m`;
      $("sch-speed").textContent = `n1 = ${(s.omega_1_set_rad_s * RPM).toFixed(0)} rpm`;
    },
  },
  disc_roller: {
    section: "stand-b", apply: "apply-b", readings: "readings-b", strobe: false, label: "stand B",
    controls: [
      { name: "normal_force_N", id: "b_normal_force_N", toSI: (v) => v, fromSI: (v) => v },
      { name: "l_m", id: "b_l_mm", toSI: (v) => v / 1000, fromSI: (v) => +(v * 1000).toPrecision(6) },
      { name: "sigma_rad", id: "b_sigma_deg", toSI: (v) => v / DEG, fromSI: (v) => +(v * DEG).toPrecision(6) },
      { name: "speed_step", id: "b_speed_step", toSI: (v) => v, fromSI: (v) => v },
      { name: "direction", id: "b_direction", toSI: (v) => v, fromSI: (v) => v },
    ],
    traces: [{ name: "roller_speed", label: "ω roller", axis: "speed", color: "#1565c0" }, { name: "disc_speed", label: "ω disc", axis: "speed", color: "#c62828" },
             { name: "F_T", label: "F_T", axis: "load", color: "#2e7d32" }, { name: "F_V", label: "F_V", axis: "load", color: "#6a1b9a" },
             { name: "T_Mo", label: "T_Mo [N, N m]", axis: "load", color: "#ef6c00" }],
    columns: [["F<sub>N</sub> [N]", (r) => r.settings.normal_force], ["l [mm]", (r) => tidy(r.settings.l * 1000)],
              ["σ [°]", (r) => tidy(r.settings.sigma * DEG)], ["step", (r) => r.settings.speed_step],
              ["direction", (r) => r.settings.direction], ["gate [s]", (r) => tidy(r.gate_time_s)],
              ["F<sub>T</sub> [V]", (r) => r.recorder_V.F_T.mean.toPrecision(6)], ["F<sub>V</sub> [V]", (r) => r.recorder_V.F_V.mean.toPrecision(6)],
              ["T<sub>Mo</sub> [V]", (r) => r.recorder_V.T_Mo.mean.toPrecision(6)]],
    schematic(s) {
      $("sch-b-force").textContent = `F_N = ${s.normal_force_N} N`;
      $("sch-b-l").textContent = `l = ${(s.l_m * 1000).toFixed(1)} mm`;
      $("sch-b-sigma").textContent = `σ = ${(s.sigma_rad * DEG).toFixed(2)}°`;
      $("sch-b-speed").textContent = `roller ${[24, 48, 72][s.speed_step - 1]} rpm`;
      $("sch-b-direction").textContent = s.direction > 0 ? "forward ⟳" : "reverse ⟲";
      $("sch-roller").setAttribute("transform", `translate(${Math.max(-60, Math.min(60, s.l_m * 2500))} 0)`);
    },
  },
};
const stand = () => STANDS[lab.session.stand];
const outputs = () => lab.spec[lab.session.stand].outputs;

async function request(method, path, body) {
  // every call carries the class token (if any); a dead server is shown as such, not as "settled"
  const options = { method, headers: { "Content-Type": "application/json" } };
  if (lab.token) options.headers["X-Lab-Token"] = lab.token;
  if (body !== undefined) options.body = JSON.stringify(body);
  let response;
  try { response = await fetch(path, options); } catch (error) { unreachable(true); throw Object.assign(new Error("the lab server is unreachable: is it running?"), { field: "server" }); }
  unreachable(false);
  let data;
  try { data = await response.json(); } catch (error) { throw Object.assign(new Error(`HTTP ${response.status}`), { field: "server", status: response.status }); }
  if (!response.ok) { const e = new Error(data.error); e.field = data.field; e.status = response.status; throw e; }
  return data;
}

function unreachable(down) {
  $("offline").hidden = !down;
  document.body.dataset.server = down ? "unreachable" : "up";
  if (down && $("status").dataset.state !== "idle") setStatus("offline", "server unreachable");
}

// a link (download) that carries the token
const withToken = (path) => lab.token ? `${path}${path.includes("?") ? "&" : "?"}token=${encodeURIComponent(lab.token)}` : path;

async function api(method, path, body) {
  lab.busy++;  // while this page waits for its own answer, sync() leaves the session alone
  try { return await request(method, path, body); } finally { lab.busy--; }
}

async function sync() {
  // another tab (or window) of the same session changed it: show the new state
  if (!lab.session || lab.busy) return;
  let state;
  try { state = await request("GET", `/api/sessions/${lab.session.id}`); } catch (error) { return; }
  if (lab.session && lab.session.exercise) lab.session.exercise = state.exercise;
  if (lab.busy || !lab.session || state.id !== lab.session.id || state.version === lab.session.version) return;
  const point = $("answer-point").value;
  await enter(state);
  if (point !== "") $("answer-point").value = point;
  live();
}

function showError(error) {
  $("control-error").textContent = error.field ? `${error.field}: ${error.message}` : String(error.message || error);
}

// ------------------------------------------------------------------------------------ session

async function openSession(body) {
  try {
    const state = await api("POST", "/api/sessions", body);
    location.hash = "session=" + state.id;
    await enter(state);
    await settleNow();
  } catch (error) { $("exercise-info").textContent = `${error.field || ""}: ${error.message}`; $("exercise-info").dataset.error = error.status || "x"; }
}

async function openExercise() {
  // a class: the student's token (given by the teacher), or the class's join code which issues one
  const student = $("student").value.trim(), key = $("token").value.trim();
  try {
    if (/^[0-9a-f]{32}$/.test(key)) lab.token = key;
    else lab.token = (await api("POST", "/api/join", { student, join_code: key })).token;
    sessionStorage.setItem("rig-lab-token", lab.token);
    $("my-token").textContent = `your token: ${lab.token} (keep it: it opens your work from any browser)`;
  } catch (error) { $("exercise-info").textContent = `${error.field || ""}: ${error.message}`; $("exercise-info").dataset.error = error.status || "x"; return; }
  await openSession({ stand: $("exercise").selectedOptions[0].dataset.stand, exercise: $("exercise").value });
}

async function settleNow() {
  // a session that has not settled since it opened (or since the server restarted): settle at its settings
  lab.session.version = (await api("POST", `/api/sessions/${lab.session.id}/controls`, { settings: {} })).version;
  live();
}

async function enter(state) {
  const fresh = !lab.session || lab.session.id !== state.id;
  lab.session = state;
  if (fresh) { lab.answers = {}; lab.shownTwin = {}; lab.dropped = {}; }
  for (const [point, values] of Object.entries(state.answers || {})) lab.answers[point] = values;
  $("bench").hidden = false;
  for (const s of Object.values(STANDS)) $(s.section).hidden = s !== stand();
  for (const s of Object.values(STANDS)) $(s.readings).hidden = s !== stand();
  $("strobe-figure").hidden = !stand().strobe;
  if (fresh) { $("gate_time").value = lab.spec[state.stand].gate_time_s.default; buildSheet(); }
  const ex = state.exercise;
  $("session-info").textContent = `session ${state.id} · ${stand().label}` + (ex ? ` · exercise ${ex.id}: ${ex.title}` : " · practice");
  $("submit").hidden = $("final-label").hidden = !ex;
  $("reset").hidden = !!ex;
  showRules(ex);
  showSettings(state.settings, state.free);
  $("strobe_ratio").value = state.strobe_ratio;
  $("points").tBodies[0].innerHTML = "";
  $("answer-point").innerHTML = "";
  state.readings.forEach(addReadings);
  if (state.readings.length) showReadings(state.readings[state.readings.length - 1], false);
  if (fresh) fillAnswers();
  document.body.dataset.stand = state.stand;
  downloads();
}

function showRules(ex) {
  // an exercise's rules and what the student has used of them
  if (!ex) { $("rules").textContent = ""; return; }
  const tol = Object.entries(ex.tolerance).map(([n, t]) => `${n} ±` + [t.relative ? `${+(t.relative * 100).toPrecision(3)} %` : "", t.absolute ? `${t.absolute}` : "",
    t.uncertainty ? `${t.uncertainty} × your U95` : ""].filter(Boolean).join(" or ")).join(", ");
  $("rules").innerHTML = `Checks left: <b id="checks-left">${ex.checks_left}</b> of ${ex.checks} · attempts used: <b id="attempts-used">${ex.attempts_used}</b> of ${ex.attempts}` +
    (ex.deadline ? ` · deadline ${ex.deadline}` : "") + (ex.min_gate_s ? ` · gate at least ${ex.min_gate_s} s` : "") +
    (ex.final ? " · <b>final submission made</b>" : "") + `<br><small>tolerances: ${tol}</small>`;
  $("submit").disabled = ex.final;
  $("save").hidden = !ex.final;
  $("download-log").hidden = !ex.final;
}

function fillAnswers() {
  // the values the student last checked for the chosen point (kept by the server, also across a restart)
  const given = lab.answers[$("answer-point").value] || {};
  for (const input of document.querySelectorAll("#answer-inputs input[id^=ans-]")) { const v = given[input.id.slice(4)]; input.value = v === undefined ? "" : v; }
}

// TeX rendered by the vendored KaTeX (static/vendor/katex); plain text if it failed to load
const tex = (t, display = false) => window.katex ? katex.renderToString(t, { throwOnError: false, displayMode: display }) : `<code>${t}</code>`;

function buildSheet() {
  // the lab sheet of this stand: one row per step of the method, with its equations and an input
  // per quantity (symbol, unit), so that a wrong value is located to its step
  const spec = lab.spec[lab.session.stand];
  $("points").tHead.innerHTML = "<tr><th>point</th>" + stand().columns.map(([h]) => `<th>${h}</th>`).join("") + "<th>drop</th></tr>";
  $("answer-inputs").innerHTML = `<table id="steps"><tbody>` + spec.steps.map((st, k) =>
    `<tr id="step-${st.key}" data-ok=""><th>${k + 1}. ${st.text}</th><td class="tex">${tex(st.tex)}</td><td>` +
    st.quantities.map((q) => `<label>${tex(q.symbol)}${q.unit === "1" ? "" : ` [${q.unit}]`} <input id="ans-${q.name}" type="number" step="any" title="${q.name}"></label>` +
      (stated(q.name) ? ` <label>${tex(`U_{95}(${q.symbol})`)} <input id="ans-U95_${q.name}" type="number" step="any" title="your U95 of ${q.name}"></label>` : "")).join(" ") +
    "</td></tr>").join("") + "</tbody></table>";
  $("optional-note").textContent = spec.optional.join(", ");
  $("nu-chart").innerHTML = ""; $("nu-values").textContent = "";
  $("verdict").innerHTML = ""; $("verdict").dataset.result = "";
  $("reduction").hidden = true; $("submitted").innerHTML = ""; $("saved").textContent = "";
}

function showSettings(s, free) {
  for (const c of stand().controls) {
    const value = s[c.name] === undefined ? 1 : s[c.name];  // stand A has no direction setting: forward
    $(c.id).value = c.fromSI(value);
    $(c.id).disabled = !(c.always || free.includes(c.name));
  }
  stand().schematic(s);
}

// ------------------------------------------------------------------------------------ controls

async function apply() {
  $("control-error").textContent = "";
  const settings = {};
  for (const c of stand().controls) {
    if (!(c.always || lab.session.free.includes(c.name))) continue;
    const value = $(c.id).value === "" ? NaN : c.toSI(Number($(c.id).value));
    if (!Number.isFinite(value)) { showError({ field: `settings.${c.name}`, message: "enter a number" }); return; }
    const now = lab.session.settings[c.name] === undefined ? 1 : lab.session.settings[c.name];
    if (Math.abs(value - now) > 1e-12 * Math.max(1, Math.abs(value))) settings[c.name] = value;
  }
  setStatus("settling", "computing…");
  try {
    const answer = await api("POST", `/api/sessions/${lab.session.id}/controls`, { settings });
    lab.session.settings = answer.settings;
    lab.session.version = answer.version;
    showSettings(answer.settings, lab.session.free);
    live();
  } catch (error) {
    showError(error);
    showSettings(lab.session.settings, lab.session.free);  // the stand stays as it was
    if (error.field === "server") setStatus("offline", "server unreachable"); else setStatus("settled", "settled (unchanged)");
  }
}

async function setStrobe() {
  try {
    await api("POST", `/api/sessions/${lab.session.id}/controls`, { strobe_ratio: Number($("strobe_ratio").value) });
    live();
  } catch (error) { showError(error); }
}

function setStatus(state, text) { $("status").dataset.state = state; $("status").textContent = text; }

// ------------------------------------------------------------------------------------ live values

function live() {
  if (lab.source) lab.source.close();
  if (lab.drift) cancelAnimationFrame(lab.drift);
  const ratio = Number($("ratio").value);
  $("ratio-shown").textContent = `simulated time runs ${ratio}× real time`;
  lab.series = { t: [], phases: [] };
  for (const tr of stand().traces) lab.series[tr.name] = [];
  setStatus("settling", "settling…");
  const source = new EventSource(withToken(`/api/sessions/${lab.session.id}/live?ratio=${ratio}`));
  lab.source = source;
  source.addEventListener("frame", (event) => {
    const f = JSON.parse(event.data);
    lab.series.t.push(...f.t);
    for (const [name, values] of Object.entries(f.series)) lab.series[name].push(...values);
    const now = f.t[f.t.length - 1];
    if (f.strobe_phase !== null) lab.series.phases.push([now, f.strobe_phase]);
    $("clock").textContent = `t = ${now.toFixed(2)} s`;
    drawTraces(f.settle_s);
    if (stand().strobe) drawStrobe(f.strobe_phase);
  });
  source.addEventListener("settled", (event) => {
    const f = JSON.parse(event.data);
    source.close();
    setStatus("settled", `settled after ${f.settle_s.toFixed(2)} s of simulated time`);
    if (stand().strobe) steadyStrobe(ratio, f.strobe_drift_marks_s);
  });
  source.onerror = async () => {
    // the stream broke off (a busy or restarted server): the settled state is the server's all the same
    source.close();
    if (lab.source !== source || $("status").dataset.state !== "settling") return;
    try {
      const state = await request("GET", `/api/sessions/${lab.session.id}`);
      if (lab.source === source && state.settle_s !== null) setStatus("settled", `settled after ${state.settle_s.toFixed(2)} s of simulated time (stream interrupted)`);
    } catch (error) { showError(error); if (error.field === "server") setStatus("offline", "server unreachable"); }
  };
}

function drawTraces(settle) {
  // the drive train over time: speeds on the left axis, loads (brake moment; F_T, F_V, T_Mo) on the right
  const c = $("speeds"), g = c.getContext("2d"), s = lab.series, traces = stand().traces;
  g.clearRect(0, 0, c.width, c.height);
  if (!s.t.length) return;
  const values = (axis) => traces.filter((tr) => tr.axis === axis).flatMap((tr) => s[tr.name]);
  const tMax = Math.max(s.t[s.t.length - 1], settle + 0.5);
  const speeds = values("speed"), wMax = Math.max(...speeds.map(Math.abs), 1) * 1.1, signed = Math.min(...speeds) < 0;
  const bAbs = Math.max(...values("load").map(Math.abs), 0.1) * 1.2;
  const top = 10, bottom = c.height - 20, mid = (top + bottom) / 2;
  const x = (t) => 40 + (t / tMax) * (c.width - 50);
  const maps = { speed: signed ? (w) => mid - (w / wMax) * (bottom - top) / 2 : (w) => bottom - (w / wMax) * (bottom - top),
                 load: (b) => mid - (b / bAbs) * (bottom - top) / 2 };
  g.strokeStyle = "#999"; g.strokeRect(40, top, c.width - 50, bottom - top);
  g.fillStyle = "#333"; g.font = "10px sans-serif"; g.strokeStyle = "#333";
  for (const v of ticks(0, tMax, 6)) { g.beginPath(); g.moveTo(x(v), bottom); g.lineTo(x(v), bottom + 4); g.stroke(); g.fillText(String(+v.toPrecision(3)), x(v) - 6, bottom + 13); }
  for (const v of ticks(signed ? -wMax : 0, wMax, 4)) { const yy = maps.speed(v); g.beginPath(); g.moveTo(36, yy); g.lineTo(40, yy); g.stroke(); g.fillText(String(+v.toPrecision(3)), 2, yy + 3); }
  g.font = "11px sans-serif";
  g.fillText(`ω [rad/s] (left axis); loads on ±${bAbs.toPrecision(3)} (N, N m)`, 44, 22);
  g.fillText("t [s]", c.width - 40, c.height - 6);
  g.setLineDash([4, 3]); g.strokeStyle = "#aaa"; g.beginPath(); g.moveTo(x(settle), top); g.lineTo(x(settle), bottom); g.stroke(); g.setLineDash([]);
  let label = 50;
  for (const tr of traces) {
    const map = maps[tr.axis], ys = s[tr.name];
    g.strokeStyle = tr.color; g.beginPath();
    ys.forEach((v, i) => (i ? g.lineTo(x(s.t[i]), map(v)) : g.moveTo(x(s.t[i]), map(v))));
    g.stroke();
    g.fillStyle = tr.color; g.fillText(tr.label, label, 40); label += g.measureText(tr.label).width + 10;
  }
}

function drawStrobe(phase) {
  const c = $("strobe"), g = c.getContext("2d"), z = lab.spec.yoke.marks.wheel_2, r = c.width / 2 - 8;
  g.clearRect(0, 0, c.width, c.height);
  g.save(); g.translate(c.width / 2, c.height / 2);
  g.fillStyle = "#222"; g.beginPath(); g.arc(0, 0, r, 0, 2 * Math.PI); g.fill();
  g.strokeStyle = "#fff"; g.lineWidth = 2;
  const shift = phase === null ? 0 : (phase * 2 * Math.PI) / z;
  for (let k = 0; k < z; k++) {
    const a = shift + (2 * Math.PI * k) / z, inner = k % 5 === 0 ? r * 0.7 : r * 0.82;
    g.beginPath(); g.moveTo(inner * Math.cos(a), inner * Math.sin(a)); g.lineTo(r * Math.cos(a), r * Math.sin(a)); g.stroke();
  }
  g.strokeStyle = "#f44"; g.beginPath(); g.moveTo(r + 6, 0); g.lineTo(r - 10, 0); g.stroke();
  g.restore();
}

function steadyStrobe(ratio, rate) {
  // after settling, the marks keep the drift the server found in the steady tail [marks/s]
  const p = lab.series.phases, drift = rate === null ? 0 : rate;
  $("strobe-drift").textContent = Math.abs(drift) < 0.01 ? "marks stand still" : `marks drift ${drift.toFixed(2)} marks/s`;
  $("strobe-drift").dataset.rate = drift;
  const shown = Math.sign(drift) * Math.min(Math.abs(drift) * ratio, 20);  // faster than the eye follows: shown at 20/s
  const start = performance.now(), phase0 = p.length ? p[p.length - 1][1] : 0;
  const step = (now) => { drawStrobe(phase0 + shown * (now - start) / 1000); lab.drift = requestAnimationFrame(step); };
  lab.drift = requestAnimationFrame(step);
}

// ------------------------------------------------------------------------------------ gate

async function record() {
  $("control-error").textContent = "";
  $("record").disabled = true;
  try {
    const answer = await api("POST", `/api/sessions/${lab.session.id}/record`, { gate_time_s: Number($("gate_time").value) });
    lab.session.readings[answer.readings.point] = answer.readings;
    lab.session.reduced = answer.reduced;
    lab.session.version = answer.version;
    await runGate(answer.readings);
    addReadings(answer.readings);
    showReadings(answer.readings, true);
  } catch (error) { showError(error); }
  $("record").disabled = false;
}

function runGate(r) {
  // the gate is open for gate time / time ratio of real time: stand A's counters count, stand B's recorder runs
  const ratio = Number($("ratio").value), duration = (1000 * r.gate_time_s) / ratio;
  return new Promise((resolve) => {
    const start = performance.now();
    const tick = (now) => {
      const f = Math.min((now - start) / duration, 1);
      if (r.counts) {
        $("counter-1").textContent = Math.floor(f * r.counts.wheel_1);
        $("counter-2").textContent = Math.floor(f * r.counts.wheel_2);
      } else $("recording").textContent = f < 1 ? `recording: ${(f * r.gate_time_s).toFixed(1)} s` : "";
      if (f < 1) requestAnimationFrame(tick); else resolve();
    };
    requestAnimationFrame(tick);
  });
}

function showReadings(r, select) {
  if (r.counts) {
    $("counter-1").textContent = r.counts.wheel_1;
    $("counter-2").textContent = r.counts.wheel_2;
    $("marks").textContent = `${r.marks.wheel_1}, ${r.marks.wheel_2}`;
    $("dynamometer").textContent = `${r.dynamometer_V.mean.toPrecision(6)} ± ${r.dynamometer_V.std.toPrecision(2)} (${r.dynamometer_V.samples} samples, step ${r.dynamometer_V.resolution.toPrecision(3)})`;
    $("calibration").textContent = `${r.calibration.sensitivity_V_per_N.toPrecision(6)}, ${r.calibration.offset_V.toPrecision(4)}`;
    $("balance").textContent = `${tidy(r.balance_N_m.T2)} (readings ${r.balance_N_m.readings.map(tidy).join(", ")}; step ${r.balance_N_m.resolution.toPrecision(3)})`;
  } else {
    for (const [name, ch] of Object.entries(r.recorder_V)) {
      $(`rec-${name}`).textContent = `${ch.mean.toPrecision(6)} ± ${ch.std.toPrecision(2)} (${ch.samples} samples, step ${ch.resolution.toPrecision(3)})`;
      $(`cal-${name}`).textContent = ch.sensitivity.toPrecision(6);
      $(`off-${name}`).textContent = ch.offset.toPrecision(4);
    }
  }
  if (select) $("answer-point").value = r.point;
  document.body.dataset.recorded = lab.session.readings.length;
}

function addReadings(r) {
  if ($(`point-${r.point}`)) return;  // already shown (a sync from another tab came first)
  const row = $("points").tBodies[0].insertRow();
  row.id = `point-${r.point}`;
  row.insertCell().textContent = r.point;
  for (const [, cell] of stand().columns) row.insertCell().textContent = cell(r);
  const drop = document.createElement("input");
  drop.type = "checkbox"; drop.id = `drop-${r.point}`; drop.title = "drop this point: left out of the results plot and the submission";
  drop.checked = !!lab.dropped[r.point];
  drop.onchange = () => { lab.dropped[r.point] = drop.checked; row.classList.toggle("dropped", drop.checked); drawResults(); };
  row.insertCell().append(drop);
  const option = document.createElement("option");
  option.value = option.textContent = r.point;
  $("answer-point").append(option);
}

// ------------------------------------------------------------------------------------ sheet

// an exercise whose tolerance of a quantity is a multiple of the student's own stated U95 asks for it
const stated = (name) => { const t = lab.session.exercise && lab.session.exercise.tolerance[name]; return !!(t && t.uncertainty); };

function answersOf() {
  const answers = {};
  for (const input of document.querySelectorAll("#answer-inputs input[id^=ans-]")) if (input.value !== "") answers[input.id.slice(4)] = Number(input.value);
  return answers;
}

async function check() {
  const point = Number($("answer-point").value), answers = answersOf();
  try {
    const v = await api("POST", `/api/sessions/${lab.session.id}/check`, { point, answers });
    lab.answers[point] = answers;
    lab.shownTwin[point] = true;
    const perValue = Object.values(v.values).every((x) => x.ok !== undefined);
    const lines = perValue ? Object.entries(v.values).map(([name, x]) =>
      `<span class="${x.ok ? "ok" : "wrong"}" id="v-${name}">${name}: ${x.ok ? "✓" : "✗"}</span>`)
      : Object.entries(v.steps).filter(([, ok]) => ok !== null).map(([step, ok]) =>
      `<span class="${ok ? "ok" : "wrong"}" id="s-${step}">${step.replace("_", " ")}: ${ok ? "within tolerance" : "not within tolerance"}</span>`);
    if (v.checks_left !== undefined) { lab.session.exercise.checks_left = v.checks_left; showRules(lab.session.exercise); }
    $("verdict").innerHTML = `<p>point ${point}: ${lines.join(" · ")}</p>` + (v.passed
      ? `<p class="ok" id="verdict-text">every value agrees with the reduction of your readings within its tolerance</p>`
      : `<p class="wrong" id="verdict-text">go back to ${v.sent_back_to.text}</p>`);
    $("verdict").dataset.result = v.passed ? "passed" : `back:${v.sent_back_to.step}`;
    for (const [step, ok] of Object.entries(v.steps || {})) $(`step-${step}`).dataset.ok = ok === null ? "" : ok ? "yes" : "no";
    drawResults();
  } catch (error) {
    $("verdict").innerHTML = `<p class="wrong" id="verdict-text">${error.field}: ${error.message}</p>`;
    $("verdict").dataset.result = `error:${error.field}`;
  }
}

function showReduction() {
  const rows = lab.session.reduced || [], names = outputs();
  if (lab.session.exercise && !rows.length) { $("verdict").innerHTML = "<p>In an exercise the twin's reduction is shown after you submit.</p>"; return; }
  const t = $("reduction");
  t.tHead.innerHTML = "<tr><th>point</th>" + names.map((n) => `<th>${n}</th><th>U95</th>`).join("") + "<th>note</th></tr>";
  t.tBodies[0].innerHTML = "";
  for (const r of rows) {
    const row = t.tBodies[0].insertRow();
    row.insertCell().textContent = r.point;
    for (const n of names) {
      const cell = row.insertCell(); cell.className = `red-${n}`; cell.dataset.value = r.values[n];
      cell.textContent = r.values[n] === null ? "—" : sig(r.values[n], 5);  // five significant digits; the float in data-value
      row.insertCell().textContent = r.values[`U95_${n}`] === null ? "—" : r.values[`U95_${n}`].toPrecision(2);
    }
    row.insertCell().textContent = r.reason;
    lab.shownTwin[r.point] = true;
  }
  t.hidden = false;
  drawResults();
}

function drawResults() {
  // mu_v, mu_T over l/a: the student's (filled) beside the twin's (open, U95 bars). The axes are
  // scaled to the twin's values, so one wild entry cannot squeeze the others: a value off the
  // plot is drawn as a triangle at its edge, with the value in its tooltip. Dropped points are left out.
  const svg = $("results"), rows = (lab.session.reduced || []).filter((r) => lab.shownTwin[r.point] && !lab.dropped[r.point]);
  const pts = [];
  for (const r of rows) {
    const v = r.values;
    for (const m of ["mu_v", "mu_T"]) if (v[m] !== null) pts.push({ x: v.l_over_a, y: v[m], u: v[`U95_${m}`] || 0, twin: true, m });
    const a = lab.answers[r.point];
    if (a) for (const m of ["mu_v", "mu_T"]) if (a[m] !== undefined) pts.push({ x: a.l_over_a ?? v.l_over_a, y: a[m], twin: false, m });
  }
  const twins = pts.filter((p) => p.twin), ref = twins.length ? twins : pts;
  const W = 460, H = 220, L = 45, R = 10, T = 10, B = 30;
  const xs = ref.map((p) => p.x).filter(Number.isFinite), ys = ref.flatMap((p) => [p.y - (p.u || 0), p.y + (p.u || 0)]).filter(Number.isFinite);
  let x0 = Math.min(-0.5, ...xs), x1 = Math.max(0.5, ...xs), y0 = Math.min(0, ...ys), y1 = Math.max(0.6, ...ys);
  const padX = 0.1 * (x1 - x0), padY = 0.1 * (y1 - y0); x0 -= padX; x1 += padX; y1 += padY;
  const x = (v) => L + (v - x0) / (x1 - x0) * (W - L - R), y = (v) => H - B - (v - y0) / (y1 - y0) * (H - T - B);
  let s = `<rect x="${L}" y="${T}" width="${W - L - R}" height="${H - T - B}" fill="none" stroke="#999"/>`;
  for (const v of ticks(x0, x1, 6)) s += `<line x1="${x(v)}" x2="${x(v)}" y1="${H - B}" y2="${H - B + 4}" stroke="#333"/><text x="${x(v) - 8}" y="${H - B + 15}">${+v.toPrecision(3)}</text>`;
  for (const v of ticks(y0, y1, 5)) s += `<line x1="${L - 4}" x2="${L}" y1="${y(v)}" y2="${y(v)}" stroke="#333"/><text x="4" y="${y(v) + 4}">${+v.toPrecision(3)}</text>`;
  s += `<text x="${W - 70}" y="${H - 2}">l/a [1]</text><text x="${L + 4}" y="${T + 12}">μ [1]</text>`;
  for (const p of pts) {
    const color = p.m === "mu_v" ? "#1565c0" : "#c62828", cx = x(Math.min(x1, Math.max(x0, p.x)));
    if (p.twin) { s += `<line x1="${cx}" x2="${cx}" y1="${y(p.y - p.u)}" y2="${y(p.y + p.u)}" stroke="${color}"/><circle class="twin" cx="${cx}" cy="${y(p.y)}" r="5" fill="none" stroke="${color}"/>`; continue; }
    if (p.y > y1 || p.y < y0 || p.x > x1 || p.x < x0) {
      const cy = p.y > y1 ? T + 6 : p.y < y0 ? H - B - 6 : y(p.y), dir = p.y > y1 ? -1 : 1;
      s += `<path class="student off-scale" d="M${cx - 5} ${cy - 4 * dir} L${cx + 5} ${cy - 4 * dir} L${cx} ${cy + 5 * dir} Z" fill="${color}"><title>${p.m} = ${p.y} (off the plot)</title></path>`;
    } else s += `<circle class="student" cx="${cx}" cy="${y(p.y)}" r="3.5" fill="${color}"/>`;
  }
  s += `<text x="${L + 60}" y="${T + 12}" fill="#1565c0">μv</text><text x="${L + 85}" y="${T + 12}" fill="#c62828">μT</text>`;
  svg.innerHTML = s;
}

async function save() {
  try { const r = await api("POST", `/api/sessions/${lab.session.id}/save`, {}); $("saved").textContent = `saved on the server: ${r.path}`; $("saved").dataset.path = r.path; }
  catch (error) { $("saved").textContent = `${error.field}: ${error.message}`; }
}

async function submit() {
  const answers = Object.entries(lab.answers).filter(([point]) => !lab.dropped[point]).map(([point, values]) => ({ point: Number(point), values }));
  const final = $("final").checked;
  $("submitted").dataset.done = "";
  try {
    const r = await api("POST", `/api/sessions/${lab.session.id}/submit`, { answers, final });
    const head = `<p id="attempt" data-final="${r.final}">attempt ${r.attempt} at ${r.time_utc}${r.final ? ": final, graded" : `: counted; ${r.attempts_left} left`}</p>`;
    $("submitted").innerHTML = head + r.results.map((p) => `<p id="graded-${p.point}" class="${p.passed ? "ok" : "wrong"}">point ${p.point}: ${p.passed ? "passed" : `not passed: ${p.sent_back_to.text}`}` +
      (p.truth ? `; true μ = ${p.truth.mu.toFixed(4)}` : "") + "</p>").join("");
    const state = await api("GET", `/api/sessions/${lab.session.id}`);
    lab.session.exercise = state.exercise; showRules(state.exercise);
    if (r.final) { lab.session.reduced = state.reduced; showReduction(); }  // now released
    $("submitted").dataset.done = "yes";
  } catch (error) { $("submitted").innerHTML = `<p class="wrong" id="submit-error">${error.field}: ${error.message}</p>`; $("submitted").dataset.done = `error:${error.status}`; }
}

function downloads() {
  $("download-csv").href = withToken(`/api/sessions/${lab.session.id}/readings.csv`);
  $("download-log").href = withToken(`/api/sessions/${lab.session.id}/log.h5`);
}

async function teacher(token) {
  // the teacher's view: the class's students, tokens and grade book (only this token gets them)
  lab.token = token;
  const c = await api("GET", "/api/class");
  $("teacher").hidden = false; $("mode").hidden = true;
  $("teacher-title").textContent = c.title;
  $("grades-link").href = withToken("/api/grades.csv");
  const rows = c.grades.map((g) => `<tr><td>${g.student}</td><td>${g.exercise}</td><td>${g.attempts}</td><td>${g.time_utc}</td><td>${g.final ? "final" : "open"}</td><td>${g.passed}/${g.points}</td></tr>`);
  $("gradebook").tBodies[0].innerHTML = rows.join("");
  $("roster").tBodies[0].innerHTML = c.students.map((s) => `<tr><td>${s.student}</td><td><code>${s.token}</code></td></tr>`).join("");
  document.body.dataset.teacher = "yes";
}

// ------------------------------------------------------------------------------------ start

function standData(tableId, geometry) {
  // the stand's data as the sheet needs them: symbol, value, unit (the code name as a tooltip)
  for (const [name, g] of Object.entries(geometry)) {
    const row = $(tableId).querySelector("tbody").insertRow();
    row.dataset.name = name; row.dataset.si = g.value; row.title = name;
    row.insertCell().innerHTML = tex(g.symbol || name);
    row.insertCell().textContent = `${+(g.shown_value ?? g.value).toPrecision(6)} ${g.shown_unit || g.unit}`;
  }
}

// ------------------------------------------------------------------------------------ nu lookup

async function lookupNu() {
  // the contact law's nu_T, nu_v, nu_0 at the chosen point's load (b/a) and the entered l/a, c/a, alpha'
  const point = Number($("answer-point").value), body = { point };
  for (const n of ["l_over_a", "c_over_a", "alpha_prime"]) body[n] = Number($(`nu-${n}`).value === "" ? NaN : $(`nu-${n}`).value);
  $("nu-values").dataset.done = "";
  try {
    const r = await api("POST", `/api/sessions/${lab.session.id}/nu`, body);
    $("nu-values").innerHTML = `b/a = <span id="nu-b_over_a">${sig(r.b_over_a, 4)}</span> · ` +
      ["nu_T", "nu_v", "nu_0"].map((n) => `${tex(`\\${n.replace("_", "_")}`)} = <span id="nu-out-${n}">${sig(r[n], 5)}</span>`).join(" · ");
    drawNu(r, body.alpha_prime);
    $("nu-values").dataset.done = "yes";
  } catch (error) { $("nu-values").textContent = `${error.field}: ${error.message}`; $("nu-values").dataset.done = "error"; }
}

const sig = (x, n = 4) => (x === null || x === undefined || !Number.isFinite(x)) ? "—" : String(+x.toPrecision(n));

function drawNu(r, alpha) {
  // nu_T, nu_v, nu_0 over alpha' (log axis) at this l/a, c/a: ticks, labels, the chosen alpha' marked
  const W = 460, H = 220, L = 50, R = 10, T = 10, B = 35, c = r.curve, a = c.alpha_prime;
  const lx = (v) => L + (Math.log10(v) - Math.log10(a[0])) / (Math.log10(a[a.length - 1]) - Math.log10(a[0])) * (W - L - R);
  const all = [...c.nu_T, ...c.nu_v, ...c.nu_0].filter(Number.isFinite), lo = Math.min(0, ...all), hi = Math.max(...all);
  const y = (v) => H - B - (v - lo) / ((hi - lo) || 1) * (H - T - B);
  let s = `<rect x="${L}" y="${T}" width="${W - L - R}" height="${H - T - B}" fill="none" stroke="#999"/>`;
  for (let e = Math.ceil(Math.log10(a[0])); e <= Math.log10(a[a.length - 1]); e++) for (const m of [1, 2, 5]) {
    const v = m * 10 ** e; if (v < a[0] || v > a[a.length - 1]) continue;
    s += `<line x1="${lx(v)}" x2="${lx(v)}" y1="${H - B}" y2="${H - B + 4}" stroke="#333"/><text x="${lx(v) - 6}" y="${H - B + 15}">${+v.toPrecision(2)}</text>`;
  }
  for (const v of ticks(lo, hi, 5)) s += `<line x1="${L - 4}" x2="${L}" y1="${y(v)}" y2="${y(v)}" stroke="#333"/><text x="4" y="${y(v) + 4}">${+v.toPrecision(3)}</text>`;
  s += `<text x="${W - 90}" y="${H - 3}">α' [1], log scale</text><text x="${L + 4}" y="${T + 12}">ν [1]</text>`;
  const colors = { nu_T: "#c62828", nu_v: "#1565c0", nu_0: "#2e7d32" };
  for (const [n, col] of Object.entries(colors)) {
    s += `<polyline fill="none" stroke="${col}" points="${a.map((v, k) => `${lx(v)},${y(c[n][k])}`).join(" ")}"/>`;
    s += `<text x="${L + 8 + 40 * Object.keys(colors).indexOf(n)}" y="${T + 26}" fill="${col}">ν${n.slice(3)}</text>`;
  }
  if (Number.isFinite(alpha) && alpha >= a[0] && alpha <= a[a.length - 1]) s += `<line x1="${lx(alpha)}" x2="${lx(alpha)}" y1="${T}" y2="${H - B}" stroke="#777" stroke-dasharray="4 3"/>`;
  $("nu-chart").innerHTML = s;
}

function ticks(lo, hi, n) {
  // round tick values covering [lo, hi] (1, 2, 5 x 10^k steps)
  const raw = (hi - lo) / n || 1, p = 10 ** Math.floor(Math.log10(raw)), step = [1, 2, 5, 10].map((m) => m * p).find((x) => x >= raw);
  const out = []; for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-12; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return out;
}

async function init() {
  lab.spec = await api("GET", "/api/stands");
  standData("stand-data", lab.spec.yoke.geometry);
  standData("stand-b-data", lab.spec.disc_roller.geometry);
  for (const w of lab.spec.disc_roller.settings.normal_force_N.choices) {
    const o = document.createElement("option"); o.value = w; o.textContent = `${w} N`; $("b_normal_force_N").append(o);
  }
  const ex = await api("GET", "/api/exercises");
  for (const e of ex.exercises) { const o = document.createElement("option"); o.value = e.id; o.textContent = `${e.id}: ${e.title}`; o.dataset.stand = e.stand; $("exercise").append(o); }
  $("open-exercise").disabled = !ex.exercises.length;
  $("open-practice").onclick = () => openSession({ stand: "yoke" });
  $("open-practice-b").onclick = () => openSession({ stand: "disc_roller" });
  $("open-exercise").onclick = openExercise;
  $("apply").onclick = apply; $("apply-b").onclick = apply; $("record").onclick = record; $("set-strobe").onclick = setStrobe;
  $("answer-point").onchange = fillAnswers;
  $("check").onclick = check; $("nu-lookup").onclick = lookupNu;
  $("reset").onclick = () => { if (!lab.session.exercise) openSession({ stand: lab.session.stand }); };  // practice: a fresh stand
  $("nu-copy").onclick = () => { for (const n of ["l_over_a", "c_over_a", "alpha_prime"]) $(`nu-${n}`).value = $(`ans-${n}`).value; }; $("show-reduction").onclick = showReduction; $("save").onclick = save; $("submit").onclick = submit;
  const t = location.hash.match(/teacher=([0-9a-f]+)/);
  if (t) { try { await teacher(t[1]); } catch (error) { $("session-info").textContent = `${error.field}: ${error.message}`; } document.body.dataset.ready = "yes"; return; }
  const m = location.hash.match(/session=([0-9a-f]+)/);
  if (m) {
    try {
      const state = await api("GET", `/api/sessions/${m[1]}`);
      await enter(state);
      if (state.settle_s === null) await settleNow(); else live();
    } catch (error) { $("session-info").textContent = `${error.message}`; }
  }
  setInterval(sync, SYNC_MS);
  document.body.dataset.ready = "yes";
}

init();

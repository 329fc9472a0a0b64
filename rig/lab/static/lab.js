// friction-rig virtual lab: the page only draws what the server (rig.lab.app) sends; every number
// comes from rig.stands and sensors on the server. Plain JS, no library, no other host.
"use strict";

const $ = (id) => document.getElementById(id);
const OUTPUTS = ["i_k", "l_over_a", "c_over_a", "nu_T", "nu_v", "mu_v", "mu_T"];
const lab = { spec: null, session: null, series: null, source: null, drift: null, answers: {}, shownTwin: {}, busy: 0 };
const SYNC_MS = 2000;  // how often the page asks whether another tab changed the session

async function request(method, path, body) {
  const options = { method, headers: { "Content-Type": "application/json" } };
  if (body !== undefined) options.body = JSON.stringify(body);
  const response = await fetch(path, options);
  const data = await response.json();
  if (!response.ok) { const e = new Error(data.error); e.field = data.field; e.status = response.status; throw e; }
  return data;
}

async function api(method, path, body) {
  lab.busy++;  // while this page waits for its own answer, sync() leaves the session alone
  try { return await request(method, path, body); } finally { lab.busy--; }
}

async function sync() {
  // another tab (or window) of the same session changed it: show the new state
  if (!lab.session || lab.busy) return;
  let state;
  try { state = await request("GET", `/api/sessions/${lab.session.id}`); } catch (error) { return; }
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
    lab.answers = {}; lab.shownTwin = {};
    await enter(state);
    lab.session.version = (await api("POST", `/api/sessions/${state.id}/controls`, { strobe_ratio: 1 })).version;
    live();
  } catch (error) { $("exercise-info").textContent = `${error.field || ""}: ${error.message}`; }
}

async function enter(state) {
  lab.session = state;
  $("bench").hidden = false;
  const ex = state.exercise;
  $("session-info").textContent = `session ${state.id}` + (ex ? ` · exercise ${ex.id}: ${ex.title}` : " · practice");
  $("submit").hidden = !ex;
  showSettings(state.settings, state.free);
  $("strobe_ratio").value = state.strobe_ratio;
  $("points").tBodies[0].innerHTML = "";
  $("answer-point").innerHTML = "";
  state.readings.forEach(addReadings);
  if (state.readings.length) showReadings(state.readings[state.readings.length - 1], false);
}

function showSettings(s, free) {
  $("normal_force_N").value = s.normal_force_N;
  $("delta_h_mm").value = +(s.delta_h_m * 1000).toPrecision(6);
  $("brake_setpoint_N_m").value = s.brake_setpoint_N_m;
  $("speed_rpm").value = +(s.omega_1_set_rad_s * 60 / (2 * Math.PI)).toPrecision(6);
  const inputs = { normal_force_N: "normal_force_N", delta_h_m: "delta_h_mm", brake_setpoint_N_m: "brake_setpoint_N_m",
                   omega_1_set_rad_s: "speed_rpm" };
  for (const [name, id] of Object.entries(inputs)) $(id).disabled = !free.includes(name);
  $("sch-force").textContent = `F_N = ${s.normal_force_N} N`;
  $("sch-dh").textContent = `Δh = ${(s.delta_h_m * 1000).toFixed(2)} mm`;
  $("sch-brake").textContent = `T_set = ${s.brake_setpoint_N_m} N m`;
  $("sch-speed").textContent = `n1 = ${(s.omega_1_set_rad_s * 60 / (2 * Math.PI)).toFixed(0)} rpm`;
}

// ------------------------------------------------------------------------------------ controls

async function apply() {
  $("control-error").textContent = "";
  const settings = {};
  const read = (id) => ($(id).value === "" ? NaN : Number($(id).value));
  const wanted = { normal_force_N: read("normal_force_N"), delta_h_m: read("delta_h_mm") / 1000,
                   brake_setpoint_N_m: read("brake_setpoint_N_m"), omega_1_set_rad_s: read("speed_rpm") * 2 * Math.PI / 60 };
  for (const [name, value] of Object.entries(wanted)) {
    if (!lab.session.free.includes(name)) continue;
    if (!Number.isFinite(value)) { showError({ field: `settings.${name}`, message: "enter a number" }); return; }
    if (Math.abs(value - lab.session.settings[name]) > 1e-12 * Math.max(1, Math.abs(value))) settings[name] = value;
  }
  setStatus("settling", "computing…");
  try {
    const answer = await api("POST", `/api/sessions/${lab.session.id}/controls`, { settings });
    lab.session.settings = answer.settings;
    lab.session.version = answer.version;
    showSettings(answer.settings, lab.session.free);
    live();
  } catch (error) { showError(error); setStatus("settled", "settled (unchanged)"); }
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
  lab.series = { t: [], omega_1: [], omega_2: [], brake_moment: [], phases: [] };
  setStatus("settling", "settling…");
  const source = new EventSource(`/api/sessions/${lab.session.id}/live?ratio=${ratio}`);
  lab.source = source;
  source.addEventListener("frame", (event) => {
    const f = JSON.parse(event.data);
    for (const key of ["t", "omega_1", "omega_2", "brake_moment"]) lab.series[key].push(...f[key]);
    const now = f.t[f.t.length - 1];
    if (f.strobe_phase !== null) lab.series.phases.push([now, f.strobe_phase]);
    $("clock").textContent = `t = ${now.toFixed(2)} s`;
    drawSpeeds(f.settle_s);
    drawStrobe(f.strobe_phase);
  });
  source.addEventListener("settled", (event) => {
    const f = JSON.parse(event.data);
    source.close();
    setStatus("settled", `settled after ${f.settle_s.toFixed(2)} s of simulated time`);
    steadyStrobe(ratio, f.strobe_drift_marks_s);
  });
  source.onerror = () => { source.close(); };
}

function drawSpeeds(settle) {
  const c = $("speeds"), g = c.getContext("2d"), s = lab.series;
  g.clearRect(0, 0, c.width, c.height);
  if (!s.t.length) return;
  const tMax = Math.max(s.t[s.t.length - 1], settle + 0.5), wMax = Math.max(...s.omega_1, ...s.omega_2, 1) * 1.1;
  const bAbs = Math.max(...s.brake_moment.map(Math.abs), 0.1) * 1.2;
  const x = (t) => 40 + (t / tMax) * (c.width - 50), yw = (w) => c.height - 20 - (w / wMax) * (c.height - 30);
  const yb = (b) => (c.height - 10) / 2 - (b / bAbs) * (c.height - 30) / 2;
  g.strokeStyle = "#999"; g.strokeRect(40, 10, c.width - 50, c.height - 30);
  g.fillStyle = "#333"; g.font = "11px sans-serif";
  g.fillText(`ω [rad/s], 0..${wMax.toFixed(1)}`, 44, 22); g.fillText(`t [s], 0..${tMax.toFixed(1)}`, c.width - 100, c.height - 6);
  g.setLineDash([4, 3]); g.strokeStyle = "#aaa"; g.beginPath(); g.moveTo(x(settle), 10); g.lineTo(x(settle), c.height - 20); g.stroke(); g.setLineDash([]);
  const line = (ys, map, color) => { g.strokeStyle = color; g.beginPath(); ys.forEach((v, i) => (i ? g.lineTo(x(s.t[i]), map(v)) : g.moveTo(x(s.t[i]), map(v)))); g.stroke(); };
  line(s.omega_1, yw, "#1565c0"); line(s.omega_2, yw, "#c62828"); line(s.brake_moment, yb, "#2e7d32");
  g.fillStyle = "#1565c0"; g.fillText("ω1", 50, 40); g.fillStyle = "#c62828"; g.fillText("ω2", 70, 40);
  g.fillStyle = "#2e7d32"; g.fillText(`brake moment (±${bAbs.toFixed(2)} N m)`, 90, 40);
}

function drawStrobe(phase) {
  const c = $("strobe"), g = c.getContext("2d"), z = lab.spec.marks.wheel_2, r = c.width / 2 - 8;
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
    await countGate(answer.readings);
    addReadings(answer.readings);
    showReadings(answer.readings, true);
  } catch (error) { showError(error); }
  $("record").disabled = false;
}

function countGate(r) {
  // the counters count while the gate is open (gate time / time ratio of real time)
  const ratio = Number($("ratio").value), duration = (1000 * r.gate_time_s) / ratio;
  return new Promise((resolve) => {
    const start = performance.now();
    const tick = (now) => {
      const f = Math.min((now - start) / duration, 1);
      $("counter-1").textContent = Math.floor(f * r.counts.wheel_1);
      $("counter-2").textContent = Math.floor(f * r.counts.wheel_2);
      if (f < 1) requestAnimationFrame(tick); else resolve();
    };
    requestAnimationFrame(tick);
  });
}

// a reading without the binary rounding noise of its decimal steps (0.4018, not 0.40180000000000005)
const tidy = (x) => +x.toPrecision(12);

function showReadings(r, select) {
  $("counter-1").textContent = r.counts.wheel_1;
  $("counter-2").textContent = r.counts.wheel_2;
  $("marks").textContent = `${r.marks.wheel_1}, ${r.marks.wheel_2}`;
  $("dynamometer").textContent = `${r.dynamometer_V.mean.toPrecision(6)} ± ${r.dynamometer_V.std.toPrecision(2)} (${r.dynamometer_V.samples} samples, step ${r.dynamometer_V.resolution.toPrecision(3)})`;
  $("calibration").textContent = `${r.calibration.sensitivity_V_per_N.toPrecision(6)}, ${r.calibration.offset_V.toPrecision(4)}`;
  $("balance").textContent = `${tidy(r.balance_N_m.T2)} (readings ${r.balance_N_m.readings.map(tidy).join(", ")}; step ${r.balance_N_m.resolution.toPrecision(3)})`;
  if (select) $("answer-point").value = r.point;
  document.body.dataset.recorded = lab.session.readings.length;
}

function addReadings(r) {
  if ($(`point-${r.point}`)) return;  // already shown (a sync from another tab came first)
  const s = r.settings, row = $("points").tBodies[0].insertRow();
  row.id = `point-${r.point}`;
  for (const v of [r.point, s.normal_force, (s.delta_h * 1000).toFixed(3), s.brake_setpoint, r.counts.wheel_1,
                   r.counts.wheel_2, r.gate_time_s, r.dynamometer_V.mean.toPrecision(6), tidy(r.balance_N_m.T2)]) row.insertCell().textContent = v;
  const option = document.createElement("option");
  option.value = option.textContent = r.point;
  $("answer-point").append(option);
}

// ------------------------------------------------------------------------------------ sheet

function answersOf() {
  const answers = {};
  for (const name of OUTPUTS) { const v = $(`ans-${name}`).value; if (v !== "") answers[name] = Number(v); }
  return answers;
}

async function check() {
  const point = Number($("answer-point").value), answers = answersOf();
  try {
    const v = await api("POST", `/api/sessions/${lab.session.id}/check`, { point, answers });
    lab.answers[point] = answers;
    lab.shownTwin[point] = true;
    const lines = Object.entries(v.values).map(([name, x]) =>
      `<span class="${x.ok ? "ok" : "wrong"}" id="v-${name}">${name}: ${x.ok ? "✓" : "✗"}</span>`);
    $("verdict").innerHTML = `<p>point ${point}: ${lines.join(" · ")}</p>` + (v.passed
      ? `<p class="ok" id="verdict-text">every value agrees with the reduction within its uncertainty</p>`
      : `<p class="wrong" id="verdict-text">go back to ${v.sent_back_to.text}</p>`);
    $("verdict").dataset.result = v.passed ? "passed" : `back:${v.sent_back_to.step}`;
    drawResults();
  } catch (error) {
    $("verdict").innerHTML = `<p class="wrong" id="verdict-text">${error.field}: ${error.message}</p>`;
    $("verdict").dataset.result = `error:${error.field}`;
  }
}

function showReduction() {
  const rows = lab.session.reduced || [];
  if (lab.session.exercise && !rows.length) { $("verdict").innerHTML = "<p>In an exercise the twin's reduction is shown after you submit.</p>"; return; }
  const t = $("reduction");
  t.tHead.innerHTML = "<tr><th>point</th>" + OUTPUTS.map((n) => `<th>${n}</th><th>U95</th>`).join("") + "<th>note</th></tr>";
  t.tBodies[0].innerHTML = "";
  for (const r of rows) {
    const row = t.tBodies[0].insertRow();
    row.insertCell().textContent = r.point;
    for (const n of OUTPUTS) {
      const cell = row.insertCell(); cell.className = `red-${n}`; cell.textContent = r.values[n] === null ? "—" : String(r.values[n]);
      row.insertCell().textContent = r.values[`U95_${n}`] === null ? "—" : r.values[`U95_${n}`].toPrecision(2);
    }
    row.insertCell().textContent = r.reason;
    lab.shownTwin[r.point] = true;
  }
  t.hidden = false;
  drawResults();
}

function drawResults() {
  const svg = $("results"), rows = (lab.session.reduced || []).filter((r) => lab.shownTwin[r.point]);
  const pts = [];
  for (const r of rows) {
    const v = r.values;
    for (const m of ["mu_v", "mu_T"]) if (v[m] !== null) pts.push({ x: v.l_over_a, y: v[m], u: v[`U95_${m}`], twin: true, m });
    const a = lab.answers[r.point];
    if (a) for (const m of ["mu_v", "mu_T"]) pts.push({ x: a.l_over_a, y: a[m], twin: false, m });
  }
  const W = 460, H = 220, x = (l) => 40 + ((l + 1.2) / 2.4) * (W - 50);
  const yMax = Math.max(0.6, ...pts.map((p) => p.y + (p.u || 0))) * 1.05, y = (m) => H - 25 - (m / yMax) * (H - 35);
  let s = `<rect x="40" y="10" width="${W - 50}" height="${H - 35}" fill="none" stroke="#999"/>`;
  s += `<text x="${W - 60}" y="${H - 8}">l/a</text><text x="4" y="20">μ</text><text x="4" y="${y(0) + 4}">0</text><text x="4" y="${y(yMax / 1.05) + 4}">${(yMax / 1.05).toFixed(2)}</text>`;
  for (const l of [-1, 0, 1]) s += `<text x="${x(l) - 4}" y="${H - 10}">${l}</text>`;
  for (const p of pts) {
    const color = p.m === "mu_v" ? "#1565c0" : "#c62828";
    if (p.twin) s += `<line x1="${x(p.x)}" x2="${x(p.x)}" y1="${y(p.y - p.u)}" y2="${y(p.y + p.u)}" stroke="${color}"/><circle class="twin" cx="${x(p.x)}" cy="${y(p.y)}" r="5" fill="none" stroke="${color}"/>`;
    else s += `<circle class="student" cx="${x(p.x)}" cy="${y(p.y)}" r="3.5" fill="${color}"/>`;
  }
  s += `<text x="50" y="24" fill="#1565c0">μv</text><text x="70" y="24" fill="#c62828">μT</text>`;
  svg.innerHTML = s;
}

async function save() {
  try { const r = await api("POST", `/api/sessions/${lab.session.id}/save`, {}); $("saved").textContent = `saved: ${r.path}`; $("saved").dataset.path = r.path; }
  catch (error) { $("saved").textContent = `${error.field}: ${error.message}`; }
}

async function submit() {
  const answers = Object.entries(lab.answers).map(([point, values]) => ({ point: Number(point), values }));
  try {
    const r = await api("POST", `/api/sessions/${lab.session.id}/submit`, { answers });
    $("submitted").innerHTML = r.results.map((p) => `<p id="graded-${p.point}">point ${p.point}: ${p.passed ? "passed" : "not passed"}; true μ = ${p.truth.mu.toFixed(4)}</p>`).join("");
    lab.session.reduced = (await api("GET", `/api/sessions/${lab.session.id}`)).reduced;  // now released
    showReduction();
    $("submitted").dataset.done = "yes";
  } catch (error) { $("submitted").innerHTML = `<p class="wrong">${error.field}: ${error.message}</p>`; }
}

// ------------------------------------------------------------------------------------ start

async function init() {
  lab.spec = (await api("GET", "/api/stands")).yoke;
  for (const [name, g] of Object.entries(lab.spec.geometry)) {
    const row = $("stand-data").querySelector("tbody").insertRow();
    row.insertCell().textContent = name; row.insertCell().textContent = `${+g.value.toPrecision(6)} ${g.unit}`;
    row.title = g.source;
  }
  const ex = await api("GET", "/api/exercises");
  for (const e of ex.exercises) { const o = document.createElement("option"); o.value = e.id; o.textContent = `${e.id}: ${e.title}`; $("exercise").append(o); }
  $("open-exercise").disabled = !ex.exercises.length;
  $("open-practice").onclick = () => openSession({ stand: "yoke" });
  $("open-exercise").onclick = () => openSession({ stand: "yoke", exercise: $("exercise").value, student: $("student").value });
  $("apply").onclick = apply; $("record").onclick = record; $("set-strobe").onclick = setStrobe;
  $("check").onclick = check; $("show-reduction").onclick = showReduction; $("save").onclick = save; $("submit").onclick = submit;
  const m = location.hash.match(/session=([0-9a-f]+)/);
  if (m) {
    try { await enter(await api("GET", `/api/sessions/${m[1]}`)); live(); }
    catch (error) { $("session-info").textContent = `${error.message}`; }
  }
  setInterval(sync, SYNC_MS);
  document.body.dataset.ready = "yes";
}

init();

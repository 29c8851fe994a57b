// swingsim serve's page: the form and sliders build a leg request (docs/serve.md), the
// server simulates it with the library, and the numbers and stick figure show the answer.
// While a slider is dragged, at most one request is under way: the inputs that come
// meanwhile are coalesced into one request with the newest knobs, and an answer for knobs
// that have moved on is dropped, so the numbers always belong to the knobs shown.
'use strict';

// Labels and units of the editable keys (the file's keys, in the file's units).
const kFieldLabels = {
  'height_m': ['height', 'm'],
  'body_mass_kg': ['body mass', 'kg'],
  'knee_friction_Nm': ['knee friction', 'N m'],
  'sound_limb_swing_time_s': ['sound-limb swing time', 's'],
  'hip_moment.time_scale': ['hip moment time scale', ''],
  'socket.piston_stiffness_N_per_m': ['socket piston stiffness (empty: rigid)', 'N/m'],
  'socket.piston_damping_N_s_per_m': ['socket piston damping (empty: rigid)', 'N s/m'],
  'socket.rotation_stiffness_Nm_per_rad': ['socket rotation stiffness (empty: rigid)', 'N m/rad'],
  'socket.rotation_damping_Nm_s_per_rad': ['socket rotation damping (empty: rigid)', 'N m s/rad'],
  'socket.mass_kg': ['socket mass (empty: rigid)', 'kg'],
};
for (const seg of ['thigh', 'shank', 'foot']) {
  kFieldLabels[`segments.${seg}.length_m`] = [`${seg} length`, 'm'];
  kFieldLabels[`segments.${seg}.mass_kg`] = [`${seg} mass`, 'kg'];
  kFieldLabels[`segments.${seg}.com_from_distal_m`] = [`${seg} COM from distal end`, 'm'];
  kFieldLabels[`segments.${seg}.inertia_kgm2`] = [`${seg} inertia about COM`, 'kg m\u00b2'];
}

const state = {
  participant: null, participantYaml: null, edits: {}, knee: null, kneeYaml: null, yaml: {},
  latest: 0, inputTime: null, inFlight: 0, wanted: false,
};
window.swingsimUpdates = [];  // ms from a knob's input to the numbers shown (the browser test reads it)

const $ = (id) => document.getElementById(id);

function legRequest() {
  const body = {
    lowering_m: Number($('lowering').value),
    added_mass_kg: Number($('mass').value),
    added_mass_position_m: Number($('position').value),
    knee_settings: kneeSettings(),
    edits: state.edits,
  };
  if (state.participantYaml !== null) body.participant_yaml = state.participantYaml;
  else body.participant = state.participant;
  if (state.kneeYaml !== null) body.knee_yaml = state.kneeYaml;
  else if (state.knee) body.knee = state.knee;
  return body;
}

// model_scale, and a microprocessor knee's swing-state damping sliders where it has them.
function kneeSettings() {
  const settings = { 'knee_effects.model_scale': Number($('scale').value) };
  for (const slider of document.querySelectorAll('#knee-states input[type=range]')) settings[slider.name] = Number(slider.value);
  return settings;
}

// A microprocessor knee's swing-state settings, each a slider stepping at its resolution (the
// step a prosthetist can set, as swingsim tune gives its result): the damping (0.1 N m s/rad)
// and stiffness (1 N m/rad), 0 to 4 times the file's value, and the equilibrium angle (1 deg),
// 0 to 120 deg; the shipped tunes move all three.
const kStateKnobs = [
  { key: 'damping_Nm_s_per_rad', label: 'damping', unit: 'N m s/rad', step: 0.1, digits: 1 },
  { key: 'stiffness_Nm_per_rad', label: 'stiffness', unit: 'N m/rad', step: 1, digits: 0 },
  { key: 'equilibrium_deg', label: 'equilibrium', unit: 'deg', step: 1, digits: 0, max: 120 },
];

function buildKneeStates(states) {
  const box = $('knee-states');
  box.textContent = '';
  states.forEach((state, i) => {
    for (const knob of kStateKnobs) {
      if (state[knob.key] === null) continue;
      const key = `impedance_state_machine.states[${i}].${knob.key}`;
      const row = document.createElement('div');
      row.className = 'slider';
      row.innerHTML = '<label></label><input type="range"><output></output>';
      const slider = row.querySelector('input');
      const top = knob.max || Math.max(knob.step * 10, Math.ceil(4 * state[knob.key] / knob.step) * knob.step);
      // A file value off the knob's grid is kept as it is (the swing is the file's); a moved
      // slider then steps at the resolution only once the value is on the grid.
      const onGrid = Math.abs(state[knob.key] / knob.step - Math.round(state[knob.key] / knob.step)) < 1e-9;
      Object.assign(slider, { id: `state-${i}-${knob.label}`, name: key, min: 0, max: top, step: onGrid ? knob.step : 'any',
                              value: state[knob.key] });
      row.querySelector('label').textContent = `${state.name} ${knob.label}`;
      row.querySelector('label').htmlFor = slider.id;
      const output = row.querySelector('output');
      // At the resolution's digits, or (a file's value off the grid) as the file gives it, at most 3 decimals.
      const show = () => {
        const v = Number(slider.value);
        const onStep = Math.abs(v / knob.step - Math.round(v / knob.step)) < 1e-9;
        output.textContent = `${onStep ? v.toFixed(knob.digits) : String(Number(v.toFixed(3)))} ${knob.unit}`;
      };
      slider.addEventListener('input', () => { show(); scheduleSimulate(); });
      slider.addEventListener('show', show);  // a value set by the page (a tuning), not the user
      show();
      const error = document.createElement('p');
      error.className = 'field-error';
      error.dataset.errorFor = key;
      box.append(row, error);
    }
  });
}

async function post(path, body) {
  const response = await fetch(path, {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body),
  });
  return { status: response.status, json: await response.json() };
}

function clearErrors() {
  for (const e of document.querySelectorAll('.field-error')) e.textContent = '';
  for (const f of document.querySelectorAll('.field.invalid')) f.classList.remove('invalid');
}

// An error beside the field its key names, or under the numbers when no field has it.
function showError(json) {
  clearErrors();
  const key = json.key || '';
  const target = document.querySelector(`.field-error[data-error-for="${CSS.escape(key)}"]`);
  if (target) {
    target.textContent = json.message || json.error;
    const field = target.closest('.field');
    if (field) field.classList.add('invalid');
  } else {
    $('run-error').textContent = json.error;
  }
}

function fmt(value, digits, unit) {
  return value === null || value === undefined ? 'none' : `${value.toFixed(digits)} ${unit}`;
}

// A request the server refused: its error beside its field, and no numbers that belong to
// other knobs.
function showNoSwing(json) {
  showError(json);
  for (const id of ['swing-time', 'peak-flexion', 'toe-clearance', 'stop-impact', 'socket-give']) $(id).textContent = '-';
  $('figure').innerHTML = '';
}

function showSwing(json) {
  clearErrors();
  $('swing-time').textContent = json.swing_time_s === null ? 'not reached' : fmt(json.swing_time_s, 4, 's');
  $('peak-flexion').textContent = fmt(json.peak_knee_flexion_deg, 1, 'deg');
  $('toe-clearance').textContent = fmt(json.min_toe_clearance_m, 3, 'm');
  const impact = json.stop_impacts && json.stop_impacts[0];
  $('stop-impact').textContent = impact ?
    `${impact.impact_rate_rad_s.toFixed(2)} rad/s at ${impact.time_s.toFixed(4)} s` : 'none';
  const socket = json.socket_peak;
  $('socket-give').textContent = socket ?
    `${(socket.piston_m * 1000).toFixed(2)} mm, ${socket.rotation_deg.toFixed(2)} deg` : 'rigid';
  $('figure').innerHTML = json.stick_figure_svg || '';
}

// One request for the knobs as they are now. An answer is shown only if it answers the newest
// request and no knob moved while it was under way (then the newest knobs go out at once
// and this answer is dropped): the numbers shown always belong to the knobs shown.
async function simulateNow() {
  clearSweep();
  document.body.dataset.busy = '1';
  const id = ++state.latest;
  const started = state.inputTime;
  state.inputTime = null;  // the next input starts the next measurement
  state.inFlight += 1;
  $('status').textContent = 'simulating...';
  let answer;
  try {
    answer = await post('api/simulate', legRequest());
  } catch (e) {
    $('status').textContent = `no answer: ${e}`;
    return;
  } finally {
    state.inFlight -= 1;
  }
  if (state.wanted) {
    state.wanted = false;
    simulateNow();
    return;
  }
  if (id !== state.latest) return;  // a newer request is under way: this answer is stale
  if (answer.status === 200) showSwing(answer.json); else showNoSwing(answer.json);
  const ms = started === null ? null : performance.now() - started;
  if (ms !== null) window.swingsimUpdates.push(ms);
  $('status').textContent = ms === null ? 'ready' : `updated in ${ms.toFixed(0)} ms`;
  if (state.inFlight === 0) document.body.dataset.busy = '0';
}

// A knob moved: its request goes out at once when none is under way, else when the answer
// comes (the inputs meanwhile become one request, with the newest knobs). body[data-busy] is
// '1' from the input until the answer for the knobs shown is on the page.
function scheduleSimulate() {
  document.body.dataset.busy = '1';
  if (state.inputTime === null) state.inputTime = performance.now();
  if (state.inFlight > 0) {
    state.wanted = true;
    return;
  }
  simulateNow();
}

function buildForm(fields) {
  const form = $('fields');
  form.textContent = '';
  for (const [key, value] of Object.entries(fields)) {
    const [label, unit] = kFieldLabels[key] || [key, ''];
    const row = document.createElement('div');
    row.className = 'field';
    row.innerHTML = `<label></label><span><input type="text" inputmode="decimal"><span class="unit"></span></span>`;
    const input = row.querySelector('input');
    row.querySelector('label').textContent = label;
    row.querySelector('.unit').textContent = unit;
    input.name = key;
    input.id = `field-${key}`;
    row.querySelector('label').htmlFor = input.id;
    // Six significant digits on the page (an imported model's 0.438772163... reads 0.438772); the
    // exact value stays the file's and is sent only once the field is edited.
    input.value = value === null ? '' : typeof value === 'number' ? String(Number(value.toPrecision(6))) : String(value);
    if (typeof value === 'number') input.title = `in the file: ${value}`;
    input.addEventListener('change', () => {
      if (input.value.trim() === '') delete state.edits[key]; else state.edits[key] = input.value.trim();
      state.inputTime = performance.now();
      simulateNow();
    });
    const error = document.createElement('p');
    error.className = 'field-error';
    error.dataset.errorFor = key;
    row.append(error);
    form.append(row);
  }
}

// The knee's own settings on its sliders (model_scale, the states' damping), their steps as
// built (a tuning sets 'any'), and the tuning's knob list; no result of another leg or knee stays.
function showKneeSettings(json) {
  const scale = json.knee_settings['knee_effects.model_scale'];
  $('scale').max = Math.max(3, Math.ceil(scale));
  $('scale').min = Math.min(0.2, scale);
  $('scale').step = 0.05;
  $('scale').value = scale;
  $('scale').dispatchEvent(new Event('show'));
  for (const [id, step] of [['lowering', 0.005], ['mass', 0.05], ['position', 0.01]]) $(id).step = step;
  buildKneeStates(json.knee_states);
  buildTuneKnobs();
  for (const id of ['sweep-summary', 'sweep-figure', 'tune-summary']) $(id).textContent = '';
}

// Loads the participant (shipped or uploaded): its form, its knee, then one swing.
async function loadParticipant() {
  const body = legRequest();
  delete body.knee;
  body.edits = {};
  body.knee_settings = {};
  const answer = await post('api/participant', body);
  if (answer.status !== 200) { showError(answer.json); return; }
  state.edits = {};
  state.knee = null;
  state.yaml = { participant: answer.json.participant_yaml, knee: answer.json.knee_yaml, name: answer.json.name };
  buildForm(answer.json.fields);
  showKneeSettings(answer.json);
  $('knee').value = state.kneeYaml === null ? answer.json.knee_model : '';
  $('lowering').max = Math.min(0.2, Math.floor(answer.json.max_lowering_m * 200) / 200);
  simulateNow();
}

// A knee chosen from the list (or uploaded: it then stays for the participants loaded after
// it, so a participant whose knee_model is that file can be uploaded next): its swing-state
// sliders, then one swing.
async function loadKnee() {
  state.knee = $('knee').value;
  state.kneeYaml = null;
  $('knee-upload').value = '';
  $('knee-states').textContent = '';  // the old knee's states do not belong to this one
  await describeKnee(showNoSwing);
}

// A knee model file: kept (and sent with every request) only once the server has read it;
// a refused one leaves the knee as it was.
async function uploadKnee() {
  const file = $('knee-upload').files[0];
  if (!file) return;
  const before = { kneeYaml: state.kneeYaml, knee: state.knee };
  state.kneeYaml = await file.text();
  state.knee = null;
  if (await describeKnee(showError)) return;
  Object.assign(state, before);  // the knee shown stays, with its sliders
  $('knee-upload').value = '';
}

// The current knee's sliders from the server, then one swing; false if refused (`showRefusal`
// shows why).
async function describeKnee(showRefusal) {
  const body = { ...legRequest(), knee_settings: {} };  // the new knee's own settings
  const answer = await post('api/participant', body);
  if (answer.status !== 200) { showRefusal(answer.json); return false; }
  showKneeSettings(answer.json);
  state.inputTime = performance.now();
  simulateNow();
  return true;
}

function download(name, text, type = 'application/yaml') {
  const link = document.createElement('a');
  link.href = URL.createObjectURL(new Blob([text], { type }));
  link.download = name;
  link.click();
  URL.revokeObjectURL(link.href);
}

async function exportYaml(which) {
  const answer = await post('api/participant', legRequest());
  if (answer.status !== 200) { showError(answer.json); return; }
  if (which === 'participant') download(`${answer.json.name}.yaml`, answer.json.participant_yaml);
  else download(`${answer.json.knee_model}.yaml`, answer.json.knee_yaml);
}

// The leg changed (every change asks for a new swing): a sweep shown belongs to the leg
// before, so it is cleared, never left beside the new leg.
function clearSweep() {
  if ($('sweep-summary').textContent === '') return;
  $('sweep-summary').textContent = 'the leg changed: run the sweep again';
  $('sweep-figure').innerHTML = '';
}

async function runSweep() {
  $('sweep-summary').textContent = 'sweeping...';
  const asked = JSON.stringify(legRequest());
  const answer = await post('api/sweep', legRequest());
  if (JSON.stringify(legRequest()) !== asked) {  // the leg moved meanwhile: this answer is for another leg
    $('sweep-summary').textContent = 'the leg changed while sweeping; run the sweep again';
    return;
  }
  if (answer.status !== 200) { $('sweep-summary').textContent = ''; showError(answer.json); return; }
  const s = answer.json;
  let text = s.fastest_lowering_m === null ? 'no lowering ended a swing' :
    `fastest swing ${s.fastest_swing_time_s.toFixed(4)} s at ${(s.fastest_lowering_m * 1000).toFixed(0)} mm`;
  if (s.symmetry) text += `; ${s.symmetry.text}`;
  // A jump of the swing time (a rebound past the zone of stability): no answer is read across it.
  for (const j of s.jumps) text += `; jump: ${j.text}`;
  if (s.added_mass_kg > 0) text += ` (with the added ${s.added_mass_kg.toFixed(2)} kg at ${s.added_mass_position_m.toFixed(2)} m below the knee)`;
  $('sweep-summary').textContent = text;
  $('sweep-figure').innerHTML = s.figure_svg;
}

// An OpenSim model made a participant by import-osim's sequence; the page then holds it as an upload.
async function importOsim() {
  const file = $('osim-upload').files[0];
  if (!file) return;
  $('export-status').textContent = `importing ${file.name}...`;
  // The prosthesis's masses, as import-osim's --shank-mass-kg and --foot-mass-kg (empty: the model's).
  const mass = (id) => ($(id).value === '' ? undefined : Number($(id).value));
  const answer = await post('api/import_osim', {
    osim_text: await file.text(), file_name: file.name, side: $('osim-side').value, knee: $('knee').value || undefined,
    shank_mass_kg: mass('osim-shank-mass'), foot_mass_kg: mass('osim-foot-mass'),
  });
  $('export-status').textContent = '';
  if (answer.status !== 200) { showError(answer.json); return; }
  state.participantYaml = answer.json.participant_yaml;
  $('upload').value = '';
  await loadParticipant();
  $('export-status').textContent = `imported ${answer.json.name} from ${file.name}: its hip moment is the project's default, an assumption`;
}

async function exportOsim() {
  const answer = await post('api/export_osim', { ...legRequest(), side: $('osim-side').value });
  if (answer.status !== 200) { showError(answer.json); return; }
  download(answer.json.osim_file_name, answer.json.osim_text, 'application/xml');
  download(answer.json.sto_file_name, answer.json.sto_text, 'text/plain');
  $('export-status').textContent = `${answer.json.osim_file_name} and ${answer.json.sto_file_name}: in OpenSim, File > Open Model, then File > Load Motion`;
}

async function exportReport() {
  $('export-status').textContent = 'sweeping for the report...';
  const answer = await post('api/report', legRequest());
  if (answer.status !== 200) { $('export-status').textContent = ''; showError(answer.json); return; }
  download(answer.json.file_name, answer.json.html, 'text/html');
  $('export-status').textContent = `${answer.json.file_name}: the sweep of this leg (and of it with the added mass, if any)`;
}

// The knobs the tuning may move: the sliders of the lowering, model_scale and the states' damping.
function tunableSliders() {
  return [$('lowering'), $('scale'), ...document.querySelectorAll('#knee-states input[type=range]'), $('mass'), $('position')];
}
const kTuneKeys = {
  lowering: 'lowering_m', scale: 'knee_effects.model_scale', mass: 'added_mass_kg', position: 'added_mass_below_knee_m',
};

function buildTuneKnobs() {
  const box = $('tune-knobs');
  box.textContent = '';
  for (const slider of tunableSliders()) {
    const row = document.createElement('label');
    row.className = 'tune-knob';
    row.innerHTML = '<input type="checkbox"> <span></span>';
    row.querySelector('input').value = slider.id;
    row.querySelector('input').checked = slider.id === 'lowering' || slider.id === 'scale';
    row.querySelector('span').textContent = document.querySelector(`label[for="${slider.id}"]`).textContent;
    box.append(row);
  }
}

// The tuning's targets by gait (assumptions, said on the page): peak knee flexion window (deg)
// and the least toe clearance (m).
const kTuneDefaults = {
  running: { flexion: [60, 90], clearance: 0.08 },  // studies/tune-p1-damping.yaml
  walking: { flexion: [55, 70], clearance: 0.01 },  // Winter's natural cadence peaks at 67 deg
};

function setTuneDefaults() {
  const d = kTuneDefaults[$('tune-gait').value];
  $('tune-flexion-min').value = d.flexion[0];
  $('tune-flexion-max').value = d.flexion[1];
  $('tune-clearance').value = d.clearance;
}

// The targets as the form holds them; an empty swing time is the sound limb's.
function tuneTargets() {
  const targets = {
    peak_knee_flexion_deg: [Number($('tune-flexion-min').value), Number($('tune-flexion-max').value)],
    min_toe_clearance_m: Number($('tune-clearance').value),
  };
  if ($('tune-time').value !== '') targets.swing_time_s = Number($('tune-time').value);
  return targets;
}

async function runTune() {
  const knobs = [];
  for (const box of document.querySelectorAll('#tune-knobs input:checked')) {
    const slider = $(box.value);
    const key = kTuneKeys[slider.id] || slider.name;
    knobs.push({ key, min: Number(slider.min), max: Number(slider.max), log_scale: key === 'knee_effects.model_scale' });
  }
  $('tune-summary').textContent = 'tuning...';
  $('tune-button').disabled = true;
  const asked = JSON.stringify(legRequest());
  let answer;
  try {
    answer = await post('api/tune', { ...legRequest(), knobs, targets: tuneTargets() });
  } finally {
    $('tune-button').disabled = false;
  }
  if (JSON.stringify(legRequest()) !== asked) {  // the leg or a knob moved meanwhile: this answer is for another leg
    $('tune-summary').textContent = 'the leg changed while tuning; tune again';
    return;
  }
  if (answer.status !== 200) { $('tune-summary').textContent = ''; showError(answer.json); return; }
  const t = answer.json;
  const value = (k) => (k.key === 'lowering_m' ? `${(k.value * 1000).toFixed(1)} mm` : `${Number(k.value.toPrecision(4))}`);
  const parts = t.knobs.map((k) => `${k.key} ${value(k)}${k.at_range_end ? ' (at a range end)' : ''}`);
  const time = t.targets.find((x) => x.quantity === 'swing_time_s');
  const unmet = t.targets.filter((x) => !x.met).map((x) => x.quantity);
  const flexion = t.targets.find((x) => x.quantity === 'peak_knee_flexion_deg');
  const clearance = t.targets.find((x) => x.quantity === 'min_toe_clearance_m');
  const targetsText = `targets: swing ${time.min.toFixed(3)} s, peak flexion ${flexion.min.toFixed(0)}-${flexion.max.toFixed(0)} deg, ` +
    `toe clearance at least ${clearance.min.toFixed(3)} m`;
  $('tune-summary').textContent = `${t.feasible ? '' : 'NO SETTING MEETS THE LIMITS; closest: '}${parts.join(', ')}: swing ` +
    `${time.value.toFixed(4)} s${unmet.length ? `; not met: ${unmet.join(', ')}` : '; every target met'} ` +
    `(${t.evaluations} swings, ${t.seconds.toFixed(1)} s${t.interrupted ? ', stopped at the server\'s time budget: the best so far' : ''}). ` +
    `${targetsText}. ${t.resolution ? t.resolution : ''} ${t.identifiable ? '' : t.identifiability}`;
  for (const k of t.knobs) {
    const slider = tunableSliders().find((s) => (kTuneKeys[s.id] || s.name) === k.key);
    if (!slider) continue;
    slider.step = 'any';  // the tuned value itself (on the knob's grid: swingsim tune's resolution)
    slider.value = k.value;
    slider.dispatchEvent(new Event('input'));
  }
}

function bindSlider(id, digits, unit) {
  const slider = $(id);
  const show = () => { $(`${id}-value`).textContent = `${Number(slider.value).toFixed(digits)}${unit}`; };
  slider.addEventListener('input', () => { show(); scheduleSimulate(); });
  slider.addEventListener('show', show);  // a value set by the page, not the user: shown, no request
  show();
}

async function start() {
  const files = await (await fetch('api/files')).json();
  for (const [select, names] of [[$('participant'), files.participants], [$('knee'), files.knee_models]])
    for (const name of names) select.append(new Option(name, name));
  state.participant = files.participants.includes('p1') ? 'p1' : files.participants[0];
  $('participant').value = state.participant;
  $('participant').addEventListener('change', () => {
    state.participant = $('participant').value;
    state.participantYaml = null;
    $('upload').value = '';
    loadParticipant();
  });
  $('upload').addEventListener('change', async () => {
    const file = $('upload').files[0];
    if (!file) return;
    state.participantYaml = await file.text();
    loadParticipant();
  });
  $('knee').addEventListener('change', loadKnee);
  $('knee-upload').addEventListener('change', uploadKnee);
  bindSlider('lowering', 3, ' m');
  bindSlider('mass', 2, ' kg');
  bindSlider('position', 2, ' m');
  bindSlider('scale', 2, '');
  $('export-participant').addEventListener('click', () => exportYaml('participant'));
  $('export-knee').addEventListener('click', () => exportYaml('knee'));
  $('sweep-button').addEventListener('click', runSweep);
  $('osim-upload').addEventListener('change', importOsim);
  $('export-osim').addEventListener('click', exportOsim);
  $('export-report').addEventListener('click', exportReport);
  $('tune-button').addEventListener('click', runTune);
  $('tune-gait').addEventListener('change', setTuneDefaults);
  await loadParticipant();
}

start();

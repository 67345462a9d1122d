// Runs the book's JavaScript crossing models (book/_static/vbi-explorers/vbi-model.js) on the
// explorer settings of a JSON file and writes what they compute, for tests/widgets/test_js_port.py
// to compare with vbi_lib.
//
//   node port_check.js CASES.json OUT_DIR
//
// CASES.json: {"cases": [{control values of vbi_lib.widgets.Scenario}, ...]}.  OUT_DIR gets
// results.json (one entry per case: the SI setting's numbers, the results' scalars and where
// each history lies in arrays.f64) and arrays.f64 (every history, float64, little-endian).
"use strict";

const fs = require("fs");
const path = require("path");

const model = require(path.join(__dirname, "..", "..", "..", "book", "_static", "vbi-explorers", "vbi-model.js"));

const [casesFile, outDir] = process.argv.slice(2);
const cases = JSON.parse(fs.readFileSync(casesFile, "utf8")).cases;
const chunks = [];
let offset = 0;

function store(values) {
  const array = Float64Array.from(values);
  chunks.push(Buffer.from(array.buffer));
  const where = [offset, array.length];
  offset += array.length;
  return where;
}

const results = cases.map((values) => {
  try {
    const started = process.hrtime.bigint();
    const { setting, notes } = model.scenarioSetting(values);
    const built = process.hrtime.bigint();
    const run = model.simulate(setting);
    const finished = process.hrtime.bigint();
    const out = {
      setting: {
        spans: setting.bridge.spans,
        EI: setting.bridge.EI,
        mass_per_length: setting.bridge.mass_per_length,
        damping_ratio: setting.bridge.damping_ratio,
        mass: setting.vehicle.mass,
        stiffness: setting.vehicle.stiffness,
        damping: setting.vehicle.damping,
        speed: setting.speed,
        bridge_start: setting.bridge_start,
        model: setting.model,
        modes: setting.modes,
        coupled: setting.coupled,
      },
      road_x: store(setting.road.x),
      road_elevation: store(setting.road.elevation),
      position: store(run.position),
      contact_force: store(run.contact_force),
      vehicle_displacement: store(run.vehicle_displacement),
      midspan: run.midspan_displacement.map(store),
      series_midspan: run.series ? run.series.midspan.map(store) : null,
      dt: run.dt,
      default_dt: run.default_dt,
      nodes: run.nodes,
      peak: run.peak,
      static: run.static_deflection,
      daf: run.daf,
      series: run.series ? { peak: run.series.peak, static: run.series.static, daf: run.series.daf } : null,
      omega: run.modes,
      contact_force_amplification: run.contact_force_amplification,
      peak_contact_position: run.peak_contact_position,
      min_contact_force_ratio: run.min_contact_force_ratio,
      tension_fraction: run.tension_fraction,
      lost_contact: run.lost_contact,
      notes: [...notes, ...run.notes],
      road_ms: Number(built - started) / 1e6,
      run_ms: Number(finished - built) / 1e6,
    };
    return out;
  } catch (error) {
    return { error: String(error && error.message ? error.message : error) };
  }
});

// the ports of numpy's random phases and of scipy's FFT length, probed directly
const probes = JSON.parse(fs.readFileSync(casesFile, "utf8")).probes || {};
const reportCases = JSON.parse(fs.readFileSync(casesFile, "utf8")).report_cases || [];
const reports = reportCases.map(([values, speeds, name]) => {
  try {
    const files = model.reportParameters(values, speeds, name);
    return { files: files.map((f) => ({ name: f.name, text: f.text })), note: files.note };
  } catch (error) {
    return { error: String(error.message) };
  }
});
const probed = {
  uniform: (probes.uniform || []).map(([seed, count]) => Array.from(model.uniform(seed, 0.0, 2.0 * Math.PI, count))),
  next_fast_len: (probes.next_fast_len || []).map((n) => model.nextFastLen(n)),
};

fs.mkdirSync(outDir, { recursive: true });
fs.writeFileSync(path.join(outDir, "arrays.f64"), Buffer.concat(chunks));
fs.writeFileSync(path.join(outDir, "results.json"), JSON.stringify({ results, probed, reports, ranges: model.RANGES,
  units: model.UNITS, iso_class_means: model.ISO_CLASS_MEANS, iso_band: model.ISO_BAND,
  max_road_shift_ft: model.MAX_ROAD_SHIFT_FT, road_spacing: model.ROAD_SPACING, report: model.REPORT }, (key, value) =>
  (typeof value === "number" && !Number.isFinite(value) ? String(value) : value)));

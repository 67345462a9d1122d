/* vbi-explorers.js: the static book's explorers, computed in the reader's browser (issue 25).
 *
 * Each root element [data-vbi-explorer] (written by vbi_lib.widgets.page) carries the JSON
 * specification of its controls; this file builds them as plain HTML inputs, runs the port of
 * the crossing models (vbi-model.js) and draws with uPlot.  The contract, for tests and users:
 *
 * - every control is an <input> whose name is the parameter it sets (speed, span, ...): a
 *   slider and a box to type in (percent controls take percent), or radio buttons;
 * - the DAF readout is [data-vbi-readout=daf] (its data-value holds the DAFs in full);
 * - window.vbiExplorers[i].settings() returns the setting of the readout's crossing in SI,
 *   {bridge: {spans, EI, mass_per_length, damping_ratio}, vehicle: {mass, stiffness, damping},
 *   speed, bridge_start, model, modes, coupled, road: {x, elevation}}, which vbi.simulate
 *   runs to the same DAF;
 * - the URL's hash holds every control that differs from its start value, so a setting can
 *   be shared as a link; a bad value (typed or in a link) is refused with a message and the
 *   display stays that of the controls;
 * - each redraw dispatches a "vbi-drawn" event on the root with the time it took.
 */
(function () {
  "use strict";
  const M = window.vbiModel;
  const U = M.UNITS;
  const registry = (window.vbiExplorers = window.vbiExplorers || []);
  let uid = 0;

  // ------------------------------------------------------------------------------ helpers
  function el(tag, attrs, ...children) {
    const node = document.createElement(tag);
    for (const [key, value] of Object.entries(attrs || {})) {
      if (value === null || value === undefined || value === false) continue;
      if (key === "class") node.className = value;
      else if (key === "text") node.textContent = value;
      else node.setAttribute(key, value === true ? "" : value);
    }
    for (const child of children) if (child !== null && child !== undefined) node.append(child);
    return node;
  }

  /** A number as a control shows it: at most 6 significant digits, no trailing zeros. */
  function shown(value) {
    if (!Number.isFinite(value)) return String(value);
    return String(Number(value.toPrecision(6)));
  }

  function fixed(value, digits) {
    return Number.isFinite(value) ? value.toFixed(digits) : "NaN";
  }

  function unitText(unit) {
    return unit ? (unit === "%" ? " %" : " " + unit) : "";
  }

  const NUMBER = /^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$/;

  function percentOf(fraction) {
    return `${Math.round(fraction * 100)}%`;
  }

  // ------------------------------------------------------------------------------ controls
  /** A number: a slider and a box to type in, both named after the parameter. */
  class NumberControl {
    constructor(spec, explorer) {
      this.spec = spec;
      this.explorer = explorer;
      this.name = spec.name;
      this.value = spec.value;
      const id = `vbi-${++uid}-${spec.name}`;
      const helpId = `${id}-help`;
      const label = spec.label + (spec.unit ? ` [${spec.unit}]` : "");
      this.slider = el("input", {
        type: "range", name: spec.name, id, min: spec.min, max: spec.max, step: spec.step,
        value: spec.value, "aria-describedby": helpId, title: spec.help,
      });
      this.box = el("input", {
        type: "text", name: spec.name, class: "vbi-typed", inputmode: "decimal", size: 7,
        value: shown(spec.value), "aria-label": `${label}, typed`, title: spec.help,
      });
      this.element = el("div", { class: "vbi-control", "data-control": spec.name },
        el("label", { for: id, title: spec.help, text: label }),
        this.slider, this.box,
        el("span", { class: "vbi-help", id: helpId, text: spec.help }));
      this.slider.addEventListener("input", () => {
        this.value = Number(this.slider.value);
        this.box.value = shown(this.value);
        explorer.changed(this);
      });
      this.box.addEventListener("change", () => this.typed(this.box.value));
      this.box.addEventListener("keydown", (event) => {
        if (event.key === "Enter") {
          event.preventDefault();
          this.typed(this.box.value);
        }
      });
    }

    /** Read a typed (or linked) value; refuse it with a sentence, keeping the last value. */
    typed(text) {
      const spec = this.spec;
      const raw = String(text).trim();
      const keeps = `the explorer keeps ${shown(this.value)}${unitText(spec.unit)}`;
      let problem = null;
      let value = NaN;
      if (!NUMBER.test(raw)) problem = `${spec.name}=${JSON.stringify(raw)} is not a number; ${keeps}`;
      else {
        value = Number(raw);
        const range = `${shown(spec.min)} to ${shown(spec.max)}${unitText(spec.unit)}`;
        if (!Number.isFinite(value)) problem = `${spec.name}=${raw} is not a finite number; ${keeps}`;
        else if (spec.kind === "integer" && !Number.isInteger(value)) {
          problem = `${spec.name}=${raw} must be a whole number from ${range}; ${keeps}`;
        } else if (value < spec.min || value > spec.max) {
          problem = `${spec.name}=${raw}${unitText(spec.unit)} is outside ${range}; ${keeps}`;
        }
      }
      if (problem) {
        this.box.value = shown(this.value);
        this.explorer.refused(problem);
        return false;
      }
      this.set(value);
      this.explorer.changed(this);
      return true;
    }

    set(value) {
      this.value = value;
      this.slider.value = value;
      this.box.value = shown(value);
    }

    /** The value in the library's units (a fraction for a percent control). */
    libraryValue() {
      return this.value / (this.spec.scale || 1);
    }

    show(visible) {
      this.element.hidden = !visible;
    }
  }

  /** A choice: radio buttons named after the parameter. */
  class ChoiceControl {
    constructor(spec, explorer) {
      this.spec = spec;
      this.explorer = explorer;
      this.name = spec.name;
      this.value = spec.value;
      this.inputs = [];
      const legend = el("legend", { text: spec.label, title: spec.help });
      this.element = el("fieldset", { class: "vbi-control vbi-choice", "data-control": spec.name,
        title: spec.help }, legend);
      const options = el("span", { class: "vbi-options" });
      this.element.append(options);
      spec.options.forEach(([value, label], i) => {
        const input = el("input", { type: "radio", name: spec.name, value: String(value),
          checked: value === spec.value, "data-index": i });
        input.addEventListener("change", () => {
          if (!input.checked) return;
          this.value = spec.options[i][0];
          explorer.changed(this);
        });
        this.inputs.push(input);
        options.append(el("label", { class: "vbi-option" }, input, " " + label));
      });
      this.element.append(el("span", { class: "vbi-help", text: spec.help }));
    }

    typed(text) {
      const found = this.spec.options.find(([value]) => String(value) === String(text).trim());
      if (!found) {
        const offered = this.spec.options.map(([value]) => String(value)).join(", ");
        this.explorer.refused(`${this.name}=${JSON.stringify(String(text))} is not offered; use ` +
          `one of ${offered}; the explorer keeps ${this.value}`);
        return false;
      }
      this.set(found[0]);
      this.explorer.changed(this);
      return true;
    }

    set(value) {
      this.value = value;
      this.inputs.forEach((input, i) => { input.checked = this.spec.options[i][0] === value; });
    }

    libraryValue() {
      return this.value;
    }

    show(visible) {
      this.element.hidden = !visible;
    }
  }

  // ------------------------------------------------------------------------------ plots
  /** A uPlot line chart that follows its container's width. */
  class LinePlot {
    constructor(container, options) {
      this.container = container;
      this.options = options;
      this.plot = null;
      this.key = null;
      this.observer = new ResizeObserver(() => {
        if (this.plot) this.plot.setSize({ width: this.width(), height: options.height });
      });
      this.observer.observe(container);
    }

    width() {
      return Math.max(280, this.container.clientWidth || 600);
    }

    /** data: [x, y1, y2, ...]; series: [{label, stroke, dash, points}], as uPlot's. */
    draw(data, series, extra) {
      const key = JSON.stringify(series.map((s) => s.label)) + (extra && extra.key ? extra.key : "");
      this.extra = extra || {};
      if (!this.plot || key !== this.key) {
        if (this.plot) this.plot.destroy();
        const self = this;
        this.plot = new window.uPlot({
          width: this.width(),
          height: this.options.height,
          legend: { show: true, live: false },
          cursor: { show: true, drag: { x: false, y: false } },
          scales: { x: { time: false } },
          axes: [
            { label: this.options.xLabel, size: 40 },
            { label: this.options.yLabel, size: 56 },
          ],
          series: [{ label: this.options.xLabel }, ...series],
          hooks: { drawClear: [(u) => self.shade(u)], draw: [(u) => self.marks(u)] },
        }, data, this.container);
        this.key = key;
      } else this.plot.setData(data);
    }

    /** The bridge's extent, lightly shaded, behind the curves. */
    shade(u) {
      const band = this.extra.band;
      if (!band) return;
      const ctx = u.ctx;
      const left = u.valToPos(band[0], "x", true);
      const right = u.valToPos(band[1], "x", true);
      ctx.save();
      ctx.fillStyle = "rgba(120, 120, 120, 0.10)";
      ctx.fillRect(left, u.bbox.top, right - left, u.bbox.height);
      ctx.restore();
    }

    /** A vertical line at the readout's crossing (the sweeps). */
    marks(u) {
      const at = this.extra.mark;
      if (at === undefined || at === null || !(at >= u.scales.x.min && at <= u.scales.x.max)) return;
      const x = u.valToPos(at, "x", true);
      const ctx = u.ctx;
      ctx.save();
      ctx.strokeStyle = "rgba(0, 0, 0, 0.55)";
      ctx.setLineDash([4, 3]);
      ctx.beginPath();
      ctx.moveTo(x, u.bbox.top);
      ctx.lineTo(x, u.bbox.top + u.bbox.height);
      ctx.stroke();
      ctx.restore();
    }
  }

  // viridis, 9 stops (matplotlib's), interpolated
  const VIRIDIS = [[68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141],
    [39, 173, 129], [92, 200, 99], [170, 220, 50], [253, 231, 37]];

  function viridis(t) {
    const x = Math.min(Math.max(t, 0), 1) * (VIRIDIS.length - 1);
    const i = Math.min(Math.floor(x), VIRIDIS.length - 2);
    const f = x - i;
    const c = VIRIDIS[i].map((a, k) => Math.round(a + f * (VIRIDIS[i + 1][k] - a)));
    return `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
  }

  /** The frequency map: cells coloured by DAF, crosses where contact was lost. */
  class HeatMap {
    constructor(container) {
      this.container = container;
      this.canvas = el("canvas", { class: "vbi-heatmap", role: "img",
        "aria-label": "DAF over the frequency ratio and the speed" });
      container.append(this.canvas);
      this.observer = new ResizeObserver(() => this.last && this.draw(...this.last));
      this.observer.observe(container);
    }

    draw(map, mark) {
      this.last = [map, mark];
      const width = Math.max(300, this.container.clientWidth || 600);
      const height = 340;
      const ratio = window.devicePixelRatio || 1;
      this.canvas.width = width * ratio;
      this.canvas.height = height * ratio;
      this.canvas.style.width = `${width}px`;
      this.canvas.style.height = `${height}px`;
      const ctx = this.canvas.getContext("2d");
      ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
      ctx.clearRect(0, 0, width, height);
      const box = { left: 62, top: 12, right: width - 90, bottom: height - 46 };
      const nr = map.ratio.length;
      const ns = map.speed.length;
      const values = map.daf.flat().filter((v) => v !== null && Number.isFinite(v));
      const lo = values.length ? Math.min(...values) : 1;
      const hi = values.length ? Math.max(...values, lo + 1e-6) : 2;
      const cw = (box.right - box.left) / nr;
      const ch = (box.bottom - box.top) / ns;
      for (let i = 0; i < ns; i++) {
        for (let j = 0; j < nr; j++) {
          const v = map.daf[i][j];
          const x = box.left + j * cw;
          const y = box.bottom - (i + 1) * ch;
          ctx.fillStyle = v === null || v === undefined || !Number.isFinite(v) ? "#ddd" : viridis((v - lo) / (hi - lo));
          ctx.fillRect(x, y, Math.ceil(cw), Math.ceil(ch));
          if (map.lost && map.lost[i] && map.lost[i][j]) {
            ctx.strokeStyle = "#fff";
            ctx.lineWidth = 1.5;
            ctx.beginPath();
            ctx.moveTo(x + cw * 0.3, y + ch * 0.3);
            ctx.lineTo(x + cw * 0.7, y + ch * 0.7);
            ctx.moveTo(x + cw * 0.7, y + ch * 0.3);
            ctx.lineTo(x + cw * 0.3, y + ch * 0.7);
            ctx.stroke();
          }
        }
      }
      // axes: ratio along x, speed (mph) up
      ctx.fillStyle = "#222";
      ctx.font = "12px sans-serif";
      ctx.textAlign = "center";
      const rStep = Math.max(1, Math.round(nr / 7));
      for (let j = 0; j < nr; j += rStep) ctx.fillText(map.ratio[j].toFixed(2), box.left + (j + 0.5) * cw, box.bottom + 16);
      ctx.fillText("truck frequency / bridge first frequency [-]", (box.left + box.right) / 2, height - 8);
      ctx.textAlign = "right";
      const sStep = Math.max(1, Math.round(ns / 8));
      for (let i = 0; i < ns; i += sStep) ctx.fillText((map.speed[i] / U.mph).toFixed(0), box.left - 6, box.bottom - (i + 0.5) * ch + 4);
      ctx.save();
      ctx.translate(16, (box.top + box.bottom) / 2);
      ctx.rotate(-Math.PI / 2);
      ctx.textAlign = "center";
      ctx.fillText("speed [mph]", 0, 0);
      ctx.restore();
      // colour bar
      const bx = box.right + 18;
      for (let k = 0; k < 100; k++) {
        ctx.fillStyle = viridis(k / 99);
        ctx.fillRect(bx, box.bottom - ((k + 1) * (box.bottom - box.top)) / 100, 14, (box.bottom - box.top) / 100 + 1);
      }
      ctx.fillStyle = "#222";
      ctx.textAlign = "left";
      ctx.fillText(fixed(hi, 2), bx + 18, box.top + 10);
      ctx.fillText(fixed(lo, 2), bx + 18, box.bottom);
      ctx.fillText("DAF", bx + 18, (box.top + box.bottom) / 2);
      // the readout's cell
      if (mark) {
        const fx = (mark.ratio - map.ratio[0]) / ((map.ratio[nr - 1] - map.ratio[0]) || 1);
        const fy = (mark.speed - map.speed[0]) / ((map.speed[ns - 1] - map.speed[0]) || 1);
        const x = box.left + (0.5 + fx * (nr - 1)) * cw;
        const y = box.bottom - (0.5 + fy * (ns - 1)) * ch;
        if (fx >= -0.5 / nr && fx <= 1 + 0.5 / nr && fy >= -0.5 / ns && fy <= 1 + 0.5 / ns) {
          ctx.strokeStyle = "#e8175d";
          ctx.lineWidth = 2;
          ctx.beginPath();
          ctx.arc(x, y, 7, 0, 2 * Math.PI);
          ctx.stroke();
        }
      }
    }
  }

  // ------------------------------------------------------------------------------ words
  function dafText(dafs) {
    const values = dafs.filter((d) => Number.isFinite(d));
    if (!values.length) return "no DAF (no span was pushed down during the crossing)";
    if (dafs.length === 1) return `DAF ${values[0].toFixed(3)}`;
    return "DAF " + dafs.map((d, j) => (Number.isFinite(d) ? `${d.toFixed(3)} (span ${j + 1})` : null))
      .filter(Boolean).join(", ");
  }

  function contactWords(run) {
    if (run.min_contact_force_ratio < 0) {
      return ["vbi-bad", "sprung mass: the tyre would leave the road (the contact force fell to " +
        `${fixed(run.min_contact_force_ratio, 2)} × the weight and was tensile for ` +
        `${percentOf(run.tension_fraction)} of the time on the bridge): this DAF is outside the ` +
        "model's validity"];
    }
    return ["vbi-good", "sprung mass: contact held (smallest contact force " +
      `${fixed(run.min_contact_force_ratio, 2)} × the weight)`];
  }

  function roadText(v) {
    let text;
    if (v.road === "flat") text = "flat";
    else if (v.road === "harmonic") text = `harmonic, wavelength ${shown(v.wavelength_ft)} ft, amplitude ${shown(v.amplitude_in)} in`;
    else if (v.road === "bump") {
      text = `bump ${shown(v.bump_height_in)} in high, ${shown(v.bump_width_ft)} ft long, crest ` +
        `${shown(v.bump_position_ft)} ft from the first support`;
    } else if (v.road === "iso-class") text = `ISO 8608 class ${v.iso_class} (w = 2), seed ${v.seed}`;
    else text = `ISO 8608 C10 = ${shown(v.c10_e6)}e-6 m³, w = ${shown(v.waviness)}, seed ${v.seed}`;
    if (v.road_shift_ft) text += `, shifted ${shown(v.road_shift_ft)} ft`;
    return text;
  }

  function modelText(v) {
    const what = v.modes === 1
      ? "the study's one-coordinate model (integrated with RK4)"
      : `${v.modes} exact beam modes (integrated with Newmark average acceleration; DAF by mode acceleration)`;
    return `${what}, ${v.coupled ? "coupled" : "decoupled: the bridge does not move the wheel"}`;
  }

  function codesText(spanM, f1) {
    const codes = M.codeAllowances(spanM, f1);
    return "design codes' DAF: " + Object.entries(codes).map(([k, d]) => `${k} ${d.toFixed(2)}`).join(", ");
  }

  // ------------------------------------------------------------------------------ explorer
  class PageExplorer {
    constructor(root, spec) {
      this.root = root;
      this.spec = spec;
      this.kind = spec.kind;
      const same = registry.filter((e) => e.kind === spec.kind).length;
      this.id = same ? `${spec.kind}${same + 1}` : spec.kind;
      this.controls = {};
      this.result = null;
      this.error = null;
      this.build();
      this.start = this.snapshot();
    }

    // -------------------------------------------------------------- building
    build() {
      const root = this.root;
      root.classList.add("vbi-ready");
      this.form = el("form", { class: "vbi-controls", autocomplete: "off" });
      this.form.addEventListener("submit", (event) => event.preventDefault());
      const sections = {};
      for (const spec of this.spec.controls) {
        const control = spec.kind === "choice" ? new ChoiceControl(spec, this) : new NumberControl(spec, this);
        this.controls[spec.name] = control;
        if (!sections[spec.section]) {
          sections[spec.section] = el("fieldset", { class: "vbi-section" }, el("legend", { text: spec.section }));
          this.form.append(sections[spec.section]);
        }
        sections[spec.section].append(control.element);
      }
      this.resetButton = el("button", { type: "button", class: "vbi-reset", title: "Put every control back to its start value", text: "Reset" });
      this.resetButton.addEventListener("click", () => this.reset());
      this.reportButton = el("button", { type: "button", class: "vbi-report", text: "Report parameters",
        title: "Write this setting as a parameter file that vbi-report accepts" });
      this.reportButton.addEventListener("click", () => this.report());
      this.downloads = el("span", { class: "vbi-downloads" });
      this.notice = el("div", { class: "vbi-notice", "data-vbi-notice": "", role: "status", "aria-live": "polite" });
      this.readout = el("div", { class: "vbi-readout", "aria-live": "polite" });
      this.plots = el("div", { class: "vbi-plots" });
      const side = el("div", { class: "vbi-output" }, this.readout, this.notice, this.plots);
      root.append(el("div", { class: "vbi-buttons" }, this.resetButton, this.reportButton, this.downloads),
        el("div", { class: "vbi-body" }, this.form, side));
      this.makePlots();
      this.showUsedControls();
    }

    makePlots() {
      const top = el("div", { class: "vbi-plot" });
      const bottom = el("div", { class: "vbi-plot" });
      this.plots.append(top, bottom);
      this.top = new LinePlot(top, { height: 220, xLabel: "distance of the truck past the first support [ft]", yLabel: "midspan / static [-]" });
      this.bottom = new LinePlot(bottom, { height: 180, xLabel: "distance of the truck past the first support [ft]", yLabel: "contact force / weight [-]" });
    }

    /** Show the road's parameters the chosen road uses; hide the others. */
    showUsedControls() {
      const roads = this.spec.road_parameters;
      const road = this.controls.road ? this.controls.road.value : null;
      const used = new Set(roads[road] || []);
      const all = new Set(Object.values(roads).flat());
      for (const control of Object.values(this.controls)) {
        if (all.has(control.spec.field)) control.show(used.has(control.spec.field));
      }
    }

    // -------------------------------------------------------------- values
    /** Every control's value in the library's units, by Scenario field. */
    values() {
      const v = {};
      for (const control of Object.values(this.controls)) {
        const spec = control.spec;
        if (spec.index !== undefined) {
          v[spec.field] = v[spec.field] || [null, null];
          v[spec.field][spec.index] = control.libraryValue();
        } else v[spec.field] = control.libraryValue();
      }
      return v;
    }

    /** The control values as shown (control units), by input name. */
    snapshot() {
      const out = {};
      for (const [name, control] of Object.entries(this.controls)) out[name] = control.value;
      return out;
    }

    /** Set a control by its input name, as if typed; false (and a message) if refused. */
    set(name, value) {
      const control = this.controls[name];
      if (!control) {
        this.refused(`${name} is not a control of this explorer; use ${Object.keys(this.controls).join(", ")}`);
        return false;
      }
      return control.typed(String(value));
    }

    reset() {
      for (const [name, value] of Object.entries(this.start)) this.controls[name].set(value);
      this.say("");
      this.changed(null);
    }

    /** The crossing the readout shows, as Scenario control values (library units). */
    crossingValues() {
      const v = this.values();
      delete v.speed_range_mph;
      delete v.n_speeds;
      return v;
    }

    /** The readout's crossing in SI: the contract's settings(). */
    settings() {
      const { setting } = M.scenarioSetting(this.crossingValues());
      return {
        ...setting,
        bridge: { ...setting.bridge, spans: Array.from(setting.bridge.spans) },
        road: { x: Array.from(setting.road.x), elevation: Array.from(setting.road.elevation) },
      };
    }

    // -------------------------------------------------------------- changes
    changed(control) {
      if (control && control.name === "road") this.showUsedControls();
      const pairs = [["speed_low", "speed_high"], ["ratio_low", "ratio_high"]]
        .map(([a, b]) => [this.controls[a], this.controls[b]]).filter(([a, b]) => a && b);
      for (const [low, high] of pairs) {
        if ((control === low || control === high) && !(low.value < high.value)) {
          const kept = this.previous[control.name];
          const message = `${low.name}=${shown(low.value)} must be below ${high.name}=` +
            `${shown(high.value)}; the explorer keeps ${control.name}=${shown(kept)}`;
          control.set(kept);
          this.refused(message);
          return;
        }
      }
      this.previous = this.snapshot();
      if (this.loadingHash) return; // the link's values: one update once they are all in
      this.schedule();
      this.writeHash();
    }

    /** A value refused: say why; the controls and the display keep the last valid value. */
    refused(message) {
      // a link's refusals are all said; a typed value's replaces the last sentence
      this.pendingNote = this.loadingHash && this.pendingNote ? `${this.pendingNote} ${message}` : message;
      this.say(this.pendingNote);
    }

    say(message) {
      this.notice.textContent = message ? `⚠ ${message}` : "";
    }

    /** Recompute at once, unless a recomputation ran less than a frame ago (a slider
     * dragged fast): then once, at the next frame, with the latest values. */
    schedule() {
      if (this.frame) return;
      const now = performance.now();
      this.changedAt = now;
      if (!(this.lastUpdate > now - 16)) {
        this.update();
        return;
      }
      this.frame = requestAnimationFrame(() => {
        this.frame = null;
        this.update();
      });
    }

    /** Recompute from the controls and redraw (at once: used by tests and on load). */
    update() {
      const started = this.changedAt || performance.now();
      this.changedAt = null;
      const note = this.pendingNote;
      this.pendingNote = null;
      let result;
      try {
        result = this.compute();
      } catch (error) {
        this.result = null;
        this.error = String(error.message || error);
        this.readout.innerHTML = "";
        this.readout.append(el("div", { class: "vbi-bad" }, el("b", { text: "No result for these settings. " }), this.error));
        this.blank();
        return null;
      }
      this.result = result;
      this.error = null;
      const notes = [...(note ? [note] : []), ...result.notes];
      this.say(notes.join(" "));
      const computed = performance.now();
      this.draw(result);
      const drawn = performance.now();
      this.lastUpdate = drawn;
      this.root.dispatchEvent(new CustomEvent("vbi-drawn", {
        detail: { started, computed, drawn, ms: drawn - started, compute: result.ms },
      }));
      return result;
    }

    compute() {
      const values = this.crossingValues();
      const t0 = performance.now();
      const { setting, notes } = M.scenarioSetting(values);
      const run = M.simulate(setting);
      run.ms = performance.now() - t0;
      run.notes = [...notes, ...run.notes];
      run.values = values;
      return run;
    }

    blank() {
      this.top.draw([[], []], [{ label: "no result", stroke: "#999" }]);
      this.bottom.draw([[], []], [{ label: "no result", stroke: "#999" }]);
    }

    // -------------------------------------------------------------- readouts
    readoutHead(run) {
      const [kind, words] = contactWords(run);
      const daf = el("b", { "data-vbi-readout": "daf", "data-value": JSON.stringify(run.daf.map((d) => (Number.isFinite(d) ? d : null))),
        text: dafText(run.daf) });
      const contact = el("span", { class: kind, "data-vbi-readout": "contact", text: words });
      const line = el("div", { class: "vbi-head" }, daf, " — ", contact);
      const rows = [line];
      if (run.outside) {
        rows.push(el("div", { class: "vbi-bad", text: "inputs outside their intended ranges (the note below says which): these results are outside the model's validity" }));
      }
      return rows;
    }

    crossingRows(run) {
      const v = run.values;
      const span = v.span_ft * U.ft;
      return [
        el("div", { text: `largest contact force ${fixed(run.contact_force_amplification, 2)} × the weight; ${codesText(span, v.bridge_frequency_hz)}` }),
        el("div", { text: `bridge ${shown(v.span_ft)} ft (${(span).toFixed(1)} m) × ${v.n_spans}, f₁ ${fixed(v.bridge_frequency_hz, 2)} Hz; ` +
          `speed ${shown(v.speed_mph)} mph (${(v.speed_mph * U.mph / U.kph).toFixed(1)} km/h); road: ${roadText(v)}` }),
        el("div", { text: `truck: the study's sprung mass, ${shown(v.truck_weight_kip)} kip (${(v.truck_weight_kip * U.kip / 1000).toFixed(0)} kN), ` +
          `${fixed(v.truck_frequency_hz, 2)} Hz, damping ${percentOf(v.truck_damping)} (contact assumed never to leave the road)` }),
        el("div", { text: `model: ${modelText(v)}; largest step ${fixed(run.dt * 1e3, 2)} ms; computed in this page in ${fixed(run.ms, 1)} ms` }),
      ];
    }

    draw(run) {
      this.readout.replaceChildren(...this.readoutHead(run), ...this.crossingRows(run));
      const x = Float64Array.from(run.position, (p) => (p - run.bridge_start) / U.ft);
      const ys = run.midspan_displacement.map((u, j) => Float64Array.from(u, (d) => d / run.static_deflection[j]));
      const colours = ["#1f77b4", "#ff7f0e"];
      const band = { band: [0, run.bridge.length / U.ft], key: String(run.bridge.n) };
      this.top.draw([x, ...ys], ys.map((_, j) => ({ label: `span ${j + 1}`, stroke: colours[j], width: 1.4 })), band);
      const ratio = Float64Array.from(run.contact_force, (f) => f / run.vehicle.weight);
      this.bottom.draw([x, ratio], [{ label: "contact force / weight", stroke: "#2ca02c", width: 1.2 }], band);
    }

    // -------------------------------------------------------------- the link
    writeHash() {
      if (this.loadingHash) return;
      const parts = [];
      for (const explorer of registry) {
        for (const [name, control] of Object.entries(explorer.controls)) {
          if (control.value !== explorer.start[name]) parts.push(`${explorer.id}.${name}=${encodeURIComponent(String(control.value))}`);
        }
      }
      const hash = parts.length ? "#" + parts.join("&") : "";
      if (hash !== window.location.hash && (hash || window.location.hash.includes("="))) {
        history.replaceState(null, "", window.location.pathname + window.location.search + hash);
      }
    }

    applyHash(hash) {
      const mine = [];
      for (const part of hash.replace(/^#/, "").split("&")) {
        const match = /^([a-z]+\d*)\.([a-z_0-9]+)=(.*)$/.exec(part);
        if (match && match[1] === this.id) mine.push([match[2], decodeURIComponent(match[3])]);
      }
      if (!mine.length) return;
      this.loadingHash = true;
      try {
        for (const [name, text] of mine) {
          const control = this.controls[name];
          if (!control) {
            this.refused(`the link names ${name}, which is not a control of this explorer`);
            continue;
          }
          control.typed(text);
        }
      } finally {
        this.loadingHash = false;
      }
    }

    // -------------------------------------------------------------- the report
    report() {
      let files;
      try {
        files = M.reportParameters(this.reportValues(), this.reportSpeeds(), `vbi-${this.kind}`);
      } catch (error) {
        this.say(String(error.message || error));
        return;
      }
      for (const old of this.downloads.querySelectorAll("a")) URL.revokeObjectURL(old.href);
      this.downloads.replaceChildren(" ", ...files.flatMap((file) => {
        const blob = new Blob([file.text], { type: file.name.endsWith(".csv") ? "text/csv" : "text/yaml" });
        return [el("a", { href: URL.createObjectURL(blob), download: file.name, class: "vbi-download", text: file.name }), " "];
      }));
      this.say(files.note);
    }

    reportValues() {
      return this.crossingValues();
    }

    reportSpeeds() {
      return [this.crossingValues().speed_mph];
    }
  }

  // ------------------------------------------------------------------------------ sweeps
  /** Runs crossings a few milliseconds at a time, so the page stays responsive. */
  function progressive(explorer, count, one, done) {
    const job = (explorer.job = (explorer.job || 0) + 1);
    let i = 0;
    const step = () => {
      if (job !== explorer.job) return;
      const until = performance.now() + 12;
      while (i < count && performance.now() < until) one(i++);
      done(i, count);
      if (i < count) setTimeout(step, 0);
    };
    step();
  }

  class SpeedExplorer extends PageExplorer {
    makePlots() {
      const top = el("div", { class: "vbi-plot" });
      const bottom = el("div", { class: "vbi-plot" });
      this.plots.append(top, bottom);
      this.top = new LinePlot(top, { height: 230, xLabel: "speed [mph]", yLabel: "DAF [-]" });
      this.bottom = new LinePlot(bottom, { height: 180, xLabel: "speed [mph]", yLabel: "contact force / weight [-]" });
      this.sweep = null;
    }

    sweepValues() {
      const v = this.values();
      delete v.speed_mph;
      return v;
    }

    compute() {
      const run = super.compute();
      const key = JSON.stringify(this.sweepValues());
      if (!this.sweep || this.sweep.key !== key) this.startSweep(key);
      return run;
    }

    startSweep(key) {
      const v = this.values();
      const [low, high] = v.speed_range_mph;
      const n = v.n_speeds;
      const speeds = Array.from({ length: n }, (_, i) => low + ((high - low) * i) / (n - 1));
      const sweep = (this.sweep = { key, speeds, daf: [], max: [], min: [], lost: [], done: 0, n, spans: v.n_spans });
      progressive(this, n, (i) => {
        try {
          const { setting } = M.scenarioSetting({ ...this.crossingValues(), speed_mph: speeds[i] });
          const run = M.simulate(setting);
          sweep.daf[i] = run.daf;
          sweep.max[i] = run.contact_force_amplification;
          sweep.min[i] = run.min_contact_force_ratio;
          sweep.lost[i] = run.lost_contact;
        } catch (error) {
          sweep.daf[i] = new Array(v.n_spans).fill(NaN);
        }
      }, (done) => {
        sweep.done = done;
        if (this.result) this.draw(this.result);
      });
    }

    draw(run) {
      const v = run.values;
      const sweep = this.sweep;
      const rows = this.readoutHead(run);
      if (sweep) {
        const best = sweep.daf.map((d, i) => (sweep.lost[i] ? NaN : largest(d)));
        let at = -1;
        best.forEach((d, i) => { if (Number.isFinite(d) && (at < 0 || d > best[at])) at = i; });
        const lost = sweep.lost.filter(Boolean).length;
        const progress = sweep.done < sweep.n ? `computing: ${sweep.done} of ${sweep.n} speeds done… ` : "";
        rows.push(el("div", { text: progress + (at >= 0 ? `the sweep's largest DAF among crossings that kept contact: ` +
          `${best[at].toFixed(3)} at ${shown(sweep.speeds[at])} mph; ` : "") +
          (lost ? `${lost} of ${sweep.done} speeds lost contact (marked ×): their DAFs are outside the model's validity` : `every crossing done kept contact`) }));
      }
      rows.push(...this.crossingRows(run));
      this.readout.replaceChildren(...rows);
      if (!sweep) return;
      const x = sweep.speeds.slice(0, sweep.done);
      const colours = ["#1f77b4", "#ff7f0e"];
      const series = [];
      const data = [x];
      for (let j = 0; j < v.n_spans; j++) {
        data.push(x.map((_, i) => (Number.isFinite(sweep.daf[i][j]) ? sweep.daf[i][j] : null)));
        series.push({ label: `span ${j + 1}`, stroke: colours[j], width: 1.4, points: { show: true, size: 4 } });
      }
      data.push(x.map((_, i) => (sweep.lost[i] ? largest(sweep.daf[i]) : null)));
      series.push({ label: "contact lost", stroke: "#000", width: 0, points: { show: true, size: 8, fill: "#000" } });
      const codes = M.codeAllowances(v.span_ft * U.ft, v.bridge_frequency_hz);
      for (const [name, value] of Object.entries(codes)) {
        data.push(x.map(() => value));
        series.push({ label: name, stroke: "#555", width: 1, dash: name.includes("LRFD") ? [6, 3] : name.includes("Standard") ? [8, 3, 2, 3] : [2, 3], points: { show: false } });
      }
      this.top.draw(data, series, { mark: v.speed_mph, key: String(v.n_spans) });
      this.bottom.draw([x, x.map((_, i) => sweep.max[i]), x.map((_, i) => sweep.min[i])], [
        { label: "largest", stroke: "#d62728", width: 1.2, points: { show: true, size: 4 } },
        { label: "smallest", stroke: "#9467bd", width: 1.2, points: { show: true, size: 4 } },
      ], { mark: v.speed_mph });
    }

    reportSpeeds() {
      const v = this.values();
      const speeds = [v.speed_range_mph[0], v.speed_mph, v.speed_range_mph[1]];
      return [...new Set(speeds)].sort((a, b) => a - b);
    }
  }

  class FrequencyExplorer extends PageExplorer {
    makePlots() {
      const box = el("div", { class: "vbi-plot" });
      this.plots.append(box);
      this.heat = new HeatMap(box);
      this.map = null;
    }

    crossingValues() {
      const v = this.values();
      const ratio = v.ratio;
      delete v.ratio;
      delete v.ratio_range;
      delete v.n_ratios;
      delete v.speed_range_mph;
      delete v.n_speeds;
      v.truck_frequency_hz = ratio * v.bridge_frequency_hz;
      return v;
    }

    mapValues() {
      const v = this.values();
      delete v.ratio;
      delete v.speed_mph;
      return v;
    }

    compute() {
      const run = super.compute();
      const values = this.mapValues();
      const key = JSON.stringify(values);
      if (!this.map || this.map.key !== key) {
        const pre = this.spec.precomputed && this.spec.precomputed.map;
        if (pre && !this.map && sameValues(pre.values, values)) {
          this.map = { key, ratio: pre.ratio, speed: pre.speed, daf: pre.daf, lost: pre.lost, done: pre.ratio.length * pre.speed.length, from: "library" };
        } else this.startMap(key);
      }
      return run;
    }

    startMap(key) {
      const v = this.values();
      const [rLow, rHigh] = v.ratio_range;
      const [sLow, sHigh] = v.speed_range_mph;
      const ratio = Array.from({ length: v.n_ratios }, (_, j) => rLow + ((rHigh - rLow) * j) / (v.n_ratios - 1));
      const speedMph = Array.from({ length: v.n_speeds }, (_, i) => sLow + ((sHigh - sLow) * i) / (v.n_speeds - 1));
      const map = (this.map = { key, ratio, speed: speedMph.map((s) => s * U.mph), daf: speedMph.map(() => ratio.map(() => null)),
        lost: speedMph.map(() => ratio.map(() => false)), done: 0, from: "page" });
      const n = ratio.length * speedMph.length;
      const base = this.crossingValues();
      progressive(this, n, (k) => {
        const i = Math.floor(k / ratio.length);
        const j = k % ratio.length;
        try {
          const { setting } = M.scenarioSetting({ ...base, speed_mph: speedMph[i], truck_frequency_hz: ratio[j] * v.bridge_frequency_hz });
          const run = M.simulate(setting);
          map.daf[i][j] = largest(run.daf);
          map.lost[i][j] = run.lost_contact;
        } catch (error) {
          map.daf[i][j] = null;
        }
      }, (done) => {
        map.done = done;
        if (this.result) this.draw(this.result);
      });
    }

    draw(run) {
      const v = this.values();
      const map = this.map;
      const rows = this.readoutHead(run);
      rows[0].append(` (the cell at ${shown(v.speed_mph)} mph, truck ${fixed(v.ratio * v.bridge_frequency_hz, 2)} Hz: ratio ${fixed(v.ratio, 2)})`);
      if (map) {
        const n = map.ratio.length * map.speed.length;
        const finite = map.daf.flat().filter((d, k) => d !== null && !map.lost[Math.floor(k / map.ratio.length)][k % map.ratio.length]);
        const lost = map.lost.flat().filter(Boolean).length;
        const from = map.from === "library" ? "computed by vbi_lib when the book was built" : "computed in this page";
        const progress = map.done < n ? `computing: ${map.done} of ${n} crossings done… ` : "";
        rows.push(el("div", { text: `${progress}the map (${from}): largest DAF among crossings that kept contact ${finite.length ? Math.max(...finite).toFixed(3) : "-"}; ` +
          `${lost} of ${map.done} lost contact (white crosses)` }));
      }
      rows.push(...this.crossingRows(run));
      this.readout.replaceChildren(...rows);
      if (map) this.heat.draw(map, { ratio: v.ratio, speed: v.speed_mph * U.mph });
    }

    blank() {
      if (this.map) this.heat.draw({ ...this.map, daf: this.map.daf.map((r) => r.map(() => null)) }, null);
    }
  }

  /** The larger DAF of the spans; null when no span has one. */
  function largest(dafs) {
    const finite = dafs.filter(Number.isFinite);
    return finite.length ? Math.max(...finite) : null;
  }

  function sameValues(a, b) {
    for (const key of Object.keys(a)) {
      const x = a[key];
      const y = b[key];
      if (Array.isArray(x) ? JSON.stringify(x) !== JSON.stringify(y) : x !== y) return false;
    }
    return true;
  }

  // ------------------------------------------------------------------------------ start
  const KINDS = { crossing: PageExplorer, speed: SpeedExplorer, frequency: FrequencyExplorer };

  function start() {
    const made = [];
    for (const root of document.querySelectorAll("[data-vbi-explorer]:not(.vbi-ready)")) {
      const source = root.querySelector("script.vbi-spec");
      if (!source) continue;
      const spec = JSON.parse(source.textContent);
      const kind = KINDS[spec.kind];
      if (!kind) continue;
      const explorer = new kind(root, spec);
      registry.push(explorer);
      made.push(explorer);
    }
    for (const explorer of made) {
      explorer.previous = explorer.snapshot();
      explorer.applyHash(window.location.hash);
      explorer.update();
    }
  }

  window.addEventListener("hashchange", () => {
    for (const explorer of registry) {
      explorer.applyHash(window.location.hash);
      explorer.update();
    }
  });

  start();
})();

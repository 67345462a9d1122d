/* vbi-model.js: the crossing models of the book's explorers, ported from vbi_lib to run in the
 * reader's browser (and in Node, for the tests that check it against the library).
 *
 * The port keeps vbi_lib's names, equation labels and rules, and vbi_lib stays the reference:
 * tests/widgets/test_js_port.py runs this file in Node on hundreds of random settings and
 * compares it with the library.
 *
 * - roads (vbi_lib.profiles): flat, harmonic, one bump, ISO 8608 (study 87) with numpy's own
 *   random phases (SeedSequence + PCG64 + Generator.uniform, ported) and scipy's FFT length;
 * - the node grid (vbi_lib.models.grid): the one-axle walker, node for node;
 * - the one-coordinate model (vbi_lib.models.one_coordinate, study 33-99): the sprung mass on
 *   psi z_b, one span or two equal spans, classical RK4, dt = 0.1 / omega_max with omega_max
 *   from the roots of the characteristic quartic (one_coordinate_step);
 * - the modal model (vbi_lib.models.modal): the sprung mass on the first N <= 10 exact modes
 *   of one span or two equal spans, Newmark average acceleration, dt = 0.1 / omega of the
 *   vehicle and the first two modes;
 * - the DAF (the definitions of issue 20, kept apart in spanDafs): the largest downward
 *   midspan displacement over the whole run, refined inside each step from the cubic Hermite
 *   interpolant (base.downward_peak), over the same model's static of each span: W / k* for
 *   the one-coordinate model (90)-(91); for the modal model the mode-acceleration
 *   displacement over the exact beam's static (three-moment equation), the N-mode series DAF
 *   tracked beside it.
 *
 * Only the study's sprung mass is ported (no quarter car, no axle groups, no footprint):
 * those need the live explorers (make explore).
 */
(function (root, factory) {
  if (typeof module === "object" && module.exports) module.exports = factory();
  else root.vbiModel = factory();
})(typeof self !== "undefined" ? self : this, function () {
  "use strict";

  // ------------------------------------------------------------------------------ units
  // vbi_lib.units: SI inside, the study's US customary units at the edges
  const inch = 0.0254;
  const ft = 12 * inch;
  const lbf = 4.4482216152605;
  const kip = 1000 * lbf;
  const mile = 5280 * ft;
  const mph = mile / 3600.0;
  const kph = 1000.0 / 3600.0;
  const g = 9.80665;
  const UNITS = { inch, ft, lbf, kip, mile, mph, kph, g };

  // ------------------------------------------------------------------------------ ranges
  // The rows of vbi_lib.ranges.RANGES the port checks (SI; the Node test compares them with
  // the library's table): hard limits refuse, soft limits are the intended use.
  const RANGES = {
    speed: { hard: [0.0, 400.0], soft: [0.0, 41.666666666666664], unit: "m/s", openLow: true,
             quantity: "vehicle speed", intended: "highway speeds up to 150 km/h" },
    sample_spacing: { hard: [0.0, Infinity], soft: [0.0, 1.0], unit: "-",
                      quantity: "profile sample spacing over the study's rule (32)",
                      intended: "at least two samples per period of the highest frequency" },
    c10: { hard: [1e-12, 0.524288], soft: [1e-12, 0.008192], unit: "m^3",
           quantity: "ISO 8608 roughness G_d(0.1 cycle/m)", intended: "classes A to E" },
    // 1 or more is an overdamped suspension: taken and noted, never refused (h20's rule)
    vehicle_damping_ratio: { hard: [0.0, Infinity], soft: [0.0, 0.5], unit: "-",
                             quantity: "damping ratio of a suspension or a tyre",
                             intended: "truck suspensions are damped 5 to 30 %, the study's truck 10 %" },
  };
  /** Most beam modes the page runs (the live explorers run up to 20). */
  const PORT_MAX_MODES = 10;

  /** The sentence saying value is outside key's soft range (vbi_lib.ranges.outside_note). */
  function outsideNote(key, value, name) {
    const spec = RANGES[key];
    const [low, high] = spec.soft;
    if (low <= value && value <= high) return null;
    const unit = spec.unit === "-" ? "" : " " + spec.unit;
    return `${name || key}=${fmtG(value, 6)}${unit} is outside the intended range from ` +
      `${fmtG(low, 4)} to ${fmtG(high, 4)}${unit} of ${spec.quantity} (${spec.intended}); ` +
      "the result is outside the model's validity";
  }

  /** Python's f"{value:.{digits}g}", near enough for messages. */
  function fmtG(value, digits) {
    if (!isFinite(value)) return String(value);
    if (value === 0) return "0";
    const exponent = Math.floor(Math.log10(Math.abs(value)));
    if (exponent < -4 || exponent >= digits) {
      const text = value.toExponential(digits - 1).replace(/\.?0+e/, "e");
      return text.replace(/e([+-])(\d)$/, "e$10$2");
    }
    return String(parseFloat(value.toPrecision(digits)));
  }

  // ------------------------------------------------------------------------------ numpy
  /** np.interp at one point: numpy's operations (compiled_base.c arr_interp). */
  function interp(x, xp, fp) {
    const n = xp.length;
    if (x < xp[0]) return fp[0];
    if (x >= xp[n - 1]) return fp[n - 1];
    let lo = 0;
    let hi = n - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (xp[mid] <= x) lo = mid;
      else hi = mid;
    }
    if (x === xp[lo]) return fp[lo];
    const slope = (fp[lo + 1] - fp[lo]) / (xp[lo + 1] - xp[lo]);
    return slope * (x - xp[lo]) + fp[lo];
  }

  // numpy.random.SeedSequence (bit_generator.pyx): the hash of a seed into PCG64's state
  const MASK32 = 0xffffffff;
  const INIT_A = 0x43b0d7e5;
  const MULT_A = 0x931e8875;
  const INIT_B = 0x8b51f9dd;
  const MULT_B = 0x58f38ded;
  const MIX_MULT_L = 0xca01f9dd;
  const MIX_MULT_R = 0x4973f715;
  const XSHIFT = 16;
  const POOL_SIZE = 4;

  function mul32(a, b) {
    return Math.imul(a, b) >>> 0;
  }

  /** The 32-bit words of a whole number >= 0, least significant first (_int_to_uint32_array). */
  function uint32Words(seed) {
    if (!Number.isSafeInteger(seed) || seed < 0) {
      throw new RangeError(`seed=${seed} must be a whole number >= 0`);
    }
    if (seed === 0) return [0];
    const words = [];
    let n = BigInt(seed);
    while (n > 0n) {
      words.push(Number(n & 0xffffffffn));
      n >>= 32n;
    }
    return words;
  }

  function seedSequenceState(seed, nWords) {
    const entropy = uint32Words(seed);
    const pool = new Array(POOL_SIZE).fill(0);
    let hashConst = INIT_A;
    const hashmix = (value) => {
      value = (value ^ hashConst) >>> 0;
      hashConst = mul32(hashConst, MULT_A);
      value = mul32(value, hashConst);
      return (value ^ (value >>> XSHIFT)) >>> 0;
    };
    const mix = (x, y) => {
      let result = (mul32(MIX_MULT_L, x) - mul32(MIX_MULT_R, y)) >>> 0;
      return (result ^ (result >>> XSHIFT)) >>> 0;
    };
    for (let i = 0; i < POOL_SIZE; i++) {
      pool[i] = hashmix(i < entropy.length ? entropy[i] : 0);
    }
    for (let src = 0; src < POOL_SIZE; src++) {
      for (let dst = 0; dst < POOL_SIZE; dst++) {
        if (src !== dst) pool[dst] = mix(pool[dst], hashmix(pool[src]));
      }
    }
    for (let src = POOL_SIZE; src < entropy.length; src++) {
      for (let dst = 0; dst < POOL_SIZE; dst++) pool[dst] = mix(pool[dst], hashmix(entropy[src]));
    }
    // generate_state
    const state = new Array(nWords);
    let hash = INIT_B;
    for (let i = 0; i < nWords; i++) {
      let value = (pool[i % POOL_SIZE] ^ hash) >>> 0;
      hash = mul32(hash, MULT_B);
      value = mul32(value, hash);
      state[i] = (value ^ (value >>> XSHIFT)) >>> 0;
    }
    return state;
  }

  // numpy's PCG64 (pcg64.h: 128-bit LCG, XSL RR output) seeded by SeedSequence
  const MASK128 = (1n << 128n) - 1n;
  const MASK64 = (1n << 64n) - 1n;
  const PCG_MULTIPLIER = (2549297995355413924n << 64n) + 4865540595714422341n;

  class PCG64 {
    constructor(seed) {
      const w = seedSequenceState(seed, 8).map(BigInt); // four uint64, little-endian words
      const v = [0, 1, 2, 3].map((i) => w[2 * i] | (w[2 * i + 1] << 32n));
      const initState = (v[0] << 64n) | v[1];
      const initSeq = (v[2] << 64n) | v[3];
      this.state = 0n;
      this.inc = ((initSeq << 1n) | 1n) & MASK128;
      this.step();
      this.state = (this.state + initState) & MASK128;
      this.step();
    }

    step() {
      this.state = (this.state * PCG_MULTIPLIER + this.inc) & MASK128;
    }

    next64() {
      this.step();
      const s = this.state;
      const value = ((s >> 64n) ^ s) & MASK64;
      const rot = s >> 122n;
      return ((value >> rot) | (value << ((64n - rot) & 63n))) & MASK64;
    }

    /** next_double: 53 random bits in [0, 1). */
    nextDouble() {
      return Number(this.next64() >> 11n) * (1.0 / 9007199254740992.0);
    }
  }

  /** numpy.random.default_rng(seed).uniform(low, high, count). */
  function uniform(seed, low, high, count) {
    const rng = new PCG64(seed);
    const range = high - low;
    const out = new Float64Array(count);
    for (let i = 0; i < count; i++) out[i] = low + range * rng.nextDouble();
    return out;
  }

  /** scipy.fft.next_fast_len(n, real=True): the least 2^a 3^b 5^c >= n (pocketfft). */
  function nextFastLen(n) {
    if (n <= 6) return n;
    let best = Infinity;
    for (let f5 = 1; f5 < best; f5 *= 5) {
      for (let f35 = f5; f35 < best; f35 *= 3) {
        let x = f35;
        while (x < n) x *= 2;
        if (x < best) best = x;
        if (x === n) return n;
      }
    }
    return best;
  }

  /** Inverse complex DFT of length n (a product of 2, 3 and 5), unscaled, by mixed-radix
   * Cooley-Tukey; twiddles from Math.cos/sin of 2 pi k / n. */
  function inverseDft(re, im) {
    const n = re.length;
    const cos = new Float64Array(n);
    const sin = new Float64Array(n);
    for (let k = 0; k < n; k++) {
      const angle = (2 * Math.PI * k) / n;
      cos[k] = Math.cos(angle);
      sin[k] = Math.sin(angle);
    }
    const factors = [];
    let rest = n;
    for (const p of [4, 2, 3, 5]) {
      while (rest % p === 0) {
        factors.push(p);
        rest /= p;
      }
    }
    if (rest !== 1) throw new Error(`inverseDft: length ${n} is not 2^a 3^b 5^c`);
    const outRe = new Float64Array(n);
    const outIm = new Float64Array(n);
    const tRe = new Float64Array(5);
    const tIm = new Float64Array(5);
    const bufRe = new Float64Array(5); // a butterfly's outputs, written once its inputs are read
    const bufIm = new Float64Array(5);
    // out[offset + ...] = DFT of in[start, start + stride, ...] of length len
    function transform(start, stride, len, level, offset) {
      if (len === 1) {
        outRe[offset] = re[start];
        outIm[offset] = im[start];
        return;
      }
      const p = factors[level];
      const m = len / p;
      for (let r = 0; r < p; r++) transform(start + r * stride, stride * p, m, level + 1, offset + r * m);
      const step = n / len; // twiddle index step
      for (let k = 0; k < m; k++) {
        for (let r = 0; r < p; r++) {
          const idx = (r * k * step) % n;
          const a = outRe[offset + r * m + k];
          const b = outIm[offset + r * m + k];
          tRe[r] = a * cos[idx] - b * sin[idx];
          tIm[r] = a * sin[idx] + b * cos[idx];
        }
        for (let q = 0; q < p; q++) {
          let sr = 0;
          let si = 0;
          for (let r = 0; r < p; r++) {
            const idx = (((r * q) % p) * m * step) % n;
            sr += tRe[r] * cos[idx] - tIm[r] * sin[idx];
            si += tRe[r] * sin[idx] + tIm[r] * cos[idx];
          }
          bufRe[q] = sr;
          bufIm[q] = si;
        }
        for (let q = 0; q < p; q++) {
          outRe[offset + q * m + k] = bufRe[q];
          outIm[offset + q * m + k] = bufIm[q];
        }
      }
    }
    transform(0, 1, n, 0, 0);
    return [outRe, outIm];
  }

  // ------------------------------------------------------------------------------ roads
  const ISO_CLASSES = "ABCDEFGH";
  /** ISO 8608 classes and the geometric mean of G_d(n0) of each [m^3] (profiles.ISO_CLASS_MEANS). */
  const ISO_CLASS_MEANS = {};
  for (let i = 0; i < ISO_CLASSES.length; i++) ISO_CLASS_MEANS[ISO_CLASSES[i]] = 16e-6 * 4.0 ** i;
  /** Spatial-frequency band of a generated road [cycle/m] (profiles.ISO_BAND). */
  const ISO_BAND = [0.011, 2.83];

  /** Stations start, start + spacing, ... covering length (profiles._stations). */
  function stations(length, spacing, start = 0.0) {
    const count = Math.floor(length / spacing + 1e-9);
    const extra = length - count * spacing > 1e-9 * length;
    const x = new Float64Array(count + 1 + (extra ? 1 : 0));
    for (let i = 0; i <= count; i++) x[i] = start + spacing * i;
    if (extra) x[count + 1] = start + length;
    return x;
  }

  function flatRoad(length, spacing) {
    const x = stations(length, spacing);
    return { x, elevation: new Float64Array(x.length), name: "flat" };
  }

  function harmonicRoad(length, spacing, wavelength, amplitude) {
    if (wavelength < 2.0 * spacing) {
      throw new RangeError(`wavelength=${wavelength} m is shorter than two samples of ` +
        `spacing=${spacing} m: the road would alias`);
    }
    const x = stations(length, spacing);
    const elevation = new Float64Array(x.length);
    for (let i = 0; i < x.length; i++) {
      elevation[i] = amplitude * Math.sin((2.0 * Math.PI * (x[i] - 0.0)) / wavelength + 0.0);
    }
    return { x, elevation, name: `harmonic ${wavelength} m` };
  }

  function bumpRoad(length, spacing, position, height, width) {
    const x = stations(length, spacing);
    const elevation = new Float64Array(x.length);
    for (let i = 0; i < x.length; i++) {
      const u = (x[i] - position) / width + 0.5;
      elevation[i] = u > 0.0 && u < 1.0 ? 0.5 * height * (1.0 - Math.cos(2.0 * Math.PI * u)) : 0.0;
    }
    return { x, elevation, name: "bump" };
  }

  /** rms of an ISO 8608 road over [low, high], refused above 1 m (profiles.check_iso_rms). */
  function checkIsoRms(level, waviness, low, high) {
    let variance;
    if (Math.abs(waviness - 1.0) < 1e-12) variance = level * 0.1 * Math.log(high / low);
    else {
      variance = level * 0.1 ** waviness * (high ** (1 - waviness) - low ** (1 - waviness));
      variance /= 1.0 - waviness;
    }
    const rms = Math.sqrt(variance);
    if (rms > 1.0) {
      throw new RangeError(`c10=${level} m^3 with waviness=${waviness} gives a road of rms ` +
        `${fmtG(rms, 3)} m; a road's rms must be at most 1 m: lower c10 or the waviness`);
    }
    return rms;
  }

  const phaseCache = new Map();

  /** Profile.iso8608: a sum of cosines with the ISO 8608 spectrum G_d(n) = c10 (n / 0.1)^-w
   * (study 87), phases from numpy.random.default_rng(seed), evaluated with one inverse FFT. */
  function isoRoad(length, spacing, level, waviness, seed) {
    const [low, high] = ISO_BAND;
    if (high >= 0.5 / spacing) throw new RangeError(`spacing=${spacing} m does not resolve the band`);
    checkIsoRms(level, waviness, Math.max(low, 1.0 / length), high);
    const x = stations(length, spacing, 0.0);
    const last = (x[x.length - 1] - 0.0) / spacing;
    const regular = Math.abs(last - Math.round(last)) < 1e-6 ? x.length : x.length - 1;
    const count = nextFastLen(x.length);
    const dn = 1.0 / (count * spacing);
    const kLow = Math.ceil(low / dn - 1e-9);
    const kHigh = Math.floor(high / dn + 1e-9);
    const ks = [];
    for (let k = kLow; k <= kHigh; k++) if (k > 0 && 2 * k < count) ks.push(k);
    if (ks.length === 0) throw new RangeError("the band holds no frequency of the grid");
    const key = `${seed}:${ks.length}`;
    let phase = phaseCache.get(key);
    if (!phase) {
      phase = uniform(seed, 0.0, 2.0 * Math.PI, ks.length);
      if (phaseCache.size > 64) phaseCache.clear();
      phaseCache.set(key, phase);
    }
    const amplitude = new Float64Array(ks.length);
    const re = new Float64Array(count);
    const im = new Float64Array(count);
    for (let i = 0; i < ks.length; i++) {
      const n = ks[i] * dn;
      amplitude[i] = Math.sqrt(2.0 * level * (n / 0.1) ** -waviness * dn);
      const c = 0.5 * count * amplitude[i];
      // spectrum[k] = c exp(i phase); irfft uses it and its conjugate at count - k
      re[ks[i]] = c * Math.cos(phase[i]);
      im[ks[i]] = c * Math.sin(phase[i]);
      re[count - ks[i]] = re[ks[i]];
      im[count - ks[i]] = -im[ks[i]];
    }
    const [outRe] = inverseDft(re, im);
    const elevation = new Float64Array(x.length);
    for (let j = 0; j < regular; j++) elevation[j] = outRe[j] / count;
    for (let j = regular; j < x.length; j++) {
      let s = 0;
      for (let i = 0; i < ks.length; i++) {
        s += amplitude[i] * Math.cos(2.0 * Math.PI * (ks[i] * dn) * (x[j] - 0.0) + phase[i]);
      }
      elevation[j] = s;
    }
    return { x, elevation, name: `ISO 8608 C10=${fmtG(level * 1e6, 6)}e-6 m^3 w=${waviness} seed=${seed}` };
  }

  /** Profile.segment(start, stop) then .shifted(offset). */
  function segmentShifted(road, start, stop, offset) {
    const x = [start];
    for (let i = 0; i < road.x.length; i++) if (road.x[i] > start && road.x[i] < stop) x.push(road.x[i]);
    x.push(stop);
    const out = new Float64Array(x.length);
    const elevation = new Float64Array(x.length);
    for (let i = 0; i < x.length; i++) {
      elevation[i] = interp(x[i], road.x, road.elevation);
      out[i] = x[i] + offset;
    }
    return { x: out, elevation, name: road.name };
  }

  // ------------------------------------------------------------------------------ scenario
  // vbi_lib.widgets.scenario: the explorers' controls (US customary units) to SI inputs
  const ROAD_SPACING = 1 * inch;
  const MAX_ROAD_SHIFT_FT = 200.0;
  const ROADS = ["flat", "harmonic", "bump", "iso-class", "iso-c10"];

  const roadCache = new Map();

  /** The road of the explorers' control values (Scenario.profile: generated roads 200 ft
   * longer than the approach and the bridge, every inch, slid back by the shift), remembered
   * for the last few settings: a slider that does not touch the road reuses it. */
  function scenarioRoad(v) {
    const fields = ["road", "approach_ft", "n_spans", "span_ft", "road_shift_ft"];
    const own = {
      flat: [], harmonic: ["wavelength_ft", "amplitude_in"],
      bump: ["bump_height_in", "bump_width_ft", "bump_position_ft"],
      "iso-class": ["iso_class", "seed"], "iso-c10": ["c10_e6", "waviness", "seed"],
    }[v.road];
    const key = JSON.stringify([...fields, ...own].map((f) => v[f]));
    const cached = roadCache.get(key);
    if (cached) return cached;
    const notes = [];
    const length = (v.approach_ft + v.n_spans * v.span_ft + MAX_ROAD_SHIFT_FT) * ft;
    let road;
    if (v.road === "flat") road = flatRoad(length, ROAD_SPACING);
    else if (v.road === "harmonic") {
      road = harmonicRoad(length, ROAD_SPACING, v.wavelength_ft * ft, v.amplitude_in * inch);
    } else if (v.road === "bump") {
      road = bumpRoad(length, ROAD_SPACING, (v.approach_ft + v.bump_position_ft) * ft,
        v.bump_height_in * inch, v.bump_width_ft * ft);
    } else {
      const level = v.road === "iso-class" ? ISO_CLASS_MEANS[v.iso_class] : v.c10_e6 * 1e-6;
      if (level === undefined) throw new RangeError(`iso_class=${v.iso_class} must be one of A to H`);
      const note = outsideNote("c10", level, v.road === "iso-class" ? `iso_class='${v.iso_class}': c10` : "c10");
      if (note) notes.push(note);
      road = isoRoad(length, ROAD_SPACING, level, v.road === "iso-class" ? 2.0 : v.waviness, v.seed);
    }
    const shift = v.road_shift_ft * ft;
    if (shift !== 0.0) {
      const first = road.x[0];
      const end = road.x[road.x.length - 1];
      if (shift >= end - first) throw new RangeError(`road_shift_ft=${v.road_shift_ft} must be shorter than the road`);
      road = segmentShifted(road, first + shift, end, -shift);
    }
    const out = { road, notes };
    if (roadCache.size >= 8) roadCache.delete(roadCache.keys().next().value);
    roadCache.set(key, out);
    return out;
  }

  /** The SI setting of the explorers' control values (fields of vbi_lib.widgets.Scenario).
   * Returns {setting, notes}; throws RangeError naming the field for values it refuses. */
  function scenarioSetting(v) {
    if (!ROADS.includes(v.road)) {
      throw new RangeError(`road=${JSON.stringify(v.road)} runs only live (make explore); ` +
        `in the page: ${ROADS.join(", ")}`);
    }
    if (v.n_spans !== 1 && v.n_spans !== 2) throw new RangeError(`n_spans=${v.n_spans} must be 1 or 2`);
    if (!(Number.isInteger(v.modes) && v.modes >= 1 && v.modes <= PORT_MAX_MODES)) {
      throw new RangeError(`modes=${v.modes} must be a whole number from 1 to ` +
        `${PORT_MAX_MODES} in the page (more modes: make explore)`);
    }
    if (!(v.truck_damping >= 0.0 && v.truck_damping < Infinity)) {
      throw new RangeError(`truck_damping=${v.truck_damping} must be a finite number, 0 or more`);
    }
    const notes = [];
    const dampingNote = outsideNote("vehicle_damping_ratio", v.truck_damping, "truck_damping");
    if (dampingNote) notes.push(dampingNote);
    const span = v.span_ft * ft;
    const massPerLength = (v.bridge_weight_kip_per_ft * kip) / ft / g;
    const omegaB = 2.0 * Math.PI * v.bridge_frequency_hz;
    const EI = (omegaB ** 2 * massPerLength * span ** 4) / Math.PI ** 4;
    const mass = (v.truck_weight_kip * kip) / g;
    const omegaV = 2.0 * Math.PI * v.truck_frequency_hz;
    const { road, notes: roadNotes } = scenarioRoad(v);
    notes.push(...roadNotes);
    const setting = {
      bridge: {
        spans: new Array(v.n_spans).fill(span),
        EI,
        mass_per_length: massPerLength,
        damping_ratio: v.bridge_damping,
      },
      vehicle: { mass, stiffness: mass * omegaV ** 2, damping: 2.0 * v.truck_damping * mass * omegaV },
      speed: v.speed_mph * mph,
      bridge_start: road.x[0] + v.approach_ft * ft,
      model: v.modes === 1 ? "one-coordinate" : "modal",
      modes: v.modes === 1 ? null : v.modes,
      coupled: Boolean(v.coupled),
      road: { x: road.x, elevation: road.elevation },
    };
    return { setting, notes };
  }

  // ------------------------------------------------------------------------------ bridge
  /** The study's beam (vbi_lib.Bridge): one span or two equal continuous spans. */
  function makeBridge(b) {
    const n = b.spans.length;
    const L = b.spans[0];
    if ((n !== 1 && n !== 2) || b.spans.some((s) => s !== L)) {
      throw new RangeError(`bridge.spans=${JSON.stringify(b.spans)}: the page runs one span or ` +
        "two equal spans (other layouts: make explore, model='modal')");
    }
    const supports = [];
    for (let j = 0; j <= n; j++) supports.push(L * j);
    const midspans = [];
    for (let j = 0; j < n; j++) midspans.push((j + 0.5) * L);
    const mb = b.mass_per_length;
    const omega = Math.PI ** 2 * Math.sqrt(b.EI / (mb * L ** 4)); // (37)
    const mStar = (n * mb * L) / 2.0; // (36), (62)
    const kStar = (n * Math.PI ** 4 * b.EI) / (2.0 * L ** 3); // (37), (63)
    return {
      n, L, EI: b.EI, mass_per_length: mb, damping_ratio: b.damping_ratio,
      supports, midspans, length: supports[n], circular_frequency: omega,
      first_frequency_hz: omega / (2.0 * Math.PI),
      generalized_mass: mStar, generalized_stiffness: kStar,
      generalized_damping: 2.0 * b.damping_ratio * omega * mStar, // (40)-(43)
    };
  }

  /** Exact static deflection (down positive) of midspan j under a unit load at a [m/N]
   * (beam_statics.continuous_statics: three-moment equation, one or two equal spans). */
  function exactInfluence(bridge, j, a) {
    const L = bridge.L;
    const EI = bridge.EI;
    const n = bridge.n;
    const k = Math.min(Math.max(a >= L && n > 1 ? 1 : 0, 0), n - 1); // the load's span
    const al = a - bridge.supports[k];
    const bl = L - al;
    let m1 = 0.0; // moment over the interior support
    if (n === 2) {
      const rhs = k === 0 ? -((1.0 * al * bl * (L + al)) / L) : -((1.0 * al * bl * (L + bl)) / L);
      m1 = rhs / (2.0 * (L + L));
    }
    const s = 0.5 * L; // the midspan of span j
    const rest = L - s;
    const mLeft = j === 0 ? 0.0 : m1;
    const mRight = j === 0 && n === 2 ? m1 : 0.0;
    let w0 = 0.0;
    if (k === j) {
      w0 = s <= al
        ? (1.0 * bl * s * (L ** 2 - bl ** 2 - s ** 2)) / (6.0 * L * EI)
        : (1.0 * al * rest * (L ** 2 - al ** 2 - rest ** 2)) / (6.0 * L * EI);
    }
    return w0 + (mLeft * rest * (L ** 2 - rest ** 2) + mRight * s * (L ** 2 - s ** 2)) / (6.0 * L * EI);
  }

  /** Largest exact static midspan deflection of span j under a unit load anywhere [m/N]:
   * L^3 / 48 EI on one span; on two equal spans the influence line a (9 L^2 - 13 a^2) / 192 EI
   * of the loaded span peaks at a = 3 L / sqrt(39), 3 L^3 / (32 sqrt(39) EI). */
  function exactStaticPeak(bridge) {
    const L = bridge.L;
    if (bridge.n === 1) return L ** 3 / (48.0 * bridge.EI);
    return (3.0 * L ** 3) / (32.0 * Math.sqrt(39.0) * bridge.EI);
  }

  // ------------------------------------------------------------------------------ modes
  /** The first positive roots of tan z = tanh z (modes.propped_cantilever_roots), by bisection
   * of sin z - cos z tanh z in (n pi, n pi + pi / 2) to the last bit. */
  function proppedCantileverRoot(n) {
    let lo = n * Math.PI + 1e-9;
    let hi = n * Math.PI + 0.5 * Math.PI - 1e-12;
    const f = (z) => Math.sin(z) - Math.cos(z) * Math.tanh(z);
    let flo = f(lo);
    for (let i = 0; i < 200; i++) {
      const mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      const fm = f(mid);
      if (fm === 0) return mid;
      if ((fm < 0) === (flo < 0)) {
        lo = mid;
        flo = fm;
      } else hi = mid;
    }
    return 0.5 * (lo + hi);
  }

  /** The first count mass-normalised modes of one span or two equal spans (vbi_lib.modes),
   * in closed form: sines (one span, and the antisymmetric family of two spans) and the
   * propped cantilevers of the symmetric family (tan lambda L = tanh lambda L). */
  function beamModes(bridge, count) {
    const L = bridge.L;
    const mb = bridge.mass_per_length;
    const list = [];
    if (bridge.n === 1) {
      for (let i = 1; i <= count; i++) list.push({ kind: "sine", k: (i * Math.PI) / L, scale: Math.sqrt(2.0 / (mb * L)) });
    } else {
      let sine = 1;
      let sym = 1;
      let zSym = proppedCantileverRoot(1);
      while (list.length < count) {
        if (sine * Math.PI < zSym) {
          list.push({ kind: "sine", k: (sine * Math.PI) / L, scale: 1.0 / Math.sqrt(mb * L) });
          sine++;
        } else {
          const lam = zSym / L;
          const r = Math.sin(zSym) / Math.sinh(zSym);
          const norm2 = L / 2 - Math.sin(2 * zSym) / (4 * lam) +
            (Math.sin(zSym) ** 2 / Math.tanh(zSym)) / (2 * lam) - (r * r * L) / 2;
          list.push({ kind: "symmetric", k: lam, z: zSym, scale: 1.0 / Math.sqrt(2 * mb * norm2) });
          sym++;
          zSym = proppedCantileverRoot(sym);
        }
      }
    }
    const root = Math.sqrt(bridge.EI / mb);
    const omega = new Float64Array(count);
    for (let i = 0; i < count; i++) omega[i] = list[i].k ** 2 * root;
    return { count, list, omega, length: bridge.length, L };
  }

  /** Shapes and slopes of every mode at xi from the bridge start, into phi and dphi. */
  function shapeValues(modes, xi, phi, dphi) {
    const L = modes.L;
    for (let i = 0; i < modes.count; i++) {
      const m = modes.list[i];
      if (m.kind === "sine") {
        phi[i] = m.scale * Math.sin(m.k * xi);
        dphi[i] = m.scale * m.k * Math.cos(m.k * xi);
      } else {
        // each span a propped cantilever; s from the nearer outer end
        const right = xi > L;
        const s = right ? 2 * L - xi : xi;
        const lam = m.k;
        // sinh(lam s) / sinh(lam L) written to stay finite for high modes
        const ratio = Math.exp(lam * (s - L)) * (1 - Math.exp(-2 * lam * s)) / (1 - Math.exp(-2 * m.z));
        const cratio = Math.exp(lam * (s - L)) * (1 + Math.exp(-2 * lam * s)) / (1 - Math.exp(-2 * m.z));
        const sz = Math.sin(m.z);
        phi[i] = m.scale * (Math.sin(lam * s) - sz * ratio);
        const slope = m.scale * lam * (Math.cos(lam * s) - sz * cratio);
        dphi[i] = right ? -slope : slope;
      }
    }
  }

  // ------------------------------------------------------------------------------ the grid
  /** The one-axle node grid (models.grid: walk_start, walk, _walked_grid, node_grid): every
   * profile sample, the supports and the stop; gaps longer than step cut evenly; np.interp. */
  function nodeGrid(road, bridge, speed, bridgeStart, dt, stop) {
    const px = road.x;
    const pe = road.elevation;
    const n = px.length;
    const step = speed * dt;
    const edges = bridge.supports;
    const supports = [];
    for (const e of edges) {
      const s = bridgeStart + e;
      if (s >= px[0] && s <= stop) supports.push(s);
    }
    const tol = 1e-12 * Math.max(1.0, Math.abs(stop));
    const xs = [];
    const es = [];
    let i = 1;
    let j = supports.length > 0 && supports[0] === px[0] ? 1 : 0;
    let stopTaken = stop === px[0];
    let previous = px[0];
    let a = 0.0;
    let b = px[0];
    let width = 0.0;
    let widest = 0.0;
    let pieces = 0;
    let piece = 0;
    let k = 0;
    let left = true;
    let sloped = -1;
    let slope = 0.0;
    while (left) {
      let x;
      if (piece >= pieces) {
        a = b;
        let found = false;
        let best;
        for (;;) {
          best = Infinity;
          if (i < n && px[i] < stop) best = px[i];
          if (j < supports.length && supports[j] < best) best = supports[j];
          if (!stopTaken && stop < best) best = stop;
          if (best === Infinity) break;
          if (i < n && px[i] === best) i++;
          if (j < supports.length && supports[j] === best) j++;
          if (!stopTaken && stop === best) stopTaken = true;
          const kept = best - previous > tol;
          previous = best;
          if (kept) {
            found = true;
            break;
          }
        }
        if (found) {
          b = best;
          const gap = b - a;
          let count;
          if (gap <= step) {
            count = 1;
            width = gap;
          } else {
            count = Math.ceil(gap / step - 1e-9);
            if (count < 1) count = 1;
            width = gap / count;
          }
          if (width > widest) widest = width;
          pieces = count;
          piece = 0;
          x = a;
        } else {
          left = false;
          x = a;
        }
      } else x = a + piece * width;
      piece++;
      while (k + 1 < n && px[k + 1] <= x) k++;
      xs.push(x);
      if (x === px[k] || k + 1 >= n) es.push(pe[k]);
      else {
        if (sloped !== k) {
          slope = (pe[k + 1] - pe[k]) / (px[k + 1] - px[k]);
          sloped = k;
        }
        es.push(slope * (x - px[k]) + pe[k]);
      }
    }
    const count = xs.length;
    const spanOfStep = new Int32Array(count);
    const last = edges[edges.length - 1];
    for (let q = 0; q < count - 1; q++) {
      const middle = 0.5 * (xs[q] + xs[q + 1]) - bridgeStart;
      let span = 0;
      if (middle > 0.0 && middle < last) {
        span = 1;
        while (span < edges.length - 1 && edges[span] <= middle) span++;
      }
      spanOfStep[q] = span;
    }
    return { x: Float64Array.from(xs), elevation: Float64Array.from(es), spanOfStep, dtMax: widest / speed };
  }

  // ------------------------------------------------------------------------------ peaks
  /** Smallest value inside a step of the cubic Hermite interpolant (base.hermite_min). */
  function hermiteMin(a0, a1, d0, d1, h) {
    const m0 = h * d0;
    const m1 = h * d1;
    const rise = a1 - a0;
    const c3 = m0 + m1 - 2.0 * rise;
    const c2 = 3.0 * rise - 2.0 * m0 - m1;
    const c1 = m0;
    let best = Math.min(a0, a1);
    const qa = 3.0 * c3;
    const qb = 2.0 * c2;
    const qc = c1;
    const disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0) return best;
    const sign = qb > 0 || (qb === 0 && !Object.is(qb, -0)) ? 1 : -1;
    const q = -0.5 * (qb + sign * Math.sqrt(disc));
    for (let k = 0; k < 2; k++) {
      let t;
      if (k === 0) {
        if (qa === 0.0) continue;
        t = q / qa;
      } else {
        if (q === 0.0) continue;
        t = qc / q;
      }
      if (t > 0.0 && t < 1.0) best = Math.min(best, a0 + ((c3 * t + c2) * t + c1) * t);
    }
    return best;
  }

  /** Largest downward deflection within a step, displacements positive up (base.downward_peak). */
  function downwardPeak(m0, m1, v0, v1, h) {
    if (v0 * v1 <= 0.0) return -hermiteMin(m0, m1, v0, v1, h);
    return Math.max(-m0, -m1);
  }

  // ------------------------------------------------------------------------------ one coordinate
  /** Largest eigenvalue modulus of A at one wheel position (one_coordinate_step
   * .largest_root_modulus): Aberth's iteration on the characteristic quartic. */
  function largestRootModulus(c, psi, dpsi, coupled) {
    const { mv, kv, cv, mb, kb, cb, speed } = c;
    let kz = 0.0;
    let cz = 0.0;
    if (coupled) {
      kz = kv * psi + cv * speed * dpsi;
      cz = cv * psi;
    }
    const b1 = cb + psi * cz;
    const b0 = kb + psi * kz;
    const lead = mv * mb;
    const coef = [
      1.0,
      (mv * b1 + cv * mb) / lead,
      (mv * b0 + cv * b1 + kv * mb - psi * cz * cv) / lead,
      (cv * b0 + kv * b1 - psi * (cz * kv + kz * cv)) / lead,
      (kv * b0 - psi * kz * kv) / lead,
    ];
    const quadratic = (qa, qb, qc) => {
      const disc = qb * qb - 4.0 * qa * qc;
      const root = disc >= 0 ? [Math.sqrt(disc), 0] : [0, Math.sqrt(-disc)];
      const q = qb >= 0.0 ? [-0.5 * (qb + root[0]), -0.5 * root[1]] : [-0.5 * (qb - root[0]), 0.5 * root[1]];
      if (q[0] === 0 && q[1] === 0) return [[0, 0], [0, 0]];
      return [cdiv(q, [qa, 0]), cdiv([qc, 0], q)];
    };
    const z = [...quadratic(mv, cv, kv), ...quadratic(mb, b1, b0)];
    const scale = Math.abs(coef[4]) ** 0.25 + 1e-300;
    for (let i = 0; i < 4; i++) {
      const f = 1.0 + 1e-3 * (i + 1);
      z[i] = [z[i][0] * f + 1e-3 * scale * 0.5 * i, z[i][1] * f + 1e-3 * scale];
    }
    for (let iteration = 0; iteration < 200; iteration++) {
      let largest = 0.0;
      for (let i = 0; i < 4; i++) {
        let p = [coef[0], 0];
        let dp = [0, 0];
        for (let k = 1; k < 5; k++) {
          dp = cadd(cmul(dp, z[i]), p);
          p = cadd(cmul(p, z[i]), [coef[k], 0]);
        }
        const ratio = dp[0] !== 0 || dp[1] !== 0 ? cdiv(p, dp) : [0, 0];
        let pull = [0, 0];
        for (let jj = 0; jj < 4; jj++) if (jj !== i) pull = cadd(pull, cdiv([1, 0], csub(z[i], z[jj])));
        const change = cdiv(ratio, csub([1, 0], cmul(ratio, pull)));
        z[i] = csub(z[i], change);
        largest = Math.max(largest, Math.hypot(...change) / (Math.hypot(...z[i]) + 1e-300));
      }
      if (largest < 1e-15) break;
    }
    return Math.max(...z.map((w) => Math.hypot(w[0], w[1])));
  }

  function cadd(a, b) { return [a[0] + b[0], a[1] + b[1]]; }
  function csub(a, b) { return [a[0] - b[0], a[1] - b[1]]; }
  function cmul(a, b) { return [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]]; }
  function cdiv(a, b) {
    // Smith's algorithm, as CPython's complex division
    if (Math.abs(b[0]) >= Math.abs(b[1])) {
      if (b[0] === 0 && b[1] === 0) return [NaN, NaN];
      const r = b[1] / b[0];
      const d = b[0] + b[1] * r;
      return [(a[0] + a[1] * r) / d, (a[1] - a[0] * r) / d];
    }
    const r = b[0] / b[1];
    const d = b[0] * r + b[1];
    return [(a[0] * r + a[1]) / d, (a[1] * r - a[0]) / d];
  }

  /** omega_max over psi = 0, 1/4, ..., 1 with the half sine's slope (one_coordinate_step). */
  function oneCoordinateOmegaMax(bridge, vehicle, speed, coupled) {
    const c = {
      mv: vehicle.mass, kv: vehicle.stiffness, cv: vehicle.damping,
      mb: bridge.generalized_mass, kb: bridge.generalized_stiffness, cb: bridge.generalized_damping,
      // A depends on the speed only through the damper's convective term
      speed: coupled && vehicle.damping !== 0.0 ? speed : 0.0,
    };
    let largest = 0.0;
    for (let i = 0; i < 5; i++) {
      const psi = i / 4.0;
      const dpsi = (Math.PI / bridge.L) * Math.sqrt(Math.max(0.0, 1.0 - psi ** 2));
      largest = Math.max(largest, largestRootModulus(c, psi, dpsi, coupled));
    }
    return largest;
  }

  /** RK4 over the nodes, the study's state space (51)-(58), (72)-(81), (95)-(99); the
   * states (u_v, u_v', z_b, z_b') and the contact force R = m_v g + F at every node. */
  function oneCoordinateKernel(grid, bridge, vehicle, speed, start, coupled) {
    const x = grid.x;
    const elevation = grid.elevation;
    const n = x.length;
    const mv = vehicle.mass;
    const kv = vehicle.stiffness;
    const cv = vehicle.damping;
    const mb = bridge.generalized_mass;
    const kb = bridge.generalized_stiffness;
    const cb = bridge.generalized_damping;
    const weight = mv * g;
    const wave = Math.PI / bridge.L;
    const uv = new Float64Array(n);
    const vv = new Float64Array(n);
    const zb = new Float64Array(n);
    const zd = new Float64Array(n);
    const contact = new Float64Array(n);
    // the rows of A that are not 0 or 1: ydot = A y + B U + f, filled by fill()
    const M = new Float64Array(3 * 11);
    function fill(off, psi, dpsi) {
      let kz = 0.0;
      let cz = 0.0;
      if (coupled) {
        kz = kv * psi + cv * speed * dpsi;
        cz = cv * psi;
      }
      M[off + 0] = -kv / mv; // A[1,0]
      M[off + 1] = -cv / mv; // A[1,1]
      M[off + 2] = kz / mv; // A[1,2]
      M[off + 3] = cz / mv; // A[1,3]
      M[off + 4] = kv / mv; // B[1,0]
      M[off + 5] = cv / mv; // B[1,1]
      M[off + 6] = (psi * kv) / mb; // A[3,0]
      M[off + 7] = (psi * cv) / mb; // A[3,1]
      M[off + 8] = (-kb - psi * kz) / mb; // A[3,2]
      M[off + 9] = (-cb - psi * cz) / mb; // A[3,3]
      M[off + 10] = (-psi * mv * g) / mb; // f[3], with B[3,*] below
    }
    const Bv = new Float64Array(3 * 2);
    function fillB(slot, psi) {
      Bv[slot * 2] = (-psi * kv) / mb; // B[3,0]
      Bv[slot * 2 + 1] = (-psi * cv) / mb; // B[3,1]
    }
    const out = new Float64Array(4);
    function derivative(slot, z0, z1, z2, z3, e, r) {
      const o = slot * 11;
      out[0] = z1;
      out[1] = M[o] * z0 + M[o + 1] * z1 + M[o + 2] * z2 + M[o + 3] * z3 + M[o + 4] * e + M[o + 5] * r;
      out[2] = z3;
      out[3] = M[o + 6] * z0 + M[o + 7] * z1 + M[o + 8] * z2 + M[o + 9] * z3 +
        Bv[slot * 2] * e + Bv[slot * 2 + 1] * r + M[o + 10];
    }
    // psi and dpsi/dx at a station, into sh[0], sh[1] (zero off the bridge)
    const sh = new Float64Array(2);
    const shape = (xx, on) => {
      if (!on) {
        sh[0] = 0.0;
        sh[1] = 0.0;
        return;
      }
      const xi = xx - start;
      sh[0] = Math.sin(wave * xi);
      sh[1] = wave * Math.cos(wave * xi);
    };
    let y0 = elevation[0];
    let y1 = 0.0;
    let y2 = 0.0;
    let y3 = 0.0;
    uv[0] = y0;
    const summary = startSummary();
    const k1 = new Float64Array(4);
    const k2 = new Float64Array(4);
    const k3 = new Float64Array(4);
    for (let k = 0; k < n - 1; k++) {
      const xa = x[k];
      const xb = x[k + 1];
      const dx = xb - xa;
      const h = dx / speed;
      const rate = ((elevation[k + 1] - elevation[k]) / dx) * speed;
      const on = grid.spanOfStep[k] > 0;
      shape(xa, on);
      fill(0, sh[0], sh[1]);
      fillB(0, sh[0]);
      shape(0.5 * (xa + xb), on);
      fill(11, sh[0], sh[1]);
      fillB(1, sh[0]);
      shape(xb, on);
      fill(22, sh[0], sh[1]);
      fillB(2, sh[0]);
      const ea = elevation[k];
      const em = 0.5 * (elevation[k] + elevation[k + 1]);
      const eb = elevation[k + 1];
      derivative(0, y0, y1, y2, y3, ea, rate);
      k1.set(out);
      const force = weight + mv * k1[1];
      contact[k] = force;
      if (on) trackContact(summary, force, xa, h);
      derivative(1, y0 + 0.5 * h * k1[0], y1 + 0.5 * h * k1[1], y2 + 0.5 * h * k1[2], y3 + 0.5 * h * k1[3], em, rate);
      k2.set(out);
      derivative(1, y0 + 0.5 * h * k2[0], y1 + 0.5 * h * k2[1], y2 + 0.5 * h * k2[2], y3 + 0.5 * h * k2[3], em, rate);
      k3.set(out);
      derivative(2, y0 + h * k3[0], y1 + h * k3[1], y2 + h * k3[2], y3 + h * k3[3], eb, rate);
      y0 += (h * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + out[0])) / 6.0;
      y1 += (h * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + out[1])) / 6.0;
      y2 += (h * (k1[2] + 2.0 * k2[2] + 2.0 * k3[2] + out[2])) / 6.0;
      y3 += (h * (k1[3] + 2.0 * k2[3] + 2.0 * k3[3] + out[3])) / 6.0;
      uv[k + 1] = y0;
      vv[k + 1] = y1;
      zb[k + 1] = y2;
      zd[k + 1] = y3;
    }
    // the last node starts no step: its force uses the last step's matrices and slope
    const k = n - 1;
    const on = grid.spanOfStep[k - 1] > 0;
    shape(x[k], on);
    fill(22, sh[0], sh[1]);
    fillB(2, sh[0]);
    const slope = (elevation[k] - elevation[k - 1]) / (x[k] - x[k - 1]);
    derivative(2, y0, y1, y2, y3, elevation[k], slope * speed);
    contact[k] = weight + mv * out[1];
    if (on) trackContact(summary, contact[k], x[k], 0.0);
    return { vehicleDisplacement: uv, vehicleVelocity: vv, zb, zd, contact, summary };
  }

  // ------------------------------------------------------------------------------ modal
  /** Newmark average acceleration on the sprung mass and N modes (modal._kernel); the
   * implicit equations of a step reduce to one scalar equation for the suspension force. */
  function modalKernel(grid, bridge, vehicle, speed, start, coupled, modes) {
    const x = grid.x;
    const elevation = grid.elevation;
    const nNodes = x.length;
    const N = modes.count;
    const mv = vehicle.mass;
    const kv = vehicle.stiffness;
    const cv = vehicle.damping;
    const weight = mv * g;
    const eps = 1.0; // the convective term v phi' q is kept (convective=True)
    const cpl = coupled ? 1.0 : 0.0;
    const zeta = bridge.damping_ratio;
    const y = new Float64Array(N);
    const v = new Float64Array(N);
    const a = new Float64Array(N);
    const yt = new Float64Array(N);
    const vt = new Float64Array(N);
    const r = new Float64Array(N);
    const gvec = new Float64Array(N);
    const dd = new Float64Array(N);
    const phi = new Float64Array(N);
    const dphi = new Float64Array(N);
    const twoZw = new Float64Array(N);
    const w2 = new Float64Array(N);
    for (let i = 0; i < N; i++) {
      twoZw[i] = 2.0 * zeta * modes.omega[i];
      w2[i] = modes.omega[i] * modes.omega[i];
    }
    const q = new Float64Array(nNodes * N);
    const qd = new Float64Array(nNodes * N);
    const uvHist = new Float64Array(nNodes);
    const vvHist = new Float64Array(nNodes);
    const contact = new Float64Array(nNodes);
    let uv = elevation[0];
    let vv = 0.0;
    uvHist[0] = uv;
    const summary = startSummary();
    let forceB = 0.0;
    for (let k = 0; k < nNodes - 1; k++) {
      const xa = x[k];
      const xb = x[k + 1];
      const h = (xb - xa) / speed;
      const rate = ((elevation[k + 1] - elevation[k]) / (xb - xa)) * speed;
      const on = grid.spanOfStep[k] > 0;
      const beta = 0.25 * h * h;
      const gamma = 0.5 * h;
      if (on) shapeValues(modes, xa - start, phi, dphi);
      else {
        phi.fill(0);
        dphi.fill(0);
      }
      let ub = 0.0;
      let ubd = 0.0;
      for (let i = 0; i < N; i++) {
        ub += phi[i] * y[i];
        ubd += phi[i] * v[i] + eps * speed * dphi[i] * y[i];
      }
      const force = kv * (cpl * ub + elevation[k] - uv) + cv * (cpl * ubd + rate - vv);
      const av = force / mv;
      for (let i = 0; i < N; i++) a[i] = -twoZw[i] * v[i] - w2[i] * y[i] - phi[i] * (weight + force);
      contact[k] = weight + force;
      if (on) trackContact(summary, weight + force, xa, h);
      for (let i = 0; i < N; i++) {
        yt[i] = y[i] + h * v[i] + beta * a[i];
        vt[i] = v[i] + gamma * a[i];
      }
      const uvt = uv + h * vv + beta * av;
      const vvt = vv + gamma * av;
      if (on) shapeValues(modes, xb - start, phi, dphi);
      const sv = kv * beta + cv * gamma;
      ub = 0.0;
      ubd = 0.0;
      for (let i = 0; i < N; i++) {
        ub += phi[i] * yt[i];
        ubd += phi[i] * vt[i] + eps * speed * dphi[i] * yt[i];
      }
      const fTilde = kv * (cpl * ub + elevation[k + 1] - uvt) + cv * (cpl * ubd + rate - vvt);
      let denominator = 1.0 + sv / mv;
      let numerator = fTilde;
      for (let i = 0; i < N; i++) {
        dd[i] = 1.0 + twoZw[i] * gamma + w2[i] * beta;
        r[i] = -twoZw[i] * vt[i] - w2[i] * yt[i] - phi[i] * weight;
        gvec[i] = cpl * (sv * phi[i] + cv * eps * speed * beta * dphi[i]);
        denominator += (gvec[i] * phi[i]) / dd[i];
        numerator += (gvec[i] * r[i]) / dd[i];
      }
      forceB = numerator / denominator;
      const avb = forceB / mv;
      for (let i = 0; i < N; i++) {
        a[i] = (r[i] - phi[i] * forceB) / dd[i];
        y[i] = yt[i] + beta * a[i];
        v[i] = vt[i] + gamma * a[i];
        q[(k + 1) * N + i] = y[i];
        qd[(k + 1) * N + i] = v[i];
      }
      uv = uvt + beta * avb;
      vv = vvt + gamma * avb;
      uvHist[k + 1] = uv;
      vvHist[k + 1] = vv;
    }
    contact[nNodes - 1] = weight + forceB;
    if (grid.spanOfStep[nNodes - 2] > 0) trackContact(summary, weight + forceB, x[nNodes - 1], 0.0);
    return { vehicleDisplacement: uvHist, vehicleVelocity: vvHist, q, qd, contact, summary };
  }

  function modalTimeStep(bridge, vehicle, modes) {
    // the vehicle's circular frequency as scipy.linalg.eigh(k, m) gives it for one dof
    // (LAPACK's dsygst divides by the square of the Cholesky factor sqrt(m))
    const root = Math.sqrt(vehicle.mass);
    const highest = Math.sqrt(Math.max(vehicle.stiffness / (root * root), 0.0));
    let omega = highest;
    for (let i = 0; i < Math.min(2, modes.count); i++) omega = Math.max(omega, modes.omega[i]);
    return DEFAULT_OMEGA_DT / omega;
  }

  // ------------------------------------------------------------------------------ summaries
  function startSummary() {
    return { maxForce: -Infinity, maxAt: NaN, minForce: Infinity, tensionTime: 0.0, bridgeTime: 0.0 };
  }

  /** Account the contact force at station x held for h seconds (base.track_contact). */
  function trackContact(s, force, x, h) {
    if (force > s.maxForce) {
      s.maxForce = force;
      s.maxAt = x;
    }
    if (force < s.minForce) s.minForce = force;
    s.bridgeTime += h;
    if (force < 0.0) s.tensionTime += h;
  }

  // ------------------------------------------------------------------------------ the DAF
  /** The span DAFs of one crossing, by the definitions of issue 20 (DAF-DEFINITION.md).
   *
   * The largest downward displacement at each midspan over the whole run (Hermite-refined
   * inside each step) over the largest static one of the same model under the vehicle's
   * weight: one-coordinate psi(mid_j) z_b over W / k* (90)-(91); modal, the mode-acceleration
   * displacement sum phi_n(m_j) q_n + c_j, c_j = R [sum phi_n(m_j) phi_n(x) / omega_n^2 -
   * eta_j(x)], over W max eta_j (the exact beam), beside the N-mode series over its own
   * N-mode static.  A span never pushed down gets NaN.
   */
  function spanDafs(run) {
    const { bridge, vehicle, grid, speed, start } = run;
    const x = grid.x;
    const n = x.length;
    const weight = vehicle.mass * g;
    const nSpans = bridge.n;
    const peak = (u, rate, secant) => {
      let best = -Infinity;
      for (let k = 0; k < n - 1; k++) {
        const h = (x[k + 1] - x[k]) / speed;
        const s = secant ? (secant[k + 1] - secant[k]) / h : 0.0;
        const value = downwardPeak(u[k], u[k + 1], rate[k] + s, rate[k + 1] + s, h);
        if (value > best) best = value;
      }
      return best;
    };
    const daf = (p, staticValue) => (p > 0.0 ? p / staticValue : NaN);
    const out = { peak: [], static: [], daf: [], midspan: [] };
    if (run.model === "one-coordinate") {
      const staticValue = weight / bridge.generalized_stiffness;
      for (let j = 0; j < nSpans; j++) {
        const sign = j === 0 ? 1.0 : -1.0; // psi at midspan of span j + 1
        const u = run.zb.map((z) => sign * z);
        const rate = run.zd.map((z) => sign * z);
        const p = peak(u, rate, null);
        out.midspan.push(u);
        out.peak.push(p);
        out.static.push(staticValue);
        out.daf.push(daf(p, staticValue));
      }
      return out;
    }
    const modes = run.modes;
    const N = modes.count;
    const phiMid = [];
    const phi = new Float64Array(N);
    const dphi = new Float64Array(N);
    for (let j = 0; j < nSpans; j++) {
      shapeValues(modes, bridge.midspans[j], phi, dphi);
      phiMid.push(Float64Array.from(phi));
    }
    out.series = { peak: [], static: [], daf: [], midspan: [] };
    const seriesInfluence = (j, xi) => {
      shapeValues(modes, xi, phi, dphi);
      let s = 0.0;
      for (let i = 0; i < N; i++) s += (phiMid[j][i] * phi[i]) / modes.omega[i] ** 2;
      return s;
    };
    // the modes under the wheel at every node on the bridge, once for all spans
    const under = new Float64Array(n * N);
    const onBridge = new Uint8Array(n);
    for (let k = 0; k < n; k++) {
      const xi = x[k] - start;
      if (xi >= 0.0 && xi <= bridge.length && run.contact[k] !== 0.0) {
        onBridge[k] = 1;
        shapeValues(modes, xi, phi, dphi);
        for (let i = 0; i < N; i++) under[k * N + i] = phi[i] / modes.omega[i] ** 2;
      }
    }
    for (let j = 0; j < nSpans; j++) {
      const series = new Float64Array(n);
      const seriesRate = new Float64Array(n);
      const correction = new Float64Array(n);
      for (let k = 0; k < n; k++) {
        let s0 = 0.0;
        let s1 = 0.0;
        for (let i = 0; i < N; i++) {
          s0 += phiMid[j][i] * run.q[k * N + i];
          s1 += phiMid[j][i] * run.qd[k * N + i];
        }
        series[k] = s0;
        seriesRate[k] = s1;
        if (onBridge[k]) {
          let line = 0.0;
          for (let i = 0; i < N; i++) line += phiMid[j][i] * under[k * N + i];
          correction[k] = run.contact[k] * (line - exactInfluence(bridge, j, x[k] - start));
        }
      }
      const u = series.map((s, k) => s + correction[k]);
      const p = peak(u, seriesRate, correction);
      const staticValue = weight * exactStaticPeak(bridge);
      out.midspan.push(u);
      out.peak.push(p);
      out.static.push(staticValue);
      out.daf.push(daf(p, staticValue));
      const ps = peak(series, seriesRate, null);
      const staticSeries = weight * largestSeriesStatic(bridge, (xi) => seriesInfluence(j, xi), j);
      out.series.midspan.push(series);
      out.series.peak.push(ps);
      out.series.static.push(staticSeries);
      out.series.daf.push(daf(ps, staticSeries));
    }
    return out;
  }

  /** Largest N-mode static midspan deflection of span j under a unit load (modes
   * .largest_static_deflection): 201 samples over the span, then a golden-section refinement. */
  function largestSeriesStatic(bridge, line, j) {
    const a0 = bridge.supports[j];
    const a1 = bridge.supports[j + 1];
    let best = -Infinity;
    let at = 0;
    for (let i = 0; i <= 200; i++) {
      const xi = a0 + ((a1 - a0) * i) / 200;
      const value = line(xi);
      if (value > best) {
        best = value;
        at = i;
      }
    }
    let lo = a0 + ((a1 - a0) * Math.max(at - 1, 0)) / 200;
    let hi = a0 + ((a1 - a0) * Math.min(at + 1, 200)) / 200;
    const ratio = (Math.sqrt(5) - 1) / 2;
    let c = hi - ratio * (hi - lo);
    let d = lo + ratio * (hi - lo);
    let fc = line(c);
    let fd = line(d);
    while (hi - lo > 1e-12 * (a1 - a0)) {
      if (fc > fd) {
        hi = d;
        d = c;
        fd = fc;
        c = hi - ratio * (hi - lo);
        fc = line(c);
      } else {
        lo = c;
        c = d;
        fc = fd;
        d = lo + ratio * (hi - lo);
        fd = line(d);
      }
    }
    return Math.max(best, fc, fd);
  }

  // ------------------------------------------------------------------------------ simulate
  const DEFAULT_OMEGA_DT = 0.1;

  /** One crossing of the study's sprung mass (vbi_lib.simulate) from the SI setting of the
   * explorers' contract: {bridge: {spans, EI, mass_per_length, damping_ratio}, vehicle:
   * {mass, stiffness, damping}, speed, bridge_start, model, modes, coupled, road: {x,
   * elevation}}.  Throws RangeError naming the setting's key for what it cannot run. */
  function simulate(setting) {
    const bridge = makeBridge(setting.bridge);
    const vehicle = setting.vehicle;
    const speed = setting.speed;
    if (!(speed > RANGES.speed.hard[0] && speed <= RANGES.speed.hard[1])) {
      throw new RangeError(`speed=${speed} must be above 0 and at most 400 m/s`);
    }
    const road = setting.road;
    const start = setting.bridge_start;
    const stop = start + bridge.length + 0.0 + speed * 0.0;
    const first = road.x[0];
    const end = road.x[road.x.length - 1];
    if (start < first || start + bridge.length > end + 1e-9 * Math.max(1.0, Math.abs(start + bridge.length))) {
      throw new RangeError(`the profile (stations ${fmtG(first, 6)} to ${fmtG(end, 6)} m) does not ` +
        "cover the approach and the bridge");
    }
    const model = setting.model;
    const coupled = setting.coupled !== false;
    let dt;
    let modes = null;
    if (model === "one-coordinate") {
      if (setting.modes !== null && setting.modes !== undefined) {
        throw new RangeError(`modes=${setting.modes} applies to model='modal'`);
      }
      dt = DEFAULT_OMEGA_DT / oneCoordinateOmegaMax(bridge, vehicle, speed, coupled);
    } else if (model === "modal") {
      const count = setting.modes;
      if (!(Number.isInteger(count) && count >= 1 && count <= PORT_MAX_MODES)) {
        throw new RangeError(`modes=${count} must be a whole number from 1 to ${PORT_MAX_MODES}`);
      }
      modes = beamModes(bridge, count);
      dt = modalTimeStep(bridge, vehicle, modes);
    } else throw new RangeError(`model=${JSON.stringify(model)} must be 'one-coordinate' or 'modal'`);
    const grid = nodeGrid(road, bridge, speed, start, dt, stop);
    const kernel = model === "one-coordinate"
      ? oneCoordinateKernel(grid, bridge, vehicle, speed, start, coupled)
      : modalKernel(grid, bridge, vehicle, speed, start, coupled, modes);
    const run = { ...kernel, model, bridge, vehicle, grid, speed, start, modes };
    const spans = spanDafs(run);
    const weight = vehicle.mass * g;
    const s = kernel.summary;
    const minRatio = s.minForce / weight;
    const tension = s.bridgeTime > 0 ? s.tensionTime / s.bridgeTime : 0.0;
    const notes = [];
    const f = Math.sqrt(vehicle.stiffness / vehicle.mass) / (2 * Math.PI);
    const speedNote = outsideNote("speed", speed);
    if (speedNote) notes.push(speedNote);
    const spacing = unevenSpacing(road);
    if (spacing !== null) {
      const fMax = DEFAULT_OMEGA_DT / dt / (2.0 * Math.PI);
      const note = outsideNote("sample_spacing", (spacing * 2.0 * fMax) / speed,
        `profile spacing ${fmtG(spacing, 3)} m x 2 x ${fmtG(fMax, 3)} Hz / speed`);
      if (note) notes.push(note);
    }
    for (let j = 0; j < bridge.n; j++) {
      if (!(spans.peak[j] > 0)) {
        notes.push(`span ${j + 1} was never pushed down during the run (its midspan only rose): ` +
          "its DAF is not defined");
      }
    }
    if (spans.series) {
      for (let j = 0; j < bridge.n; j++) {
        const a = spans.daf[j];
        const b = spans.series.daf[j];
        if (Math.abs(a - b) > 0.01 * Math.abs(a)) {
          notes.push(`span ${j + 1}: the ${modes.count}-mode series gives a DAF of ${b.toFixed(3)}, ` +
            `more than 1 % from the mode-acceleration DAF ${a.toFixed(3)}: more modes would settle it`);
        }
      }
    }
    if (minRatio < 0) {
      notes.push(`contact lost: the contact force fell to ${minRatio.toFixed(2)} times the weight ` +
        `and was tensile for ${Math.round(tension * 100)}% of the time on the bridge; the model ` +
        "assumes the tyre never leaves the road, so this result is outside its validity (a real " +
        "tyre would lift off)");
    }
    return {
      model,
      bridge,
      vehicle: { ...vehicle, weight, frequency_hz: f },
      speed,
      bridge_start: start,
      position: grid.x,
      elevation: grid.elevation,
      span_of_step: grid.spanOfStep,
      dt: grid.dtMax,
      default_dt: dt,
      nodes: grid.x.length,
      vehicle_displacement: kernel.vehicleDisplacement,
      contact_force: kernel.contact,
      midspan_displacement: spans.midspan,
      peak: spans.peak,
      static_deflection: spans.static,
      daf: spans.daf,
      series: spans.series || null,
      modes: modes ? Array.from(modes.omega) : null,
      contact_force_amplification: s.maxForce / weight,
      peak_contact_position: s.maxAt,
      min_contact_force_ratio: minRatio,
      tension_fraction: tension,
      lost_contact: minRatio < 0,
      outside: notes.some((t) => t.includes("outside the intended range")),
      notes,
    };
  }

  /** The largest sample interval of a road that is not a straight line [m], else null
   * (base._uneven_spacing). */
  function unevenSpacing(road) {
    const x = road.x;
    const e = road.elevation;
    if (x.length <= 2) return null;
    let lo = Infinity;
    let hi = -Infinity;
    let big = 0;
    let widest = 0;
    for (let i = 0; i < x.length - 1; i++) {
      const s = (e[i + 1] - e[i]) / (x[i + 1] - x[i]);
      lo = Math.min(lo, s);
      hi = Math.max(hi, s);
      big = Math.max(big, Math.abs(s));
      widest = Math.max(widest, x[i + 1] - x[i]);
    }
    return hi - lo > 1e-9 * Math.max(1e-12, big) ? widest : null;
  }

  // ------------------------------------------------------------------------------ codes
  /** The design codes' DAF (1 + IM) for a bridge (widgets.readouts.code_allowances). */
  function codeAllowances(spanMetres, firstFrequencyHz) {
    const freq = [1.0, 2.5, 4.5, 6.0];
    const allowance = [0.2, 0.4, 0.4, 0.25];
    return {
      "AASHTO LRFD": 1.0 + 0.33,
      "AASHTO Standard": 1.0 + Math.min(50.0 / (spanMetres / ft + 125.0), 0.3),
      "OHBDC 1983": 1.0 + interp(firstFrequencyHz, freq, allowance),
    };
  }

  // ------------------------------------------------------------------------------ reports
  // vbi_lib.widgets.report_file: the setting as today's report keys (the same text)
  const REPORT = {
    dampingWarned: 0.5, // vehicle.damping_ratio: taken above it, and warned of
    maxSpeed: 150 * kph, // speeds
    maxSpeeds: 20,
    minApproach: 0.0, // profile.approach_length [m]: must be above it
  };

  /** Scenario.road_text: the road in words. */
  function roadText(v) {
    let text;
    if (v.road === "flat") text = "flat";
    else if (v.road === "harmonic") {
      text = `harmonic, wavelength ${fmtG(v.wavelength_ft, 6)} ft, amplitude ${fmtG(v.amplitude_in, 6)} in`;
    } else if (v.road === "bump") {
      text = `bump ${fmtG(v.bump_height_in, 6)} in high, ${fmtG(v.bump_width_ft, 6)} ft long, ` +
        `crest ${fmtG(v.bump_position_ft, 6)} ft from the first support`;
    } else if (v.road === "iso-class") text = `ISO 8608 class ${v.iso_class} (w = 2), seed ${v.seed}`;
    else text = `ISO 8608 C10 = ${fmtG(v.c10_e6, 6)}e-6 m³, w = ${fmtG(v.waviness, 6)}, seed ${v.seed}`;
    if (v.road_shift_ft) text += `, shifted ${fmtG(v.road_shift_ft, 6)} ft`;
    return text;
  }

  /** A profile coordinate in full: Python's f"{x:.16e}". */
  function coordinate(value) {
    const text = (value === 0 ? 0 : value).toExponential(16);
    return text.replace(/e([+-])(\d)$/, "e$10$2");
  }

  /** The report parameter file of an explorer's setting (report_file.report_files): an array
   * of {name, text} (the parameter file, and the deck profile it names if the road is not a
   * generated ISO class), with the array's note.  Throws RangeError naming the control for a
   * setting the report cannot take. */
  function reportParameters(v, speedsMph, name = "vbi-explorer") {
    const refuse = (control, shown, rule) =>
      new RangeError(`${control}=${shown} ${rule}; the report parameter file was not written`);
    const num = (x) => fmtG(x, 10);
    const speeds = [...new Set(speedsMph.map(Number))].sort((a, b) => a - b);
    if (!(speeds.length >= 1 && speeds.length <= REPORT.maxSpeeds)) {
      throw refuse("speeds", String(speeds.length), `must be 1 to ${REPORT.maxSpeeds} speeds`);
    }
    for (const speed of speeds) {
      if (!(speed * mph <= REPORT.maxSpeed)) {
        throw refuse("speed_mph", `${num(speed)} mph`, `is above the report's ` +
          `${num(REPORT.maxSpeed / mph)} mph (150 km/h): lower the speed`);
      }
    }
    const generated = v.road === "iso-class" && v.road_shift_ft === 0;
    const approach = v.approach_ft * ft;
    const lines = [
      "# Report parameters written by a vbi explorer from its current setting:",
      `#   vbi-report ${name}.yaml --output-dir reports/out`,
      "# The report runs the study's one-coordinate model, coupled (and decoupled as a",
      "# bound), with the study's sprung mass; the explorer ran " +
        (v.modes === 1 ? "the one-coordinate model" : `${v.modes} beam modes`) +
        (v.coupled ? ", coupled." : ", decoupled."),
    ];
    if (generated) {
      lines.push(`# The report draws its own ISO 8608 class ${v.iso_class} road (seed ${v.seed}) ` +
        "over the approach and the bridge: the same kind of road as the explorer's, not the same samples.");
    } else {
      lines.push(`# The deck the explorer drives (${roadText(v)}) is ${name}-deck.csv beside ` +
        "this file; the report puts its own flat approach before it.");
    }
    if (v.truck_damping > REPORT.dampingWarned) {
      lines.push(`# The suspension is damped ${num(v.truck_damping * 100)} % of critical, above ` +
        `the intended ${num(REPORT.dampingWarned * 100)} % (from 100 % it is overdamped): the ` +
        "report takes it and warns of it.");
    }
    if (approach <= REPORT.minApproach) {
      lines.push(`# The explorer's approach of ${num(v.approach_ft)} ft is none, so the report's ` +
        "own rule sets the approach.");
    }
    const bridgeText = `${num(v.span_ft)} ft span` + (v.n_spans === 2 ? " x 2" : "");
    lines.push(
      `title: "vbi explorer: ${bridgeText}, ${num(speeds[0])} mph"`,
      "bridge:",
      `  span: ${num(v.span_ft)} ft`,
      `  n_spans: ${v.n_spans}`,
      `  mass_per_length: ${num(v.bridge_weight_kip_per_ft)} kip/ft`,
      `  first_frequency: ${num(v.bridge_frequency_hz)} Hz`,
      `  damping_ratio: ${num(v.bridge_damping * 100)} %`,
      "vehicle:",
      `  mass: ${num(v.truck_weight_kip)} kip`,
      `  frequency: ${num(v.truck_frequency_hz)} Hz`,
      `  damping_ratio: ${num(v.truck_damping * 100)} %`,
      "profile:",
    );
    const files = [];
    if (generated) lines.push(`  iso_class: ${v.iso_class}`, `  seed: ${v.seed}`, "  spacing: 1 in");
    else {
      lines.push(`  file: ${name}-deck.csv`, "  length_unit: m");
      files.push({ name: `${name}-deck.csv`, text: deckText(v) });
    }
    if (approach > REPORT.minApproach) lines.push(`  approach_length: ${num(v.approach_ft)} ft`);
    lines.push("speeds: [" + speeds.map((s) => `${num(s)} mph`).join(", ") + "]");
    const out = [{ name: `${name}.yaml`, text: lines.join("\n") + "\n" }, ...files];
    const beside = files.length ? ` and ${files[0].name} beside it` : "";
    out.note = `Report parameters: ${name}.yaml${beside}; run vbi-report ${name}.yaml --output-dir reports/out.`;
    return out;
  }

  /** The deck the explorer drives, from the first support [m] (report_file._deck_text). */
  function deckText(v) {
    const { road } = scenarioRoad(v);
    const start = road.x[0] + v.approach_ft * ft;
    const span = v.span_ft * ft;
    const length = span * v.n_spans;
    const tolerance = 1e-9 * Math.max(1.0, length);
    const stations = [start];
    for (const x of road.x) if (x > start + tolerance && x < start + length - tolerance) stations.push(x);
    stations.push(start + length);
    const lines = ["# deck profile written by a vbi explorer: station from the first support [m], elevation [m]"];
    for (const x of stations) lines.push(`${coordinate(x - start)},${coordinate(interp(x, road.x, road.elevation))}`);
    return lines.join("\n") + "\n";
  }

  return {
    UNITS, RANGES, REPORT, PORT_MAX_MODES, reportParameters, roadText, ISO_CLASS_MEANS, ISO_BAND, ROADS, ROAD_SPACING, MAX_ROAD_SHIFT_FT,
    DEFAULT_OMEGA_DT, scenarioSetting, simulate, spanDafs, makeBridge, beamModes, shapeValues,
    exactInfluence, exactStaticPeak, nodeGrid, downwardPeak, oneCoordinateOmegaMax,
    modalTimeStep, codeAllowances, uniform, seedSequenceState, nextFastLen, inverseDft,
    isoRoad, stations, interp, outsideNote, fmtG,
  };
});

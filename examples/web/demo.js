// demo.js - the fov browser demo (examples/web): one ES module that is both the page's script
// and the Web Worker's (new Worker(import.meta.url, {type: 'module'})). No framework, no
// bundler, no SharedArrayBuffer: each worker instantiates its own copy of the WebAssembly
// modules (sdf.wasm, lp.wasm, pt.wasm, or their .simd.wasm builds), renders a band of rows
// through the headers' row-range entry points and posts the band's RGBA bytes back; the page
// composes them on one canvas.
//
// Hooks (window.fovDemo):
//   setGazeSource(fn)   fn(timeMs) -> {x, y} in [0, 1] of the image (or null: keep the last);
//                       an eye tracker or a recorded path; null returns to the selector's source
//   setGazeFilter(fn)   fn({x, y, t}) -> {x, y}, pixels of the rendered image: every gaze sample
//                       passes through it before the renderer (the default passes it through)
//   gazeState()         the simulated eye tracker's last sample: raw and filtered gaze (pixels),
//                       the margin (degrees), the filter's noise estimate; stepGaze(tMs) pushes
//                       one sample at time tMs and returns gazeState() (tests/web)
// The simulated eye tracker (gaze source "sim") goes through the headers' gaze filter and
// latency margin (GAZE INPUT of fovsdf.h / fovlp.h / fovpt.h) in gaze.wasm (web_gaze.c), which
// the page itself loads: the filtered gaze drives the renderer (checkbox "filter"), and the
// margin for the stated accuracy and the latency goes to the workers (checkbox "margin"),
// whose glue widens the fovea with fovsdf_ / fovlp_ / fovpt_config_gaze_margin.
//   setOptions(o), renderOnce(o), measure(o), pause(), resume(), restart(), getGaze(), stats(),
//   crashWorker(k)      used by tests/web (see each function)
// Query flags: ?simd=0 forces the scalar modules, ?workers=N, ?ignore_gaze=1 makes the glue
// foveate at the image centre whatever the gaze (the negative control of tests/web).

const IS_WORKER = typeof window === 'undefined';

// ---------------------------------------------------------------- worker -------------------
function workerMain() {
    let mods = null;   // { sdf, lp, pt } exports
    const mem = (m) => m.memory.buffer;
    const stats = (m) => Array.from(new Float64Array(mem(m), m.stats_ptr(), 8));
    const band = (m, w, y0, y1) => new Uint8Array(mem(m), m.rgba_ptr() + 4 * w * y0, 4 * w * (y1 - y0)).slice();
    let W = 0, H = 0, ignore = 0;
    const check = (r, what) => { if (r < 0) throw new Error(`${what} failed: fov_result ${r}`); return r; };

    async function init(a) {
        const load = async (name) => {
            const url = new URL(`${name}${a.simd ? '.simd' : ''}.wasm`, a.base);
            const res = await fetch(url);
            if (!res.ok) throw new Error(`cannot load ${url.pathname}: HTTP ${res.status}`);
            const { instance } = await WebAssembly.instantiate(await res.arrayBuffer(), {});
            return instance.exports;
        };
        mods = { sdf: await load('sdf'), lp: await load('lp'), pt: await load('pt') };
        ignore = a.ignoreGaze ? 1 : 0;
        return {};
    }

    const ops = {
        init,
        setup(a) {
            W = a.w; H = a.h;
            if (a.mod === 'sdf') {
                check(mods.sdf.sdf_setup(a.scene, W, H, ignore), 'sdf_setup');
                return { fovY: mods.sdf.sdf_fov_y(), foveaDeg: mods.sdf.sdf_fovea_deg() };
            }
            if (a.mod === 'lp') {
                check(mods.lp.lp_setup(a.scene, W, H, a.preset, a.taa ? 1 : 0, ignore), 'lp_setup');
                return { fovY: mods.lp.lp_fov_y() };
            }
            check(mods.pt.pt_setup(W, H, a.method, ignore), 'pt_setup');
            return { fovY: mods.pt.pt_fov_y(), foveaDeg: mods.pt.pt_fovea_deg() };
        },
        sdf(a) {
            const m = mods.sdf;
            check(m.sdf_render(a.method, a.gx, a.gy, a.cam, a.y0, a.y1, a.overlay ? 1 : 0, a.frame, a.margin || 0), 'sdf_render');
            return { y0: a.y0, y1: a.y1, rgba: band(m, W, a.y0, a.y1), stats: stats(m) };
        },
        lpShade(a) {   // every worker: begin the frame, shade its share of the sample rows
            const m = mods.lp;
            check(m.lp_begin(a.gx, a.gy, a.cam, a.margin || 0), 'lp_begin');
            const rows = m.lp_sample_rows_count();
            const r0 = Math.floor(rows * a.k / a.n), r1 = Math.floor(rows * (a.k + 1) / a.n);
            const n = check(m.lp_shade(r0, r1), 'lp_shade');
            return {
                slots: new Uint32Array(mem(m), m.lp_io_slot(), n).slice(),
                vals: new Float32Array(mem(m), m.lp_io_val(), 4 * n).slice(),
                stats: stats(m),
            };
        },
        lpFinish(a) {  // worker 0: scatter every share, reconstruct, TAA, encode
            const m = mods.lp;
            for (const p of a.parts) {
                new Uint32Array(mem(m), m.lp_io_slot(), p.slots.length).set(p.slots);
                new Float32Array(mem(m), m.lp_io_val(), p.vals.length).set(p.vals);
                check(m.lp_scatter(p.slots.length), 'lp_scatter');
            }
            check(m.lp_finish(a.overlay ? 1 : 0), 'lp_finish');
            return { y0: 0, y1: H, rgba: band(m, W, 0, H), stats: stats(m), discR: m.lp_disc_radius() };
        },
        lpRef(a) {
            const m = mods.lp;
            check(m.lp_reference(a.cam, a.y0, a.y1), 'lp_reference');
            return { y0: a.y0, y1: a.y1, rgba: band(m, W, a.y0, a.y1), stats: stats(m) };
        },
        pt(a) {
            const m = mods.pt;
            check(m.pt_render(a.which, a.gx, a.gy, a.cam, a.y0, a.y1, a.overlay ? 1 : 0, a.margin || 0), 'pt_render');
            return { y0: a.y0, y1: a.y1, rgba: band(m, W, a.y0, a.y1), stats: stats(m) };
        },
        ptRestart() { check(mods.pt.pt_restart(), 'pt_restart'); return {}; },
        // tests/web: an uncaught error in the worker, which the page must report as a death
        crash() { setTimeout(() => { throw new Error('worker crash requested (fovDemo.crashWorker)'); }, 0); return {}; },
    };

    self.onmessage = async (e) => {
        const { id, op, args } = e.data;
        try {
            const result = await ops[op](args || {});
            const transfer = result && result.rgba ? [result.rgba.buffer] : [];
            self.postMessage({ id, ok: true, result }, transfer);
        } catch (err) {
            self.postMessage({ id, ok: false, error: String(err && err.message || err) });
        }
    };
}

// ---------------------------------------------------------------- page ---------------------
function pageMain() {
    const $ = (id) => document.getElementById(id);
    const q = new URLSearchParams(location.search);
    const errBox = $('error');
    const showError = (msg) => {
        errBox.textContent = msg;
        errBox.hidden = false;
        document.body.dataset.state = 'error';
    };
    let readyResolve, readyReject;
    const ready = new Promise((res, rej) => { readyResolve = res; readyReject = rej; });
    ready.catch(() => {});   // reported in the page; tests read fovDemo.state

    if (typeof WebAssembly !== 'object' || typeof WebAssembly.instantiate !== 'function') {
        showError('This browser has no WebAssembly: the demo cannot run.');
        window.fovDemo = { ready, state: 'error' };
        readyReject(new Error('no WebAssembly'));
        return;
    }
    if (typeof Worker !== 'function') {
        showError('This browser has no Web Workers: the demo cannot run.');
        window.fovDemo = { ready, state: 'error' };
        readyReject(new Error('no Worker'));
        return;
    }
    // a tiny module with one SIMD128 instruction (i8x16.splat, i8x16.popcnt)
    const SIMD_PROBE = new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0,
        10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11]);
    const simdSupported = WebAssembly.validate(SIMD_PROBE);
    const useSimd = simdSupported && q.get('simd') !== '0';
    const ignoreGaze = q.get('ignore_gaze') === '1';

    const canvas = $('view'), ctx2d = canvas.getContext('2d');
    const over = $('overlay'), octx = over.getContext('2d');
    const opt = {
        mode: 'sdf', sdfMethod: 'cone_fov', scene: 0, preset: 2, taa: true, ptMethod: 'layers',
        res: '640x360', scale: 1, workers: Math.max(1, Math.min(8, navigator.hardwareConcurrency || 2)),
        overlay: false, ref: 'alternate', orbit: false, gazeSource: 'mouse', noiseDeg: 0.5, latencyMs: 50,
        gazeFilter: true, gazeMargin: true, accuracyDeg: 0.5, simSeed: 1,
    };
    if (q.get('workers')) opt.workers = Math.max(1, Math.min(16, parseInt(q.get('workers'), 10) || 1));
    if (q.get('res')) opt.res = q.get('res');
    if (q.get('mode')) opt.mode = q.get('mode');

    // ---- workers ----
    let workers = [], nextId = 1, pending = new Map(), W = 0, H = 0, info = {}, camAngle = 0, frameNo = 0;
    function call(k, op, args, transfer) {
        return new Promise((resolve, reject) => {
            const id = nextId++;
            pending.set(id, { resolve, reject, k });
            workers[k].postMessage({ id, op, args }, transfer || []);
        });
    }
    function killWorkers() {
        for (const w of workers) w.terminate();
        workers = [];
        for (const [, p] of pending) p.reject(new Error('workers restarted'));
        pending.clear();
    }
    async function startWorkers(n) {
        killWorkers();
        const base = new URL('./', import.meta.url).href;
        for (let k = 0; k < n; ++k) {
            const w = new Worker(import.meta.url, { type: 'module' });
            w.onmessage = (e) => {
                const p = pending.get(e.data.id);
                if (!p) return;
                pending.delete(e.data.id);
                if (e.data.ok) p.resolve(e.data.result); else p.reject(new Error(`worker ${k}: ${e.data.error}`));
            };
            const die = (e) => {
                const msg = `Worker ${k} died: ${e.message || 'no message'} (${e.filename || 'demo.js'}:${e.lineno || '?'})`;
                showError(msg);
                for (const [id, p] of pending) if (p.k === k) { pending.delete(id); p.reject(new Error(msg)); }
                if (e.preventDefault) e.preventDefault();
            };
            w.onerror = die;
            w.onmessageerror = () => die({ message: 'message could not be read' });
            workers.push(w);
        }
        await Promise.all(workers.map((_, k) => call(k, 'init', { simd: useSimd, base, ignoreGaze })));
    }

    // ---- geometry, gaze ----
    let mouse = { x: 0.5, y: 0.5 }, gaze = { x: 0, y: 0 }, customSource = null, gazeFilter = null;
    const simQueue = [];
    // gaze.wasm (web_gaze.c): the headers' gaze filter and margin, loaded at start
    let gazeMod = null, gazeState = null, rngState = 1;
    const rand = () => {   // mulberry32: the simulated tracker's noise repeats for a seed
        rngState = (rngState + 0x6D2B79F5) >>> 0;
        let t = rngState;
        t = Math.imul(t ^ (t >>> 15), t | 1);
        t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
        return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
    function pxPerDeg() {
        const fy = (info.fovY || 50) * Math.PI / 180;
        return (H / 2) / Math.tan(fy / 2) * Math.tan(Math.PI / 180);
    }
    function gaussian() {
        let u = 0, v = 0;
        while (u === 0) u = rand();
        while (v === 0) v = rand();
        return Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * v);
    }
    // the simulated eye tracker: the mouse, delayed by latencyMs, plus Gaussian noise of
    // noiseDeg degrees (standard deviation per axis; seeded by simSeed at each configure)
    function simulatedTracker(now) {
        simQueue.push({ t: now, x: mouse.x, y: mouse.y });
        while (simQueue.length > 1 && simQueue[1].t <= now - opt.latencyMs) simQueue.shift();
        const s = simQueue[0], sd = opt.noiseDeg * pxPerDeg();
        return { x: s.x + gaussian() * sd / W, y: s.y + gaussian() * sd / H };
    }
    function updateGaze(now) {
        let g = null;
        if (customSource) g = customSource(now);
        else if (opt.gazeSource === 'fixed') g = { x: 0.5, y: 0.5 };
        else if (opt.gazeSource === 'sim') g = simulatedTracker(now);
        else g = mouse;
        if (!g) return;
        let p = { x: Math.min(Math.max(g.x, 0), 1) * W, y: Math.min(Math.max(g.y, 0), 1) * H, t: now };
        if (gazeFilter) p = gazeFilter(p) || p;   // the gaze filter hook
        const raw = { x: Math.min(Math.max(p.x, 0), W), y: Math.min(Math.max(p.y, 0), H) };
        gaze = raw;
        gazeState = null;
        if (customSource || opt.gazeSource !== 'sim' || !gazeMod) return;
        // the simulated tracker's sample through the headers' filter (always fed, so that the
        // margin has its state; "filter" off: the renderer takes the raw sample)
        const r = gazeMod.gaze_push(now, raw.x, raw.y);
        if (r < 0) throw new Error(`gaze_push failed: fov_result ${r}`);
        const c = { x: gazeMod.gaze_x(), y: gazeMod.gaze_y() };
        const filtered = opt.gazeFilter ? { x: Math.min(Math.max(c.x, 0), W), y: Math.min(Math.max(c.y, 0), H) } : { ...raw };
        let marginDeg = 0;
        if (opt.gazeMargin) {
            marginDeg = gazeMod.gaze_margin(Math.max(0, opt.accuracyDeg || 0), Math.max(0, opt.latencyMs || 0));
            if (!(marginDeg >= 0)) throw new Error(`gaze_margin failed: fov_result ${marginDeg}`);
        }
        gaze = filtered;
        gazeState = { t: now, raw, filtered, cFiltered: c, marginDeg, filter: !!opt.gazeFilter, margin: !!opt.gazeMargin,
            noiseDeg: gazeMod.gaze_noise_deg(), saccade: gazeMod.gaze_saccade() === 1, resets: gazeMod.gaze_resets() };
    }
    const marginNow = () => (gazeState ? gazeState.marginDeg : 0);
    const toMouse = (cx, cy) => {
        const r = canvas.getBoundingClientRect();
        mouse = { x: (cx - r.left) / r.width, y: (cy - r.top) / r.height };
    };
    canvas.addEventListener('mousemove', (e) => toMouse(e.clientX, e.clientY));
    over.addEventListener('mousemove', (e) => toMouse(e.clientX, e.clientY));
    const onTouch = (e) => { if (e.touches.length) { toMouse(e.touches[0].clientX, e.touches[0].clientY); e.preventDefault(); } };
    over.addEventListener('touchstart', onTouch, { passive: false });
    over.addEventListener('touchmove', onTouch, { passive: false });
    window.addEventListener('keydown', (e) => {
        const step = 0.03;
        if (e.target && e.target.tagName === 'SELECT') return;
        if (e.key === 'ArrowLeft') mouse.x = Math.max(0, mouse.x - step);
        else if (e.key === 'ArrowRight') mouse.x = Math.min(1, mouse.x + step);
        else if (e.key === 'ArrowUp') mouse.y = Math.max(0, mouse.y - step);
        else if (e.key === 'ArrowDown') mouse.y = Math.min(1, mouse.y + step);
        else if (e.key === 'a' || e.key === 'A') camAngle -= 0.05;
        else if (e.key === 'd' || e.key === 'D') camAngle += 0.05;
        else return;
        e.preventDefault();
    });

    // ---- configuration ----
    // configured: what the workers are set up for ({ key, mode }), null while (re)configuring
    // or after a failure (tick renders nothing then). Everything that calls the workers outside
    // tick (configure, renderOnce, measure, restart) runs through serial(), one after the
    // other, and holds a pause (pauses > 0: tick renders nothing) while it runs; userPaused is
    // fovDemo.pause() / resume().
    let configured = null, busy = false, pauses = 0, userPaused = false, chain = Promise.resolve();
    const SDF_METHOD = { cone_fov: 8, fipr: 7 }, PT_METHOD = { layers: 1, selective: 3 };
    const idle = async () => { while (busy) await new Promise((r) => setTimeout(r, 5)); };
    function serial(fn) {   // fn runs after every earlier serial(fn) settled, with tick held off
        const p = chain.then(async () => {
            pauses++;
            try { await idle(); return await fn(); } finally { pauses--; }
        });
        chain = p.catch(() => {});
        return p;
    }
    async function configure() {   // only through serial()
        const o = { ...opt };
        const [rw, rh] = o.res.split('x').map((v) => parseInt(v, 10));
        const w = Math.max(16, Math.round(rw * o.scale)), h = Math.max(16, Math.round(rh * o.scale));
        const key = JSON.stringify([o.workers, useSimd]);
        const prevKey = configured ? configured.key : null;
        configured = null;
        if (prevKey !== key) await startWorkers(o.workers);
        W = w; H = h;
        canvas.width = W; canvas.height = H;
        over.width = W; over.height = H;
        for (const c of [canvas, over]) { c.style.width = `${rw}px`; c.style.height = `${rh}px`; }
        const mod = o.mode;
        const args = { mod, w: W, h: H, scene: o.scene, preset: o.preset, taa: o.taa, method: PT_METHOD[o.ptMethod] };
        const res = await Promise.all(workers.map((_, k) => call(k, 'setup', args)));
        info = res[0];
        rngState = (opt.simSeed >>> 0) || 1;
        simQueue.length = 0;
        const gr = gazeMod.gaze_setup(info.fovY || 50, W, H);
        if (gr < 0) throw new Error(`gaze_setup failed: fov_result ${gr}`);
        configured = { key, mode: mod };
        frameNo = 0;
        timing.fov.reset(); timing.ref.reset();
        updateGaze(performance.now());
    }
    function bands(align) {
        const n = workers.length, out = [];
        let per = Math.ceil(H / n / align) * align;
        for (let k = 0, y = 0; k < n; ++k, y += per) out.push([Math.min(y, H), Math.min(y + per, H)]);
        return out;
    }
    const sum = (rs, i) => rs.reduce((a, r) => a + r.stats[i], 0);

    // ---- one frame ----
    async function renderFrame(reference) {
        if (!configured) throw new Error('the demo is not set up (a configuration failed)');
        const mode = configured.mode;
        const g = { gx: gaze.x, gy: gaze.y, cam: camAngle, margin: reference ? 0 : marginNow() };
        const t0 = performance.now();
        let parts, s = {};
        if (mode === 'sdf') {
            const method = reference ? 4 : SDF_METHOD[opt.sdfMethod];
            parts = await Promise.all(bands(16).map(([y0, y1], k) =>
                call(k, 'sdf', { ...g, method, y0, y1, overlay: opt.overlay && !reference, frame: frameNo })));
            s.evalsPx = sum(parts, 0) / (W * H);
            s.traced = sum(parts, 2) / (W * H);
            if (!reference) s.foveaDeg = parts[0].stats[4];
        } else if (mode === 'lp') {
            if (reference) {
                parts = await Promise.all(bands(1).map(([y0, y1], k) => call(k, 'lpRef', { cam: camAngle, y0, y1 })));
                s.evalsPx = sum(parts, 0) / (W * H);
                s.traced = 1;
            } else {
                const shares = await Promise.all(workers.map((_, k) => call(k, 'lpShade', { ...g, k, n: workers.length })));
                const fin = await call(0, 'lpFinish', { parts: shares.map((p) => ({ slots: p.slots, vals: p.vals })), overlay: opt.overlay });
                parts = [fin];
                info.discR = fin.discR;
                s.evalsPx = sum(shares, 0) / (W * H);
                s.traced = fin.stats[3] / (W * H);
                s.foveaDeg = fin.stats[4];   // the gaze disc, degrees (0: this preset has none)
            }
        } else {
            parts = await Promise.all(bands(1).map(([y0, y1], k) =>
                call(k, 'pt', { ...g, which: reference ? 1 : 0, y0, y1, overlay: opt.overlay && !reference })));
            s.raysPx = sum(parts, 1) / (W * H);
            s.samplesPx = sum(parts, 0) / (W * H);
            s.traced = sum(parts, 2) / (W * H);
            s.accumulated = parts[0].stats[4];
            if (!reference) s.foveaDeg = parts[0].stats[6];
        }
        const ms = performance.now() - t0;
        const img = new ImageData(W, H);
        for (const p of parts) img.data.set(p.rgba, 4 * W * p.y0);
        frameNo++;
        s.marginDeg = reference ? 0 : marginNow();
        return { ms, img, s, gaze: { ...gaze } };
    }
    function draw(img) {
        ctx2d.putImageData(img, 0, 0);
    }
    let lastFoveaDeg = 0;   // the fovea the last foveated frame was rendered with (margin included)
    function drawOverlay() {
        octx.clearRect(0, 0, W, H);
        const lp = configured && configured.mode === 'lp';
        const r = lp ? (info.discR || 0) : (lastFoveaDeg || info.foveaDeg || 0) * pxPerDeg();
        octx.strokeStyle = 'rgba(255,255,255,0.8)';
        octx.lineWidth = 1;
        if ((opt.overlay || gazeState) && r > 0) { octx.beginPath(); octx.arc(gaze.x, gaze.y, r, 0, 2 * Math.PI); octx.stroke(); }
        if (gazeState) {
            // the fovea without the margin (dashed), and the raw sample (a red x)
            const r0 = lp ? (gazeState.marginDeg > 0 && lastFoveaDeg > 0 ? r * Math.tan((lastFoveaDeg - gazeState.marginDeg) * Math.PI / 180) / Math.tan(lastFoveaDeg * Math.PI / 180) : 0)
                : (info.foveaDeg || 0) * pxPerDeg();
            if (gazeState.marginDeg > 0 && r0 > 0) {
                octx.setLineDash([3, 3]); octx.beginPath(); octx.arc(gaze.x, gaze.y, r0, 0, 2 * Math.PI); octx.stroke(); octx.setLineDash([]);
            }
            const q = gazeState.raw;
            octx.strokeStyle = 'rgba(255,80,80,0.9)';
            octx.beginPath();
            octx.moveTo(q.x - 3, q.y - 3); octx.lineTo(q.x + 3, q.y + 3);
            octx.moveTo(q.x - 3, q.y + 3); octx.lineTo(q.x + 3, q.y - 3);
            octx.stroke();
            octx.strokeStyle = 'rgba(255,255,255,0.8)';
        }
        octx.beginPath();
        octx.moveTo(gaze.x - 5, gaze.y); octx.lineTo(gaze.x + 5, gaze.y);
        octx.moveTo(gaze.x, gaze.y - 5); octx.lineTo(gaze.x, gaze.y + 5);
        octx.stroke();
    }

    // ---- timing (mean over the last 20 frames of each kind) ----
    const mk = () => ({ v: [], s: {}, add(ms, s) { this.v.push(ms); if (this.v.length > 20) this.v.shift(); this.s = s; },
        ms() { return this.v.length ? this.v.reduce((a, b) => a + b, 0) / this.v.length : 0; }, reset() { this.v = []; this.s = {}; } });
    const timing = { fov: mk(), ref: mk() };
    let alternate = 0;
    function panel() {
        const f = timing.fov.ms(), r = timing.ref.ms();
        const fmt = (ms) => ms ? `${ms.toFixed(1)} ms (${(1000 / ms).toFixed(1)} fps)` : '-';
        $('t-fov').textContent = fmt(f);
        $('t-ref').textContent = fmt(r);
        $('t-ratio').textContent = f && r ? `${(r / f).toFixed(2)}x` : '-';
        const per = (s) => s.evalsPx !== undefined ? `${s.evalsPx.toFixed(1)} evaluations/px`
            : s.raysPx !== undefined ? `${s.raysPx.toFixed(2)} rays/px, ${s.samplesPx.toFixed(2)} samples/px` : '-';
        $('t-cost').textContent = `${per(timing.fov.s)} (reference ${per(timing.ref.s)})`;
        $('t-traced').textContent = timing.fov.s.traced !== undefined ? `${(100 * timing.fov.s.traced).toFixed(1)} %` : '-';
        $('t-acc').textContent = timing.fov.s.accumulated !== undefined ? `${timing.fov.s.accumulated} frames` : '-';
        const gs = gazeState;
        $('t-gaze').textContent = gs ? `raw (${gs.raw.x.toFixed(1)}, ${gs.raw.y.toFixed(1)}), ${gs.filter ? 'filtered' : 'unfiltered'} (${gs.filtered.x.toFixed(1)}, ${gs.filtered.y.toFixed(1)}) px; `
            + `margin ${gs.margin ? gs.marginDeg.toFixed(2) + ' deg' : 'off'}; fovea ${lastFoveaDeg.toFixed(2)} deg; noise est. ${gs.noiseDeg.toFixed(2)} deg${gs.saccade ? ', saccade' : ''}`
            : `(${gaze.x.toFixed(1)}, ${gaze.y.toFixed(1)}) px`;
        $('t-build').textContent = `${useSimd ? 'SIMD128' : 'scalar'}${simdSupported ? '' : ' (no SIMD128 in this browser)'}, ${workers.length} worker(s), ${W}x${H}`;
    }

    async function tick() {
        requestAnimationFrame(tick);
        if (busy || pauses > 0 || userPaused || !configured) return;
        busy = true;
        try {
            const now = performance.now();
            if (opt.orbit) camAngle = 0.3 * Math.sin(now / 4000);
            updateGaze(now);
            let reference = opt.ref === 'only';
            if (opt.ref === 'alternate') { reference = (alternate++ % 2) === 1; }
            const fr = await renderFrame(reference);
            (reference ? timing.ref : timing.fov).add(fr.ms, fr.s);
            if (!reference && fr.s.foveaDeg !== undefined) lastFoveaDeg = fr.s.foveaDeg;
            if (!reference || opt.ref === 'only') draw(fr.img);
            drawOverlay();
            panel();
        } catch (err) {
            if (!/workers restarted/.test(String(err))) showError(String(err.message || err));
        } finally {
            busy = false;
        }
    }
    // ---- controls ----
    function bind(id, key, conv) {
        const el = $(id);
        const get = () => (el.type === 'checkbox' ? el.checked : conv ? conv(el.value) : el.value);
        if (el.type === 'checkbox') el.checked = !!opt[key]; else el.value = String(opt[key]);
        el.addEventListener('change', async () => {
            opt[key] = get();
            syncControls();
            if (['mode', 'sdfMethod', 'overlay', 'ref', 'orbit', 'gazeSource', 'noiseDeg', 'latencyMs', 'gazeFilter', 'gazeMargin', 'accuracyDeg'].includes(key)) {
                if (key === 'mode') await reconfigure();
                timing.fov.reset(); timing.ref.reset();
                return;
            }
            await reconfigure();
        });
    }
    async function reconfigure() {
        try { await serial(configure); } catch (err) { showError(String(err.message || err)); }
    }
    const ptRestartAll = async () => {
        if (configured && configured.mode === 'pt') await Promise.all(workers.map((_, k) => call(k, 'ptRestart')));
    };
    function syncControls() {
        for (const el of document.querySelectorAll('[data-mode]')) el.hidden = el.dataset.mode !== opt.mode;
        $('sim-opts').hidden = opt.gazeSource !== 'sim';
        $('scene-label').hidden = opt.mode === 'pt';
    }
    const num = (v) => parseFloat(v);
    const int = (v) => parseInt(v, 10);
    const wsel = $('workers');
    for (let n = 1; n <= Math.max(8, navigator.hardwareConcurrency || 1, opt.workers); ++n) {
        const o = document.createElement('option');
        o.value = String(n); o.textContent = String(n);
        wsel.appendChild(o);
    }
    bind('mode', 'mode'); bind('sdf-method', 'sdfMethod'); bind('scene', 'scene', int); bind('preset', 'preset', int);
    bind('taa', 'taa'); bind('pt-method', 'ptMethod'); bind('res', 'res'); bind('scale', 'scale', num);
    bind('workers', 'workers', int); bind('overlay-toggle', 'overlay'); bind('ref', 'ref'); bind('orbit', 'orbit');
    bind('gaze-source', 'gazeSource'); bind('noise', 'noiseDeg', num); bind('latency', 'latencyMs', num);
    bind('gaze-filter', 'gazeFilter'); bind('gaze-margin', 'gazeMargin'); bind('accuracy', 'accuracyDeg', num);
    $('restart').addEventListener('click', async () => {
        try {
            await serial(async () => { await ptRestartAll(); timing.fov.reset(); timing.ref.reset(); });
        } catch (err) { showError(String(err.message || err)); }
    });
    syncControls();

    // ---- the API ----
    const api = {
        ready, state: 'loading', simd: useSimd, simdSupported, ignoreGaze,
        setGazeSource(fn) { customSource = typeof fn === 'function' ? fn : null; },
        setGazeFilter(fn) { gazeFilter = typeof fn === 'function' ? fn : null; },
        getGaze() { return { ...gaze }; },
        gazeState() { return gazeState ? JSON.parse(JSON.stringify(gazeState)) : null; },
        // one gaze sample at time tMs (after the last one's; the tracker's clock), as a frame
        // would take it; the animation should be paused. Returns gazeState().
        stepGaze(tMs) { updateGaze(tMs); return api.gazeState(); },
        getMouse() { return { ...mouse }; },
        options() { return { ...opt, width: W, height: H, workersRunning: workers.length }; },
        // set options (the control names of opt) and rebuild; resolves when set up
        setOptions: (o) => serial(async () => {
            Object.assign(opt, o);
            for (const [id, key] of [['mode', 'mode'], ['sdf-method', 'sdfMethod'], ['scene', 'scene'], ['preset', 'preset'],
                ['taa', 'taa'], ['pt-method', 'ptMethod'], ['res', 'res'], ['scale', 'scale'], ['workers', 'workers'],
                ['overlay-toggle', 'overlay'], ['ref', 'ref'], ['orbit', 'orbit'], ['gaze-source', 'gazeSource'],
                ['noise', 'noiseDeg'], ['latency', 'latencyMs'], ['gaze-filter', 'gazeFilter'], ['gaze-margin', 'gazeMargin'],
                ['accuracy', 'accuracyDeg']]) {
                const el = $(id);
                if (el.type === 'checkbox') el.checked = !!opt[key]; else el.value = String(opt[key]);
            }
            syncControls();
            await configure();
            return api.options();
        }),
        // the animation stops (after the frame in flight) until resume(); renderOnce and
        // measure still render, and leave it paused
        pause: async () => { userPaused = true; await idle(); },
        resume: () => { userPaused = false; },
        // `frames` frames (default 1) rendered, the last drawn on the canvas: the foveated view
        // or the reference; fovpt: both views restart first, so the frames accumulate; fovlp
        // with TAA: they build its history. Resolves with the last one's timing and counts.
        // The animation (unless paused) goes on afterwards and draws over it.
        renderOnce: (o = {}) => serial(async () => {
            updateGaze(performance.now());
            await ptRestartAll();
            let fr = null;
            for (let i = 0; i < Math.max(1, o.frames || 1); ++i) fr = await renderFrame(!!o.reference);
            if (!o.reference && fr.s.foveaDeg !== undefined) lastFoveaDeg = fr.s.foveaDeg;
            draw(fr.img);
            drawOverlay();
            return { ms: fr.ms, s: fr.s, gaze: fr.gaze, width: W, height: H };
        }),
        // frame times of the foveated and the reference frame, rendered interleaved in this page
        // (after a warm-up pair): the fastest of `frames` each (the least disturbed by other
        // load on the machine) and the median
        measure: (o = {}) => serial(async () => {
            const n = o.frames || 6, fov = [], ref = [];
            await renderFrame(false); await renderFrame(true);   // warm-up
            for (let i = 0; i < n; ++i) { fov.push((await renderFrame(false)).ms); ref.push((await renderFrame(true)).ms); }
            const med = (a) => a.slice().sort((x, y) => x - y)[a.length >> 1];
            return { msFov: Math.min(...fov), msRef: Math.min(...ref), medFov: med(fov), medRef: med(ref) };
        }),
        restart: () => serial(ptRestartAll),
        stats() { return { fovMs: timing.fov.ms(), refMs: timing.ref.ms(), fov: timing.fov.s, ref: timing.ref.s }; },
        // tests/web: make worker k throw an uncaught error (the page shows "Worker k died")
        crashWorker(k = 0) { return call(k, 'crash'); },
    };
    window.fovDemo = api;

    (async () => {
        try {
            try {
                const sz = await (await fetch(new URL('sizes.json', import.meta.url))).json();
                const kb = (b) => `${(b / 1024).toFixed(0)} KiB`;
                $('t-sizes').textContent = ['sdf', 'lp', 'pt'].map((m) => `${m} ${kb(sz[m])} / ${kb(sz[m + '.simd'])}`).join(', ') + ' (scalar / SIMD128)';
            } catch (e) { $('t-sizes').textContent = 'sizes.json missing'; }
            const gurl = new URL('gaze.wasm', import.meta.url);
            const gres = await fetch(gurl);
            if (!gres.ok) throw new Error(`cannot load ${gurl.pathname}: HTTP ${gres.status}`);
            gazeMod = (await WebAssembly.instantiate(await gres.arrayBuffer(), {})).instance.exports;
            await serial(configure);
            api.state = 'ready';
            document.body.dataset.state = 'ready';
            readyResolve(api);
            requestAnimationFrame(tick);
        } catch (err) {
            api.state = 'error';
            showError(`Could not start: ${err.message || err}`);
            readyReject(err);
        }
    })();
}

if (IS_WORKER) workerMain(); else pageMain();

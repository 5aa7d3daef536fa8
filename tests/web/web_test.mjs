// tests/web/web_test.mjs - the browser demo (examples/web) in a real browser: Debian's
// chromium, headless, driven by playwright-core (pinned in tests/web/package.json and
// package-lock.json; install: apt-get install chromium, then npm ci in tests/web).
//
//   node tests/web/web_test.mjs [--csv FILE] [--bench] [--debug DIR]
//
// Builds the page (examples/web/build.sh into build/web/), serves it from 127.0.0.1 (a static
// server in this process) and checks, each a PASS or FAIL line, closing with "N passed, N failed":
//   load         the page reaches ready (fovDemo.state) with the SIMD128 modules where the
//                browser validates the SIMD probe, and with the scalar ones under ?simd=0
//   gaze <mode>  the sharp region follows the mouse. The mouse moves (real input events) to two
//                distant points A and B of the canvas; at each the foveated frame is drawn and
//                read back from the canvas, and so is the full-resolution reference rendered by
//                the same module (sdf: the cone tracer at every pixel; lp: fovsdf at every pixel;
//                pt: UNIFORM at the layers' spp / Whitted 16 spp for selective; pt views start
//                afresh and accumulate PT_FRAMES frames). For a disc of radius R_DISC pixels
//                around each point P: err_on(P) = the mean absolute difference (0..255) against
//                the reference while the gaze is at P, err_off(P) = the same while the gaze is
//                at the other point. Pass when err_on(P) <= the mode's ON_MAX (the sharp region
//                equals the reference: 0.5 for the tracers that shade the same samples; larger
//                for selective, which supersamples towards its 16-spp reference) and
//                err_off(P) >= err_on(P) + OFF_GAP at both points, and the frames with the gaze
//                at A and at B differ.
//   control <mode>  the same page with ?ignore_gaze=1 (the glue foveates at the image centre
//                whatever the gaze): A and B are far from the centre, so err_on(P) > ON_MAX must
//                hold at both (the region at the gaze is not sharp), which a build that follows
//                the gaze violates; and the gaze check must fail
//   workers <mode>  1 and 2 workers give the same image, byte for byte (at 160x90; lp with TAA
//                off and on, 3 frames)
//   gaze hooks   fovDemo.setGazeSource and setGazeFilter drive the gaze; the simulated eye
//                tracker with 0 deg noise and 0 ms latency gives the mouse
//   gaze margin glue  the glue (in node) rejects a NaN, infinite or negative gaze margin;
//                gaze.wasm rejects a NaN sample and restarts its filter on a timestamp out of order
//   gaze filter  the simulated eye tracker (seeded noise 0.5 deg, a still mouse, 120 samples at
//                120 Hz through fovDemo.stepGaze): the headers' filter (gaze.wasm) at least halves
//                the RMS error of the gaze rendered with; the same seed gives the same samples
//   gaze filter off  the gaze rendered with is then the raw sample (the filter still runs)
//   gaze margin  sdf, lp C Fov, pt layers: the fovea radius the glue reports with the margin on
//                exceeds the one with it off by at least the margin
//   overlapping changes  setOptions and renderOnce called at once (as quick changes in the page
//                do) run one after the other without errors; the animation resumes after them
//   camera angle the glue (in node) rejects a NaN or infinite camera angle with an error code
//                and renders with a huge one (its reduction ends)
//   errors       no page errors and no console errors in any of the pages
//   shown <case> the page shows a clear error (#error) without WebAssembly (removed by an init
//                script), when a module fails to load (HTTP 404 for the .wasm files) and when a
//                worker dies (fovDemo.crashWorker: an uncaught error in the worker)
// --screenshot FILE also saves a PNG of the page (docs/img/web_demo.png; with --shot-only
// nothing else: make web-screenshot).
// It also measures frames per second of the foveated and the reference frame, interleaved in
// the page (fovDemo.measure: the fastest of 3 frames each, --bench 7) and writes them to --csv
// (default build/web_test/web.csv): mode,scene,width,height,workers,simd,fps_foveated,
// fps_reference,ratio. --bench measures the full grid (320x180 and 640x360, 1 and 2 workers,
// scalar and SIMD, every mode) for bench/results/web.csv (make bench-web) and skips the checks.
// Outside CI a missing chromium or node_modules prints SKIP with what to install; with CI=true
// it is a FAIL.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const ROOT = path.resolve(HERE, '../..');
const OUT = path.join(ROOT, 'build/web');
const IS_CI = process.env.CI === 'true';
const args = process.argv.slice(2);
const argOf = (name, def) => { const i = args.indexOf(name); return i >= 0 && i + 1 < args.length ? args[i + 1] : def; };
const BENCH = args.includes('--bench');
const CSV = argOf('--csv', path.join(ROOT, 'build/web_test/web.csv'));
const DEBUG = argOf('--debug', null);
const SHOT = argOf('--screenshot', null);

let passed = 0, failed = 0;
const pass = (name, detail) => { passed++; console.log(`PASS ${name}${detail ? `: ${detail}` : ''}`); };
const fail = (name, detail) => { failed++; console.log(`FAIL ${name}: ${detail}`); };
const done = () => { console.log(`${passed} passed, ${failed} failed`); process.exit(failed ? 1 : 0); };
// the watchdog: a hung browser call (page.evaluate has no timeout of its own) ends the run as a
// failure after WATCHDOG_S seconds (tests/web/run.sh also wraps node in `timeout 900`)
const WATCHDOG_S = BENCH ? 3600 : 600;
setTimeout(() => { fail('watchdog', `the test did not finish within ${WATCHDOG_S} s`); done(); }, WATCHDOG_S * 1000).unref();
// page.evaluate with a timeout (ms): the demo's renderOnce / measure / setOptions wait for the
// frame in flight and the workers; a hang fails the call instead of the whole run
const CALL_MS = BENCH ? 600000 : 120000;
function ev(page, fn, arg, ms = CALL_MS) {
    let timer;
    const t = new Promise((_, rej) => { timer = setTimeout(() => rej(new Error(`page call timed out after ${ms} ms`)), ms); });
    return Promise.race([page.evaluate(fn, arg), t]).finally(() => clearTimeout(timer));
}
const missing = (name, what) => {
    if (IS_CI) fail(name, `${what} (CI=true: a missing tool is a failure)`);
    else console.log(`SKIP ${name}: ${what}`);
};

// ---- tools ----------------------------------------------------------------------------------
function findChromium() {
    const cands = [process.env.CHROMIUM, 'chromium', 'chromium-browser', 'google-chrome'].filter(Boolean);
    for (const c of cands) {
        if (c.includes('/')) { if (fs.existsSync(c)) return c; continue; }
        const r = spawnSync('sh', ['-c', `command -v ${c}`], { encoding: 'utf8' });
        if (r.status === 0 && r.stdout.trim()) return r.stdout.trim();
    }
    return null;
}
const chromiumPath = findChromium();
if (!chromiumPath) { missing('browser', 'chromium not found (apt-get install chromium)'); done(); }
let chromium;
try {
    ({ chromium } = await import(pathToFileURL(path.join(HERE, 'node_modules/playwright-core/index.mjs')).href));
} catch (e) {
    missing('playwright', `playwright-core not installed (cd tests/web && npm ci): ${e.message.split('\n')[0]}`);
    done();
}
const build = spawnSync('bash', [path.join(ROOT, 'examples/web/build.sh'), OUT], { encoding: 'utf8' });
if (build.status !== 0) {
    const why = (build.stderr || build.stdout || '').split('\n').slice(0, 4).join(' | ');
    if (/not found|No such file/.test(why)) missing('build', `clang / wasm-ld missing (apt-get install clang lld): ${why}`);
    else fail('build', `examples/web/build.sh failed: ${why}`);
    done();
}
const sizes = JSON.parse(fs.readFileSync(path.join(OUT, 'sizes.json'), 'utf8'));
pass('build', `module sizes (bytes) ${Object.entries(sizes).map(([k, v]) => `${k} ${v}`).join(', ')}`);

// the glue's camera angle (from JS, unchecked there): NaN and infinities are rejected with an
// error code, a huge finite angle renders (its reduction ends); the modules in node, 32x32
if (!BENCH && !args.includes('--shot-only')) {
    const mod = async (n) => (await WebAssembly.instantiate(fs.readFileSync(path.join(OUT, `${n}.wasm`)), {})).instance.exports;
    const [sdf, lp, pt] = [await mod('sdf'), await mod('lp'), await mod('pt')];
    const setup = [sdf.sdf_setup(0, 32, 32, 0), lp.lp_setup(0, 32, 32, 2, 1, 0), pt.pt_setup(32, 32, 1, 0)];
    const calls = {
        sdf: (a) => sdf.sdf_render(8, 16, 16, a, 0, 32, 0, 0, 0), 'lp begin': (a) => lp.lp_begin(16, 16, a, 0),
        'lp reference': (a) => lp.lp_reference(a, 0, 32), pt: (a) => pt.pt_render(0, 16, 16, a, 0, 32, 0, 0),
    };
    const bad = [];
    for (const [name, f] of Object.entries(calls)) {
        for (const a of [NaN, Infinity, -Infinity]) if (!(f(a) < 0)) bad.push(`${name}(${a}) not rejected`);
        for (const a of [1e30, -3e38, 0.5]) { const r = f(a); if (r < 0) bad.push(`${name}(${a}) = ${r}`); }
    }
    if (setup.every((r) => r === 0) && bad.length === 0) pass('camera angle', 'NaN / inf rejected, 1e30 and -3e38 render (sdf, lp, pt glue)');
    else fail('camera angle', `setup ${setup.join(' ')}; ${bad.join(', ')}`);
    // the gaze margin from JS: NaN, infinite or negative rejected with an error code by the
    // glue, 0 and 2 degrees render; gaze.wasm: a NaN sample is an error, a timestamp out of
    // order restarts the filter (counted) and the sample is taken
    const mc = {
        sdf: (m) => sdf.sdf_render(8, 16, 16, 0, 0, 32, 0, 0, m), lp: (m) => lp.lp_begin(16, 16, 0, m),
        pt: (m) => pt.pt_render(0, 16, 16, 0, 0, 32, 0, m),
    };
    const mbad = [];
    for (const [name, f] of Object.entries(mc)) {
        for (const m of [NaN, Infinity, -1]) if (!(f(m) < 0)) mbad.push(`${name}(margin ${m}) not rejected`);
        for (const m of [2, 0]) { const r = f(m); if (r < 0) mbad.push(`${name}(margin ${m}) = ${r}`); }
    }
    const gz = await mod('gaze');
    const gs = [gz.gaze_setup(50, 32, 32), gz.gaze_push(100, 10, 12), gz.gaze_push(90, 11, 12), gz.gaze_push(95, NaN, 1)];
    if (!(gs[0] === 0 && gs[1] === 0 && gs[2] === 0 && gs[3] < 0 && gz.gaze_resets() === 1 && Math.abs(gz.gaze_x() - 11) < 1e-3))
        mbad.push(`gaze.wasm: setup/push/out of order/NaN = ${gs.join(' ')}, resets ${gz.gaze_resets()}, x ${gz.gaze_x()}`);
    if (mbad.length === 0) pass('gaze margin glue', 'margin NaN / inf / -1 rejected, 0 and 2 deg render (sdf, lp, pt); gaze.wasm: NaN rejected, out of order restarts');
    else fail('gaze margin glue', mbad.join(', '));
}

// ---- static server --------------------------------------------------------------------------
const MIME = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.json': 'application/json' };
const server = http.createServer((req, res) => {
    const p = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    const f = path.join(OUT, p === '/' ? 'index.html' : p);
    if (!f.startsWith(OUT) || !fs.existsSync(f) || fs.statSync(f).isDirectory()) { res.writeHead(404); res.end('not found'); return; }
    res.writeHead(200, { 'Content-Type': MIME[path.extname(f)] || 'application/octet-stream', 'Cache-Control': 'no-store' });
    fs.createReadStream(f).pipe(res);
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const BASE = `http://127.0.0.1:${server.address().port}/`;

const browser = await chromium.launch({
    executablePath: chromiumPath, headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage'],
});
const pageErrors = [];
async function openPage(query) {
    const page = await browser.newPage({ viewport: { width: 1100, height: 760 } });
    page.setDefaultTimeout(60000);
    page.on('pageerror', (e) => pageErrors.push(`${query}: page error ${e.message}`));
    page.on('console', (m) => { if (m.type() === 'error') pageErrors.push(`${query}: console error ${m.text()}`); });
    // it starts at 320x180 (the page's default is 640x360): the checks set their own size
    await page.goto(BASE + 'index.html' + (query ? `${query}&` : '?') + 'res=320x180');
    await page.waitForFunction(() => window.fovDemo && (window.fovDemo.state === 'ready' || window.fovDemo.state === 'error'), null, { timeout: 30000 });
    const st = await page.evaluate(() => window.fovDemo.state);
    if (st !== 'ready') throw new Error(`page ${query} did not start: ${await page.textContent('#error')}`);
    // the animation stops: only renderOnce / measure draw on the canvas the checks read
    await ev(page, () => window.fovDemo.pause());
    return page;
}

// ---- helpers --------------------------------------------------------------------------------
async function readCanvas(page) {
    const b64 = await ev(page, () => {
        const c = document.getElementById('view');
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let s = '';
        for (let i = 0; i < d.length; i += 0x8000) s += String.fromCharCode.apply(null, d.subarray(i, i + 0x8000));
        return btoa(s);
    });
    return new Uint8Array(Buffer.from(b64, 'base64'));
}
async function moveMouse(page, fx, fy) {
    const box = await page.locator('#overlay').boundingBox();
    await page.mouse.move(box.x + fx * box.width, box.y + fy * box.height, { steps: 4 });
    await page.waitForFunction(([x, y]) => {
        const m = window.fovDemo.getMouse();
        return Math.abs(m.x - x) < 0.01 && Math.abs(m.y - y) < 0.01;
    }, [fx, fy], { timeout: 5000 });
}
function discErr(img, ref, w, cx, cy, r) {
    let s = 0, n = 0;
    for (let y = Math.floor(cy - r); y <= Math.ceil(cy + r); ++y)
        for (let x = Math.floor(cx - r); x <= Math.ceil(cx + r); ++x) {
            if ((x + 0.5 - cx) ** 2 + (y + 0.5 - cy) ** 2 > r * r) continue;
            const i = 4 * (y * w + x);
            for (let c = 0; c < 3; ++c) { s += Math.abs(img[i + c] - ref[i + c]); n++; }
        }
    return s / n;
}
function savePng(name, img, w, h) {   // debugging aid: a PPM (no PNG encoder needed)
    if (!DEBUG) return;
    fs.mkdirSync(DEBUG, { recursive: true });
    const buf = Buffer.alloc(w * h * 3);
    for (let i = 0; i < w * h; ++i) { buf[3 * i] = img[4 * i]; buf[3 * i + 1] = img[4 * i + 1]; buf[3 * i + 2] = img[4 * i + 2]; }
    fs.writeFileSync(path.join(DEBUG, `${name}.ppm`), Buffer.concat([Buffer.from(`P6\n${w} ${h}\n255\n`), buf]));
}

// The modes. A and B: two distant points with detail under them (fractions of the image), both
// far from the centre (where ?ignore_gaze=1 foveates); r: the disc radius (pixels).
const PT_FRAMES = 2;
const MODES = [
    { name: 'sdf cone_fov', o: { mode: 'sdf', sdfMethod: 'cone_fov', scene: 0 }, onMax: 0.5, csv: ['sdf_cone_fov', 'primitives'] },
    { name: 'sdf fipr', o: { mode: 'sdf', sdfMethod: 'fipr', scene: 0 }, onMax: 0.5, csv: ['sdf_fipr', 'primitives'] },
    { name: 'lp C Fov', o: { mode: 'lp', preset: 2, taa: false, scene: 0 }, onMax: 0.5, csv: ['lp_c_fov', 'primitives'] },
    { name: 'pt layers', o: { mode: 'pt', ptMethod: 'layers' }, onMax: 0.5, csv: ['pt_layers', 'cornell'] },
    // selective supersampling changes only edges, and its zones reach 30 deg (most of the
    // image), so the gaze changes little: small discs (r 2) on the sphere's edge right of the
    // centre and the shadow edge at the lower left, where a scan of gaze points (320x180) found
    // err_on 0.9 / 1.5 with the gaze there and 3.4 / 3.4 with the gaze at the image centre
    { name: 'pt selective', o: { mode: 'pt', ptMethod: 'selective' }, onMax: 2.2, csv: ['pt_selective', 'cornell'],
      pa: [0.68, 0.36], pb: [0.3, 0.92], r: 2 },
];
const PA = [0.25, 0.72], PB = [0.75, 0.72];
const R_DISC = 5, OFF_GAP = 1.0;
const BASE_OPT = { res: '320x180', scale: 1, overlay: false, ref: 'off', orbit: false, gazeSource: 'mouse' };

async function gazeErrors(page, m, tag) {
    const o = await ev(page, (opt) => window.fovDemo.setOptions(opt), { ...BASE_OPT, workers: 2, ...m.o });
    const w = o.width, h = o.height, nf = m.o.mode === 'pt' ? PT_FRAMES : 1;
    const imgs = [], A = m.pa || PA, B = m.pb || PB, r = m.r || R_DISC;
    for (const [fx, fy] of [A, B]) {
        await moveMouse(page, fx, fy);
        await ev(page, (f) => window.fovDemo.renderOnce({ frames: f }), nf);
        imgs.push(await readCanvas(page));
    }
    await ev(page, (f) => window.fovDemo.renderOnce({ reference: true, frames: f }), nf);
    const ref = await readCanvas(page);
    savePng(`${tag}_${m.csv[0]}_A`, imgs[0], w, h); savePng(`${tag}_${m.csv[0]}_B`, imgs[1], w, h); savePng(`${tag}_${m.csv[0]}_ref`, ref, w, h);
    const pa = [A[0] * w, A[1] * h], pb = [B[0] * w, B[1] * h];
    let diff = 0;   // pixels where the frames with the gaze at A and at B differ
    for (let i = 0; i < imgs[0].length; i += 4)
        diff += imgs[0][i] !== imgs[1][i] || imgs[0][i + 1] !== imgs[1][i + 1] || imgs[0][i + 2] !== imgs[1][i + 2];
    return {
        onA: discErr(imgs[0], ref, w, pa[0], pa[1], r), offA: discErr(imgs[1], ref, w, pa[0], pa[1], r),
        onB: discErr(imgs[1], ref, w, pb[0], pb[1], r), offB: discErr(imgs[0], ref, w, pb[0], pb[1], r), diff,
    };
}
// the gaze check: sharp at the gaze, not sharp there with the gaze elsewhere, and the frames
// with the gaze at A and at B differ
const follows = (e, m) => e.diff > 0 && e.onA <= m.onMax && e.onB <= m.onMax && e.offA >= e.onA + OFF_GAP && e.offB >= e.onB + OFF_GAP;
// the control's check (?ignore_gaze=1, the foveation at the image centre): A and B are far
// from the centre, so the region at the gaze is not sharp at either point. A build that
// follows the gaze fails it (the gaze check above requires err_on <= onMax at both).
const unsharpAtGaze = (e, m) => e.onA > m.onMax && e.onB > m.onMax;
const fmtE = (e) => `err_on A ${e.onA.toFixed(2)} B ${e.onB.toFixed(2)}, err_off A ${e.offA.toFixed(2)} B ${e.offB.toFixed(2)}, frames A / B differ in ${e.diff} px`;

// the page's error reports: each case in a page of its own (its errors are expected)
async function errorCases() {
    const cases = [
        ['no WebAssembly', /no WebAssembly/, async (p) => { await p.addInitScript(() => { delete globalThis.WebAssembly; }); }, null],
        ['module load failure', /cannot load .*\.wasm: HTTP 404/, async (p) => {
            await p.route(/\.wasm$/, (r) => r.fulfill({ status: 404, body: 'missing' }));
        }, null],
        ['worker death', /Worker 1 died/, null, async (p) => { await ev(p, () => window.fovDemo.crashWorker(1)); }],
    ];
    for (const [name, re, before, after] of cases) {
        const page = await browser.newPage();
        try {
            if (before) await before(page);
            await page.goto(BASE + 'index.html?workers=2&res=320x180');
            if (after) {
                await page.waitForFunction(() => window.fovDemo && window.fovDemo.state === 'ready', null, { timeout: 30000 });
                await after(page);
            }
            await page.waitForFunction(() => !document.getElementById('error').hidden, null, { timeout: 15000 });
            const msg = await page.textContent('#error');
            if (re.test(msg)) pass(`shown ${name}`, `"${msg.trim().slice(0, 100)}"`);
            else fail(`shown ${name}`, `the page shows "${msg.trim().slice(0, 200)}", expected ${re}`);
        } catch (e) {
            fail(`shown ${name}`, `no error shown: ${String(e.message || e).split('\n')[0]}`);
        } finally {
            await page.close();
        }
    }
}

// the README's picture: the page at 640x360, fovsdf cone_fov with the overlay, gaze left of centre
async function screenshot(file) {
    const page = await browser.newPage({ viewport: { width: 1130, height: 600 } });
    await page.goto(BASE + 'index.html?workers=2');
    await page.waitForFunction(() => window.fovDemo && window.fovDemo.state === 'ready', null, { timeout: 30000 });
    await page.evaluate(() => window.fovDemo.setOptions({ mode: 'sdf', sdfMethod: 'cone_fov', scene: 0, res: '640x360', scale: 1,
        overlay: true, ref: 'alternate', orbit: false, gazeSource: 'mouse' }));
    await moveMouse(page, 0.36, 0.62);
    await page.waitForTimeout(4000);
    fs.mkdirSync(path.dirname(file), { recursive: true });
    await page.screenshot({ path: file });
    await page.close();
    pass('screenshot', `${path.relative(ROOT, file)}, ${fs.statSync(file).size} bytes`);
}

const rows = [];
async function measureRow(page, m, res, workers, simd) {
    const o = await ev(page, (opt) => window.fovDemo.setOptions(opt),
        { ...BASE_OPT, ...m.o, res, workers, ...(m.o.mode === 'lp' ? { taa: true } : {}) });
    await moveMouse(page, 0.5, 0.5);
    const t = await ev(page, (n) => window.fovDemo.measure({ frames: n }), BENCH ? 7 : 2);
    const ff = 1000 / t.msFov, fr = 1000 / t.msRef;
    rows.push([m.csv[0], m.csv[1], o.width, o.height, workers, simd ? 1 : 0, ff.toFixed(2), fr.toFixed(2), (ff / fr).toFixed(3)]);
    return { ff, fr };
}

try {
    if (SHOT && args.includes('--shot-only')) {
        await screenshot(SHOT);
    } else if (BENCH) {
        for (const simd of [true, false]) {
            const page = await openPage(simd ? '' : '?simd=0');
            const isSimd = await page.evaluate(() => window.fovDemo.simd);
            if (isSimd !== simd) { fail(`bench simd=${simd}`, 'the page did not pick the requested build'); continue; }
            for (const m of MODES) for (const res of ['320x180', '640x360']) for (const wk of [1, 2]) {
                const r = await measureRow(page, m, res, wk, simd);
                console.log(`# ${m.csv[0]} ${res} workers ${wk} ${simd ? 'simd' : 'scalar'}: ${r.ff.toFixed(1)} / ${r.fr.toFixed(1)} fps`);
            }
            await page.close();
        }
        pass('bench', `${rows.length} rows`);
    } else {
        const t0 = Date.now();
        let tp = t0;
        const phase = (what) => { const t = Date.now(); console.log(`# ${what}: ${((t - tp) / 1000).toFixed(1)} s`); tp = t; };
        const page = await openPage('');
        const simd = await page.evaluate(() => [window.fovDemo.simd, window.fovDemo.simdSupported]);
        if (simd[0] === simd[1]) pass('load', `SIMD128 ${simd[1] ? 'validated, SIMD build running' : 'not supported, scalar build running'}`);
        else fail('load', `simd supported ${simd[1]} but running simd=${simd[0]}`);
        for (const m of MODES) {
            const e = await gazeErrors(page, m, 'on');
            if (follows(e, m)) pass(`gaze ${m.name}`, fmtE(e));
            else fail(`gaze ${m.name}`, `${fmtE(e)} (need on <= ${m.onMax}, off >= on + ${OFF_GAP}, frames differ)`);
        }
        phase('gaze');
        // 1 and 2 workers at half the size (160x90: the bands and halos still split the image);
        // lp also with TAA (the page's default; worker 0 runs it over 3 frames of history)
        const WMODES = [...MODES.slice(0, 3), { name: 'lp C Fov TAA', o: { mode: 'lp', preset: 2, taa: true, scene: 0 } }, ...MODES.slice(3)];
        for (const m of WMODES) {
            const imgs = [], nf = m.o.mode === 'pt' ? PT_FRAMES : m.o.taa ? 3 : 1;
            for (const wk of [1, 2]) {
                await ev(page, (opt) => window.fovDemo.setOptions(opt), { ...BASE_OPT, scale: 0.5, ...m.o, workers: wk });
                await moveMouse(page, 0.3, 0.4);
                await ev(page, (f) => window.fovDemo.renderOnce({ frames: f }), nf);
                imgs.push(await readCanvas(page));
            }
            let diff = 0;
            for (let i = 0; i < imgs[0].length; ++i) diff += imgs[0][i] !== imgs[1][i];
            if (imgs[0].length > 0 && diff === 0) pass(`workers ${m.name}`, `1 and 2 workers: identical ${imgs[0].length / 4} pixels`);
            else fail(`workers ${m.name}`, `${diff} bytes differ between 1 and 2 workers`);
        }
        phase('workers');
        // the gaze hooks: a gaze source, a gaze filter, the simulated eye tracker (no noise, no
        // latency: the mouse itself)
        const hk = await ev(page, async () => {
            const d = window.fovDemo, o = d.options(), out = {};
            d.setGazeSource(() => ({ x: 0.1, y: 0.2 }));
            await d.renderOnce({});
            out.source = d.getGaze();
            d.setGazeFilter((p) => ({ x: p.x + 3, y: p.y }));
            await d.renderOnce({});
            out.filter = d.getGaze();
            d.setGazeFilter(null); d.setGazeSource(null);
            await d.setOptions({ gazeSource: 'sim', noiseDeg: 0, latencyMs: 0 });
            await d.renderOnce({});
            out.sim = d.getGaze(); out.mouse = d.getMouse();
            await d.setOptions({ gazeSource: 'mouse', noiseDeg: 1, latencyMs: 50 });
            out.w = o.width; out.h = o.height;
            return out;
        });
        const near = (a, x, y) => Math.abs(a.x - x) < 1e-3 && Math.abs(a.y - y) < 1e-3;
        if (near(hk.source, 0.1 * hk.w, 0.2 * hk.h) && near(hk.filter, 0.1 * hk.w + 3, 0.2 * hk.h) &&
            near(hk.sim, hk.mouse.x * hk.w, hk.mouse.y * hk.h))
            pass('gaze hooks', 'setGazeSource, setGazeFilter and the simulated tracker (0 deg, 0 ms) drive the gaze');
        else fail('gaze hooks', JSON.stringify(hk));
        // the simulated eye tracker through the headers' gaze filter (gaze.wasm): a still mouse,
        // seeded noise of 0.5 deg, samples at 120 Hz (fovDemo.stepGaze, animation paused).
        // The filtered gaze's RMS error against the mouse over samples 30..119 is at most half
        // the raw samples'; the same seed gives the same raw samples; filter off: the gaze
        // rendered with is the raw sample. Then per mode, the fovea / gaze disc / stride-1 layer
        // radius the glue reports (from its header's *_config_gaze_margin) with the margin on is
        // larger than with it off, by at least the margin (lp rounds it up to 0.25 deg).
        await moveMouse(page, 0.4, 0.45);
        const gf = await ev(page, async (BASE) => {
            const d = window.fovDemo, out = { modes: {} };
            const sim = { gazeSource: 'sim', noiseDeg: 0.5, latencyMs: 0, accuracyDeg: 0.5, simSeed: 7, gazeFilter: true, gazeMargin: true };
            await d.setOptions({ mode: 'sdf', sdfMethod: 'cone_fov', workers: 1, res: '320x180', scale: 0.5, ...sim });
            await d.pause();
            const o = d.options(), m = d.getMouse(), tx = m.x * o.width, ty = m.y * o.height;
            const run = () => {
                const t0 = performance.now() + 1000, st = [];
                for (let i = 0; i < 120; ++i) st.push({ s: d.stepGaze(t0 + i * 1000 / 120), g: d.getGaze() });
                return st;
            };
            const rms = (st, k) => Math.sqrt(st.slice(30).reduce((a, e) => a + (e.s[k].x - tx) ** 2 + (e.s[k].y - ty) ** 2, 0) / (st.length - 30));
            const a = run();
            out.raw = rms(a, 'raw'); out.filt = rms(a, 'filtered');
            out.rendered = a.every((e) => e.g.x === e.s.filtered.x && e.g.y === e.s.filtered.y);
            await d.setOptions({ simSeed: 7 });
            const b = run();
            out.same = a.every((e, i) => e.s.raw.x === b[i].s.raw.x && e.s.raw.y === b[i].s.raw.y);
            await d.setOptions({ gazeFilter: false });
            const c = run();
            out.offEq = c.every((e) => e.s.filtered.x === e.s.raw.x && e.s.filtered.y === e.s.raw.y && e.g.x === e.s.raw.x && e.g.y === e.s.raw.y);
            out.offFiltDiffers = c.some((e) => e.s.cFiltered.x !== e.s.raw.x);
            for (const [name, mo] of [['sdf', { mode: 'sdf' }], ['lp', { mode: 'lp', preset: 2, taa: false }], ['pt', { mode: 'pt', ptMethod: 'layers' }]]) {
                await d.setOptions({ ...mo, gazeFilter: true, gazeMargin: true });
                const on = await d.renderOnce({});
                await d.setOptions({ gazeMargin: false });
                const off = await d.renderOnce({});
                out.modes[name] = { on: on.s.foveaDeg, off: off.s.foveaDeg, margin: on.s.marginDeg, marginOff: off.s.marginDeg };
            }
            await d.setOptions({ ...BASE, gazeFilter: true, gazeMargin: true });
            out.error = document.getElementById('error').hidden ? '' : document.getElementById('error').textContent;
            return out;
        }, BASE_OPT);
        const fm = Object.entries(gf.modes).map(([k, v]) => `${k} ${v.off.toFixed(2)} -> ${v.on.toFixed(2)} deg (margin ${v.margin.toFixed(2)})`).join(', ');
        if (gf.filt * 2 <= gf.raw && gf.rendered && gf.same) pass('gaze filter', `still mouse, 0.5 deg seeded noise, 120 Hz: RMS raw ${gf.raw.toFixed(2)} px, filtered ${gf.filt.toFixed(2)} px (${(gf.raw / gf.filt).toFixed(1)}x), the filtered gaze drives the renderer, same seed same samples`);
        else fail('gaze filter', JSON.stringify(gf));
        if (gf.offEq && gf.offFiltDiffers) pass('gaze filter off', 'the gaze (and gazeState.filtered) is the raw sample while the C filter runs on');
        else fail('gaze filter off', JSON.stringify(gf));
        if (!gf.error && Object.values(gf.modes).every((v) => v.margin > 0 && v.marginOff === 0 && v.on > v.off && v.on >= v.off + v.margin - 1e-3))
            pass('gaze margin', fm);
        else fail('gaze margin', JSON.stringify(gf));
        // reconfigures that overlap (as two quick changes in the page do) run one after the
        // other: none fails, the last one's options hold, and renderOnce leaves the animation
        // running when it was running
        const cc = await ev(page, async () => {
            const d = window.fovDemo, out = {};
            d.resume();
            const ps = [d.setOptions({ mode: 'sdf', workers: 1, res: '320x180', scale: 0.5 }),
                d.setOptions({ mode: 'lp', taa: true, workers: 2 }), d.renderOnce({}),
                d.setOptions({ mode: 'pt', ptMethod: 'layers', workers: 3 }), d.renderOnce({ frames: 2 })];
            const rs = await Promise.allSettled(ps);
            out.rejected = rs.filter((r) => r.status === 'rejected').map((r) => String(r.reason)).join('; ');
            const o = d.options();
            out.last = `${o.mode} ${o.workersRunning} ${o.width}x${o.height}`;
            const t0 = performance.now();
            while (!(d.stats().fovMs > 0) && performance.now() - t0 < 30000) await new Promise((r) => setTimeout(r, 20));
            out.animates = d.stats().fovMs > 0;
            await d.pause();
            out.error = document.getElementById('error').hidden ? '' : document.getElementById('error').textContent;
            return out;
        });
        if (!cc.rejected && !cc.error && cc.last === 'pt 3 160x90' && cc.animates)
            pass('overlapping changes', `3 setOptions and 2 renderOnce at once: none failed, ends as ${cc.last}, the animation resumes`);
        else fail('overlapping changes', JSON.stringify(cc));
        for (const m of MODES) {
            const r = await measureRow(page, m, '320x180', 2, simd[0]);
            console.log(`# fps ${m.name} 320x180 2 workers ${simd[0] ? 'SIMD' : 'scalar'}: foveated ${r.ff.toFixed(1)}, reference ${r.fr.toFixed(1)}`);
        }
        phase('hooks, fps');
        await page.close();
        const ctl = await openPage('?ignore_gaze=1');
        for (const m of MODES) {
            const e = await gazeErrors(ctl, m, 'ctl');
            if (unsharpAtGaze(e, m) && !follows(e, m)) pass(`control ${m.name}`, `?ignore_gaze=1: not sharp at the gaze, err_on > ${m.onMax} at A and B (${fmtE(e)})`);
            else fail(`control ${m.name}`, `a build that ignores the gaze is sharp at a far gaze point or passed the gaze check (${fmtE(e)})`);
        }
        phase('control');
        await ctl.close();
        const sc = await openPage('?simd=0');
        const s0 = await sc.evaluate(() => window.fovDemo.simd);
        if (s0 === false) pass('load scalar', '?simd=0 runs the scalar modules'); else fail('load scalar', '?simd=0 still runs SIMD');
        await sc.close();
        phase('load scalar');
        await errorCases();
        phase('error cases');
        if (SHOT) await screenshot(SHOT);
        console.log(`# ${((Date.now() - t0) / 1000).toFixed(1)} s in the browser`);
    }
    if (pageErrors.length === 0) pass('errors', 'no page errors, no console errors');
    else fail('errors', pageErrors.slice(0, 5).join(' | '));
} catch (e) {
    fail('run', String(e && e.stack || e).split('\n').slice(0, 3).join(' | '));
} finally {
    await browser.close();
    server.close();
}
if (rows.length) {
    fs.mkdirSync(path.dirname(CSV), { recursive: true });
    const head = 'mode,scene,width,height,workers,simd,fps_foveated,fps_reference,ratio,browser\n';
    const ver = browser.version ? browser.version() : '';
    fs.writeFileSync(CSV, head + rows.map((r) => [...r, `chromium ${ver}`].join(',')).join('\n') + '\n');
    console.log(`# wrote ${path.relative(ROOT, CSV)} (${rows.length} rows)`);
}
done();

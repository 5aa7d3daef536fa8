// node_bench.mjs - the frames of native_bench.c rendered by the demo's WebAssembly modules in
// node (V8, one thread, no browser): the same calls, fastest of 7 after a warm-up pair,
// interleaved foveated / reference. Prints CSV rows with the columns of bench/results/web.csv
// (workers 1, simd "node-simd" or "node-scalar"); make bench-web-native appends them to
// bench/results/web_native.csv beside the native rows.
//   node examples/web/node_bench.mjs build/web simd|scalar [frames]
import fs from 'node:fs';
import path from 'node:path';

const dir = process.argv[2] || 'build/web';
const simd = process.argv[3] !== 'scalar';
const frames = parseInt(process.argv[4] || '7', 10);
const inst = (n) => new WebAssembly.Instance(new WebAssembly.Module(
    fs.readFileSync(path.join(dir, `${n}${simd ? '.simd' : ''}.wasm`))), {}).exports;
const sdf = inst('sdf'), lp = inst('lp'), pt = inst('pt');
const ok = (r, what) => { if (r < 0) throw new Error(`${what}: fov_result ${r}`); return r; };
const modes = [
    ['sdf_cone_fov', 'primitives', (w, h) => sdf.sdf_setup(0, w, h, 0), (w, h, ref, k) => sdf.sdf_render(ref ? 4 : 8, w / 2, h / 2, 0, 0, h, 0, k, 0)],
    ['sdf_fipr', 'primitives', (w, h) => sdf.sdf_setup(0, w, h, 0), (w, h, ref, k) => sdf.sdf_render(ref ? 4 : 7, w / 2, h / 2, 0, 0, h, 0, k, 0)],
    ['lp_c_fov', 'primitives', (w, h) => lp.lp_setup(0, w, h, 2, 1, 0), (w, h, ref) => {
        if (ref) return lp.lp_reference(0, 0, h);
        ok(lp.lp_begin(w / 2, h / 2, 0, 0), 'lp_begin');
        const n = ok(lp.lp_shade(0, lp.lp_sample_rows_count()), 'lp_shade');
        ok(lp.lp_scatter(n), 'lp_scatter');
        return lp.lp_finish(0);
    }],
    ['pt_layers', 'cornell', (w, h) => pt.pt_setup(w, h, 1, 0), (w, h, ref) => pt.pt_render(ref ? 1 : 0, w / 2, h / 2, 0, 0, h, 0, 0)],
    ['pt_selective', 'cornell', (w, h) => pt.pt_setup(w, h, 3, 0), (w, h, ref) => pt.pt_render(ref ? 1 : 0, w / 2, h / 2, 0, 0, h, 0, 0)],
];
for (const [name, scene, setup, frame] of modes) {
    for (const [w, h] of [[320, 180], [640, 360]]) {
        ok(setup(w, h), `${name} setup`);
        ok(frame(w, h, 0, 0), name); ok(frame(w, h, 1, 0), name);
        let tf = Infinity, tr = Infinity;
        for (let i = 0; i < frames; ++i) {
            let t = performance.now(); ok(frame(w, h, 0, i + 1), name); tf = Math.min(tf, performance.now() - t);
            t = performance.now(); ok(frame(w, h, 1, i + 1), name); tr = Math.min(tr, performance.now() - t);
        }
        const ff = 1000 / tf, fr = 1000 / tr;
        console.log([name, scene, w, h, 1, simd ? 'node-simd' : 'node-scalar', ff.toFixed(2), fr.toFixed(2), (ff / fr).toFixed(3)].join(','));
    }
}

// pt_rays.mjs - fovpt closest-hit Mrays/s natively and in WebAssembly on the same rays, in one
// run (make bench-pt-wasm builds the programs into build/ptw/ and runs this):
//   node bench/wasm/pt_rays.mjs [DIR=build/ptw] [ROUNDS=5] [W=320] [H=240]
// Rounds interleave the builds: native SSE2 (DIR/rays_native, one traversal pass after a
// warm-up, one process per round), native scalar (rays_native_scalar, FOVPT_NO_SIMD),
// wasm SIMD128 (rays.simd.wasm) and wasm scalar (rays.wasm) in node (V8, one thread, warmed
// up by one pass before the rounds); the fastest pass of each build is kept. Prints Mrays/s
// of the camera and the bounce rays, the ratio native SSE2 time / the build's time, and
// Times are CPU time (the native thread's; node's process, whose compiler threads are idle
// after the warm-up), so other load on the machine counts less than in wall-clock time.
// whether the build's hits (count and sum of t) equal native SSE2's: the same rays were traced.
import fs from 'node:fs';
import path from 'node:path';
import { execFileSync } from 'node:child_process';

const dir = process.argv[2] || 'build/ptw';
const rounds = parseInt(process.argv[3] || '5', 10);
const W = process.argv[4] || '320', H = process.argv[5] || '240';
const builds = [
    { name: 'native sse2', exe: 'rays_native' },
    { name: 'native scalar', exe: 'rays_native_scalar' },
    { name: 'wasm simd128', wasm: 'rays.simd.wasm' },
    { name: 'wasm scalar', wasm: 'rays.wasm' },
];
for (const b of builds) {
    b.best = [Infinity, Infinity];
    if (b.wasm) {
        b.x = new WebAssembly.Instance(new WebAssembly.Module(fs.readFileSync(path.join(dir, b.wasm))), {}).exports;
        const r = b.x.rays_setup(+W, +H);
        if (r !== 0) throw new Error(`${b.wasm} rays_setup: fov_result ${r}`);
        b.n = [b.x.rays_count(0), b.x.rays_count(1)];
        for (const k of [0, 1]) b.x.rays_trace(k);   // warm-up (V8 tiers up)
    }
}
for (let i = 0; i < rounds; ++i) {
    for (const b of builds) {
        if (b.exe) {
            const f = execFileSync(path.join(dir, b.exe), [W, H, '1'], { encoding: 'utf8' }).trim().split(/\s+/);
            b.n = [+f[2], +f[3]];
            b.sum = [`${f[4]} ${(+f[6]).toPrecision(12)}`, `${f[5]} ${(+f[7]).toPrecision(12)}`];
            for (const k of [0, 1]) b.best[k] = Math.min(b.best[k], +f[k]);
        } else {
            b.sum = [];
            for (const k of [0, 1]) {
                const t0 = process.cpuUsage();
                const hits = b.x.rays_trace(k);
                const dt = process.cpuUsage(t0);
                b.best[k] = Math.min(b.best[k], (dt.user + dt.system) / 1000);
                b.sum[k] = `${hits} ${b.x.rays_tsum(k).toPrecision(12)}`;
            }
        }
    }
}
const ref = builds[0];
console.log(`fovpt closest hit, 224x224 height field (100352 triangles), ${W}x${H}: ${ref.n[0]} camera + ${ref.n[1]} bounce rays, fastest of ${rounds} interleaved rounds, one thread`);
console.log('build          camera Mrays/s  bounce Mrays/s  camera: native sse2 time / time  bounce: same  same hits as native sse2');
for (const b of builds) {
    const m = [0, 1].map((k) => b.n[k] / b.best[k] / 1000);
    const q = [0, 1].map((k) => ref.best[k] / b.best[k]);
    const same = b.sum[0] === ref.sum[0] && b.sum[1] === ref.sum[1];
    console.log(`${b.name.padEnd(14)} ${m[0].toFixed(2).padStart(14)}  ${m[1].toFixed(2).padStart(14)}  ${q[0].toFixed(3).padStart(31)}  ${q[1].toFixed(3).padStart(12)}  ${same ? 'yes' : `NO (${b.sum.join(' / ')} vs ${ref.sum.join(' / ')})`}`);
}

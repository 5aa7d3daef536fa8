// run_wasi.mjs - runs a wasm32-wasi command module under Node's WASI (node:wasi, preview1).
// usage: node run_wasi.mjs PROGRAM.wasm [ARGS...]
// The program's stdout/stderr are the process's; its exit code becomes ours (a trap: 134).
// No directories are pre-opened and the environment is empty: the module gets no file access.
import { readFile } from 'node:fs/promises';
import process from 'node:process';
import { WASI } from 'node:wasi';

const [file, ...args] = process.argv.slice(2);
if (!file) {
  process.stderr.write('usage: node run_wasi.mjs PROGRAM.wasm [ARGS...]\n');
  process.exit(2);
}
const wasi = new WASI({ version: 'preview1', args: [file, ...args], env: {}, preopens: {},
                        returnOnExit: true });
try {
  const module = await WebAssembly.compile(await readFile(file));
  const imports = typeof wasi.getImportObject === 'function'
    ? wasi.getImportObject() : { wasi_snapshot_preview1: wasi.wasiImport };
  const instance = await WebAssembly.instantiate(module, imports);
  process.exitCode = wasi.start(instance);
} catch (e) {
  process.stderr.write(`run_wasi.mjs: ${e && e.stack ? e.stack : e}\n`);
  process.exitCode = 134;
}

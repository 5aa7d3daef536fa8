# fov - foveated rendering single-header libraries.
#   make demo    render the built-in scenes with every tracer into out/ and print the figures,
#                then a fovlp frame sequence (out/lp/) and a fovpt image (out/pt_basic.ppm)
#   make test    the whole test suite (closing line: "N passed, N failed");
#                make test T=fovsdf runs only the sections whose name contains fovsdf
#                (comma-separated patterns: T=fuzz, T=compile, T=examples,programs, T=metrics;
#                the section names are listed at the top of tests/run_all.sh)
#   make bench   the benchmarks (bench-sdf: run time against error, bench/results/sdf.csv;
#                bench-lp: fovlp samples, speed-up and error per ring, bench/results/lp.csv,
#                          moving camera and gaze, bench/results/lp_moving.csv;
#                bench-pt: fovpt methods per visual field, bench/results/pt.csv;
#                bench-perceptual: the three headers' savings at equal perceived quality per
#                          display, bench/results/perceptual.csv; BENCH_ARGS=--quick);
#                bench-gaze: the gaze filter, margin and prediction on generated gaze traces,
#                          bench/results/gaze.csv (about a second);
#                make bench-sdf FULL=1 / bench-lp FULL=1 / bench-pt FULL=1 run the whole grid;
#                make bench-sdf-native / bench-sdf-nosimd add rows of a -march=native and a
#                FOVSDF_NO_SIMD build to sdf.csv, bench-sdf-all runs the three builds
#   make fuzz    fuzz every tests/fuzz/fuzz_<target>.c with libFuzzer (clang) for FUZZ_SECONDS
#                (default 60) each; new inputs go to build/fuzz/corpus/<target>/, crashes to
#                build/fuzz/crashes/<target>/; make fuzz FUZZ_SECONDS=10 FUZZ_TARGETS=fovsdf
#   make install PREFIX=/usr/local (DESTDIR too): the three headers into $(PREFIX)/include/fov/,
#                fov.pc into $(PREFIX)/share/pkgconfig/ (nothing is built; CMake: docs/build.md)
#   make gallery the README's pictures: build/gallery renders PPMs into build/gallery_ppm/,
#                examples/gallery_png.py (python3, standard library) writes docs/img/*.png
#   make web     the browser demo (examples/web: the three headers in WebAssembly, the mouse as
#                the gaze) into build/web/; make web-serve serves it on 127.0.0.1 (WEB_PORT, 8000);
#                make bench-web: frames per second in headless chromium, bench/results/web.csv
#   make examples, make clean
# Nothing here is needed to *use* the headers: copy fovsdf.h into your project.

CC      ?= cc
CFLAGS  ?= -O2
STD     := -std=c99 -D_POSIX_C_SOURCE=200809L
WARN    := -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion
BUILD   := build

.PHONY: all demo test fuzz examples gallery bench bench-sdf bench-sdf-native bench-sdf-nosimd \
        bench-sdf-all bench-lp bench-pt bench-pt-throughput bench-pt-sampler bench-sdf-acuity bench-perceptual bench-gaze clean install \
        web web-serve bench-web bench-web-native web-screenshot bench-pt-wasm

all: examples

$(BUILD)/sdf_basic: examples/sdf_basic.c fovsdf.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) $(WARN) -I. $< -lm -o $@

$(BUILD)/sdf_scenes: examples/sdf_scenes.c fovsdf.h examples/common.h examples/fovmetrics.h examples/fovrun.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) -Wall -Wextra -I. $< -lm -pthread -o $@

$(BUILD)/bench_sdf: bench/bench_sdf.c bench/sdf_naive.h fovsdf.h tests/common/fovimg.h examples/common.h examples/fovmetrics.h examples/fovrun.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) -Wall -Wextra -I. $< -lm -pthread -o $@

# fovsdf's acuity-driven foveation against full resolution at one display (not in make bench)
$(BUILD)/bench_sdf_acuity: bench/bench_sdf_acuity.c fovsdf.h examples/fovmetrics.h examples/fovrun.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) -Wall -Wextra -I. $< -lm -pthread -o $@

bench-sdf-acuity: $(BUILD)/bench_sdf_acuity
	./$(BUILD)/bench_sdf_acuity $(ARGS)

$(BUILD)/pt_basic: examples/pt_basic.c fovpt.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) $(WARN) -I. $< -lm -o $@

# Embree (Debian libembree-dev) gives the reference ray throughput when it is installed
EMBREE  := $(if $(wildcard /usr/include/embree3/rtcore.h),-DPT_HAVE_EMBREE -lembree3)

$(BUILD)/bench_pt: bench/bench_pt.c examples/pt_scenes.h examples/fovmetrics.h examples/lp_pt_shade.h fovpt.h fovlp.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) -Wall -Wextra -I. $< -lm -pthread $(EMBREE) -o $@

# tinybvh (optional; a local copy of its tiny_bvh.h, never committed): make bench-pt
# TINYBVH=/path/to/tiny_bvh.h adds its throughput rows (bench/tinybvh_row.cpp, AVX2 + FMA)
CXX     ?= c++
TBVH_BIN := $(if $(TINYBVH),bench_pt_tinybvh,bench_pt)
$(BUILD)/tinybvh_row.o: bench/tinybvh_row.cpp $(TINYBVH)
	@mkdir -p $(BUILD)
	$(CXX) -O2 -mavx2 -mfma -w -DTINYBVH_HEADER='"$(abspath $(TINYBVH))"' -c $< -o $@

$(BUILD)/bench_pt_tinybvh: bench/bench_pt.c examples/pt_scenes.h fovpt.h $(BUILD)/tinybvh_row.o
	$(CC) $(STD) $(CFLAGS) -Wall -Wextra -I. -DPT_HAVE_TINYBVH $< $(BUILD)/tinybvh_row.o -lstdc++ -lm -pthread $(EMBREE) -o $@

# the throughput rows of three fovpt builds (default SSE2, AVX2, FOVPT_NO_SIMD), each beside
# Embree (and tinybvh with TINYBVH=...) in its own run: build/tp_<build>/pt.csv, pt_bvh.csv
bench-pt-throughput: $(if $(TINYBVH),$(BUILD)/tinybvh_row.o)
	@for v in sse2 avx2 nosimd; do \
	  case $$v in avx2) f="-mavx2 -mfma";; nosimd) f="-DFOVPT_NO_SIMD";; *) f="";; esac; \
	  mkdir -p $(BUILD)/tp_$$v; \
	  $(CC) $(STD) $(CFLAGS) -ffp-contract=off $$f -Wall -Wextra -I. bench/bench_pt.c \
	    $(if $(TINYBVH),-DPT_HAVE_TINYBVH $(BUILD)/tinybvh_row.o -lstdc++) -lm -pthread $(EMBREE) \
	    -o $(BUILD)/bench_pt_$$v || exit 1; \
	  echo "== fovpt build $$v"; \
	  ./$(BUILD)/bench_pt_$$v --throughput --out $(BUILD)/tp_$$v/pt.csv || exit 1; \
	done

# fovpt's samplers side by side: RANDOM and SOBOL, error against 2048 spp, frame times
$(BUILD)/pt_sampler: bench/pt_sampler.c examples/pt_scenes.h fovpt.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) -Wall -Wextra -I. $< -lm -o $@

bench-pt-sampler: $(BUILD)/pt_sampler
	./$(BUILD)/pt_sampler --out bench/results/pt_sampler.csv

# fovpt_config_acuity: samples per pixel at three displays, error by cause (bench/pt_acuity.c)
$(BUILD)/pt_acuity: bench/pt_acuity.c examples/pt_scenes.h examples/fovmetrics.h fovpt.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) -Wall -Wextra -I. $< -lm -o $@

$(BUILD)/lp_sdf: examples/lp_sdf.c examples/lp_sdf_shade.h fovlp.h fovsdf.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) $(WARN) -I. $< -lm -o $@

# fovlp + fovpt: path tracing at fovlp's log-polar positions (fovpt_shade_points), TAA
$(BUILD)/lp_pt: examples/lp_pt.c examples/lp_pt_shade.h examples/pt_scenes.h fovlp.h fovpt.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) $(WARN) -I. $< -lm -o $@

# stereo: two off-axis eyes side by side, each with its own gaze (issue 16)
$(BUILD)/sdf_stereo: examples/sdf_stereo.c fovsdf.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) $(WARN) -I. $< -lm -o $@

$(BUILD)/pt_stereo: examples/pt_stereo.c fovpt.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) $(WARN) -I. $< -lm -o $@

examples: $(BUILD)/sdf_basic $(BUILD)/sdf_scenes $(BUILD)/lp_sdf $(BUILD)/pt_basic $(BUILD)/lp_pt \
          $(BUILD)/sdf_stereo $(BUILD)/pt_stereo

demo: $(BUILD)/sdf_scenes $(BUILD)/lp_sdf $(BUILD)/pt_basic
	./$(BUILD)/sdf_scenes --out out
	@mkdir -p out/lp
	./$(BUILD)/lp_sdf --frames 8 --out out/lp
	./$(BUILD)/pt_basic > out/pt_basic.ppm
	@echo "images: out/ (fovsdf scenes per tracer), out/lp/ (fovlp frames), out/pt_basic.ppm (fovpt)"

# the README's gallery: deterministic (one thread, no clock, -ffp-contract=off)
$(BUILD)/gallery: examples/gallery.c examples/lp_sdf_shade.h examples/pt_scenes.h fovsdf.h fovlp.h fovpt.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) $(WARN) -ffp-contract=off -I. $< -lm -o $@

gallery: $(BUILD)/gallery $(BUILD)/pt_basic
	@mkdir -p $(BUILD)/gallery_ppm
	./$(BUILD)/gallery --out $(BUILD)/gallery_ppm
	./$(BUILD)/pt_basic --pair > $(BUILD)/gallery_ppm/pt_denoise.ppm
	python3 examples/gallery_png.py docs/img $(BUILD)/gallery_ppm/*.ppm

test:
	@T='$(T)' bash tests/run_all.sh

# tests/fuzz/run.sh reads FUZZ_SECONDS, FUZZ_TARGETS, FUZZ_MAX_LEN, FUZZ_TIMEOUT, FUZZ_FLAGS
fuzz:
	@$(if $(FUZZ_SECONDS),FUZZ_SECONDS=$(FUZZ_SECONDS)) $(if $(FUZZ_TARGETS),FUZZ_TARGETS="$(FUZZ_TARGETS)") bash tests/fuzz/run.sh fuzz

bench-sdf: $(BUILD)/bench_sdf
	@mkdir -p bench/results
	./$(BUILD)/bench_sdf $(if $(FULL),--full) $(BENCH_ARGS)

# the second builds of bench-sdf: -O2 -march=native, and -DFOVSDF_NO_SIMD (scalar); their rows
# are appended to bench/results/sdf.csv (columns simd and build tell them apart);
# make bench-sdf-all runs the three builds one after the other
$(BUILD)/bench_sdf_native: bench/bench_sdf.c bench/sdf_naive.h fovsdf.h tests/common/fovimg.h examples/common.h examples/fovmetrics.h examples/fovrun.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) -O2 -march=native -DBENCH_SDF_BUILD='"native"' -Wall -Wextra -I. $< -lm -pthread -o $@

$(BUILD)/bench_sdf_nosimd: bench/bench_sdf.c bench/sdf_naive.h fovsdf.h tests/common/fovimg.h examples/common.h examples/fovmetrics.h examples/fovrun.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) -DFOVSDF_NO_SIMD -DBENCH_SDF_BUILD='"nosimd"' -Wall -Wextra -I. $< -lm -pthread -o $@

bench-sdf-native: $(BUILD)/bench_sdf_native
	@mkdir -p bench/results
	./$(BUILD)/bench_sdf_native --append $(if $(FULL),--full) $(BENCH_ARGS)

bench-sdf-nosimd: $(BUILD)/bench_sdf_nosimd
	@mkdir -p bench/results
	./$(BUILD)/bench_sdf_nosimd --append $(if $(FULL),--full) $(BENCH_ARGS)

bench-sdf-all: bench-sdf
	$(MAKE) bench-sdf-native bench-sdf-nosimd

bench-pt: $(BUILD)/$(TBVH_BIN)
	@mkdir -p bench/results
	nice ./$(BUILD)/$(TBVH_BIN) $(if $(FULL),--full) $(BENCH_ARGS)

$(BUILD)/bench_lp: bench/bench_lp.c fovlp.h fovsdf.h examples/lp_sdf_shade.h examples/fovmetrics.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) -Wall -Wextra -I. $< -lm -o $@

bench-lp: $(BUILD)/bench_lp
	@mkdir -p bench/results
	./$(BUILD)/bench_lp $(if $(FULL),--full) $(BENCH_ARGS)

bench: bench-sdf bench-lp bench-pt bench-perceptual bench-gaze

# issue 16: fov_gaze_filter and the latency margin on generated gaze traces (bench/bench_gaze.c)
$(BUILD)/bench_gaze: bench/bench_gaze.c fovsdf.h bench/gaze_trace.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) $(WARN) -I. $< -lm -o $@

bench-gaze: $(BUILD)/bench_gaze
	@mkdir -p bench/results
	./$(BUILD)/bench_gaze --out bench/results/gaze.csv

# issue 13: fovsdf, fovlp and fovpt against full resolution by the eye-filtered FLIP of
# examples/fovmetrics.h at three displays (bench/bench_perceptual.c)
$(BUILD)/bench_perceptual: bench/bench_perceptual.c fovsdf.h fovlp.h fovpt.h examples/lp_sdf_shade.h examples/pt_scenes.h examples/fovmetrics.h examples/fovrun.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) -Wall -Wextra -I. $< -lm -pthread -o $@

# fovpt runs in a second process beside fovsdf and fovlp; the two CSVs are then joined
bench-perceptual: $(BUILD)/bench_perceptual
	@mkdir -p bench/results
	nice ./$(BUILD)/bench_perceptual --headers pt --out bench/results/perceptual.pt.tmp $(BENCH_ARGS) & \
	nice ./$(BUILD)/bench_perceptual --headers sdf,lp --out bench/results/perceptual.sdf.tmp $(BENCH_ARGS); \
	wait $$! && cat bench/results/perceptual.sdf.tmp > bench/results/perceptual.csv && \
	tail -n +2 bench/results/perceptual.pt.tmp >> bench/results/perceptual.csv && \
	rm -f bench/results/perceptual.sdf.tmp bench/results/perceptual.pt.tmp

clean:
	rm -rf $(BUILD) out

# the headers and a pkg-config file (cmake/fov.pc.in, as CMake's install writes it); the
# version is fovsdf.h's FOVSDF_VERSION_MAJOR.MINOR.PATCH
PREFIX     ?= /usr/local
INCLUDEDIR ?= $(PREFIX)/include/fov
PCDIR      ?= $(PREFIX)/share/pkgconfig
install:
	install -d '$(DESTDIR)$(INCLUDEDIR)' '$(DESTDIR)$(PCDIR)'
	install -m 644 fovsdf.h fovlp.h fovpt.h '$(DESTDIR)$(INCLUDEDIR)/'
	@v=$$(for p in MAJOR MINOR PATCH; do sed -n "s/^#define FOVSDF_VERSION_$$p  *\([0-9][0-9]*\).*/\1/p" fovsdf.h; done | paste -sd.); \
	case "$$v" in [0-9]*.[0-9]*.[0-9]*) ;; *) echo "make install: no FOVSDF_VERSION_* in fovsdf.h" >&2; exit 1;; esac; \
	sed -e 's|@FOV_PC_PREFIX@|$(PREFIX)|' \
	    -e 's|@FOV_PC_INCLUDEDIR@|$(patsubst $(PREFIX)/%,$${prefix}/%,$(INCLUDEDIR))|' \
	    -e "s|@FOV_PC_VERSION@|$$v|" cmake/fov.pc.in > '$(DESTDIR)$(PCDIR)/fov.pc' && \
	echo "fov $$v: $(DESTDIR)$(INCLUDEDIR)/{fovsdf,fovlp,fovpt}.h, $(DESTDIR)$(PCDIR)/fov.pc"

# issue 10 stress scenes: pixels behind the first surface, false hits, misses, evaluations and
# time per method at 1 and 4 spp (bench/results/stress.csv; BENCH_ARGS e.g. --size 320 180)
.PHONY: bench-stress
$(BUILD)/bench_stress: bench/bench_stress.c fovsdf.h tests/common/fovstress.h
	@mkdir -p $(BUILD)
	$(CC) $(STD) $(CFLAGS) $(WARN) -I. $< -lm -o $@

bench-stress: $(BUILD)/bench_stress
	@mkdir -p bench/results
	nice ./$(BUILD)/bench_stress $(BENCH_ARGS)

# issue 15: the browser demo (examples/web/build.sh: clang --target=wasm32 -ffreestanding
# -nostdlib, scalar and SIMD128 builds of each module) and its server; tests/web/web_test.mjs
# drives it in headless chromium (make test T=web; bench-web writes bench/results/web.csv)
WEB_PORT ?= 8000
web:
	bash examples/web/build.sh $(BUILD)/web

web-serve: web
	@echo "fov web demo: http://127.0.0.1:$(WEB_PORT)/  (Ctrl-C stops the server)"
	cd $(BUILD)/web && python3 -m http.server $(WEB_PORT) --bind 127.0.0.1

bench-web: web
	@mkdir -p bench/results
	node tests/web/web_test.mjs --bench --csv bench/results/web.csv

# the README's picture of the page (headless chromium, tests/web)
web-screenshot: web
	node tests/web/web_test.mjs --screenshot docs/img/web_demo.png --shot-only

# the same frames natively (examples/web/native_bench.c: the demo's glue built with gcc and
# libm, one thread; FOV_NO_LIBM natively has no hardware square root) and by the same WebAssembly modules in node (examples/web/node_bench.mjs, V8, one
# thread): bench/results/web_native.csv, for the WebAssembly-against-native comparison
bench-web-native: web
	@mkdir -p $(BUILD) bench/results
	@echo "mode,scene,width,height,workers,simd,fps_foveated,fps_reference,ratio" > bench/results/web_native.csv
	for m in sdf lp pt; do \
	    $(CC) $(STD) -O2 -ffp-contract=off -Wall -Wextra -DWEB_NATIVE -DWEB_NATIVE_LIBM -DWEB_MODULE_$$m \
	        examples/web/native_bench.c -lm -o $(BUILD)/native_bench_$$m && \
	        ./$(BUILD)/native_bench_$$m >> bench/results/web_native.csv || exit 1; \
	done
	node examples/web/node_bench.mjs $(BUILD)/web simd >> bench/results/web_native.csv
	node examples/web/node_bench.mjs $(BUILD)/web scalar >> bench/results/web_native.csv
	cat bench/results/web_native.csv

# fovpt closest-hit Mrays/s on the same rays: native gcc (SSE2 and FOVPT_NO_SIMD, libm) and
# the browser demo's wasm32 builds (scalar and SIMD128, FOV_NO_LIBM) in node, interleaved
# (bench/wasm/pt_rays.c, bench/wasm/pt_rays.mjs; a few seconds)
WASM_FLAGS := --target=wasm32 -std=c99 -O2 -ffp-contract=off -ffreestanding -nostdlib \
	-Wall -Wextra -Wshadow -Wdouble-promotion -Werror -Wl,--no-entry -Wl,--strip-all \
	-Wl,-z,stack-size=1048576
bench-pt-wasm: WASM_FLAGS += -Wno-unused-function
bench-pt-wasm: WARN += -Wno-unused-function
bench-pt-wasm:
	@mkdir -p $(BUILD)/ptw
	$(CC) $(STD) -O2 -ffp-contract=off $(WARN) -DWEB_NATIVE bench/wasm/pt_rays.c -lm -o $(BUILD)/ptw/rays_native
	$(CC) $(STD) -O2 -ffp-contract=off $(WARN) -DWEB_NATIVE -DFOVPT_NO_SIMD bench/wasm/pt_rays.c -lm \
	    -o $(BUILD)/ptw/rays_native_scalar
	clang $(WASM_FLAGS) bench/wasm/pt_rays.c -o $(BUILD)/ptw/rays.wasm
	clang $(WASM_FLAGS) -msimd128 bench/wasm/pt_rays.c -o $(BUILD)/ptw/rays.simd.wasm
	nice node bench/wasm/pt_rays.mjs $(BUILD)/ptw

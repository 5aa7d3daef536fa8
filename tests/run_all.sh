#!/usr/bin/env bash
# The fov test suite. Runs every section, prints each section's FAIL/SKIP lines and its
# summary, and closes with the line "N passed, N failed" (the sum over the sections).
# Exit status 1 when anything failed. Logs: build/logs/<section>.log.
# Under CI=true a missing toolchain is a failure, never a skip (tests/compile and
# tests/xtarget enforce that).
#
# Selection: T=<pattern>[,<pattern>...] (make test T=fovsdf) runs only the sections whose name
# contains one of the patterns (shell glob characters allowed), and builds only their programs;
# the closing line stays. A T that matches no section exits 2 and lists the sections. Without
# T everything runs. The sections, in order:
#   unit tests (three_builds NAME: NAME, NAME_nolibm, NAME_sanitizers):
#     unit_fovsdf scene_fovsdf accel_fovsdf contract_fovsdf heads_fovsdf props_fovsdf naive_sdf,
#     acuity_fovsdf, prune_fovsdf,
#     fov_cells_sanitizers, unit_fovpt acuity_fovpt points_fovpt denoise_fovpt mirror_fovpt unit_fovpt_nosimd unit_fovpt_w4 unit_fovpt_avx2, unit_fovlp taa_fovlp
#     numerics_fovlp, srgb8_fovlp acuity_fovlp, api_stress, versions, stats, camera, eye, errors
#     errors_nostrings,
#     style shared refs, unit_metrics
#     unit_metrics_sanitizers flip_reference
#   examples readme programs; fuzz_replay fuzz; compile_matrix cross_targets cmake_consumers;
#   web
# e.g. T=fovsdf (the fovsdf unit tests), T=fuzz, T=compile, T=examples,programs, T=_nolibm.
# The suite block below runs twice: once to list the sections and test programs (run_section
# and build_test only record; the programs are then compiled JOBS at a time), then for real;
# keep every command in it inside run_section, build_test or three_builds.
set -u
cd "$(dirname "$0")/.."
mkdir -p build/logs build/tests
CC=${CC:-gcc}
TOTAL_P=0
TOTAL_F=0
T0=$(date +%s)
# cpu_s FILE: CPU_S = the CPU seconds (user + system) of the finished children of this shell
# (`times` runs in this shell: in a $(...) subshell it would count the subshell's children)
cpu_s() {
    times >"$1"
    CPU_S=$(awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, a, /[ms]/); s += a[1] * 60 + a[2] } printf "%.0f", s }' "$1")
}

# selected NAME: true without T, or when NAME contains one of T's comma-separated patterns
T=${T:-}
SEL_LISTING= SEL_LAST_BUILD= SEL_LAST_IMPL= SEL_BUILDS= SEL_ALL=()
selected() {
    local pat
    [ -z "$T" ] && return 0
    IFS=, read -ra SEL_PATS <<<"$T"
    for pat in "${SEL_PATS[@]}"; do
        [ -n "$pat" ] && [[ $1 == *$pat* ]] && return 0
    done
    return 1
}

# run_section NAME COMMAND...: the command must print "N passed, N failed" as a line.
run_section() {
    local name=$1; shift
    local log=build/logs/$name.log t1 rc summary p f
    if [ -n "$SEL_LISTING" ]; then
        SEL_ALL+=("$name")
        if selected "$name" && [ -n "$SEL_LAST_BUILD" ]; then
            SEL_BUILDS+=" $SEL_LAST_BUILD $SEL_LAST_IMPL "
        fi
        SEL_LAST_BUILD= SEL_LAST_IMPL=
        return 0
    fi
    selected "$name" || return 0
    flush_bg
    t1=$(date +%s)
    cpu_s build/logs/times; c1=$CPU_S
    "$@" >"$log" 2>&1
    rc=$?
    cpu_s build/logs/times
    report_section "$name" "$rc" $(( $(date +%s) - t1 )) $(( CPU_S - c1 ))
}

# report_section NAME STATUS SECONDS CPU_SECONDS: the section's FAIL/SKIP lines and summary
# from its log
report_section() {
    local name=$1 rc=$2 secs=$3 cpu=$4 log=build/logs/$1.log summary p f
    summary=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$log" | tail -1)
    if [ -z "$summary" ]; then
        p=0; f=1
        echo "FAIL [$name] no summary line (exit status $rc); last lines of $log:"
        tail -n 15 "$log" | sed 's/^/    /'
    else
        p=$(echo "$summary" | sed -E 's/^([0-9]+) passed.*/\1/')
        f=$(echo "$summary" | sed -E 's/^[0-9]+ passed, ([0-9]+) failed.*/\1/')
        if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; echo "FAIL [$name] exit status $rc"; fi
        grep -E '^(FAIL|SKIP)' "$log" | sed "s/^/  [$name] /"
    fi
    echo "[$name] $p passed, $f failed ($secs s, CPU $cpu s)"
    TOTAL_P=$((TOTAL_P + p))
    TOTAL_F=$((TOTAL_F + f))
}

# run_bg NAME COMMAND...: run_section for a test program or script that writes no file
# outside its own directory (or a mktemp one): it runs in the background, JOBS at a time, and
# its summary is printed in order by flush_bg, which the next run_section (and the end of the
# suite) calls first. So the unit tests and the light sections up to fuzz_replay share one
# pool, with one wait at its end, and no CPU idles at a wait between them.
BG_NAMES=()
run_bg() {
    local name=$1; shift
    if [ -n "$SEL_LISTING" ]; then run_section "$name" "$@"; return 0; fi
    selected "$name" || return 0
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n 2>/dev/null || true; done
    rm -f "build/logs/$name.bg"
    ( t1=$(date +%s); "$@" >"build/logs/$name.log" 2>&1
      rc=$?; cpu_s "build/logs/$name.times"
      echo "$rc $(( $(date +%s) - t1 )) $CPU_S" >"build/logs/$name.bg" ) &
    BG_NAMES+=("$name")
}
flush_bg() {
    local name rc secs cpu
    [ ${#BG_NAMES[@]} -eq 0 ] && return 0
    wait
    for name in "${BG_NAMES[@]}"; do
        rc=1 secs=0 cpu=0
        [ -f "build/logs/$name.bg" ] && read -r rc secs cpu <"build/logs/$name.bg"
        report_section "$name" "$rc" "$secs" "$cpu"
    done
    BG_NAMES=()
}

# build_test NAME SOURCE FLAGS...: compile a test program; a compile failure is a failure.
# The listing pass records every build; they are then compiled JOBS at a time (default: the
# number of CPUs) before the first section runs, and build_test reads each one's exit status.
SEL_CMDS=() SEL_CMDS_LATE=()
build_test() {
    local name=$1 src=$2 rc; shift 2
    if [ -n "$SEL_LISTING" ]; then
        SEL_LAST_BUILD=$name
        if [[ " $* " == *" -DFOV_TEST_LINK_IMPL "* ]]; then
            # linked with an implementation archive (impl_archive): compiled after them
            SEL_LAST_IMPL="$* "; SEL_LAST_IMPL=${SEL_LAST_IMPL##* build/tests/libfovimpl_}
            SEL_LAST_IMPL=${SEL_LAST_IMPL%%.a *}
            SEL_LAST_IMPL="fov_impl_sdf_$SEL_LAST_IMPL.o fov_impl_lp_$SEL_LAST_IMPL.o fov_impl_pt_$SEL_LAST_IMPL.o"
            SEL_CMDS_LATE+=("$name $src $*")
        else
            SEL_CMDS+=("$name $src $*")
        fi
        return 0
    fi
    if [ -n "$T" ] && [[ $SEL_BUILDS != *" $name "* ]]; then return 1; fi
    if [ -f "build/logs/build_$name.rc" ]; then
        rc=$(cat "build/logs/build_$name.rc")
        rm -f "build/logs/build_$name.rc"
    else
        $CC "$src" -o "build/tests/$name" "$@" >"build/logs/build_$name.log" 2>&1
        rc=$?
    fi
    if [ "$rc" -ne 0 ]; then
        echo "FAIL [build] $name: compile error, see build/logs/build_$name.log"
        sed 's/^/    /' "build/logs/build_$name.log" | head -20
        TOTAL_F=$((TOTAL_F + 1))
        return 1
    fi
    return 0
}
# prebuild_one NAME SOURCE FLAGS...: compile, leave the exit status in build/logs/build_NAME.rc
prebuild_one() {
    local name=$1 src=$2; shift 2
    $CC "$src" -o "build/tests/$name" "$@" >"build/logs/build_$name.log" 2>&1
    echo $? >"build/logs/build_$name.rc"
}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}

WARN="-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion -Werror -ffp-contract=off"
# -g1: line tables (the sanitizers' backtraces keep file:line), a quarter less compile time than -g
SAN="-O1 -g1 -ffp-contract=off -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer"

# The implementations of the three headers, compiled once per flavour (tests/common/
# fov_impl_<h>.c; -c): the test programs that three_builds marks "link" are compiled with
# -DFOV_TEST_LINK_IMPL (their file then holds only the declarations) and linked with the
# flavour's archive build/tests/libfovimpl_<flavour>.a, made from these objects after the
# first round of compiles (see the end of this file).
IMPL_FLAGS_o2="-std=c99 -O2 $WARN -I. -Itests/common"
IMPL_FLAGS_nolibm="-std=c99 -O2 $WARN -DFOV_NO_LIBM -I. -Itests/common"
IMPL_FLAGS_san="-std=c99 $SAN -I. -Itests/common"
impl_builds() {
    local fl h v
    for fl in o2 nolibm san; do
        v=IMPL_FLAGS_$fl
        for h in sdf lp pt; do
            build_test "fov_impl_${h}_$fl.o" "tests/common/fov_impl_$h.c" -c ${!v}
        done
    done
}

suite() {
# --- unit tests ---------------------------------------------------------------------------
impl_builds
# three builds of each library test program: libm, FOV_NO_LIBM, sanitizers. With a third
# argument "link" the program links the implementations compiled once (impl_builds) instead
# of compiling them itself: for programs that use the default configuration (the same code,
# compiled with the same flags, in another translation unit) through the public API and the
# test hook's wrappers of private functions (tests/common/fov_priv_{sdf,lp}.h, exported by the
# archives). Not linked: programs that configure the implementation (test_fovsdf_accel.c:
# FOVSDF_CONE_SLACK 0; test_fovsdf_scene.c: FOVSDF_DOUBLE...), use private types
# (test_fovsdf_heads.c, _prune.c: fovsdf__marcher) or test the headers' own text (versions).
three_builds() {
    local name=$1 src=$2 lo= ln= ls=
    if [ "${3:-}" = link ]; then
        lo="-DFOV_TEST_LINK_IMPL build/tests/libfovimpl_o2.a"
        ln="-DFOV_TEST_LINK_IMPL build/tests/libfovimpl_nolibm.a"
        ls="-DFOV_TEST_LINK_IMPL build/tests/libfovimpl_san.a"
    fi
    if build_test "test_$name" "$src" -std=c99 -O2 $WARN -I. -Itests/common $lo -lm; then
        run_bg "$name" "build/tests/test_$name"
    fi
    if build_test "test_${name}_nolibm" "$src" -std=c99 -O2 $WARN -DFOV_NO_LIBM -I. -Itests/common $ln -lm; then
        run_bg "${name}_nolibm" "build/tests/test_${name}_nolibm"
    fi
    if build_test "test_${name}_san" "$src" -std=c99 $SAN -I. -Itests/common $ls -lm; then
        run_bg "${name}_sanitizers" "build/tests/test_${name}_san"
    fi
}
three_builds unit_fovsdf tests/test_fovsdf.c link
three_builds scene_fovsdf tests/test_fovsdf_scene.c
three_builds accel_fovsdf tests/test_fovsdf_accel.c
three_builds contract_fovsdf tests/test_fovsdf_contract.c link
three_builds heads_fovsdf tests/test_fovsdf_heads.c
three_builds props_fovsdf tests/test_fovsdf_props.c link
three_builds batch_fovsdf tests/test_fovsdf_batch.c link
three_builds wave_fovsdf tests/test_fovsdf_wave.c link
three_builds prune_fovsdf tests/test_fovsdf_prune.c
three_builds acuity_fovsdf tests/test_fovsdf_acuity.c link
run_bg wave_variants bash tests/wave_variants.sh
three_builds naive_sdf tests/test_sdf_naive.c link
# FIPR / CONE_FOV with a lowered FOVSDF_FOV_CELLS, under ASan with NDEBUG (no assertions)
if build_test test_fovsdf_cells tests/test_fovsdf_cells.c -std=c99 $SAN -DNDEBUG -DFOVSDF_FOV_CELLS=100 -I. -Itests/common -lm; then
    run_bg fov_cells_sanitizers build/tests/test_fovsdf_cells
fi
three_builds unit_fovpt tests/test_fovpt.c
three_builds acuity_fovpt tests/test_fovpt_acuity.c link
three_builds points_fovpt tests/test_fovpt_points.c link
three_builds denoise_fovpt tests/test_fovpt_denoise.c
three_builds mirror_fovpt tests/test_fovpt_mirror.c
three_builds sampler_fovpt tests/test_fovpt_sampler.c link
# the BVH traversal without SSE (the scalar four-box test that wasm32 and Cortex-M4 run)
if build_test test_fovpt_nosimd tests/test_fovpt.c -std=c99 -O2 $WARN -DFOVPT_NO_SIMD -DFOVPT__BITREV=0 -I. -Itests/common -lm; then
    run_bg unit_fovpt_nosimd build/tests/test_fovpt_nosimd
fi
# the 4-wide SIMD walk (FOVPT_BVH_WIDTH 4, no longer the default with SIMD)
if build_test test_fovpt_w4 tests/test_fovpt.c -std=c99 -O2 $WARN -DFOVPT_BVH_WIDTH=4 -I. -Itests/common -lm; then
    run_bg unit_fovpt_w4 build/tests/test_fovpt_w4
fi
# the 8-wide AVX2 walk (FOVPT_BVH_WIDTH 8: its own node loop and collapse), where the CPU runs AVX2
if grep -qw avx2 /proc/cpuinfo 2>/dev/null; then
    # gnu99 and -ffp-contract=fast: the implementation turns contraction off itself (NUMERICS)
    if build_test test_fovpt_avx2 tests/test_fovpt.c -std=gnu99 -O2 $WARN -mavx2 -mfma -ffp-contract=fast -I. -Itests/common -lm; then
        run_bg unit_fovpt_avx2 build/tests/test_fovpt_avx2
    fi
else
    run_bg unit_fovpt_avx2 sh -c 'echo "SKIP the 8-wide AVX2 walk: this CPU has no AVX2"; echo "0 passed, 0 failed"'
fi
# fovlp.h
three_builds unit_fovlp tests/test_fovlp.c link
three_builds taa_fovlp tests/test_fovlp_taa.c link
three_builds numerics_fovlp tests/test_fovlp_numerics.c link
three_builds srgb8_fovlp tests/test_fovlp_srgb8.c link
three_builds acuity_fovlp tests/test_fovlp_acuity.c link
# all three headers through their public API as a hostile user (each case in a child process
# under an alarm: a hang or a crash fails that case)
three_builds api_stress tests/test_api_stress.c link
# each header's VERSION_STRING against its MAJOR/MINOR/PATCH macros and its first line
three_builds versions tests/test_versions.c
# the counters of the three headers: init functions, and counts that add up across calls
three_builds stats tests/test_stats.c link
# line length budgets of the headers, and every FOV*__ macro tested by #if defined
run_bg style bash tests/style.sh
# fov_camera: one type, the same defaults and handedness in the three headers, rays agree
three_builds camera tests/test_camera.c link
# fov_eye: the shared eye model against Guenter et al. 2012, densities, plans, bad input
three_builds eye tests/test_eye.c link
# fov_gaze_filter: One Euro filter with saccade reset, the latency margin, fixed foveation,
# the gaze trace generator
three_builds gaze tests/test_gaze.c link
# errors name the field and the rule, once per failure, in the default build (and with
# FOV_NO_ERROR_STRINGS: the codes still logged, every message "")
three_builds errors tests/test_errors.c link
if build_test test_errors_nostrings tests/test_errors.c -std=c99 -O2 $WARN -DFOV_NO_ERROR_STRINGS \
        -I. -Itests/common -lm; then
    run_bg errors_nostrings build/tests/test_errors_nostrings
fi
# the shared regions (tools/fov_shared.h) byte-identical in the three headers
run_bg shared bash tests/shared.sh
# no tracked file cites the internal background documents; each header has REFERENCES
run_bg refs bash tests/refs.sh
if build_test test_metrics tests/test_metrics.c -std=c99 -O2 $WARN -Itests/common -lm; then
    run_bg unit_metrics build/tests/test_metrics
fi
if build_test test_metrics_san tests/test_metrics.c -std=c99 $SAN -Itests/common -lm; then
    run_bg unit_metrics_sanitizers build/tests/test_metrics_san
fi
if build_test test_flip_reference tests/test_flip_reference.c -std=c99 -O2 $WARN -Itests/common -lm; then
    run_bg flip_reference build/tests/test_flip_reference tests/flip_reference
fi

# --- examples: they build warning-free and the demo's tracers agree with the ground truth --
run_bg examples bash tests/examples.sh
# the README: at most 250 lines, quick starts up front, its programs build and run, links
run_bg readme bash tests/readme.sh
# every program: --help / -h exit 0 with a usage text, an unknown option exits 2; the examples
# build copied out alone (the fov headers and examples/*.h)
run_bg programs bash tests/programs.sh
# --- fuzz harnesses (tests/fuzz/fuzz_*.c): the committed corpus and regression inputs
# replayed without libFuzzer (gcc ASan+UBSan and -O2 FOV_NO_LIBM), then a bounded libFuzzer
# run of each target (FUZZ_SECONDS, default 20 here, libFuzzer seed FUZZ_SEED, default 1 here,
# at most FUZZ_RUNS executions, default 100000 here: the same inputs on any machine;
# clang and libclang-rt-14-dev, a
# failure when missing under CI=true; crashes saved under build/fuzz/crashes/)
run_section fuzz_replay bash tests/fuzz/run.sh replay
FUZZ_SEED=${FUZZ_SEED:-1} FUZZ_SECONDS=${FUZZ_SECONDS:-20} FUZZ_RUNS=${FUZZ_RUNS:-100000} \
    run_section fuzz bash tests/fuzz/run.sh fuzz


# --- compile matrix, freestanding builds, other targets -----------------------------------
run_section compile_matrix bash tests/compile/run.sh
run_section cross_targets bash tests/xtarget/run.sh
run_section cmake_consumers bash tests/cmake/run.sh

# --- the browser demo (examples/web) in headless chromium: the sharp region follows the mouse
# in each mode, a build that ignores the gaze fails that check, 1 and 2 workers agree, no page
# or console errors (chromium, nodejs, npm ci in tests/web; a failure when missing under CI=true)
run_section web bash tests/web/run.sh
}

SEL_LISTING=1
suite
SEL_LISTING=
if [ -n "$T" ]; then
    n=0
    for s in "${SEL_ALL[@]}"; do selected "$s" && n=$((n + 1)); done
    if [ "$n" -eq 0 ]; then
        echo "run_all.sh: T=$T matches no section; the sections are:" >&2
        printf '  %s\n' "${SEL_ALL[@]}" >&2
        exit 2
    fi
    echo "T=$T: $n of ${#SEL_ALL[@]} sections"
fi
# the test programs, JOBS compiles at a time (flags hold no quoted spaces: word splitting is
# safe): first the implementations and the programs that compile their own, then the
# implementation archives, then the programs linked with them
rm -f build/logs/build_*.rc build/tests/libfovimpl_*.a
nb=0
prebuild_all() {
    local c args
    for c in "$@"; do
        read -ra args <<<"$c"
        if [ -n "$T" ] && [[ $SEL_BUILDS != *" ${args[0]} "* ]]; then continue; fi
        while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n 2>/dev/null || true; done
        prebuild_one "${args[@]}" &
        nb=$((nb + 1))
    done
    wait
}
# the sanitizer builds first: they take 2-3 times as long, and a long compile started last
# would leave the other CPUs idle at the end of the round
SEL_SORTED=()
for c in "${SEL_CMDS[@]}"; do [[ $c == *-fsanitize=* ]] && SEL_SORTED+=("$c"); done
for c in "${SEL_CMDS[@]}"; do [[ $c == *-fsanitize=* ]] || SEL_SORTED+=("$c"); done
prebuild_all "${SEL_SORTED[@]}"
for fl in o2 nolibm san; do
    objs=()
    for h in sdf lp pt; do
        [ -f "build/logs/build_fov_impl_${h}_$fl.o.rc" ] && [ "$(cat "build/logs/build_fov_impl_${h}_$fl.o.rc")" = 0 ] &&
            objs+=("build/tests/fov_impl_${h}_$fl.o")
    done
    [ ${#objs[@]} -eq 3 ] && ar rcs "build/tests/libfovimpl_$fl.a" "${objs[@]}"
done
prebuild_all "${SEL_CMDS_LATE[@]}"
cpu_s build/logs/times
echo "built $nb test programs in $(( $(date +%s) - T0 )) s, CPU $CPU_S s ($JOBS at a time)"
suite

flush_bg
cpu_s build/logs/times
echo "suite took $(( $(date +%s) - T0 )) s, CPU $CPU_S s ($JOBS jobs at a time)"
echo "$TOTAL_P passed, $TOTAL_F failed"
[ "$TOTAL_F" -eq 0 ]

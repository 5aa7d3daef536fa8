#!/usr/bin/env bash
# tests/fuzz/run.sh - build, replay and run the fuzz harnesses tests/fuzz/fuzz_<target>.c.
#
# Run from anywhere (it changes to the repository root):
#   bash tests/fuzz/run.sh replay            replay tests/fuzz/corpus/<t>/ and
#                                            tests/fuzz/regress/<t>/ through each harness
#                                            built without libFuzzer (see below)
#   bash tests/fuzz/run.sh fuzz              fuzz each target for FUZZ_SECONDS (default 60)
#                                            with libFuzzer
#   bash tests/fuzz/run.sh repro TARGET FILE...   replay the given inputs through TARGET's
#                                            sanitizer build (reproduce a crash)
#   bash tests/fuzz/run.sh list              the targets found
# Environment:
#   FUZZ_TARGETS   targets to run, space or comma separated; a word selects the target of
#                  that name and every target named word_* (FUZZ_TARGETS=fovsdf selects
#                  fovsdf, fovsdf_render, fovsdf_program); shell globs work (fov*). Default:
#                  all.
#   FUZZ_SECONDS   seconds of fuzzing per target (default 60; make test passes 20; 0: only
#                  run the corpus and regression inputs once through the libFuzzer build)
#   FUZZ_MAX_LEN   libFuzzer -max_len (default 4096)
#   FUZZ_TIMEOUT   libFuzzer -timeout per input, seconds (default 10): slower is a failure
#   FUZZ_SEED      libFuzzer -seed (default: none, a random seed; make test passes 1)
#   FUZZ_RUNS      at most this many executions per target (libFuzzer -runs; default: no
#                  limit; make test passes 100000): with FUZZ_SEED fixed and a clean
#                  build/fuzz/corpus, the run explores the same inputs on every machine, a
#                  prefix of them when FUZZ_SECONDS runs out first, so a faster machine does not
#                  explore inputs a slower one never checked
#   FUZZ_FLAGS     extra libFuzzer flags (e.g. "-jobs=2 -workers=2", "-only_ascii=1")
#   FUZZ_JOBS      replay builds, replays and fuzz targets run this many at a time (default:
#                  the number of CPUs; the libFuzzer builds two at a time); the results are
#                  printed in the targets' order. FUZZ_FLAGS="-jobs=N" multiplies it.
#   CC             the compiler of the replay builds (default gcc); FUZZ_CC the libFuzzer
#                  compiler (default clang)
#   CI=true        a missing clang/libFuzzer is a FAIL, not a SKIP
#
# Targets: every tests/fuzz/fuzz_<target>.c (globbed; nothing to register). A harness
# defines LLVMFuzzerTestOneInput, includes fuzz_common.h and aborts on a broken contract.
#
# replay: two builds per target, each run on every file of corpus/<t>/ and regress/<t>/
#   (tests/fuzz/replay.c: one child process per input, 20 s alarm):
#     build/fuzz/replay_<t>         $CC -O1 -g1 -fsanitize=address,undefined
#                                   (+ float-cast-overflow) -fno-sanitize-recover=all
#     build/fuzz/replay_<t>_nolibm  $CC -O2 -DFOV_NO_LIBM (the built-in math approximations)
#   Each input of each build is one check; a build that fails to compile is one failure.
#   tests/fuzz/pending/<t>/ (regression inputs whose fix is not merged yet) is not replayed:
#   bash tests/fuzz/run.sh repro <t> tests/fuzz/pending/<t>/* shows their state.
# fuzz: build/fuzz/fuzz_<t> = clang -O1 -g1 -fsanitize=fuzzer,address,undefined
#   -fno-sanitize-recover=all, run as
#     build/fuzz/fuzz_<t> -max_total_time=$FUZZ_SECONDS -max_len=$FUZZ_MAX_LEN
#        -timeout=$FUZZ_TIMEOUT -print_final_stats=1 -artifact_prefix=build/fuzz/crashes/<t>/
#        build/fuzz/corpus/<t> tests/fuzz/corpus/<t> tests/fuzz/regress/<t>
#   New inputs go to build/fuzz/corpus/<t>/ only (libFuzzer writes to its first corpus
#   directory); the committed corpus is never changed (see tests/fuzz/README.md to promote an
#   input). A crash, a leak, a timeout or an out-of-memory stops that target and is one
#   failure; the input is saved under build/fuzz/crashes/<t>/ and the command to reproduce it
#   is printed. One line per target: executions, exec/s, cov, ft (libFuzzer's counters: edges
#   and features covered), corpus size, crashes. Logs: build/fuzz/logs/.
#
# Output: PASS / FAIL / SKIP lines and the closing "N passed, N failed" (SKIPs not counted);
# exit status 1 when anything failed.
#
# Debian packages: gcc (replay), clang and libclang-rt-14-dev (libFuzzer:
# libclang_rt.fuzzer-x86_64.a, and the clang ASan/UBSan runtimes).

set -u
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$ROOT" || exit 1
B=build/fuzz
F=tests/fuzz
mkdir -p "$B/logs" "$B/corpus" "$B/crashes"
IS_CI=0
[ "${CI:-}" = true ] && IS_CI=1
CC=${CC:-gcc}
FUZZ_CC=${FUZZ_CC:-clang}
FUZZ_SECONDS=${FUZZ_SECONDS:-60}
FUZZ_MAX_LEN=${FUZZ_MAX_LEN:-4096}
FUZZ_TIMEOUT=${FUZZ_TIMEOUT:-10}
FUZZ_FLAGS=${FUZZ_FLAGS:-}
FUZZ_JOBS=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}
NPASS=0
NFAIL=0

say() { printf '%s\n' "$*"; }
pass() { say "PASS $*"; NPASS=$((NPASS + 1)); }
fail() { say "FAIL $*"; NFAIL=$((NFAIL + 1)); }
finish() { say "$NPASS passed, $NFAIL failed"; [ "$NFAIL" -eq 0 ]; exit $?; }

COMMON=(-std=c99 -D_POSIX_C_SOURCE=200809L -g1 -Wall -Wextra -Wno-unused-function -I. -Itests/common -I"$F")
SAN_GCC=(-O1 -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer)
SAN_FUZZ=(-O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)

# ---- targets -----------------------------------------------------------------------------
ALL=()
for src in "$F"/fuzz_*.c; do
    [ -e "$src" ] || continue
    t=${src##*/fuzz_}
    ALL+=("${t%.c}")
done
selected() { # NAME: is it chosen by FUZZ_TARGETS?
    local sel w
    [ -z "${FUZZ_TARGETS:-}" ] && return 0
    sel=${FUZZ_TARGETS//,/ }
    for w in $sel; do
        # shellcheck disable=SC2053
        if [[ $1 == $w || $1 == ${w}_* ]]; then return 0; fi
    done
    return 1
}
TARGETS=()
for t in "${ALL[@]}"; do selected "$t" && TARGETS+=("$t"); done

# existing input directories of a target
inputs() {
    local d
    for d in "$F/corpus/$1" "$F/regress/$1"; do [ -d "$d" ] && printf '%s\n' "$d"; done
}

# build NAME OUT COMPILER FLAGS...: compile tests/fuzz/fuzz_NAME.c (+ replay.c for gcc builds)
build() {
    build_start "$@"
    wait
    build_ok "$2"
}
# build_start: the same in the background (the builds of one step share the 2 CPUs);
# build_ok OUT after `wait` reports it
build_start() {
    local t=$1 out=$2 cc=$3 log
    shift 3
    log="$B/logs/build_${out##*/}.log"
    rm -f "$out"
    ( if "$cc" "${COMMON[@]}" "$@" "$F/fuzz_$t.c" -lm -o "$out" >"$log" 2>&1; then echo 0; else echo 1; fi >"$log.rc" ) &
}
build_ok() {
    local out=$1 log
    log="$B/logs/build_${out##*/}.log"
    if [ "$(cat "$log.rc" 2>/dev/null)" = 0 ] && [ -x "$out" ]; then return 0; fi
    fail "build ${out##*/}: compile error (log: $log): $(grep -m 3 -E 'error' "$log" | tr '\n' ' ' | cut -c1-400)"
    return 1
}

# replay_run BIN LABEL DIR...: runs the replay build on the inputs (replay.c: one check per
# input), into build/fuzz/logs/replay_LABEL.log
replay_run() {
    local bin=$1 label=$2
    shift 2
    "$bin" "$@" >"$B/logs/replay_$label.log" 2>&1
}
# replay_report LABEL: its PASS/FAIL lines and counts from the log of replay_run
replay_report() {
    local label=$1 log s p f
    log="$B/logs/replay_$label.log"
    s=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$log" | tail -1)
    if [ -z "$s" ]; then
        fail "replay $label: no summary (log: $log)"
        return
    fi
    p=${s%% passed*}
    f=${s#* passed, }; f=${f%% failed*}
    NPASS=$((NPASS + p))
    NFAIL=$((NFAIL + f))
    grep -E '^FAIL ' "$log" | while IFS= read -r line; do
        line=${line#FAIL }
        say "FAIL replay $label: $line (reproduce: bash tests/fuzz/run.sh repro ${label%_nolibm} ${line%%: *})"
    done
    [ "$f" -gt 0 ] && say "    (log with the sanitizer reports: $log)"
    say "replay $label: $p passed, $f failed"
}

# do_replay: all replay builds FUZZ_JOBS at a time, then all replays FUZZ_JOBS at a time, then
# the reports in order
do_replay() {
    local t dirs labels=() l
    for t in "${TARGETS[@]}"; do
        mapfile -t dirs < <(inputs "$t")
        [ "${#dirs[@]}" -eq 0 ] && continue
        while [ "$(jobs -rp | wc -l)" -ge "$FUZZ_JOBS" ]; do wait -n 2>/dev/null || true; done
        build_start "$t" "$B/replay_$t" "$CC" "${SAN_GCC[@]}" "$F/replay.c"
        while [ "$(jobs -rp | wc -l)" -ge "$FUZZ_JOBS" ]; do wait -n 2>/dev/null || true; done
        build_start "$t" "$B/replay_${t}_nolibm" "$CC" -O2 -DFOV_NO_LIBM "$F/replay.c"
    done
    wait
    for t in "${TARGETS[@]}"; do
        mapfile -t dirs < <(inputs "$t")
        if [ "${#dirs[@]}" -eq 0 ]; then
            fail "replay $t: no tests/fuzz/corpus/$t/ (commit a seed corpus)"
            continue
        fi
        for l in "$t" "${t}_nolibm"; do
            build_ok "$B/replay_$l" || continue
            while [ "$(jobs -rp | wc -l)" -ge "$FUZZ_JOBS" ]; do wait -n 2>/dev/null || true; done
            rm -f "$B/logs/replay_$l.log"
            replay_run "$B/replay_$l" "$l" "${dirs[@]}" &
            labels+=("$l")
        done
    done
    wait
    for l in "${labels[@]}"; do replay_report "$l"; done
}

# is libFuzzer usable? (clang present and -fsanitize=fuzzer links)
have_libfuzzer() {
    command -v "$FUZZ_CC" >/dev/null 2>&1 || return 1
    printf '#include <stdint.h>\n#include <stddef.h>\nint LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }\n' >"$B/probe.c"
    "$FUZZ_CC" "${SAN_FUZZ[@]}" "$B/probe.c" -o "$B/probe" >"$B/logs/probe.log" 2>&1
}

# the value of a libFuzzer "stat::NAME: V" line, or of "NAME: V" in its last status line
stat_of() { grep -E "^stat::$2:" "$1" | tail -1 | sed -E 's/.*: *//'; }
status_field() { grep -E '^#[0-9]+' "$1" | grep -E " $2: " | tail -1 | sed -E "s/.* $2: ([^ ]+).*/\\1/"; }

do_fuzz() {
    local t FUZZED=()
    if ! have_libfuzzer; then
        if [ "$IS_CI" = 1 ]; then
            fail "fuzz: $FUZZ_CC with libFuzzer not usable (CI=true: a missing toolchain is a failure; apt-get install clang libclang-rt-14-dev; log: $B/logs/probe.log)"
        else
            say "SKIP fuzz: install clang and libclang-rt-14-dev ($FUZZ_CC -fsanitize=fuzzer failed; log: $B/logs/probe.log)"
        fi
        return
    fi
    # build two at a time, then fuzz FUZZ_JOBS at a time
    local i
    for ((i = 0; i < ${#TARGETS[@]}; i += 2)); do
        build_start "${TARGETS[i]}" "$B/fuzz_${TARGETS[i]}" "$FUZZ_CC" "${SAN_FUZZ[@]}"
        if [ $((i + 1)) -lt ${#TARGETS[@]} ]; then
            build_start "${TARGETS[i + 1]}" "$B/fuzz_${TARGETS[i + 1]}" "$FUZZ_CC" "${SAN_FUZZ[@]}"
        fi
        wait
    done
    # fuzz FUZZ_JOBS targets at a time (each libFuzzer run is one process on one CPU), then
    # report in order
    for t in "${TARGETS[@]}"; do
        build_ok "$B/fuzz_$t" || continue
        while [ "$(jobs -rp | wc -l)" -ge "$FUZZ_JOBS" ]; do wait -n 2>/dev/null || true; done
        fuzz_one "$t" &
        FUZZED+=("$t")
    done
    wait
    for t in "${FUZZED[@]}"; do fuzz_report "$t"; done
}

# fuzz_one TARGET: the libFuzzer run; its exit status goes to the log's .rc file
fuzz_one() {
    local t=$1 dirs log limit
    mkdir -p "$B/corpus/$t" "$B/crashes/$t"
    mapfile -t dirs < <(inputs "$t")
    log="$B/logs/fuzz_$t.log"
    rm -f "$log.rc"
    # FUZZ_SECONDS=0: run the inputs once (libFuzzer's -max_total_time=0 means no limit)
    if [ "$FUZZ_SECONDS" -gt 0 ] 2>/dev/null; then limit=(-max_total_time="$FUZZ_SECONDS"); else limit=(-runs=0); fi
    # FUZZ_SEED: libFuzzer's -seed (make test fixes it, so that a commit's fuzz section
    # explores the same inputs in every run up to the time limit)
    if [ -n "${FUZZ_SEED:-}" ]; then limit+=(-seed="$FUZZ_SEED"); fi
    if [ "${FUZZ_RUNS:-0}" -gt 0 ] 2>/dev/null && [ "$FUZZ_SECONDS" -gt 0 ] 2>/dev/null; then
        limit+=(-runs="$FUZZ_RUNS")
    fi
    # shellcheck disable=SC2086
    "$B/fuzz_$t" "${limit[@]}" -max_len="$FUZZ_MAX_LEN" \
        -timeout="$FUZZ_TIMEOUT" -print_final_stats=1 -artifact_prefix="$B/crashes/$t/" \
        $FUZZ_FLAGS "$B/corpus/$t" "${dirs[@]}" >"$log" 2>&1
    echo $? >"$log.rc"
}

# fuzz_report TARGET: PASS or FAIL from the log of fuzz_one
fuzz_report() {
    local t=$1 log rc execs eps cov ft corp crash summary why how
    log="$B/logs/fuzz_$t.log"
    rc=$(cat "$log.rc" 2>/dev/null || echo 1)
    how="${FUZZ_SECONDS} s"
    [ "$FUZZ_SECONDS" -gt 0 ] 2>/dev/null || how="inputs run once"
    execs=$(stat_of "$log" number_of_executed_units)
    eps=$(stat_of "$log" average_exec_per_sec)
    cov=$(status_field "$log" cov)
    ft=$(status_field "$log" ft)
    corp=$(status_field "$log" corp)
    crash=$(grep -E "^(Test unit written to|artifact_prefix=)" "$log" | grep -oE "$B/crashes/$t/[^ ]+" | tail -1)
    summary="executions ${execs:-?}, exec/s ${eps:-?}, cov ${cov:-?}, ft ${ft:-?}, corpus ${corp:-?}"
    if [ "$rc" -eq 0 ] && [ -z "$crash" ]; then
        pass "fuzz $t: $how, $summary, crashes 0"
    else
        why=$(grep -m 1 -E '^==[0-9]+==ERROR|FUZZ CONTRACT|runtime error|ALARM|Timeout|out-of-memory' "$log" | cut -c1-300)
        if [ -n "$crash" ]; then
            fail "fuzz $t: $summary, crashes 1: $why; input saved: $crash; reproduce: bash tests/fuzz/run.sh repro $t $crash (or $B/fuzz_$t $crash); log: $log"
        else
            fail "fuzz $t: $summary: exit status $rc, no input saved: $why; log: $log"
        fi
    fi
}

do_repro() {
    local t=$1
    shift
    [ -f "$F/fuzz_$t.c" ] || { fail "repro: no target $t ($F/fuzz_$t.c)"; return; }
    [ $# -gt 0 ] || { fail "repro: no input files given"; return; }
    if build "$t" "$B/replay_$t" "$CC" "${SAN_GCC[@]}" "$F/replay.c"; then
        "$B/replay_$t" "$@"
        exit $?
    fi
}

case "${1:-}" in
    replay) [ "${#TARGETS[@]}" -gt 0 ] || fail "no fuzz target matches FUZZ_TARGETS='${FUZZ_TARGETS:-}'"; do_replay ;;
    fuzz) [ "${#TARGETS[@]}" -gt 0 ] || fail "no fuzz target matches FUZZ_TARGETS='${FUZZ_TARGETS:-}'"; do_fuzz ;;
    repro) shift; do_repro "$@" ;;
    list) printf '%s\n' "${ALL[@]}"; exit 0 ;;
    *) say "usage: bash tests/fuzz/run.sh replay | fuzz | repro TARGET FILE... | list"; exit 2 ;;
esac
finish

#!/usr/bin/env bash
# tests/compile/run.sh - the compile matrix of the fov headers.
#
# Run from the repository root:   bash tests/compile/run.sh
# Prints one line per check (PASS name / FAIL name: detail / SKIP name: reason (apt-get
# install PKG)) and ends with exactly "N passed, N failed" (SKIPs are not counted); exit
# status 1 when anything failed. With CI=true a missing toolchain is a FAIL, not a SKIP.
# Build products go to build/compile/ only (recreated on every run). JOBS=n sets the number
# of parallel compiles (default: the number of CPUs).
#
# What is checked, for every library header present at the top level (fovsdf.h, fovlp.h,
# fovpt.h; macros use the upper-case prefix: FOVSDF_IMPLEMENTATION, FOVSDF_STATIC, ...):
#   matrix      gcc, clang (C99, C11) and g++, clang++ (C++98, C++11) at -O0 compile
#               tests/compile/<hdr>.c / <hdr>.cc (the implementation plus a small program;
#               a generated TU that only instantiates the implementation when those files
#               do not exist yet) with
#                 -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion -Werror
#                 -ffp-contract=off   (C adds -Wstrict-prototypes -Wmissing-prototypes)
#               -c only; plus one -O2 cell per compiler (gcc C99, clang C11, g++ C++98,
#               clang++ C++11), linked and run: the warnings that need the optimiser's flow
#               analysis (-Wmaybe-uninitialized, -Warray-bounds, ...) do not depend on the
#               language standard, the standard's checks do not depend on -O.
#   style20     the STYLE.md rule-20 extras (front-end warnings, -O0): C99 with
#               -Wsign-conversion -Wcast-qual -Wfloat-equal added, and C++17 (-c).
#   options     every documented switch compiled alone and all together with gcc, clang and
#               g++ (FOV_NO_LIBM, FOV_NO_ERROR_STRINGS, FOVxx_STATIC, FOV_DLL, NDEBUG, and
#               FOVSDF_DOUBLE for fovsdf.h): alone at -O1 when the switch changes code paths
#               (the flow-analysis warnings such as -Wmaybe-uninitialized run from -O1; half
#               the compile time of -O2), at -O0 when it changes only linkage or attributes
#               (STATIC, DLL: front-end warnings such as -Wunused-function; STATIC is also
#               optimised in two_static_copies gcc); all together at -O2, linked and run.
#   nolibm      a FOV_NO_LIBM hosted build references no libm function (nm -u) and links
#               without -lm and runs.
#   decl_then_impl  declarations first, then FOV_IMPL, in one TU (decl_then_impl.c), linked
#               with a declarations-only TU that calls the API (decl_only_main.c); C/C,
#               C++/C++ and the two mixed-language pairs (checks the extern "C" blocks; -O0:
#               linkage does not depend on -O, and each TU holds all three implementations).
#   impl_twice  each header included twice with its implementation macro (once-guard).
#   all_three_one_tu  all present headers, FOV_IMPL, included twice in reverse orders, as C
#               and C++, linked and run.
#   two_static_copies  two TUs each with a FOVxx_STATIC copy (two_static_copies_{a,b}.c)
#               linked into one program that runs; nm shows no global fovxx_ symbol (gcc at -O2:
#               the STATIC copies optimised with libm and assertions; clang and g++ at -O0,
#               for their front-end warnings and linkage).
#   hooks_stub  every FOV_* hook (FOV_SQRTF FOV_FLOORF FOV_SINF FOV_COSF FOV_TANF FOV_ATAN2F
#               FOV_EXPF FOV_LOGF FOV_POWF FOV_MEMSET FOV_MEMCPY FOV_ASSERT) defined to the
#               user's functions (object-like and function-like macros): compiles, the object
#               references no libm/libc function except memset/memcpy, the program runs and
#               the hooks are called; defining only some math hooks must stop with #error.
#   freestanding  the implementation alone (freestanding_impl.c) with -DFOV_NO_LIBM
#               '-DFOV_ASSERT(c)=' and the warning set:
#                 clang --target=wasm32 -ffreestanding -nostdlib, linked with
#                   wasm-ld --no-entry --export-all (plus freestanding_rt.c: memset/memcpy);
#                 arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16
#                   -mfloat-abi=hard -ffreestanding at -O2 and -O0;
#                 clang --target=thumbv7em-none-eabihf, --target=riscv32 (rv32imafc,
#                   ilp32f) and --target=aarch64-none-elf (NEON) at -O2;
#               the object's undefined symbols (nm -u) must contain no software-double
#               routine (__aeabi_d*, __extendsfdf2, __truncdfsf2, __*df3, ...) and nothing
#               except memset/memcpy.
# Not here: sanitizers and unit tests (the lead's tests), cross-target rendering
# (tests/xtarget/run.sh).
#
# Debian packages: gcc g++ clang lld (wasm-ld) llvm (llvm-nm) gcc-arm-none-eabi
# binutils-arm-none-eabi.

set -u
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$ROOT" || exit 1
B=build/compile
T=tests/compile
rm -rf "$B"
mkdir -p "$B/res" "$B/obj" "$B/gen"
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
IS_CI=0
[ "${CI:-}" = true ] && IS_CI=1
START=$(date +%s)

# ---- headers present --------------------------------------------------------------------
HEADERS=()
HAVE=()
for h in fovsdf fovlp fovpt; do
    if [ -f "$h.h" ]; then
        HEADERS+=("$h")
        HAVE+=("-DFOV_HAVE_$(printf '%s' "$h" | tr '[:lower:]' '[:upper:]')")
    fi
done

CWARN="-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion -Werror -ffp-contract=off"
CONLY="-Wstrict-prototypes -Wmissing-prototypes"
STYLE20="-Wsign-conversion -Wcast-qual -Wfloat-equal"
NOLIBM_SYMS='^(sqrtf?|floorf?|sinf?|cosf?|tanf?|atan2f?|expf?|logf?|powf?|fabsf?|fmodf?|ceilf?|roundf?|truncf?|fminf?|fmaxf?|hypotf?|cbrtf?|sincosf?|exp2f?|log2f?|asinf?|acosf?|atanf?)$'
HOSTED_OK='^(memset|memcpy|__stack_chk_fail|__stack_chk_guard|_GLOBAL_OFFSET_TABLE_)$'
SOFT_DOUBLE='^(__aeabi_d.*|__aeabi_[a-z0-9]*2d|__extendsfdf2|__truncdfsf2|__[a-z]*df[0-9a-z]*)$'

# ---- reporting --------------------------------------------------------------------------
say() { printf '%s\n' "$*"; }
pass() { if [ $# -gt 1 ]; then say "PASS $1: $2"; else say "PASS $1"; fi; }
fail() { say "FAIL $1: $2"; }
# missing NAME TOOL PKG: SKIP outside CI, FAIL under CI=true
missing() {
    if [ "$IS_CI" = 1 ]; then
        fail "$1" "$2 not found (CI=true: a missing toolchain is a failure; apt-get install $3)"
    else
        say "SKIP $1: $2 not found (apt-get install $3)"
    fi
}
# need NAME TOOL PKG: true when TOOL is on PATH, else reports and returns 1
need() {
    if command -v "$2" >/dev/null 2>&1; then return 0; fi
    missing "$1" "$2" "$3"
    return 1
}
pkg_of() {
    case "$1" in
        gcc) echo gcc ;; g++) echo g++ ;; clang) echo clang ;; clang++) echo clang ;;
        wasm-ld) echo lld ;; llvm-nm) echo llvm ;;
        arm-none-eabi-gcc) echo gcc-arm-none-eabi ;; arm-none-eabi-nm) echo binutils-arm-none-eabi ;;
        *) echo "$1" ;;
    esac
}
needc() { need "$1" "$2" "$(pkg_of "$2")"; }
# errsum LOG: the first error lines of a compiler log, on one line
errsum() {
    local s
    s=$(grep -E 'error|Error|undefined' "$1" | head -n 3)
    [ -n "$s" ] || s=$(head -n 3 "$1")
    s=$(printf '%s' "$s" | tr '\n' '|' | sed 's/|/ | /g')
    printf '%s (log: %s)' "${s:0:600}" "$1"
}
# mkd NAME: a fresh build directory for a check
mkd() {
    local d
    d="$B/obj/$(printf '%s' "$1" | tr -c 'A-Za-z0-9._+-' '_')"
    mkdir -p "$d"
    printf '%s' "$d"
}
# run PROG LOGFILE: runs a test program with a timeout; echoes "exit N" on failure
runprog() {
    timeout 60 "$1" > "$2" 2>&1
    local rc=$?
    [ $rc = 0 ] && return 0
    echo "exit status $rc$( [ $rc = 124 ] && echo ' (timeout)'); output: $(head -c 300 "$2" | tr '\n' ' ') (log: $2)"
    return 1
}
# undef_syms NM OBJ: undefined symbol names, one per line, without a leading underscore on
# Mach-O style names
undef_syms() { "$1" -u "$2" 2>/dev/null | awk '{print $NF}' | sort -u; }

# ---- job runner: checks run in the background, results are printed in submission order --
SEQ=0
job() {
    SEQ=$((SEQ + 1))
    local out
    out=$(printf '%s/res/%04d' "$B" "$SEQ")
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n 2>/dev/null || true; done
    ( "$@" ) > "$out" 2> "$out.err" &
}

# ---- the checks -------------------------------------------------------------------------
langflags() { # LANG STD -> flags
    if [ "$1" = c ]; then echo "-x c -std=$2 $CWARN $CONLY"; else echo "-x c++ -std=$2 $CWARN"; fi
}

# cell NAME CC LANG STD OPT SRC LINK EXTRA...: compile SRC (and link + run when LINK=1)
cell() {
    local name=$1 cc=$2 lang=$3 std=$4 opt=$5 src=$6 link=$7
    shift 7
    needc "$name" "$cc" || return 0
    local d msg
    d=$(mkd "$name")
    # shellcheck disable=SC2046
    if ! "$cc" $(langflags "$lang" "$std") "$opt" "${HAVE[@]}" "$@" -I. -I"$T" -c "$src" \
        -o "$d/t.o" > "$d/compile.log" 2>&1; then
        fail "$name" "$(errsum "$d/compile.log")"
        return 0
    fi
    if [ "$link" = 1 ]; then
        if ! "$cc" "$d/t.o" -o "$d/t" -lm > "$d/link.log" 2>&1; then
            fail "$name" "link: $(errsum "$d/link.log")"
            return 0
        fi
        if ! msg=$(runprog "$d/t" "$d/run.log"); then fail "$name" "$msg"; return 0; fi
    fi
    pass "$name"
}

# the per-header test TU: tests/compile/<h>.c / .cc, or a generated one
tu_c() {
    if [ -f "$T/$1.c" ]; then echo "$T/$1.c"; else echo "$B/gen/$1.c"; fi
}
tu_cc() {
    if [ -f "$T/$1.cc" ]; then echo "$T/$1.cc"; else echo "$B/gen/$1.cc"; fi
}
for h in "${HEADERS[@]}"; do
    if [ ! -f "$T/$h.c" ] || [ ! -f "$T/$h.cc" ]; then
        P=$(printf '%s' "$h" | tr '[:lower:]' '[:upper:]')
        printf '/* generated by tests/compile/run.sh: %s.h has no %s/%s.c yet */\n#define %s_IMPLEMENTATION\n#include "%s.h"\nint main(void) { return 0; }\n' \
            "$h" "$T" "$h" "$P" "$h" > "$B/gen/$h.c"
        printf '#include "%s.c"\n' "$h" > "$B/gen/$h.cc"
    fi
done

# nolibm NAME CC: FOV_NO_LIBM build references no libm symbol, links without -lm, runs
nolibm() {
    local name=$1 cc=$2 h=$3
    needc "$name" "$cc" || return 0
    needc "$name" nm || return 0
    local d src bad msg
    d=$(mkd "$name")
    src=$(tu_c "$h")
    # shellcheck disable=SC2046
    if ! "$cc" $(langflags c c99) -O2 "${HAVE[@]}" -DFOV_NO_LIBM -I. -I"$T" -c "$src" \
        -o "$d/t.o" > "$d/compile.log" 2>&1; then
        fail "$name" "$(errsum "$d/compile.log")"; return 0
    fi
    bad=$(undef_syms nm "$d/t.o" | grep -E "$NOLIBM_SYMS" | tr '\n' ' ')
    if [ -n "$bad" ]; then fail "$name" "libm symbols referenced: $bad"; return 0; fi
    if ! "$cc" "$d/t.o" -o "$d/t" > "$d/link.log" 2>&1; then
        fail "$name" "link without -lm: $(errsum "$d/link.log")"; return 0
    fi
    if ! msg=$(runprog "$d/t" "$d/run.log"); then fail "$name" "$msg"; return 0; fi
    pass "$name"
}

# decl_then_impl NAME CC_IMPL LANG_IMPL CC_MAIN LANG_MAIN
decl_then_impl() {
    local name=$1 cci=$2 li=$3 ccm=$4 lm=$5 si sm
    needc "$name" "$cci" || return 0
    needc "$name" "$ccm" || return 0
    local d msg
    d=$(mkd "$name")
    [ "$li" = c ] && si="c99" || si="c++98"
    [ "$lm" = c ] && sm="c99" || sm="c++98"
    # shellcheck disable=SC2046
    if ! "$cci" $(langflags "$li" "$si") -O0 "${HAVE[@]}" -I. -I"$T" -c "$T/decl_then_impl.c" \
        -o "$d/impl.o" > "$d/impl.log" 2>&1; then
        fail "$name" "decl_then_impl.c: $(errsum "$d/impl.log")"; return 0
    fi
    # shellcheck disable=SC2046
    if ! "$ccm" $(langflags "$lm" "$sm") -O0 "${HAVE[@]}" -I. -I"$T" -c "$T/decl_only_main.c" \
        -o "$d/main.o" > "$d/main.log" 2>&1; then
        fail "$name" "decl_only_main.c: $(errsum "$d/main.log")"; return 0
    fi
    # link with the C++ driver when either side is C++
    local ld=$ccm
    [ "$li" = c++ ] && ld=$cci
    if ! "$ld" "$d/main.o" "$d/impl.o" -o "$d/t" -lm > "$d/link.log" 2>&1; then
        fail "$name" "link: $(errsum "$d/link.log")"; return 0
    fi
    if ! msg=$(runprog "$d/t" "$d/run.log"); then fail "$name" "$msg"; return 0; fi
    pass "$name"
}

# two_static NAME CC LANG STD
two_static() {
    local name=$1 cc=$2 lang=$3 std=$4 opt=$5
    needc "$name" "$cc" || return 0
    needc "$name" nm || return 0
    local d x msg glob
    d=$(mkd "$name")
    for x in a b main; do
        local l=$lang s=$std
        [ "$x" = main ] && { l="c"; s="c99"; }
        local cx=$cc
        [ "$x" = main ] && [ "$lang" = c++ ] && cx=${cc%++}
        [ "$cx" = g ] && cx=gcc
        # shellcheck disable=SC2046
        if ! "$cx" $(langflags "$l" "$s") "$opt" "${HAVE[@]}" -I. -I"$T" -c "$T/two_static_copies_$x.c" \
            -o "$d/$x.o" > "$d/$x.log" 2>&1; then
            fail "$name" "two_static_copies_$x.c: $(errsum "$d/$x.log")"; return 0
        fi
    done
    for x in a b; do
        glob=$(nm -g --defined-only "$d/$x.o" 2>/dev/null | awk '{print $NF}' | sed 's/^_//' |
               grep -E '^(fovsdf|fovlp|fovpt|fov)_' | tr '\n' ' ')
        if [ -n "$glob" ]; then
            fail "$name" "global symbols in the STATIC copy two_static_copies_$x.o: $glob"; return 0
        fi
    done
    if ! "$cc" "$d/main.o" "$d/a.o" "$d/b.o" -o "$d/t" -lm > "$d/link.log" 2>&1; then
        fail "$name" "link: $(errsum "$d/link.log")"; return 0
    fi
    if ! msg=$(runprog "$d/t" "$d/run.log"); then fail "$name" "$msg"; return 0; fi
    pass "$name"
}

# hooks NAME CC LANG STD DEFINE: hooks_stub.c compiled, symbols checked, linked, run
hooks() {
    local name=$1 cc=$2 lang=$3 std=$4
    shift 4
    needc "$name" "$cc" || return 0
    needc "$name" gcc || return 0
    needc "$name" nm || return 0
    local d bad msg
    d=$(mkd "$name")
    # shellcheck disable=SC2046
    if ! "$cc" $(langflags "$lang" "$std") -O2 "${HAVE[@]}" "$@" -I. -I"$T" -c "$T/hooks_stub.c" \
        -o "$d/hooks.o" > "$d/compile.log" 2>&1; then
        fail "$name" "$(errsum "$d/compile.log")"; return 0
    fi
    bad=$(undef_syms nm "$d/hooks.o" | grep -vE '^hook_' | grep -vE "$HOSTED_OK" | tr '\n' ' ')
    if [ -n "$bad" ]; then
        fail "$name" "hooks_stub.o references functions besides the hooks and memset/memcpy: $bad"
        return 0
    fi
    # shellcheck disable=SC2046
    if ! gcc $(langflags c c99) -O2 -c "$T/hooks_stub_fns.c" -o "$d/fns.o" > "$d/fns.log" 2>&1; then
        fail "$name" "hooks_stub_fns.c: $(errsum "$d/fns.log")"; return 0
    fi
    if ! "$cc" "$d/hooks.o" "$d/fns.o" -o "$d/t" -lm > "$d/link.log" 2>&1; then
        fail "$name" "link: $(errsum "$d/link.log")"; return 0
    fi
    if ! msg=$(runprog "$d/t" "$d/run.log"); then fail "$name" "$msg"; return 0; fi
    pass "$name" "$(head -n 1 "$d/run.log")"
}

# hooks_partial NAME CC: only FOV_SQRTF defined -> the compile must fail with an #error
hooks_partial() {
    local name=$1 cc=$2
    needc "$name" "$cc" || return 0
    local d
    d=$(mkd "$name")
    # shellcheck disable=SC2046
    if "$cc" $(langflags c c99) -O0 "${HAVE[@]}" -DHOOKS_PARTIAL -I. -I"$T" -c "$T/hooks_stub.c" \
        -o "$d/hooks.o" > "$d/compile.log" 2>&1; then
        fail "$name" "defining only FOV_SQRTF compiled without an #error"; return 0
    fi
    if ! grep -q '#error' "$d/compile.log" && ! grep -qi 'error: .*FOV_' "$d/compile.log"; then
        fail "$name" "the compile failed, but not with the hooks' #error: $(errsum "$d/compile.log")"
        return 0
    fi
    pass "$name" "$(grep -m1 -o 'error: .*' "$d/compile.log" | head -c 160)"
}

# symcheck NAME NM OBJ: no soft-double routine, no undefined symbol besides memset/memcpy.
# Allowed as well: the ARM EABI names of memset/memcpy (__aeabi_memcpy4, __aeabi_memclr8,
# ...; clang emits them for struct copies) and the wasm linker-synthesised globals
# (__stack_pointer, ...), which are not functions of any library.
FREE_OK='^(memset|memcpy|__aeabi_mem(cpy|set|clr)[48]?|__stack_pointer|__indirect_function_table|__memory_base|__table_base)$'
symcheck() {
    local name=$1 nmtool=$2 obj=$3 dbl rt other
    dbl=$(undef_syms "$nmtool" "$obj" | grep -E "$SOFT_DOUBLE" | tr '\n' ' ')
    rt=$(undef_syms "$nmtool" "$obj" | grep -vE "$SOFT_DOUBLE" | grep -vE "$FREE_OK" |
         grep -E '^__' | tr '\n' ' ')
    other=$(undef_syms "$nmtool" "$obj" | grep -vE "$SOFT_DOUBLE" | grep -vE "$FREE_OK" |
            grep -vE '^__' | tr '\n' ' ')
    if [ -n "$dbl" ] || [ -n "$rt" ] || [ -n "$other" ]; then
        fail "$name" "undefined symbols besides memset/memcpy: software double: ${dbl:-none}; compiler runtime (libgcc/compiler-rt) helpers: ${rt:-none}; other: ${other:-none} ($nmtool -u $obj)"
        return 1
    fi
    return 0
}

FREE_DEFS=(-DFOV_NO_LIBM '-DFOV_ASSERT(c)=')

free_wasm() {
    local name="freestanding wasm32 (clang -ffreestanding -nostdlib, wasm-ld --no-entry --export-all)"
    needc "$name" clang || return 0
    needc "$name" wasm-ld || return 0
    needc "$name" llvm-nm || return 0
    local d
    d=$(mkd "$name")
    # shellcheck disable=SC2046
    if ! clang --target=wasm32 -ffreestanding -nostdlib $(langflags c c99) -O2 "${HAVE[@]}" \
        "${FREE_DEFS[@]}" -I. -c "$T/freestanding_impl.c" -o "$d/impl.o" > "$d/compile.log" 2>&1; then
        fail "$name" "$(errsum "$d/compile.log")"; return 0
    fi
    symcheck "$name" llvm-nm "$d/impl.o" || return 0
    # shellcheck disable=SC2046
    if ! clang --target=wasm32 -ffreestanding -nostdlib $(langflags c c99) -O2 -c "$T/freestanding_rt.c" \
        -o "$d/rt.o" > "$d/rt.log" 2>&1; then
        fail "$name" "freestanding_rt.c: $(errsum "$d/rt.log")"; return 0
    fi
    if ! wasm-ld --no-entry --export-all "$d/impl.o" "$d/rt.o" -o "$d/lib.wasm" > "$d/link.log" 2>&1; then
        fail "$name" "wasm-ld: $(errsum "$d/link.log")"; return 0
    fi
    # the same through the clang driver
    if ! clang --target=wasm32 -nostdlib -Wl,--no-entry -Wl,--export-all "$d/impl.o" "$d/rt.o" \
        -o "$d/lib2.wasm" > "$d/link2.log" 2>&1; then
        fail "$name" "clang -Wl,--no-entry: $(errsum "$d/link2.log")"; return 0
    fi
    pass "$name" "$(wc -c < "$d/lib.wasm") bytes"
}

free_m4() {
    local opt=$1
    local name="freestanding cortex-m4f (arm-none-eabi-gcc -mfloat-abi=hard -ffreestanding $opt)"
    needc "$name" arm-none-eabi-gcc || return 0
    needc "$name" arm-none-eabi-nm || return 0
    local d
    d=$(mkd "$name")
    # shellcheck disable=SC2046
    if ! arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -ffreestanding \
        $(langflags c c99) "$opt" "${HAVE[@]}" "${FREE_DEFS[@]}" -I. -c "$T/freestanding_impl.c" \
        -o "$d/impl.o" > "$d/compile.log" 2>&1; then
        fail "$name" "$(errsum "$d/compile.log")"; return 0
    fi
    symcheck "$name" arm-none-eabi-nm "$d/impl.o" || return 0
    pass "$name" "no __aeabi_d*/__extendsfdf2/__truncdfsf2; undefined: $(undef_syms arm-none-eabi-nm "$d/impl.o" | tr '\n' ' ')"
}

free_clang() { # NAME TARGET FLAGS...
    local name=$1 target=$2
    shift 2
    needc "$name" clang || return 0
    needc "$name" llvm-nm || return 0
    local d
    d=$(mkd "$name")
    # shellcheck disable=SC2046
    if ! clang --target="$target" "$@" -ffreestanding $(langflags c c99) -O2 "${HAVE[@]}" \
        "${FREE_DEFS[@]}" -I. -c "$T/freestanding_impl.c" -o "$d/impl.o" > "$d/compile.log" 2>&1; then
        fail "$name" "$(errsum "$d/compile.log")"; return 0
    fi
    symcheck "$name" llvm-nm "$d/impl.o" || return 0
    pass "$name" "undefined: $(undef_syms llvm-nm "$d/impl.o" | tr '\n' ' ')"
}

# ---- submit -----------------------------------------------------------------------------
if [ ${#HEADERS[@]} = 0 ]; then
    say "FAIL headers: none of fovsdf.h fovlp.h fovpt.h found in $ROOT"
fi

for h in "${HEADERS[@]}"; do
    P=$(printf '%s' "$h" | tr '[:lower:]' '[:upper:]')
    src=$(tu_c "$h")
    srcxx=$(tu_cc "$h")
    # the matrix: every compiler and standard at -O0 (the language checks), and one -O2 cell
    # per compiler (the flow-analysis warnings, which do not depend on the standard), linked
    # and run: gcc c99, clang c11, g++ c++98, clang++ c++11
    for cc in gcc clang; do
        for std in c99 c11; do
            job cell "matrix $cc -std=$std -O0 $(basename "$src")" "$cc" c "$std" -O0 "$src" 0
        done
        std=c99
        [ "$cc" = clang ] && std=c11
        job cell "matrix $cc -std=$std -O2 $(basename "$src") (linked, run)" "$cc" c "$std" -O2 "$src" 1
    done
    for cc in g++ clang++; do
        for std in c++98 c++11; do
            job cell "matrix $cc -std=$std -O0 $(basename "$srcxx")" "$cc" c++ "$std" -O0 "$srcxx" 0
        done
        std=c++98
        [ "$cc" = clang++ ] && std=c++11
        job cell "matrix $cc -std=$std -O2 $(basename "$srcxx") (linked, run)" "$cc" c++ "$std" -O2 "$srcxx" 1
    done
    # STYLE.md rule 20 extras (front-end warnings: -O0)
    for cc in gcc clang; do
        # shellcheck disable=SC2086
        job cell "style20 $cc -std=c99 -O0 $STYLE20 $(basename "$src")" "$cc" c c99 -O0 "$src" 0 $STYLE20
    done
    for cc in g++ clang++; do
        job cell "style20 $cc -std=c++17 -O0 $(basename "$srcxx")" "$cc" c++ c++17 -O0 "$srcxx" 0
    done
    # documented options, alone and together
    opts="FOV_NO_LIBM FOV_NO_ERROR_STRINGS ${P}_STATIC FOV_DLL NDEBUG"
    [ "$h" = fovsdf ] && opts="$opts FOVSDF_DOUBLE"
    all=()
    for o in $opts; do all+=("-D$o"); done
    for cc in gcc clang g++; do
        lang="c"; std="c99"; s=$src
        [ "$cc" = g++ ] && { lang=c++; std=c++11; s=$srcxx; }
        for o in $opts; do
            # the switches that change only linkage or attributes: -O0 (their warnings come
            # from the front end); those that change code (NO_ERROR_STRINGS compiles the
            # message building out): -O1
            ol=-O1
            case $o in *_STATIC|FOV_DLL) ol=-O0 ;; esac
            job cell "options $cc -std=$std $ol -D$o $(basename "$s")" "$cc" "$lang" "$std" "$ol" "$s" 0 "-D$o"
        done
        job cell "options $cc -std=$std -O2 all of: $opts" "$cc" "$lang" "$std" -O2 "$s" 1 "${all[@]}"
    done
    job nolibm "nolibm gcc: FOV_NO_LIBM $h references no libm symbol, links without -lm, runs" gcc "$h"
    job nolibm "nolibm clang: FOV_NO_LIBM $h references no libm symbol, links without -lm, runs" clang "$h"
done

job decl_then_impl "decl_then_impl gcc (C impl, C main)" gcc c gcc c
job decl_then_impl "decl_then_impl clang (C impl, C main)" clang c clang c
job decl_then_impl "decl_then_impl g++ (C++ impl, C++ main)" g++ c++ g++ c++
job decl_then_impl "decl_then_impl mixed (C impl by gcc, C++ main by g++)" gcc c g++ c++
job decl_then_impl "decl_then_impl mixed (C++ impl by g++, C main by gcc)" g++ c++ gcc c

job cell "impl_twice gcc -std=c99 (linked, run)" gcc c c99 -O0 "$T/impl_twice.c" 1
job cell "impl_twice g++ -std=c++11 (linked, run)" g++ c++ c++11 -O0 "$T/impl_twice.c" 1

job cell "all_three_one_tu gcc -std=c99 (linked, run)" gcc c c99 -O2 "$T/all_three_one_tu.c" 1
job cell "all_three_one_tu clang -std=c11 (linked, run)" clang c c11 -O0 "$T/all_three_one_tu.c" 1
job cell "all_three_one_tu g++ -std=c++98 (linked, run)" g++ c++ c++98 -O0 "$T/all_three_one_tu.c" 1
job cell "all_three_one_tu clang++ -std=c++11 (linked, run)" clang++ c++ c++11 -O2 "$T/all_three_one_tu.c" 1

job two_static "two_static_copies gcc -std=c99 -O2 (a + b + main linked, run)" gcc c c99 -O2
job two_static "two_static_copies clang -std=c11 -O0 (a + b + main linked, run)" clang c c11 -O0
job two_static "two_static_copies g++ -std=c++11 -O0 (a + b as C++, main as C)" g++ c++ c++11 -O0

job hooks "hooks_stub gcc -std=c99 (object-like hook macros)" gcc c c99
job hooks "hooks_stub clang -std=c11 (function-like hook macros)" clang c c11 -DHOOKS_FUNCTION_LIKE
job hooks "hooks_stub g++ -std=c++98 (object-like hook macros)" g++ c++ c++98
job hooks_partial "hooks_stub partial math hooks stop with #error (gcc)" gcc

job free_wasm
job free_m4 -O2
job free_m4 -O0
job free_clang "freestanding thumbv7em-none-eabihf (clang -mcpu=cortex-m4 -mfpu=fpv4-sp-d16)" \
    thumbv7em-none-eabihf -mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard
job free_clang "freestanding riscv32 (clang -march=rv32imafc -mabi=ilp32f)" \
    riscv32-unknown-elf -march=rv32imafc -mabi=ilp32f
job free_clang "freestanding aarch64 (clang --target=aarch64-none-elf: fovpt's NEON traversal)" \
    aarch64-none-elf

wait

# ---- report -----------------------------------------------------------------------------
passed=0
failed=0
for f in "$B"/res/[0-9][0-9][0-9][0-9]; do
    [ -f "$f" ] || continue
    if [ ! -s "$f" ]; then
        say "FAIL internal: check $(basename "$f") printed nothing: $(head -c 300 "$f.err")"
        failed=$((failed + 1))
        continue
    fi
    cat "$f"
    passed=$((passed + $(grep -c '^PASS ' "$f")))
    failed=$((failed + $(grep -c '^FAIL ' "$f")))
done
[ ${#HEADERS[@]} = 0 ] && failed=$((failed + 1))
gen=$(for g in "$B"/gen/*.c; do [ -f "$g" ] && printf '%s ' "$(basename "$g")"; done)
say "# headers: ${HEADERS[*]:-none}${gen:+ (generated matrix TU, no $T/<hdr>.c yet: $gen)}; $(($(date +%s) - START)) s; logs in $B/obj/"
say "$passed passed, $failed failed"
[ "$failed" = 0 ]

#!/usr/bin/env bash
# tests/cmake/run.sh - the fov headers consumed through build systems (docs/build.md).
#
# Run from anywhere:   bash tests/cmake/run.sh
# Builds the tiny consumer project tests/cmake/consumer (main.c: the three headers with
# FOV_IMPL; each config resolves; FOVSDF_VERSION_STRING equals the version the build system
# reports) once per way of getting the headers, runs it, and prints one line per way (PASS name /
# FAIL name: detail / SKIP name: reason (apt-get install -y PKG)), then exactly
# "N passed, N failed" (SKIPs are not counted); exit status 1 when anything failed. With
# CI=true a missing cmake, pkg-config or git is a FAIL, not a SKIP. Everything happens under
# build/cmake-test/ (recreated, and removed at the end unless KEEP=1); no network. The ways
# after cmake_install run JOBS at a time (default: the number of CPUs); the lines print in
# the order below, each with its own seconds.
#   cmake_install      configure + build + `cmake --install --prefix P` of the repository with
#                      CC and CXX pointing at no compiler (so nothing is compiled and no
#                      language is enabled), P differing from the configured prefix: the three
#                      headers land byte-identical in P/include/fov/, P/share/cmake/fov/ holds
#                      fovConfig.cmake, fovConfigVersion.cmake and fovTargets.cmake, fov.pc says
#                      prefix=P, and no test is registered (FOV_BUILD_TESTS defaults to OFF)
#   in_source_refused  `cmake .` in a copy of the repository fails at configure with a message
#                      and the Makefile stays as it was (CMake would generate its own there)
#   add_subdirectory   add_subdirectory(<repository>)
#   fetchcontent_git   FetchContent_Declare(GIT_REPOSITORY file://<a git copy of the working
#                      tree> GIT_TAG <its commit>) + FetchContent_MakeAvailable
#   fetchcontent_disconnected  FETCHCONTENT_FULLY_DISCONNECTED=ON and
#                      FETCHCONTENT_SOURCE_DIR_FOV=<repository>, GIT_REPOSITORY unreachable
#   find_package       find_package(fov <version> EXACT CONFIG REQUIRED COMPONENTS fovsdf
#                      fovlp fovpt) from P; fov_DIR must be P's; find_package(fov 99.0) and a
#                      missing component must not be found
#   cxx_find_package   the same from a C++-only project (LANGUAGES CXX, main.c copied to main.cc,
#                      C++11), linking the umbrella fov::fov
#   tests_option       -DFOV_BUILD_TESTS=ON builds tests/test_versions.c and main.c; ctest passes
#   pkg_config         `pkg-config --cflags --libs fov` from P's fov.pc (Cflags -IP/include/fov,
#                      Libs -lm, --modversion = the version), main.c built with them alone
#   make_install       `make install PREFIX=Q` (and PREFIX=/opt/fov DESTDIR=S: files under S,
#                      fov.pc still says /opt/fov); Q's fov.pc equals P's but for the prefix
#                      line; then the pkg_config build against Q
# The expected version is read from fovsdf.h's first line ("fovsdf.h - vX.Y.Z - ..."), not
# from the macros CMake and the Makefile parse.
# Debian packages: cmake pkg-config git gcc make.

set -u
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$ROOT" || exit 1
B=$ROOT/build/cmake-test
rm -rf "$B"
mkdir -p "$B/out"
IS_CI=0
[ "${CI:-}" = true ] && IS_CI=1
CC=${CC:-cc}
export CC
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
START=$(date +%s)

# ---- reporting: each way is a function that prints one PASS, FAIL or SKIP line ----------
pass() { echo "PASS $1"; }
fail() { local name=$1; shift; echo "FAIL $name: $*"; }
skip() {
    if [ "$IS_CI" = 1 ]; then
        fail "$1" "$2 not found (CI=true: a missing tool is a failure;" \
            "apt-get install -y cmake pkg-config git)"
    else
        echo "SKIP $1: $2 not found (apt-get install -y cmake pkg-config git)"
    fi
}
have() { command -v "$1" >/dev/null 2>&1; }
# logtail LOG: the first error lines of a log (else its last lines), on one line
logtail() {
    local s
    s=$(grep -E -A 2 'CMake Error|error:|Error [0-9]|undefined reference|FAILED|failed' "$1" |
        head -n 6)
    [ -n "$s" ] || s=$(tail -n 4 "$1")
    printf '%s (log: %s)' "$(printf '%s' "$s" | tr -s '\n ' '| ' | cut -c1-500)" "$1"
}
# job runner: run_way NAME runs way_NAME in the background (at most JOBS at once), its
# line goes to $B/out/NN_NAME with the seconds it took; report prints them in order
NWAY=0
run_way() {
    local name=$1
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n 2>/dev/null || sleep 0.2; done
    NWAY=$((NWAY + 1))
    local out
    out=$B/out/$(printf '%02d' "$NWAY")_$name
    (
        t0=$(date +%s)
        line=$("way_$name")
        printf '%s (%d s)\n' "$line" "$(( $(date +%s) - t0 ))" >"$out"
    ) &
}

EXPECT=$(sed -n '1s/^.*fovsdf\.h - v\([0-9][0-9]*\.[0-9][0-9]*\.[0-9][0-9]*\) .*/\1/p' fovsdf.h)
if [ -z "$EXPECT" ]; then
    fail version "no vX.Y.Z on fovsdf.h's first line"
    echo "0 passed, 1 failed"
    exit 1
fi
echo "fovsdf.h declares $EXPECT"

# a copy of the consumer project outside the repository's include path
SRC=$B/consumer-src
cp -r tests/cmake/consumer "$SRC"
P=$B/prefix
# CMake must not pick up a fov from the user's package registry
NOREG="-DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON"
HAVE_CMAKE=0
have cmake && HAVE_CMAKE=1
HAVE_PC=0
have pkg-config && HAVE_PC=1

# consumer NAME CMAKE_ARGS...: configure, build and run the consumer in $B/NAME; prints a
# FAIL line and returns 1 on failure
consumer() {
    local name=$1 d=$B/$1; shift
    if ! cmake --no-warn-unused-cli -S "$SRC" -B "$d" -DFOV_EXPECT_VERSION="$EXPECT" $NOREG "$@" \
            >"$B/$name.log" 2>&1; then
        fail "$name" "configure: $(logtail "$B/$name.log")"; return 1
    fi
    if ! cmake --build "$d" >>"$B/$name.log" 2>&1; then
        fail "$name" "build: $(logtail "$B/$name.log")"; return 1
    fi
    if ! "$d/consumer" >>"$B/$name.log" 2>&1; then
        fail "$name" "the consumer failed: $(logtail "$B/$name.log")"; return 1
    fi
    return 0
}

# same_headers DIR: the three headers in DIR are the repository's
same_headers() {
    local h
    for h in fovsdf.h fovlp.h fovpt.h; do
        cmp -s "$h" "$1/$h" || { echo "$1/$h differs from $h or is missing"; return 1; }
    done
}

# pc_build NAME PCDIR PREFIX: checks fov.pc in PCDIR, builds main.c with its flags, runs it
pc_build() {
    local name=$1 pcdir=$2 prefix=$3 ver cflags libs
    ver=$(PKG_CONFIG_PATH="$pcdir" pkg-config --modversion fov 2>"$B/$name.log") ||
        { fail "$name" "pkg-config --modversion fov: $(logtail "$B/$name.log")"; return; }
    # trailing blanks dropped: pkgconf ends its output with a space
    cflags=$(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags fov | sed 's/[[:space:]]*$//')
    libs=$(PKG_CONFIG_PATH="$pcdir" pkg-config --libs fov | sed 's/[[:space:]]*$//')
    [ "$ver" = "$EXPECT" ] ||
        { fail "$name" "--modversion '$ver', fovsdf.h says '$EXPECT'"; return; }
    [ "$cflags" = "-I$prefix/include/fov" ] ||
        { fail "$name" "--cflags '$cflags', expected '-I$prefix/include/fov'"; return; }
    [ "$libs" = "-lm" ] || { fail "$name" "--libs '$libs', expected '-lm'"; return; }
    # shellcheck disable=SC2086
    if ! $CC -std=c99 -Wall -Wextra -Werror $cflags "-DFOV_EXPECT_VERSION=\"$ver\"" \
            "$SRC/main.c" -o "$B/$name.bin" $libs >>"$B/$name.log" 2>&1; then
        fail "$name" "build with pkg-config's flags: $(logtail "$B/$name.log")"; return
    fi
    "$B/$name.bin" >>"$B/$name.log" 2>&1 ||
        { fail "$name" "the consumer failed: $(logtail "$B/$name.log")"; return; }
    pass "$name"
}

# ---- the ways ---------------------------------------------------------------------------
way_cmake_install() {
    [ $HAVE_CMAKE = 1 ] || { skip cmake_install cmake; return; }
    local d=$B/install-build log=$B/cmake_install.log compilers objs why
    if ! CC=/nonexistent/cc CXX=/nonexistent/c++ cmake -S "$ROOT" -B "$d" \
            -DCMAKE_INSTALL_PREFIX="$B/wrong-prefix" >"$log" 2>&1; then
        fail cmake_install "configure without a compiler: $(logtail "$log")"
    elif ! CC=/nonexistent/cc cmake --build "$d" >>"$log" 2>&1; then
        fail cmake_install "build: $(logtail "$log")"
    elif ! cmake --install "$d" --prefix "$P" >>"$log" 2>&1; then
        fail cmake_install "install: $(logtail "$log")"
    elif compilers=$(find "$d/CMakeFiles" -name 'CMake*Compiler.cmake' | head -3) &&
            [ -n "$compilers" ]; then
        fail cmake_install "a compiler was enabled: $compilers"
    elif objs=$(find "$d" \( -name '*.o' -o -name '*.a' -o -name '*.so' \) | head -3) &&
            [ -n "$objs" ]; then
        fail cmake_install "something was built: $objs"
    elif [ -e "$d/CTestTestfile.cmake" ]; then
        fail cmake_install "tests registered without FOV_BUILD_TESTS"
    elif ! why=$(same_headers "$P/include/fov"); then
        fail cmake_install "$why"
    elif ! ls "$P/share/cmake/fov/fovConfig.cmake" "$P/share/cmake/fov/fovConfigVersion.cmake" \
            "$P/share/cmake/fov/fovTargets.cmake" >/dev/null 2>&1; then
        fail cmake_install "missing package files in $P/share/cmake/fov:" \
            "$(ls "$P/share/cmake/fov" 2>&1 | tr '\n' ' ')"
    elif ! grep -qx "prefix=$P" "$P/share/pkgconfig/fov.pc" 2>/dev/null; then
        fail cmake_install "$P/share/pkgconfig/fov.pc lacks prefix=$P:" \
            "$(head -n 1 "$P/share/pkgconfig/fov.pc" 2>&1)"
    elif grep -q wrong-prefix "$P/share/cmake/fov/"*.cmake "$P/share/pkgconfig/fov.pc"; then
        fail cmake_install "the configured prefix leaked into the installed files"
    else
        touch "$B/installed"
        pass cmake_install
    fi
}

# `cmake .` in a copy of the repository stops at configure and leaves the Makefile alone
way_in_source_refused() {
    [ $HAVE_CMAKE = 1 ] || { skip in_source_refused cmake; return; }
    local d=$B/in-source log=$B/in_source_refused.log
    mkdir -p "$d"
    cp -r CMakeLists.txt cmake Makefile fovsdf.h fovlp.h fovpt.h "$d/"
    if (cd "$d" && cmake .) >"$log" 2>&1; then
        fail in_source_refused "cmake . in the source tree succeeded"
    elif ! cmp -s Makefile "$d/Makefile"; then
        fail in_source_refused "cmake . replaced the Makefile"
    elif ! grep -q "in-source build would overwrite" "$log"; then
        fail in_source_refused "no explanation: $(logtail "$log")"
    else
        pass in_source_refused
    fi
}

way_add_subdirectory() {
    [ $HAVE_CMAKE = 1 ] || { skip add_subdirectory cmake; return; }
    consumer add_subdirectory -DFOV_MODE=subdir -DFOV_SOURCE_DIR="$ROOT" && pass add_subdirectory
}

# FetchContent from a git repository holding the working tree as it is (tracked and new files)
way_fetchcontent_git() {
    [ $HAVE_CMAKE = 1 ] || { skip fetchcontent_git cmake; return; }
    have git || { skip fetchcontent_git git; return; }
    local G=$B/fov-git
    mkdir -p "$G"
    if git -C "$ROOT" rev-parse --git-dir >/dev/null 2>&1; then
        git -C "$ROOT" ls-files -co --exclude-standard -z | tar -C "$ROOT" --null -T - -cf - |
            tar -C "$G" -xf -
    else
        tar -C "$ROOT" --exclude=./build --exclude=./out -cf - . | tar -C "$G" -xf -
    fi
    if ! (cd "$G" && git init -q && git add -A &&
          git -c user.name=fov-test -c user.email=fov-test@localhost commit -qm snapshot) \
            >"$B/fetchcontent_git.log" 2>&1; then
        fail fetchcontent_git "could not make the git copy: $(logtail "$B/fetchcontent_git.log")"
        return
    fi
    consumer fetchcontent_git -DFOV_MODE=fetch -DFOV_GIT_URL="file://$G" \
        -DFOV_GIT_TAG="$(git -C "$G" rev-parse HEAD)" && pass fetchcontent_git
}

way_fetchcontent_disconnected() {
    [ $HAVE_CMAKE = 1 ] || { skip fetchcontent_disconnected cmake; return; }
    consumer fetchcontent_disconnected -DFOV_MODE=fetch -DFOV_GIT_URL=https://fov.invalid/fov.git \
        -DFOV_GIT_TAG=main -DFETCHCONTENT_FULLY_DISCONNECTED=ON \
        -DFETCHCONTENT_SOURCE_DIR_FOV="$ROOT" && pass fetchcontent_disconnected
}

way_find_package() {
    [ $HAVE_CMAKE = 1 ] || { skip find_package cmake; return; }
    [ -e "$B/installed" ] ||
        { fail find_package "no installed prefix (cmake_install failed)"; return; }
    consumer find_package -DFOV_MODE=package -DCMAKE_PREFIX_PATH="$P" || return
    if grep -q "fov_DIR=$P/share/cmake/fov\$" "$B/find_package.log"; then
        pass find_package
    else
        fail find_package "fov_DIR is not $P/share/cmake/fov:" \
            "$(grep fov_DIR= "$B/find_package.log")"
    fi
}

way_cxx_find_package() {
    [ $HAVE_CMAKE = 1 ] || { skip cxx_find_package cmake; return; }
    [ -e "$B/installed" ] ||
        { fail cxx_find_package "no installed prefix (cmake_install failed)"; return; }
    consumer cxx_find_package -DFOV_MODE=package -DFOV_CXX=ON -DCMAKE_PREFIX_PATH="$P" || return
    if grep -q 'The C compiler identification' "$B/cxx_find_package.log"; then
        fail cxx_find_package "a C compiler was enabled in the C++-only project"
    else
        pass cxx_find_package
    fi
}

way_tests_option() {
    [ $HAVE_CMAKE = 1 ] || { skip tests_option cmake; return; }
    local d=$B/tests-option log=$B/tests_option.log
    if ! cmake -S "$ROOT" -B "$d" -DFOV_BUILD_TESTS=ON >"$log" 2>&1; then
        fail tests_option "configure: $(logtail "$log")"
    elif ! cmake --build "$d" >>"$log" 2>&1; then
        fail tests_option "build: $(logtail "$log")"
    elif ! (cd "$d" && ctest --output-on-failure) >>"$log" 2>&1; then
        fail tests_option "ctest: $(logtail "$log")"
    elif ! grep -q '100% tests passed, 0 tests failed out of 2' "$log"; then
        fail tests_option "ctest did not run the two tests: $(logtail "$log")"
    else
        pass tests_option
    fi
}

way_pkg_config() {
    [ $HAVE_PC = 1 ] || { skip pkg_config pkg-config; return; }
    [ -e "$B/installed" ] ||
        { fail pkg_config "no installed prefix (cmake_install failed or was skipped)"; return; }
    pc_build pkg_config "$P/share/pkgconfig" "$P"
}

way_make_install() {
    local Q=$B/make-prefix S=$B/stage log=$B/make_install.log why
    if ! have make; then
        skip make_install make
    elif ! make -s install PREFIX="$Q" >"$log" 2>&1; then
        fail make_install "make install PREFIX=$Q: $(logtail "$log")"
    elif ! make -s install PREFIX=/opt/fov DESTDIR="$S" >>"$log" 2>&1; then
        fail make_install "make install DESTDIR=$S: $(logtail "$log")"
    elif ! why=$(same_headers "$Q/include/fov") ||
            ! why=$(same_headers "$S/opt/fov/include/fov"); then
        fail make_install "$why"
    elif ! grep -qx "prefix=/opt/fov" "$S/opt/fov/share/pkgconfig/fov.pc" 2>/dev/null; then
        fail make_install "with DESTDIR, fov.pc lacks prefix=/opt/fov"
    elif [ -e "$B/installed" ] &&
            ! cmp -s "$Q/share/pkgconfig/fov.pc" \
                <(sed "s|^prefix=.*|prefix=$Q|" "$P/share/pkgconfig/fov.pc"); then
        fail make_install "its fov.pc differs from CMake's beyond the prefix line"
    elif [ $HAVE_PC = 0 ]; then
        skip make_install pkg-config
    else
        pc_build make_install "$Q/share/pkgconfig" "$Q"
    fi
}

# cmake_install first (find_package, pkg_config and make_install use its prefix), then the rest
run_way cmake_install
wait
for w in in_source_refused add_subdirectory fetchcontent_git fetchcontent_disconnected \
         find_package cxx_find_package tests_option pkg_config make_install; do
    run_way "$w"
done
wait

cat "$B"/out/*
NP=$(cat "$B"/out/* | grep -c '^PASS')
NF=$(cat "$B"/out/* | grep -c '^FAIL')
# a way that printed nothing is a failure
NOUT=$(cat "$B"/out/* | grep -c -E '^(PASS|FAIL|SKIP)')
[ "$NOUT" -eq "$NWAY" ] || { echo "FAIL runner: $NWAY ways, $NOUT result lines"; NF=$((NF + 1)); }
echo "cmake tests took $(( $(date +%s) - START )) s"
[ "${KEEP:-0}" = 1 ] || rm -rf "$B"
echo "$NP passed, $NF failed"
[ "$NF" -eq 0 ]
